#!/usr/bin/env bash
# desktop.multipass-deferred: the multipass exercise in a real window (Xvfb), frozen at t = 0.6, its
# keys pressed: 0 (post: shadow blur -> none), 9 (shading: forward -> deferred), , twice (lights:
# 0 -> 8 -> 32). The settings the app prints on P must say so; the window's frame must match
# `penumbra render` of them (mean <= 1.5 levels, <= 0.5% of the pixels off by more than 16); the
# CLI's deferred frame must equal its forward one within 2 levels but on 0.1% of the pixels (where
# the shadow test flips between the two programs), and the lights must show (the frame with
# --lights 0 differs by more than 8 levels on over 2% of the pixels).
# usage: deferred.sh PENUMBRA_DESKTOP PENUMBRA OUT_DIR
set -euo pipefail
app=$1 cli=$2 out=$3/multipass-deferred
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
rm -f "$out"/*.png
log="$out/desktop.log"
if ! xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise multipass --time 0.6 --frames 8 --keys "09,,p" \
     --screenshot "$out/desktop.png" >"$log" 2>&1; then
  echo "desktop multipass-deferred: penumbra-desktop failed:"; cat "$log"; exit 1
fi
grep -q "^8 frames" "$log" || { echo "desktop multipass-deferred: did not render 8 frames:"; cat "$log"; exit 1; }
command=$(grep -m 1 "^penumbra render " "$log") || { echo "desktop multipass-deferred: P printed no command:"; cat "$log"; exit 1; }
for want in "--post none" "--shading deferred" "--lights 32"; do
  [[ "$command" == *"$want "* ]] || { echo "desktop multipass-deferred: P printed '$command', no '$want'"; exit 1; }
done
read -r -a args <<<"${command#penumbra render }"
render() {  # render FILE OPTION VALUE: the printed command with OPTION's value replaced
  local file=$1 opt=$2 value=$3 a=("${args[@]}")
  for i in "${!a[@]}"; do [ "${a[$i]}" = "$opt" ] && a[$((i + 1))]=$value; done
  "$cli" render "${a[@]}" --out "$out/$file.png" >/dev/null 2>&1
}
render cli --shading deferred
render forward --shading forward
render dark --lights 0
python3 - "$here" "$out" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from check_png import read_rgb
out = sys.argv[2]
def load(name):
    return read_rgb(f"{out}/{name}.png")
w, h, win = load("desktop")
cw, ch, cli = load("cli")
_, _, fwd = load("forward")
_, _, dark = load("dark")
assert (w, h) == (cw, ch), f"window {w}x{h}, CLI {cw}x{ch}"
n = w * h
def px_diff(a, b, level):  # pixels with any channel off by more than level
    return sum(1 for i in range(n) if max(abs(a[3 * i + c] - b[3 * i + c]) for c in range(3)) > level)
mean = sum(abs(x - y) for x, y in zip(win, cli)) / len(win)
off = px_diff(win, cli, 16)
assert mean <= 1.5 and off <= 0.005 * n, f"the window differs from penumbra render: mean {mean:.3f}, {off} px > 16"
flips = px_diff(cli, fwd, 2)
assert flips <= 0.001 * n, f"deferred differs from forward by more than 2 levels on {flips} px"
lit = px_diff(cli, dark, 8)
assert lit > 0.02 * n, f"32 lights change only {lit} px by more than 8 levels"
print(f"multipass-deferred: window against CLI mean {mean:.3f}, {off} px > 16; deferred against forward {flips} px > 2; "
      f"the lights change {lit} px ({100 * lit / n:.1f}%)")
PY
