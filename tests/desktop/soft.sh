#!/usr/bin/env bash
# desktop.soft-penumbra: the soft shadows exercise in a real window (Xvfb), the scene still at t = 0
# (the teapot on the table), in its visibility view: the teapot's shadow is there, and with the
# light's radius of 0.3 the penumbra, measured on the screenshots (check_soft.py), is wider than
# without one: PCSS against PCF 4x4's constant blur and Heckbert-Herf (64 light samples) against
# the hard shadow.
# usage: soft.sh PENUMBRA_DESKTOP OUT_DIR
set -euo pipefail
app=$1 out=$2/soft
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"

exercise=soft time=0
source "$here/visibility_shots.sh"

shot hard --light-radius 0 --filter hard
shot pcf --light-radius 0 --filter pcf4x4
shot pcss --light-radius 0.3 --filter pcss
shot samples --light-radius 0.3 --area-samples 64 --area-per-frame 0
grep -q "^light samples 64 of 64" "$out/samples.log" || { echo "desktop soft: not 64 light samples:"; cat "$out/samples.log"; exit 1; }
cd "$here"
python3 check_soft.py shadow "$out/pcss.png" 0.01 0.4
python3 check_soft.py shadow "$out/samples.png" 0.01 0.4
python3 check_soft.py wider "$out/pcss.png" "$out/pcf.png" 1.5
python3 check_soft.py wider "$out/samples.png" "$out/hard.png" 2
