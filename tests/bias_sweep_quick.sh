#!/usr/bin/env bash
# `penumbra bias-sweep --quick` runs and writes well-formed outputs: a CSV with a row per
# measurement and numbers in range, the Markdown table, and SVG charts. Never checks timings.
set -euo pipefail
penumbra=$1 out=$2
rm -rf "$out"
"$penumbra" bias-sweep --quick --out-dir "$out" --size 128 >/dev/null
csv="$out/bias_sweep.csv"
[ -s "$csv" ] || { echo "no $csv"; exit 1; }
head -n1 "$csv" | grep -q '^scene,elevation_deg,encoding,precision,filter,bias,' || { echo "bad header"; exit 1; }
# 2 scenes x 3 elevations x 3 encodings x 2 precisions x 5 biases
rows=$(($(wc -l <"$csv") - 1))
[ "$rows" -eq 180 ] || { echo "expected 180 rows, got $rows"; exit 1; }
awk -F, 'NR > 1 && ($9 < 0 || $9 > 100 || $10 < 0 || $10 > 100 || $8 < 100) { bad++ } END { exit bad > 0 }' "$csv" \
  || { echo "a rate is out of [0, 100] or too few valid pixels"; exit 1; }
grep -q '| 30&#176; | rgba | mediump |' "$out/bias_sweep.md" || { echo "summary table incomplete"; exit 1; }
n=$(ls "$out"/*.svg | wc -l)
[ "$n" -eq 12 ] || { echo "expected 12 charts, got $n"; exit 1; }
for f in "$out"/*.svg; do grep -q '</svg>' "$f" || { echo "truncated $f"; exit 1; }; done
echo "1 passed, 0 failed"
