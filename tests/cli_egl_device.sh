#!/usr/bin/env bash
# `penumbra caps` names the implementation (GL_VENDOR, GL_RENDERER, GL_VERSION, EGL's vendor and
# version, the display's device, the fragment shader's highp and mediump formats) and lists the EGL
# devices; --egl-device N and PENUMBRA_EGL_DEVICE=N render on device N (EGL_EXT_platform_device);
# an index out of range, or not an index, is one line naming the devices there are, exit status 2,
# no output file. On Mesa without a GPU the one device is the software one (EGL_MESA_device_software).
# usage: cli_egl_device.sh PENUMBRA WORKDIR
set -uo pipefail
penumbra=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
unset PENUMBRA_EGL_DEVICE
fail=0
bad() { echo "FAIL $*"; fail=1; }

"$penumbra" caps > caps.txt 2> caps.err || bad "caps exited non-zero: $(cat caps.err)"
for line in "^GL_VENDOR: ." "^GL_RENDERER: ." "^GL_VERSION: ." "^EGL vendor: ." "^EGL version: [0-9]" \
            "^EGL display's device: ." "^fragment highp float \(glGetShaderPrecisionFormat\): range 2\^-[0-9]+ to 2\^[0-9]+, precision [0-9]+ bits$" \
            "^fragment mediump float \(glGetShaderPrecisionFormat\): range 2\^-[0-9]+ to 2\^[0-9]+, precision [0-9]+ bits$" \
            "^EGL devices: " "^in use: the default, EGL_MESA_platform_surfaceless$"; do
  grep -qE "$line" caps.txt || bad "caps has no line matching '$line'"
done
head -1 caps.txt | grep -qE "^EGL [0-9]+\.[0-9]+ surfaceless \(" || bad "caps' first line is not the surfaceless platform's: $(head -1 caps.txt)"

count=$(sed -n 's/^EGL devices: \([0-9][0-9]*\) .*/\1/p' caps.txt)
if [ -z "$count" ]; then
  echo "note: EGL lists no devices here ($(grep '^EGL devices' caps.txt)): --egl-device untried"
  [ "$fail" -eq 0 ] && echo "cli_egl_device: all passed"
  exit "$fail"
fi
[ "$(grep -cE '^  [0-9]+: .' caps.txt)" -eq "$count" ] || bad "caps says $count devices but lists $(grep -cE '^  [0-9]+: ' caps.txt)"
echo "ok caps: $count EGL device(s): $(grep -E '^  [0-9]+: ' caps.txt | sed 's/^ *//' | tr '\n' ';')"

if [ "$count" -ge 1 ]; then
  "$penumbra" caps --egl-device 0 > caps0.txt 2> caps0.err || bad "caps --egl-device 0 exited non-zero: $(cat caps0.err)"
  grep -q "^in use: EGL device 0$" caps0.txt || bad "caps --egl-device 0 does not say device 0 is in use"
  head -1 caps0.txt | grep -qE "^EGL [0-9]+\.[0-9]+ device 0 \[" || bad "caps --egl-device 0's first line: $(head -1 caps0.txt)"
  PENUMBRA_EGL_DEVICE=0 "$penumbra" caps > caps0env.txt 2>&1 && grep -q "^in use: EGL device 0$" caps0env.txt \
    || bad "PENUMBRA_EGL_DEVICE=0 caps: $(tail -1 caps0env.txt)"
  # A render on device 0 through both ways of choosing it, and the default's.
  "$penumbra" render --egl-device 0 --size 64x64 --map-size 256 --out dev0.png 2> dev0.err || bad "render --egl-device 0: $(cat dev0.err)"
  PENUMBRA_EGL_DEVICE=0 "$penumbra" render --size 64x64 --map-size 256 --out dev0env.png 2> dev0env.err \
    || bad "PENUMBRA_EGL_DEVICE=0 render: $(cat dev0env.err)"
  "$penumbra" render --size 64x64 --map-size 256 --out default.png 2> default.err || bad "render: $(cat default.err)"
  for f in dev0.png dev0env.png default.png; do [ -s "$f" ] || bad "no $f"; done
  # The same renderer by both platforms (Mesa's software device is llvmpipe): the same image.
  if [ "$(grep '^GL_RENDERER' caps.txt)" = "$(grep '^GL_RENDERER' caps0.txt)" ]; then
    cmp -s dev0.png default.png && echo "ok render on device 0: the default's image" || bad "device 0 and the default differ on one renderer"
  fi
fi

# Out of range, not an index: one line naming how many devices there are, exit 2, no file.
refused() {  # NAME EXPECTED-TEXT COMMAND...
  local name=$1 want=$2; shift 2
  "$@" > "$name.out" 2> "$name.err"
  local rc=$?
  [ "$rc" -eq 2 ] || bad "$name: exit status $rc, want 2"
  [ "$(wc -l < "$name.err")" -eq 1 ] || bad "$name: want one line on stderr, got: $(cat "$name.err")"
  grep -qF -- "$want" "$name.err" || bad "$name: '$(cat "$name.err")' does not say '$want'"
  [ ! -e "$name.png" ] || bad "$name: wrote $name.png"
  grep -q "Segmentation\|Aborted\|terminate" "$name.err" && bad "$name: crashed"
  echo "ok $name: $(cat "$name.err")"
}
if [ "$count" -eq 1 ]; then found="1 found: index 0"; elif [ "$count" -eq 0 ]; then found="none found"; else found="$count found: indices 0 to $((count - 1))"; fi
refused out-of-range "no such EGL device ($found)" "$penumbra" render --egl-device "$count" --size 16x16 --out out-of-range.png
refused out-of-range-caps "--egl-device '$((count + 5))': no such EGL device ($found)" "$penumbra" caps --egl-device $((count + 5))
refused env-out-of-range "PENUMBRA_EGL_DEVICE '$count': no such EGL device ($found)" \
  env PENUMBRA_EGL_DEVICE="$count" "$penumbra" render --size 16x16 --out env-out-of-range.png
refused not-an-index "expected an EGL device index" "$penumbra" render --egl-device -1 --size 16x16 --out not-an-index.png
refused env-not-an-index "expected an EGL device index" env PENUMBRA_EGL_DEVICE=gpu0 "$penumbra" caps

[ "$fail" -eq 0 ] && echo "cli_egl_device: all passed"
exit "$fail"
