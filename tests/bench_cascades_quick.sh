#!/usr/bin/env bash
# `penumbra bench --cascades --quick`: cascades against one map on the terrain, checked for
# well-formed outputs and for what they must show (never timings): the maps redrawn in every
# timed frame of the pan, the cascades' error below the one map's at the same memory, and the free
# windows' flips above the snapped ones'. Then on the bulb in a room: the cube's error below a
# tenth of the one perspective map's.
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
    # The pan moves the camera each frame: every map is drawn again in every timed frame.
    assert float(r["redrawn_pct"]) == 100.0, (r["config"], r["redrawn_pct"])
print("ok: cascades %s %% vs one map %s %%; flips snapped %s %%, free %s %%" %
      (four["error_pct"], one["error_pct"], four["flips_pct"], free["flips_pct"]))
PY
grep -q "^| 4 x 512 |" "$out/cascades.md" || { echo "FAIL: cascades.md lacks the 4 x 512 row"; exit 1; }

# The point light: a cube's faces against one perspective map.
"$penumbra" bench --cascades --quick --scenes tests/data/bulb_room.gltf --out-dir "$out/cube"
python3 - "$out/cube/cascades.csv" <<'PY'
import csv, sys
rows = {r["config"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"1 x 1024", "cube 6 x 512", "cube map 6 x 512"}, rows.keys()
one, cube, cube_map = rows["1 x 1024"], rows["cube 6 x 512"], rows["cube map 6 x 512"]
assert cube["cascades"] == "cube" and cube_map["cascades"] == "cube" and one["cascades"] == "1"
for c in (cube, cube_map):
    assert float(c["error_pct"]) < float(one["error_pct"]) / 10, (c["error_pct"], one["error_pct"])
    assert float(c["ms_per_frame"]) > 0
for c in (one, cube, cube_map):
    assert float(c["redrawn_pct"]) == 100.0, (c["config"], c["redrawn_pct"])  # the light moves each frame
# The atlas holds 3 x 2 faces; a cube map six faces: the same colour bytes, one face's depth buffer.
assert int(cube_map["map_bytes"]) < int(cube["map_bytes"]), (cube_map["map_bytes"], cube["map_bytes"])
assert float(one["ms_per_frame"]) > 0
print("ok: cube %s %%, as a cube map %s %%, vs one perspective map %s %%" %
      (cube["error_pct"], cube_map["error_pct"], one["error_pct"]))
PY
grep -q "^# A point light's cube against one perspective map" "$out/cube/cascades.md" || { echo "FAIL: the cube's cascades.md has no title"; exit 1; }
