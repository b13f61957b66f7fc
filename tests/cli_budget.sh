#!/usr/bin/env bash
# `--budget-ms` in render and plan: what was chosen is said and used, and the extremes of a budget
# give what they must whatever the machine's speed: a budget no frame can meet (1 microsecond) the
# smallest map, said so; one every frame meets (a second on a 64x64 image) the largest. Never a
# timing check. Bad values and a technique without a map are refused (exit status 2).
# usage: cli_budget.sh PENUMBRA WORKDIR
set -uo pipefail
penumbra=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
ok() { echo "ok $1"; }
bad() { echo "FAIL $1"; fail=1; }

# Nothing meets a microsecond: the smallest map, and the line says why.
"$penumbra" render --size 64x64 --frames 30 --budget-ms 0.001 > tight.out 2> tight.err || bad "tight: exit $?: $(cat tight.err)"
grep -Eq '^budget 0\.00 ms: (depthtex|rgba) hard, map 128, measured [0-9.]+ ms; over the budget at the smallest map$' tight.out &&
  ok "a budget nothing meets: map 128" || bad "tight: $(cat tight.out)"
# A second a frame: every rung fits, the controller climbs (from 512, 10 frames a step) past the
# largest map to shadow volumes, the top rung where they can draw the scene (the course).
"$penumbra" render --size 64x64 --frames 90 --budget-ms 1000 -v > wide.out 2> wide.err || bad "wide: exit $?: $(cat wide.err)"
grep -Eq '^budget 1000\.00 ms: shadow volumes, measured [0-9.]+ ms; the most accurate \(exact hard shadows\)$' wide.out &&
  ok "a budget everything meets: shadow volumes" || bad "wide: $(cat wide.out)"
grep -q '^budget: frame [0-9]*: map 512 -> map 1024' wide.err && grep -q '^budget: frame [0-9]*: map 4096 -> shadow volumes' wide.err &&
  ok "-v: each change" || bad "wide -v: $(cat wide.err)"
# With a soft filter there is no volumes rung: the largest map.
"$penumbra" render --size 64x64 --frames 90 --budget-ms 1000 --filter pcss --light-radius 0.05 > soft.out 2> soft.err &&
  grep -Eq '^budget 1000\.00 ms: (depthtex|rgba) pcss, map 4096, measured [0-9.]+ ms; the largest map' soft.out &&
  ok "a soft filter: the largest map" || bad "soft: $(cat soft.out soft.err)"
# The control: without the option, no budget line and the given map.
"$penumbra" render --size 64x64 --frames 3 > none.out 2>&1 && ! grep -q '^budget' none.out &&
  ok "no --budget-ms: no budget" || bad "none: $(cat none.out)"
# One frame asked for: it settles first, then writes the frame.
"$penumbra" render --size 64x64 --budget-ms 1000 --out one.png > one.out 2> one.err && [ -s one.png ] &&
  grep -q '^budget 1000\.00 ms: shadow volumes, .*the most accurate' one.out && ok "one frame: settled, then written" ||
  bad "one: $(cat one.out one.err)"
# plan: the note says what was chosen, and the plan's map is that size.
"$penumbra" plan --size 64x64 --budget-ms 0.001 --json > plan.json 2> plan.err || bad "plan: exit $?: $(cat plan.err)"
python3 -c '
import json
p = json.load(open("plan.json"))
notes = [n for n in p["notes"] if n.startswith("budget 0.00 ms")]
assert notes and "map 128" in notes[0], p["notes"]
maps = [r for r in p["resources"] if r["name"] == "shadow-map"]
assert maps and maps[0]["width"] == 128, maps' && ok "plan: the note and the map" || bad "plan: $(head -c 600 plan.json)"
"$penumbra" plan --size 64x64 --budget-ms 0.001 | grep -q "budget 0.00 ms: .* map 128" && ok "plan text" || bad "plan text"
# Refused: a technique without a map, a negative budget, a word.
expect_refusal() {  # expect_refusal WHAT PATTERN ARGS...
  local what=$1 pattern=$2; shift 2
  "$penumbra" "$@" > refused.out 2> refused.err; local rc=$?
  if [ $rc -eq 2 ] && grep -q -- "$pattern" refused.err; then ok "refused: $what"; else bad "$what: rc $rc: $(cat refused.err)"; fi
}
expect_refusal "volumes" "budget-ms: chooses a shadow map's settings; --technique volumes has none" \
  render --size 64x64 --technique volumes --budget-ms 8
expect_refusal "volumes (plan)" "technique volumes has none" plan --size 64x64 --technique volumes --budget-ms 8
expect_refusal "negative" "budget-ms" render --size 64x64 --budget-ms -1
expect_refusal "a word" "budget-ms" render --size 64x64 --budget-ms fast
exit $fail
