#!/usr/bin/env bash
# desktop.w09p2c-frame, desktop.w09p1-frame, desktop.stencil-frame, desktop.multipass-frame: an
# exercise with a shadow (W09P2c's shadow map, the map's view off so the whole frame is the scene;
# W09P1's planar shadow; the stencil exercise's shadow map with the teapot's outline; the multipass
# exercise's shadow blurred in screen space) in a real window (Xvfb),
# frozen at t = 0.6: the screenshot is checked as a picture of the scene (check_frame.py), not only
# its size. The P key prints the frame's settings as a `penumbra render` command; the CLI renders
# that command headless (and once more with --technique none, every pixel lit), the Embree ray
# tracer (`penumbra truth`) traces the same frame, and the window's frame must match the CLI's,
# show the table, and a shadow on it where the CLI's frame and the ray tracer have it. The title
# printed (--print-title) must be the exercise and the options the app reports as its URL query.
# usage: shadow_frame.sh PENUMBRA_DESKTOP PENUMBRA OUT_DIR w09p2c|w09p1|stencil|multipass [more penumbra-desktop options...]
# (more options go to the window only, after the test's own: `--bias 1` takes W09P2c's shadow
# away, `--time 0.9` moves it; either must make the check fail.)
set -euo pipefail
app=$1 cli=$2 exercise=$4 out=$3/$4-frame
shift 4
case $exercise in
  w09p2c) name=W09P2c own=(--map-view off) ;;
  w09p1) name=W09P1 own=() ;;
  stencil) name="Stencil effects" own=() ;;  # the outline on: the CLI's frame has it too
  multipass) name="Multipass" own=() ;;  # the shadow blurred: the CLI's frame has it too
  *) echo "shadow_frame.sh: w09p2c, w09p1, stencil or multipass, not '$exercise'"; exit 2 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
rm -rf "$out"/*.png "$out/truth"
log="$out/desktop.log"
if ! xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --exercise "$exercise" --time 0.6 "${own[@]}" --frames 5 --keys p \
     --print-title --screenshot "$out/desktop.png" "$@" >"$log" 2>&1; then
  echo "desktop $exercise-frame: penumbra-desktop failed:"; cat "$log"; exit 1
fi
grep -q "^5 frames" "$log" || { echo "desktop $exercise-frame: did not render 5 frames:"; cat "$log"; exit 1; }

# The title: the exercise, then each name=value of the app's URL query, then the ms/frame.
query=$(sed -n 's/^5 frames, median .*; //p' "$log")
title=$(sed -n 's/^title: //p' "$log" | tail -n 1)
want="$name | ${query//&/ } | "
[[ "$title" == "$want"*" ms/frame" ]] || { echo "desktop $exercise-frame: title '$title', expected '$want... ms/frame'"; exit 1; }
echo "title: $title"

# The frame's settings as the app prints them on P, rendered by the CLI.
command=$(grep -m 1 "^penumbra render " "$log") || { echo "desktop $exercise-frame: P printed no command:"; cat "$log"; exit 1; }
read -r -a args <<<"${command#penumbra render }"
"$cli" render "${args[@]}" --out "$out/cli.png" >/dev/null
for i in "${!args[@]}"; do [ "${args[$i]}" = --technique ] && args[$((i + 1))]=none; done
"$cli" render "${args[@]}" --out "$out/unshadowed.png" >/dev/null
classes=()
if "$cli" truth --score-columns >/dev/null 2>&1; then
  "$cli" truth --time 0.6 --size 512x512 --out-dir "$out/truth" >/dev/null
  classes=("$out/truth/classes.png")
else
  echo "note: penumbra built without the ray tracer (PENUMBRA_TRUTH=OFF): the shadow is checked against the CLI's frame only"
fi
python3 "$here/check_frame.py" "$out/desktop.png" "$out/cli.png" "$out/unshadowed.png" "${classes[@]}"
if [ "$exercise" = stencil ]; then
  # The outline is drawn: 0.2..5% of the window's pixels are its colour (ff8c00, within 2 levels).
  python3 - "$out/desktop.png" "$here" <<'PY'
import sys
sys.path.insert(0, sys.argv[2])
from check_png import read_png
width, height, channels, rows = read_png(sys.argv[1])
n = sum(1 for row in rows for x in range(width)
        if all(abs(row[x * channels + c] - v) <= 2 for c, v in enumerate((0xff, 0x8c, 0x00))))
share = n / (width * height)
print(f"{sys.argv[1]}: {n} outline pixels (ff8c00), {100 * share:.2f}% of the frame")
if not 0.002 <= share <= 0.05:
    sys.exit(f"{sys.argv[1]}: the outline's pixels are {100 * share:.2f}% of the frame, not 0.2..5%")
PY
fi
