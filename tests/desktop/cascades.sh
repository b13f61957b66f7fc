#!/usr/bin/env bash
# desktop.cascades-keys: the cascades exercise in a real window (Xvfb) over the kilometre of terrain,
# driven by its keys (--keys, one a frame), each last frame checked (check_cascades.py):
#   - as it starts (4 cascades, the cascades view): the four tints, and the frame `penumbra render
#     --scene tests/data/terrain_km.gltf` draws with the same options (the scene built in code is
#     the file's);
#   - Shift+N three times (4 -> 3 -> 2 -> 1): one tint, the title and the URL say cascades=1, the
#     CLI's frame of --cascades 1;
#   - W twice (2 m forward each): the frame changes and the title keeps camera=...;
#   - G, K, B (snap off, split 1, blend 0.2): the title says so and the frame is the CLI's;
#   - A (the view: colour): no tints but the grass's, the CLI's colour frame.
# usage: cascades.sh PENUMBRA_DESKTOP PENUMBRA_CLI OUT_DIR
set -euo pipefail
app=$1 cli=$2 out=$3/cascades
here=$(cd "$(dirname "$0")" && pwd)
data=$(cd "$here/../data" && pwd)
mkdir -p "$out"

exercise=cascades
scene=$data/terrain_km.gltf
source "$here/exercise_shots.sh"
cd "$here"

# The exercise keeps maps of 1024 (cascades are not matched to the screen): the CLI is told so, as
# its own default is auto (one map matched to the screen, after N N N).
shot start ""
title_has start "Cascaded shadow maps | cascades=4 cascade-split=0.95 cascade-snap=on cascade-blend=0.1 map-size=1024 aov=cascades"
python3 check_cascades.py tints "$out/start.png" 4
cli start --cascades 4 --map-size 1024 --aov cascades
python3 check_cascades.py match "$out/start.png" "$out/start-cli.png"

shot one "NNN"
title_has one "cascades=1 "
grep -q "cascades=1&" "$out/one.log" || { echo "desktop cascades one: the URL query lacks cascades=1"; exit 1; }
python3 check_cascades.py tints "$out/one.png" 1
cli one --cascades 1 --map-size 1024 --aov cascades
python3 check_cascades.py match "$out/one.png" "$out/one-cli.png"

shot walk "ww"
title_has walk "camera="
grep -q "^camera = " "$out/walk.log" || { echo "desktop cascades walk: no camera line"; exit 1; }
python3 check_cascades.py differ "$out/walk.png" "$out/start.png" 0.02
python3 check_cascades.py tints "$out/walk.png" 4

shot settings "gkb"
title_has settings "cascade-split=1 cascade-snap=off cascade-blend=0.2"
cli settings --cascades 4 --map-size 1024 --aov cascades --cascade-snap off --cascade-split 1 --cascade-blend 0.2
python3 check_cascades.py match "$out/settings.png" "$out/settings-cli.png"
python3 check_cascades.py differ "$out/settings.png" "$out/start.png" 0.005

shot color "a"
title_has color "aov=color"
cli color --cascades 4 --map-size 1024
python3 check_cascades.py match "$out/color.png" "$out/color-cli.png"
echo "desktop cascades: ok"
