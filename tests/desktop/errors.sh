#!/usr/bin/env bash
# desktop.errors: bad input to penumbra-desktop gets one line naming the problem and exit status 2,
# before any window opens (no X server is needed for these).
# usage: errors.sh PENUMBRA_DESKTOP OUT_DIR
set -uo pipefail
app=$1 out=$2
mkdir -p "$out"
fail=0
expect() {  # expect PATTERN ARGS...
  local pattern=$1; shift
  local err rc
  err=$(env -u DISPLAY "$app" "$@" 2>&1 >/dev/null); rc=$?
  if [ "$rc" -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ] || ! grep -q -- "$pattern" <<<"$err"; then
    echo "FAIL: penumbra-desktop $* -> exit $rc, stderr: $err"; fail=1
  else
    echo "ok: $* -> $err"
  fi
}
expect "unknown value 'w10'" --exercise w10
expect "unknown value 'maybe' (on, off)" --light maybe
expect "unknown value 'r16'" --encoding r16
expect "unknown value 'lowp'" --precision lowp
expect "unknown value 'inside' (scene, in-shadow)" --exercise volumes --eye inside
expect "unknown value 'zmaybe' (auto, zpass, zfail)" --volume-method zmaybe
expect "light-radius" --exercise soft --light-radius -1
expect "set by the exercise" --exercise w09p2c --technique volumes
expect "or 'auto', 'sheet'" --bias often
expect "must end in .png" --frames 3 --screenshot "$out/x.jpg"
expect "needs --frames" --screenshot "$out/x.png"
expect "width and height must be at least 1" --size 0x10
expect "is not a key here" --keys "ef!"
expect "expected WIDTHxHEIGHT" --resize 640
expect "unexpected argument" stray
[ ! -e "$out/x.png" ] && [ ! -e "$out/x.jpg" ] || { echo "FAIL: a file was written"; fail=1; }
exit $fail
