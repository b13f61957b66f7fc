#!/usr/bin/env bash
# GPU run 3 (2026-11-28): the rings at 1dbc40d (the packed map's 16-bit depth buffer): the GL ring
# without the every-variant test, the extremes ring, then the every-variant test alone.
set -u
cd "$(dirname "$0")"
out=${OUT:-/tmp/out}
mkdir -p "$out"
t0=$(date +%s)
stamp() { echo "$1 at $(( $(date +%s) - t0 )) s" | tee -a "$out/progress.log"; }
tar -xJf penumbra-bundle.tar.xz -C /tmp && stamp unpacked
B=/tmp/penumbra-bundle/run.sh
cat /tmp/penumbra-bundle/COMMIT >> "$out/progress.log"
export PENUMBRA_OUT=/tmp/ptests
cd /tmp
timeout 120 $B gl --gtest_filter='-RendererGl.EveryShaderVariantCompilesOnTheContext' > "$out/gl.log" 2>&1; echo "gl rc $?" >> "$out/gl.log"
stamp gl
timeout 90 $B extremes > "$out/extremes.log" 2>&1; echo "extremes rc $?" >> "$out/extremes.log"
stamp extremes
timeout 330 $B gl --gtest_filter='RendererGl.EveryShaderVariantCompilesOnTheContext' > "$out/variants.log" 2>&1; echo "variants rc $?" >> "$out/variants.log"
stamp variants
