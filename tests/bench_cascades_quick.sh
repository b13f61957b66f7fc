#!/usr/bin/env bash
# `penumbra bench --cascades --quick`: cascades against one map on the terrain, checked for
# well-formed outputs and for what they must show (never timings): the cascades' error below the
# one map's at the same memory, and the free windows' flips above the snapped ones'.
# usage: bench_cascades_quick.sh PENUMBRA OUT_DIR SOURCE_DIR
set -euo pipefail
penumbra=$1 out=$2 src=$3
rm -rf "$out"
cd "$src"
"$penumbra" bench --cascades --quick --out-dir "$out"
for f in cascades.csv cascades.md cascades.svg cascades.png; do
  [ -s "$out/$f" ] || { echo "FAIL: $f missing or empty"; exit 1; }
done
python3 - "$out/cascades.csv" <<'PY'
import csv, sys
rows = {r["config"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"1 x 1024", "4 x 512", "4 x 512 not snapped"}, rows.keys()
one, four, free = rows["1 x 1024"], rows["4 x 512"], rows["4 x 512 not snapped"]
assert one["map_bytes"] == four["map_bytes"], "not the same memory"
assert float(four["error_pct"]) < float(one["error_pct"]) / 2, (four["error_pct"], one["error_pct"])
assert float(free["flips_pct"]) > float(four["flips_pct"]), (free["flips_pct"], four["flips_pct"])
assert len(four["texels"].split(" / ")) == 4
for r in rows.values():
    assert float(r["ms_per_frame"]) > 0
print("ok: cascades %s %% vs one map %s %%; flips snapped %s %%, free %s %%" %
      (four["error_pct"], one["error_pct"], four["flips_pct"], free["flips_pct"]))
PY
grep -q "^| 4 x 512 |" "$out/cascades.md" || { echo "FAIL: cascades.md lacks the 4 x 512 row"; exit 1; }
