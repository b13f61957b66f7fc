#!/usr/bin/env bash
# desktop.w09p2b-rtt: W09P2b's two ways to render to a texture in a real window (Xvfb), frozen at
# t = 0.6, in a 480x320 window. rtt=copy with the texture asked at 1024 must say that a copy is no
# larger than the window (256x256 used) and draw the frame that rtt=fbo draws at 256 (mean <= 1
# level, <= 0.5% of the pixels off by more than 16); the key '.' must switch fbo -> copy; and the
# copy's picture must be on the table (the frame differs from fbo-view=camera's).
# usage: rtt.sh PENUMBRA_DESKTOP OUT_DIR
set -euo pipefail
app=$1 out=$2/w09p2b-rtt
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
rm -f "$out"/*.png
run() {  # NAME ARGS...: 6 frames, a screenshot NAME.png, the log NAME.log
  local name=$1; shift
  if ! xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise w09p2b --size 480x320 --time 0.6 --frames 6 \
       --screenshot "$out/$name.png" "$@" >"$out/$name.log" 2>&1; then
    echo "desktop w09p2b-rtt: $name failed:"; cat "$out/$name.log"; exit 1
  fi
}
run copy --rtt copy --map-size 1024
run fbo --rtt fbo --map-size 256
run key --map-size 256 --keys "." --print-title
run camera --rtt copy --map-size 256 --fbo-view camera
grep -q "note: rtt=copy: .*no larger than the window's 320 pixels: 256x256 instead of 1024x1024" "$out/copy.log" ||
  { echo "desktop w09p2b-rtt: no note on the copy's limit:"; cat "$out/copy.log"; exit 1; }
if grep -q "note: rtt=copy" "$out/fbo.log"; then echo "desktop w09p2b-rtt: the fbo run has a copy note"; exit 1; fi
grep -q "rtt=copy" "$out/key.log" || { echo "desktop w09p2b-rtt: '.' did not switch to rtt=copy:"; cat "$out/key.log"; exit 1; }
python3 - "$here" "$out" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from check_png import read_rgb
out = sys.argv[2]
def load(name):
    return read_rgb(f"{out}/{name}.png")
w, h, copy = load("copy")
_, _, fbo = load("fbo")
_, _, key = load("key")
_, _, camera = load("camera")
n = w * h
def compare(a, b):
    mean = sum(abs(x - y) for x, y in zip(a, b)) / len(a)
    off = sum(1 for i in range(n) if max(abs(a[3 * i + c] - b[3 * i + c]) for c in range(3)) > 16)
    return mean, off
mean, off = compare(copy, fbo)
assert mean <= 1.0 and off <= 0.005 * n, f"rtt=copy differs from rtt=fbo: mean {mean:.3f}, {off} px > 16"
kmean, koff = compare(key, copy)
assert kmean <= 1.0 and koff <= 0.005 * n, f"the key's copy differs from --rtt copy: mean {kmean:.3f}, {koff} px > 16"
cmean, _ = compare(copy, camera)
assert cmean > 2.0, f"the light's view and the camera's on the table look alike (mean {cmean:.3f}): no picture copied?"
print(f"w09p2b-rtt: copy against fbo mean {mean:.3f}, {off} px > 16; key against option {kmean:.3f}; "
      f"light's view against camera's {cmean:.2f}")
PY
