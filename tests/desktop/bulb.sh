#!/usr/bin/env bash
# desktop.bulb-keys: the bulb exercise (a point light's cube in the room) in a real window (Xvfb),
# driven by its keys (--keys, one a frame), each last frame checked (check_cascades.py):
#   - as it starts (the cube, 512 a face, the faces view): at least 5 of the six face tints, and the
#     frame `penumbra render --scene tests/data/bulb_room.gltf` draws with the same options (the
#     room built in code is the file's);
#   - N (one map): the title and the URL say cascades=1, the frame changes and is the CLI's;
#   - K, M (PCF 4x4, 1024 a face): the title says so and the frame is the CLI's;
#   - W twice (0.25 m forward each): the frame changes, the title keeps camera=..., the faces shown;
#   - A (the view: colour): the CLI's colour frame.
# usage: bulb.sh PENUMBRA_DESKTOP PENUMBRA_CLI OUT_DIR
set -euo pipefail
app=$1 cli=$2 out=$3/bulb
here=$(cd "$(dirname "$0")" && pwd)
data=$(cd "$here/../data" && pwd)
mkdir -p "$out"
start_options=(--cascades cube --map-size 512 --light-radius 0.05)

exercise=bulb
scene=$data/bulb_room.gltf
source "$here/exercise_shots.sh"
cd "$here"

shot start ""
title_has start "A point light's cube | cascades=cube map-size=512 cube-layout=atlas filter=hard light-radius=0.05 aov=cascades"
python3 check_cascades.py faces "$out/start.png" 5
cli start "${start_options[@]}" --aov cascades
python3 check_cascades.py match "$out/start.png" "$out/start-cli.png"

shot one "n"
title_has one "cascades=1 "
grep -q "cascades=1&" "$out/one.log" || { echo "desktop bulb one: the URL query lacks cascades=1"; exit 1; }
python3 check_cascades.py differ "$out/one.png" "$out/start.png" 0.05
cli one --cascades 1 --map-size 512 --light-radius 0.05 --aov cascades
python3 check_cascades.py match "$out/one.png" "$out/one-cli.png"

shot settings "km"
title_has settings "map-size=1024 cube-layout=atlas filter=pcf4x4"
cli settings --cascades cube --map-size 1024 --filter pcf4x4 --light-radius 0.05 --aov cascades
python3 check_cascades.py match "$out/settings.png" "$out/settings-cli.png"

shot cubemap "kc"
title_has cubemap "cube-layout=cubemap filter=pcf4x4"
cli cubemap --cascades cube --map-size 512 --cube-layout cubemap --filter pcf4x4 --light-radius 0.05 --aov cascades
python3 check_cascades.py match "$out/cubemap.png" "$out/cubemap-cli.png"
python3 check_cascades.py faces "$out/cubemap.png" 5

shot walk "ww"
title_has walk "camera="
grep -q "^camera = " "$out/walk.log" || { echo "desktop bulb walk: no camera line"; exit 1; }
python3 check_cascades.py differ "$out/walk.png" "$out/start.png" 0.02
python3 check_cascades.py faces "$out/walk.png" 4

shot color "a"
title_has color "aov=color"
cli color "${start_options[@]}"
python3 check_cascades.py match "$out/color.png" "$out/color-cli.png"
echo "desktop bulb: ok"
