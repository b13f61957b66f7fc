#!/usr/bin/env bash
# desktop.lab: penumbra-desktop --snippets FILE on W09P2c. The sheet's answer written out draws the
# frame of the sheet's answer (the app's lab with no file of its own); a file that does not compile
# is printed at its line and the window keeps drawing (with the sheet's answer, the last good
# functions); a file with none of the functions is said to be no match; a saved change is read again
# while the window runs. Bad input is exit status 2.
# usage: lab.sh PENUMBRA_DESKTOP OUT_DIR
set -uo pipefail
app=$1 out=$2/lab
here=$(cd "$(dirname "$0")" && pwd) data=$(cd "$(dirname "$0")/../data/snippets" && pwd)
rm -rf "$out" && mkdir -p "$out" || exit 1
fail=0
run() {  # run NAME ARGS...: 5 frames at t = 0.6, the visibility view, a screenshot
  local name=$1; shift
  xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise w09p2c --time 0.6 --aov visibility --filter pcf4x4 \
    --size 256x256 --frames 5 --screenshot "$out/$name.png" "$@" > "$out/$name.log" 2> "$out/$name.err"
}
run answer --snippets "$data/answer.glsl" || { echo "FAIL answer: $(cat "$out/answer.err")"; fail=1; }
grep -q "snippets: .*answer.glsl compiled" "$out/answer.log" && echo "ok answer: compiled" ||
  { echo "FAIL answer: not said compiled: $(cat "$out/answer.log")"; fail=1; }
# A file that writes none of the functions draws the sheet's answer and is said to be no match; the
# control: the answer's own file is not.
run empty --snippets "$data/comment_only.glsl" || { echo "FAIL empty: $(cat "$out/empty.err")"; fail=1; }
if grep -q "snippets: .*comment_only.glsl compiled. No function of the sheet written" "$out/empty.log" &&
   ! grep -q "No function" "$out/answer.log"; then echo "ok comment only: no function of the sheet written"
else echo "FAIL comment only: not said: $(cat "$out/empty.log")"; fail=1; fi
run broken --snippets "$data/broken.glsl" || { echo "FAIL broken: exit non-zero: $(cat "$out/broken.err")"; fail=1; }
if grep -q "snippets: .*broken.glsl:[45]: " "$out/broken.err" || grep -q "snippets: .*broken.glsl: " "$out/broken.err"; then
  echo "ok broken: $(head -1 "$out/broken.err")"
else echo "FAIL broken: no message at its line: $(cat "$out/broken.err")"; fail=1; fi
run no_bias --snippets "$data/no_bias.glsl" || { echo "FAIL no_bias: $(cat "$out/no_bias.err")"; fail=1; }
# The broken file's window draws the sheet's answer: as answer.glsl's frame (a few rounding pixels
# allowed: two programs, GLSL ES 1.00 4.6.1), and not as no_bias.glsl's (the control).
python3 - "$here" "$out/answer.png" "$out/broken.png" "$out/no_bias.png" <<'PY' || fail=1
import sys
sys.path.insert(0, sys.argv[1])
from check_png import read_rgb
def differ(a, b):
    w, h, x = read_rgb(a)
    _, _, y = read_rgb(b)
    return 100.0 * sum(1 for i in range(w * h) if abs(x[3 * i] - y[3 * i]) > 1) / (w * h)
same, control = differ(sys.argv[2], sys.argv[3]), differ(sys.argv[2], sys.argv[4])
ok = same <= 0.1 and control > 1.0
print(("ok" if ok else "FAIL") + f" frames: broken vs answer {same:.3f} % of pixels differ, no_bias vs answer {control:.3f} %")
sys.exit(0 if ok else 1)
PY
# A saved change is read while the window runs.
cp "$data/no_bias.glsl" "$out/live.glsl"
xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise w09p2c --frames 10000 --snippets "$out/live.glsl" \
  > "$out/live.log" 2> "$out/live.err" &
pid=$!
for _ in $(seq 1 100); do grep -q "live.glsl compiled" "$out/live.log" && break; sleep 0.2; done
cp "$data/answer.glsl" "$out/live.glsl"
for _ in $(seq 1 100); do grep -q "live.glsl reloaded: compiled" "$out/live.log" && break; sleep 0.2; done
pkill -TERM -P "$pid" 2> /dev/null; kill "$pid" 2> /dev/null; wait "$pid" 2> /dev/null
if grep -q "live.glsl reloaded: compiled" "$out/live.log"; then echo "ok live: reloaded"
else echo "FAIL live: not reloaded: $(cat "$out/live.log" "$out/live.err" | tail -5)"; fail=1; fi
# An option without its value is named, not the option after it (a negative number is a value).
err=$(env -u DISPLAY "$app" --exercise w09p2c --time --frames 3 2>&1 > /dev/null); rc=$?
if [ $rc -eq 2 ] && [ "$err" = "penumbra-desktop: error: --time: needs a value (got the option --frames instead) (see penumbra-desktop --help)" ]
then echo "ok --time --frames 3: $err"; else echo "FAIL --time --frames 3: exit $rc: $err"; fail=1; fi
err=$(env -u DISPLAY "$app" --exercise w09p2c --time -0.5 --frames 0 2>&1 > /dev/null)
case "$err" in *"--frames: must lie"*) echo "ok --time -0.5 is a value: $err";; *) echo "FAIL --time -0.5: $err"; fail=1;; esac
# Bad input: one line, exit status 2, no window needed.
for args in "--snippets $out/missing.glsl" "--exercise volumes --snippets $data/answer.glsl"; do
  err=$(env -u DISPLAY "$app" $args 2>&1 > /dev/null); rc=$?
  if [ $rc -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ]; then echo "FAIL $args: exit $rc: $err"; fail=1
  else echo "ok $args: $err"; fi
done
exit $fail
