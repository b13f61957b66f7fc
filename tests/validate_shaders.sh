#!/usr/bin/env bash
# Every shader file (as written, no defines) and every variant the renderer can build, validated
# as GLSL ES 1.00 by glslangValidator. usage: validate_shaders.sh PENUMBRA GLSLANGVALIDATOR OUTDIR
#
# glslangValidator takes many files in one run and compiles each on its own (no -l: nothing is
# linked), naming each file before its errors; so the 8,000-odd files go in runs of 400, not one
# process each (one each took 20 minutes beside the browser tests on 2 cores). The control: a copy
# of one variant with a type error is validated in the same runs, and must be named as failed.
set -euo pipefail
penumbra=$1 validator=$2 out=$3
rm -rf "$out"
"$penumbra" shaders --out "$out" >/dev/null
shopt -s nullglob
files=("$out"/*.vert "$out"/*.frag)
n=${#files[@]}
[ "$n" -gt 20 ] || { echo "only $n shader files written: expected every variant"; exit 1; }
bad=0
# The first line of every file, in one awk.
while IFS= read -r f; do
  echo "not GLSL ES 1.00: $f"; bad=$((bad + 1))
done < <(awk 'FNR == 1 { if ($0 != "#version 100") print FILENAME; nextfile }' "${files[@]}")
# glslang does not know GL_EXT_draw_buffers (GLES 2's several colour outputs); gl_FragData[i]
# itself is the core language's, so the G-buffer's variants are checked without the line.
grep -lx '#extension GL_EXT_draw_buffers : require' "${files[@]}" | while IFS= read -r f; do
  sed -i '/^#extension GL_EXT_draw_buffers : require$/d' "$f"
done
control_dir=$(mktemp -d)
trap 'rm -rf "$control_dir"' EXIT
control="$control_dir/control_type_error.frag"
cp "$(printf '%s\n' "${files[@]}" | grep -m1 '\.frag$')" "$control"
printf 'void penumbra_control() { int x = 1.0; }\n' >>"$control"
log="$control_dir/log"
printf '%s\0' "${files[@]}" "$control" | xargs -0 -n 400 "$validator" >"$log" 2>&1 || true
# The log: each file's name on a line of its own, then its errors, if any.
failed=$(awk -v out="$out/" -v ctl="$control" '
  index($0, out) == 1 || $0 == ctl { file = $0; next }
  /^ERROR:/ && file != "" && !(file in seen) { seen[file] = 1; print file }' "$log")
grep -qxF "$control" <<<"$failed" || { echo "the control (a type error) was not reported: is $validator validating?"; cat "$log"; exit 1; }
while IFS= read -r f; do
  [ -n "$f" ] && [ "$f" != "$control" ] || continue
  echo "FAILED: $f"
  awk -v f="$f" 'index($0, "/") == 1 || /\.(vert|frag)$/ { on = ($0 == f); next } on' "$log"
  bad=$((bad + 1))
done <<<"$failed"
echo "$((n - bad)) passed, $bad failed (of $n; the control failed as it must)"
[ "$bad" -eq 0 ]
