#!/usr/bin/env bash
# desktop.volumes-shadow: the shadow volumes exercise in a real window (Xvfb), frozen at t = 0.6, in
# its visibility view: from the scene's camera the teapot's shadow is there (a share of the
# pixels, not none, not most); with the eye moved into the shadow, depth-pass's picture differs
# from depth-fail's in a large share of the pixels (its count starts one too low) and auto's
# equals depth-fail's.
# usage: volumes.sh PENUMBRA_DESKTOP OUT_DIR
set -euo pipefail
app=$1 out=$2/volumes
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"

exercise=volumes time=0.6
source "$here/visibility_shots.sh"

shot scene
shot zpass --eye in-shadow --volume-method zpass
shot zfail --eye in-shadow --volume-method zfail
shot auto --eye in-shadow --volume-method auto
cd "$here"
python3 check_volumes.py shadow "$out/scene.png" 0.02 0.4
python3 check_volumes.py differ "$out/zpass.png" "$out/zfail.png" 0.2
python3 check_volumes.py same "$out/auto.png" "$out/zfail.png" 0.001
