#!/usr/bin/env bash
# desktop.budget: budget-ms in a real window (Xvfb): the frames' map is the controller's choice, the
# title and the URL query say so (the title and the end of the run with the error the model predicts,
# more for the smallest map than the largest), and the extremes hold whatever the machine's speed (a second a
# frame: the largest map; a microsecond: the smallest, said to be over). An exercise whose
# technique has no map refuses it (exit status 2). Never a timing check.
# usage: budget.sh PENUMBRA_DESKTOP OUT_DIR
set -uo pipefail
app=$1 out=$2/budget
mkdir -p "$out"
fail=0
run() {  # run NAME ARGS...: the app under Xvfb, its output in $out/NAME.log; returns its status
  local name=$1; shift
  xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --no-vsync --print-title -v "$@" >"$out/$name.log" 2>&1
}
run wide --exercise w09p2c --time 0.6 --frames 80 --budget-ms 1000 || { echo "FAIL wide: exit $?"; cat "$out/wide.log"; fail=1; }
grep -Eq '^budget 1000\.00 ms: (depthtex|rgba) hard, map 4096, measured [0-9.]+ ms; the largest map' "$out/wide.log" &&
  echo "ok a second a frame: map 4096" || { echo "FAIL wide: $(grep budget "$out/wide.log")"; fail=1; }
grep -q '^budget: frame [0-9]*: map 2048 -> map 4096' "$out/wide.log" && echo "ok -v: the changes" || { echo "FAIL wide -v"; fail=1; }
grep -Eq '^title: W09P2c \| .* budget-ms=1000 .*\| [0-9.]+ ms/frame \| budget: (depthtex|rgba) hard 4096, predicted error [0-9.]+ %$' "$out/wide.log" &&
  echo "ok the title" || { echo "FAIL title: $(grep '^title' "$out/wide.log")"; fail=1; }
grep -Eq '^80 frames, .*&budget-ms=1000&' "$out/wide.log" && echo "ok the URL query" || { echo "FAIL query"; fail=1; }
grep -q '^1\. shadow-map: .*4096x4096' "$out/wide.log" && echo "ok the last frame's map" || { echo "FAIL the plan's map"; fail=1; }

run tight --exercise w09p2c --time 0.6 --frames 40 --budget-ms 0.001 || { echo "FAIL tight: exit $?"; fail=1; }
grep -Eq '^budget 0\.00 ms: (depthtex|rgba) hard, map 128, measured [0-9.]+ ms; over the budget at the smallest map$' "$out/tight.log" &&
  echo "ok a microsecond: map 128, over" || { echo "FAIL tight: $(grep budget "$out/tight.log")"; fail=1; }
# The model's predicted error for each choice: more for the 128 map than the 4096 one.
w=$(sed -n 's/^predicted error \([0-9.]*\) % of the truth .*/\1/p' "$out/wide.log")
t=$(sed -n 's/^predicted error \([0-9.]*\) % of the truth .*/\1/p' "$out/tight.log")
[ -n "$w" ] && [ -n "$t" ] && python3 -c "import sys; sys.exit(0 if $t > $w > 0 else 1)" &&
  echo "ok predicted error: map 128 $t %, map 4096 $w %" || { echo "FAIL predicted: '$t' and '$w'"; fail=1; }
# The control: no budget (budget-ms=0, the page's "off"), no budget line, the exercise's own map.
run none --exercise w09p2c --time 0.6 --frames 5 || { echo "FAIL none: exit $?"; fail=1; }
! grep -q '^budget\|| budget:' "$out/none.log" && grep -q 'budget-ms=0 ' "$out/none.log" && grep -q '^1\. shadow-map: .*1024x1024 ' "$out/none.log" &&
  echo "ok no budget-ms: the exercise's map" || { echo "FAIL none: $(grep -E 'budget|shadow-map' "$out/none.log")"; fail=1; }
# Shadow volumes have no map to choose.
run volumes --exercise volumes --frames 5 --budget-ms 8; rc=$?
[ $rc -eq 2 ] && grep -q "budget-ms: chooses a shadow map's settings; --technique volumes has none" "$out/volumes.log" &&
  echo "ok refused on the volumes exercise" || { echo "FAIL volumes: rc $rc: $(cat "$out/volumes.log")"; fail=1; }
exit $fail
