#!/usr/bin/env bash
# desktop.stencil-portal: the stencil exercise with --effects portal in a real window (Xvfb), frozen
# at t = 0.6: the window's frame matches `penumbra render` of the settings the app prints on P
# (mean <= 1.5 levels, <= 0.5% of the pixels off by more than 16), the other scene's lawn is seen
# (its green: 0.5..20% of the frame, none in the CLI's frame without the portal), and its own
# shadows are in it (the CLI's frame with --technique none differs there).
# usage: portal.sh PENUMBRA_DESKTOP PENUMBRA OUT_DIR
set -euo pipefail
app=$1 cli=$2 out=$3/stencil-portal
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
rm -f "$out"/*.png
log="$out/desktop.log"
if ! xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise stencil --effects portal --time 0.6 --frames 5 --keys p \
     --screenshot "$out/desktop.png" >"$log" 2>&1; then
  echo "desktop stencil-portal: penumbra-desktop failed:"; cat "$log"; exit 1
fi
grep -q "^5 frames" "$log" || { echo "desktop stencil-portal: did not render 5 frames:"; cat "$log"; exit 1; }
command=$(grep -m 1 "^penumbra render " "$log") || { echo "desktop stencil-portal: P printed no command:"; cat "$log"; exit 1; }
[[ "$command" == *"--effects portal"* ]] || { echo "desktop stencil-portal: P printed '$command', no --effects portal"; exit 1; }
read -r -a args <<<"${command#penumbra render }"
render() {  # render FILE OPTION VALUE: the printed command with OPTION's value replaced
  local file=$1 opt=$2 value=$3 a=("${args[@]}")
  for i in "${!a[@]}"; do [ "${a[$i]}" = "$opt" ] && a[$((i + 1))]=$value; done
  "$cli" render "${a[@]}" --out "$out/$file.png" >/dev/null
}
render cli --effects portal
render no-portal --effects none
render unshadowed --technique none
python3 - "$here" "$out" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from check_png import read_png
out = sys.argv[2]
def load(name):
    w, h, c, rows = read_png(f"{out}/{name}.png")
    return w, h, [[row[x * c:x * c + 3] for x in range(w)] for row in rows]
w, h, win = load("desktop")
_, _, cli = load("cli")
_, _, none = load("no-portal")
_, _, flat = load("unshadowed")
n = w * h
diffs = [max(abs(a - b) for a, b in zip(win[y][x], cli[y][x])) for y in range(h) for x in range(w)]
mean = sum(sum(abs(a - b) for a, b in zip(win[y][x], cli[y][x])) for y in range(h) for x in range(w)) / (3 * n)
off = sum(d > 16 for d in diffs) / n
green = lambda p: p[1] > p[0] + 25 and p[1] > p[2] + 25
lawn = sum(green(win[y][x]) for y in range(h) for x in range(w)) / n
lawn_before = sum(green(none[y][x]) for y in range(h) for x in range(w))
shadowed = sum(green(flat[y][x]) and sum(cli[y][x]) < 0.6 * sum(flat[y][x]) for y in range(h) for x in range(w))
print(f"window against penumbra render: mean {mean:.3f} levels, {100 * off:.3f}% off by > 16; lawn {100 * lawn:.2f}% "
      f"of the frame ({lawn_before} green pixels without the portal); {shadowed} lawn pixels in the other scene's shadows")
bad = []
if mean > 1.5 or off > 0.005: bad.append("the window's frame is not the CLI's")
if not 0.005 <= lawn <= 0.2 or lawn_before: bad.append("the other scene's lawn is not seen through the portal alone")
if shadowed < 100: bad.append("no shadows in the other scene")
if bad: sys.exit("desktop stencil-portal: " + "; ".join(bad))
PY
