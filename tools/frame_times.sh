#!/usr/bin/env bash
# Median ms/frame of the course scene for no shadows, planar, and every encoding x filter:
# `penumbra render --frames N` per setting (each frame finished with glFinish; the shadow map is
# redrawn every frame because the light and the teapot move), repeated over R interleaved rounds;
# prints the median of the R medians as a Markdown table.
# usage: tools/frame_times.sh [PENUMBRA] [ROUNDS] [FRAMES] [extra render options...]
set -euo pipefail
penumbra=${1:-build/penumbra}; rounds=${2:-5}; frames=${3:-20}; shift $(( $# < 3 ? $# : 3 ))
configs=("--technique none" "--technique planar")
for e in r8 rgba depthtex; do for f in hard pcf2x2 pcf4x4; do configs+=("--encoding $e --filter $f"); done; done
declare -A runs
for ((r = 1; r <= rounds; r++)); do
  for c in "${configs[@]}"; do
    # shellcheck disable=SC2086
    ms=$("$penumbra" render --frames "$frames" $c "$@" | sed -n 's/.*median \([0-9.]*\) ms.*/\1/p')
    runs[$c]+="$ms "
  done
  echo "round $r/$rounds done" >&2
done
echo "| settings | median ms/frame | runs |"
echo "|---|---|---|"
for c in "${configs[@]}"; do
  med=$(tr ' ' '\n' <<<"${runs[$c]}" | grep . | sort -g | awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}')
  echo "| $c | $med | ${runs[$c]}|"
done
