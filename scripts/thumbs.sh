#!/usr/bin/env bash
# The pictures of the exercises on the pages' index (web/thumbs/NAME.png, 128x128, committed): each
# rendered by `penumbra render` with the options the exercise starts with (examples/exercise_list.cpp:
# its technique and its defaults) at t = 0.6 (the soft exercise at t = 0, where it starts still).
# W09P2a and W09P2b draw what the command line cannot (the light's view and projection drawn in
# the scene, the FBO's texture on the ground): their pictures are the nearest frame it can, the
# light's depth (the view from the light) and the shadow-mapped course scene.
# The web build copies web/thumbs/*.png into build-web/site/thumbs/ and web/pages.py puts each
# beside its exercise on index.html. Run it after changing how an exercise starts, then look at
# each picture before committing it.
# usage: bash scripts/thumbs.sh [PENUMBRA]   (default build/penumbra; build it first)
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/penumbra}
out=web/thumbs
mkdir -p "$out"
size=(--size 128x128)
thumb() {
  local name=$1; shift
  "$cli" render "${size[@]}" "$@" --out "$out/$name.png"
  echo "thumbs: $out/$name.png ($(stat -c %s "$out/$name.png") bytes): $*"
}
thumb w09p1     --time 0.6 --technique planar
thumb w09p2a    --time 0.6 --technique shadowmap --aov light-depth
thumb w09p2b    --time 0.6 --technique none
thumb w09p2c    --time 0.6 --technique shadowmap
thumb volumes   --time 0.6 --technique volumes --show-volumes on
thumb soft      --time 0 --light-radius 0.3 --filter pcss
thumb stencil   --time 0.6 --effects outline --outline-width 2
thumb multipass --time 0.6 --post shadow-blur:6
thumb cascades  --scene tests/data/terrain_km.gltf --cascades 4 --aov cascades
thumb bulb      --scene tests/data/bulb_room.gltf --cascades cube --map-size 512 --light-radius 0.05 --aov cascades
