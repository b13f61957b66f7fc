#!/usr/bin/env bash
# GPU run of 2026-11-29: the GL and extremes rings at this commit (the first on NVIDIA since the
# soft shadows' geometric horizon, GL_OES_standard_derivatives, and the lattice light samples), the
# soft bench on the card, then the every-variant compile test with the time that is left.
set -u
cd "$(dirname "$0")/../../.."
out=${OUT:-/tmp/out}
mkdir -p "$out"
t0=$(date +%s)
# At most 8 files come back: the small ones go to info.txt, the soft bench's folder to soft.tar.
stamp() { echo "$1 at $(( $(date +%s) - t0 )) s" | tee -a "$out/info.txt"; }
tar -xJf build/penumbra-bundle.tar.xz -C /tmp && stamp unpacked
B=/tmp/penumbra-bundle/run.sh
cat /tmp/penumbra-bundle/COMMIT >> "$out/info.txt"
nvidia-smi --query-gpu=name,driver_version,clocks.current.sm,clocks.max.sm --format=csv >> "$out/info.txt" 2>&1
nproc >> "$out/info.txt"
$B caps >> "$out/info.txt" 2>&1
export PENUMBRA_OUT=/tmp/ptests
cd /tmp
timeout 120 $B gl --gtest_filter='-RendererGl.EveryShaderVariantCompilesOnTheContext' > "$out/gl.log" 2>&1; echo "gl rc $?" >> "$out/gl.log"
stamp gl
timeout 120 $B extremes > "$out/extremes.log" 2>&1; echo "extremes rc $?" >> "$out/extremes.log"
stamp extremes
# Warm the card (it idles at low clocks), then the soft bench: errors are the driver's, times the card's.
timeout 20 $B penumbra render --size 1920x1080 --time 0.6 --frames 400 --out none > /dev/null 2>&1
# The bench names its scenes relative to the working directory (tests/data/...): the bundle's.
(cd /tmp/penumbra-bundle && timeout 240 $B penumbra bench --soft --out-dir /tmp/soft > "$out/soft.log" 2>&1; echo "soft rc $?" >> "$out/soft.log")
rm -f /tmp/soft/*.svg; tar -cf "$out/soft.tar" -C /tmp soft
stamp soft
nvidia-smi --query-gpu=clocks.current.sm --format=csv >> "$out/info.txt" 2>&1
left=$(( 540 - ($(date +%s) - t0) ))
if [ "$left" -gt 30 ]; then
  timeout "$left" $B gl --gtest_filter='RendererGl.EveryShaderVariantCompilesOnTheContext' > "$out/variants.log" 2>&1
  echo "variants rc $? (limit $left s)" >> "$out/variants.log"
fi
stamp variants
