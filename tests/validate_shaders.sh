#!/usr/bin/env bash
# Every shader file (as written, no defines) and every variant the renderer can build, validated
# as GLSL ES 1.00 by glslangValidator. usage: validate_shaders.sh PENUMBRA GLSLANGVALIDATOR OUTDIR
set -euo pipefail
penumbra=$1 validator=$2 out=$3
rm -rf "$out"
"$penumbra" shaders --out "$out" >/dev/null
n=0 bad=0
for f in "$out"/*.vert "$out"/*.frag; do
  head -n1 "$f" | grep -qx '#version 100' || { echo "not GLSL ES 1.00: $f"; bad=$((bad + 1)); }
  # glslang does not know GL_EXT_draw_buffers (GLES 2's several colour outputs); gl_FragData[i]
  # itself is the core language's, so the G-buffer's variants are checked without the line.
  sed -i '/^#extension GL_EXT_draw_buffers : require$/d' "$f"
  if ! log=$("$validator" "$f" 2>&1); then
    echo "FAILED: $f"; echo "$log"; bad=$((bad + 1))
  fi
  n=$((n + 1))
done
[ "$n" -gt 20 ] || { echo "only $n shader files written: expected every variant"; exit 1; }
echo "$((n - bad)) passed, $bad failed"
[ "$bad" -eq 0 ]
