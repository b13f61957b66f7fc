#!/usr/bin/env bash
# desktop.title: penumbra-desktop's window title, read off the X server (xwininfo), is the exercise
# and its controls with the page's names and values, and follows the keys: E (encoding) and F
# (filter) pressed in the window (--keys) change it at once, each change printed (--print-title)
# and the last one the title the window has. The keys are printed at start, each with the option
# it changes.
# usage: title.sh PENUMBRA_DESKTOP OUT_DIR
set -euo pipefail
app=$1 out=$2/title
mkdir -p "$out"
log="$out/desktop.log" titles="$out/window-titles.txt"
rm -f "$log" "$titles"
command -v xwininfo >/dev/null || { echo "desktop title: xwininfo missing (Debian's x11-utils: bash scripts/setup.sh)"; exit 1; }

# Inside the virtual X server: the app runs until its title shows the second key's change, the
# window's title is read from the server, then the app (started here, by its pid) is stopped.
export app log titles
xvfb-run -a -s "-screen 0 1280x1024x24" bash -c '
  "$app" --exercise w09p2c --time 0.6 --frames 10000 --keys ef --print-title >"$log" 2>&1 &
  pid=$!
  for _ in $(seq 300); do
    grep -q "^title: .*filter=pcf4x4" "$log" && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  sleep 0.3
  xwininfo -root -tree | grep -o "\"W09P2c | [^\"]*\"" >"$titles" || true
  kill "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
'

fail=0
printed=$(sed -n 's/^title: //p' "$log")
echo "printed titles:"; sed 's/^/  /' <<<"$printed"
echo "window titles (xwininfo):"; sed 's/^/  /' "$titles"
base="W09P2c | light=on jump=on budget-ms=0 max-error=0 encoding=ENC filter=FILTER bias=auto map-faces=auto precision=highp map-size=1024 aov=color map-view=on time=0.6 | "
expect_line() {  # expect_line N ENC FILTER: the Nth title printed
  local want=${base/ENC/$2}
  want=${want/FILTER/$3}
  local got
  got=$(sed -n "${1}p" <<<"$printed")
  if [[ "$got" != "$want"*" ms/frame" ]]; then echo "FAIL: title $1 is '$got', expected '$want... ms/frame'"; fail=1; fi
}
expect_line 1 rgba hard      # as started
expect_line 2 depthtex hard  # E: rgba -> depthtex (llvmpipe has the depth texture)
expect_line 3 depthtex pcf4x4  # F: hard -> pcf4x4
grep -q "^encoding = depthtex" "$log" || { echo "FAIL: E did not report 'encoding = depthtex'"; fail=1; }
grep -q "^filter = pcf4x4" "$log" || { echo "FAIL: F did not report 'filter = pcf4x4'"; fail=1; }
# The window's own title: the last one printed, up to its ms/frame (which changes twice a second).
# (The server lists GLFW's window and, with no window manager, helper windows named as it started.)
last=$(sed -n 3p <<<"$printed")
if [ -z "$last" ] || ! grep -Fq "\"${last% | *} | " "$titles"; then
  echo "FAIL: no window's title starts with the last title printed '${last% | *} | '"; fail=1
fi
# The keys printed at start, each with the option it changes.
for pair in "E|encoding" "F|filter" "M|map-size" "L|light" "\[ \]|bias" "U|bias" "Space|time" "4|exercise w09p2c"; do
  key=${pair%|*} option=${pair#*|}
  grep -Eq "^  $key +$option " "$log" || { echo "FAIL: no key line for '$key' changing '$option'"; fail=1; }
done
[ "$fail" = 0 ] && echo "desktop title: the title follows E and F, and the window has it"
exit "$fail"
