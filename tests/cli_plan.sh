#!/usr/bin/env bash
# `penumbra plan`: for each technique (and the light-depth AOV) the plan prints as JSON that parses,
# lists its passes and resources, and names the same passes, in the same order, as
# `penumbra render -v` prints for the frame it renders; --frames 2 shows the map reused.
# usage: cli_plan.sh PENUMBRA WORKDIR
set -uo pipefail
penumbra=$1 work=$2 data=$(cd "$(dirname "$0")/data" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
check() {  # check NAME ARGS...: the plan's passes (JSON) equal render -v's
  local name=$1; shift
  if ! "$penumbra" plan "$@" --json > "$name.json" 2> "$name.err"; then
    echo "FAIL $name: penumbra plan exited non-zero: $(cat "$name.err")"; fail=1; return
  fi
  local planned rendered
  planned=$(python3 -c '
import json, sys
p = json.load(open(sys.argv[1]))
assert p["passes"] and p["resources"], "no passes or no resources"
for r in p["resources"]:
    assert r["bytes"] == r["width"] * r["height"] * ((4 * (6 if r["cube"] else 1) if r["color"] else 0) + (4 if r["depth_texture"] else 0)
        + {None: 0, "depth16": 2, "depth24": 4, "depth24-stencil8": 4, "depth-stencil": 4}[r["depth_buffer"]]), r
for q in p["passes"]:
    assert q["target"]["resource"] == "window" or any(r["name"] == q["target"]["resource"] for r in p["resources"])
    # An atlas whose tiles are all drawn is cleared whole first, by a pass that only clears.
    assert q["draws"] or (q["name"] == "shadow-map clear" and q["clear"] and not q["target"]["clip"]), q["name"] + " draws nothing"
print(" ".join(q["name"].replace(" ", "_") for q in p["passes"]))' "$name.json") || { echo "FAIL $name: bad plan JSON"; fail=1; return; }
  rendered=$("$penumbra" render -v "$@" 2>&1 >/dev/null | sed -n 's/^[0-9]*\. \([^:]*\):.*/\1/p' | tr ' ' '_' | tr '\n' ' ' | sed 's/ $//')
  if [ "$planned" != "$rendered" ]; then
    echo "FAIL $name: plan '$planned', render -v '$rendered'"; fail=1
  else
    echo "ok $name: $planned"
  fi
}
check shadowmap --technique shadowmap --size 64x64 --map-size 256
check planar --technique planar --size 64x64
check none --technique none --size 64x64
check light-depth --aov light-depth --size 64x64 --map-size 256
check gltf --scene "$data/sphere_over_plane.gltf" --size 64x64 --filter pcf4x4 --bias auto
check volumes --technique volumes --size 64x64
check volumes-eye-in-shadow --technique volumes --eye in-shadow --show-volumes on --size 64x64
check volumes-count --technique volumes --aov stencil-count --volume-method zfail --size 64x64
check cascades --scene "$data/terrain_km.gltf" --cascades 4 --map-size 256 --size 64x64
check cascades-aov --scene "$data/terrain_km.gltf" --cascades auto --aov cascades --map-size 256 --size 64x64
# Cascades: one clear of the atlas, then one pass per tile of it, auto's reason printed; a point light gets one map and a note.
"$penumbra" plan --scene "$data/terrain_km.gltf" --cascades auto --map-size 256 --size 64x64 --json > auto.json &&
python3 -c '
import json
p = json.load(open("auto.json"))
c = p["cascades"]
assert c["why"].startswith("auto: 4 cascades: the receivers in view span view depths"), c["why"]
assert [q["name"] for q in p["passes"]][:5] == ["shadow-map clear"] + ["shadow-map cascade %d" % i for i in range(4)]
assert [l["tile"] for l in c["list"]] == [[0, 0], [256, 0], [0, 256], [256, 256]], c["list"]
m = [r for r in p["resources"] if r["name"] == "shadow-map"][0]
assert (m["width"], m["height"]) == (512, 512), m' && echo "ok cascades auto: 4 tiles, the reason" \
  || { echo "FAIL cascades auto"; fail=1; }
"$penumbra" plan --cascades 4 --size 64x64 | grep -q "note: --cascades 4: one map instead, cascades need a directional light" \
  && echo "ok cascades point light: one map, a note" || { echo "FAIL cascades with the course's point light"; fail=1; }
# A point light's cube: auto picks it for the bulb in the room (one pass per face, each into its
# tile of a 3 x 2 atlas, the reason and the faces printed); render -v names the same passes.
check cube --scene "$data/bulb_room.gltf" --cascades cube --map-size 128 --size 64x64 --filter pcf4x4
"$penumbra" plan --scene "$data/bulb_room.gltf" --cascades auto --map-size 128 --size 64x64 --json > cube.json &&
python3 -c '
import json
p = json.load(open("cube.json"))
assert p["cascades"]["why"] == "auto: a cube: the point light is inside the receivers\x27 bounds", p["cascades"]["why"]
c = p["cube"]
faces = [f for f in c["faces"] if f["drawn"]]
assert [q["name"] for q in p["passes"]][:len(faces) + 1] == ["shadow-map clear"] + ["shadow-map face " + f["face"] for f in faces]
assert [f["tile"] for f in c["faces"]] == [[0, 0], [128, 0], [256, 0], [0, 128], [128, 128], [256, 128]], c["faces"]
m = [r for r in p["resources"] if r["name"] == "shadow-map"][0]
assert (m["width"], m["height"]) == (384, 256), m' && echo "ok cube auto: the faces in a 3 x 2 atlas, the reason" \
  || { echo "FAIL cube auto"; fail=1; }
# (into a file first: grep -q stops reading at its match, and pipefail would count the plan's SIGPIPE)
"$penumbra" plan --scene "$data/bulb_room.gltf" --cascades cube --size 64x64 > cube.txt && grep -q "^cube: 6 of 6 faces drawn" cube.txt \
  && echo "ok cube: the faces printed" || { echo "FAIL cube's text plan"; fail=1; }
# --cube-layout cubemap: one square texture of six faces, each pass into its face.
check cube-map --scene "$data/bulb_room.gltf" --cascades cube --cube-layout cubemap --map-size 128 --size 64x64
"$penumbra" plan --scene "$data/bulb_room.gltf" --cascades cube --cube-layout cubemap --map-size 128 --size 64x64 --json > cube-map.json &&
python3 -c '
import json
p = json.load(open("cube-map.json"))
assert p["cube"]["layout"] == "cubemap", p["cube"]
m = [r for r in p["resources"] if r["name"] == "shadow-map"][0]
assert (m["width"], m["height"]) == (128, 128), m
faces = [q["target"].get("face") for q in p["passes"] if q["name"].startswith("shadow-map face ")]
assert faces and all(f == q for f, q in zip(faces, [x["face"] for x in p["cube"]["faces"] if x["drawn"]])), faces' \
  && echo "ok cube map: one 128 x 128 cube texture, a pass per drawn face into that face" || { echo "FAIL cube map"; fail=1; }
"$penumbra" plan --scene "$data/terrain_km.gltf" --cascades cube --size 64x64 > cube-sun.txt &&
  grep -q "note: --cascades cube: one map instead, the light is directional" cube-sun.txt \
  && echo "ok cube with a sun: one map, a note" || { echo "FAIL cube with a directional light"; fail=1; }
# Issue 56: a spot light's 80-degree cone over a long ground gets the cube's faces it reaches, and
# --map-size auto says what it chose and why.
"$penumbra" plan --scene "$data/wide_cone.gltf" --size 64x64 --map-size auto > wide-cone.txt &&
  grep -q "^cascades: auto: a cube: the spot light lights receivers in view beyond one frustum's 75 degrees a side" wide-cone.txt &&
  grep -q "^cube: 4 of 6 faces drawn" wide-cone.txt && grep -q "^map size: auto 1024: .*(the image counted as 512 pixels a side)" wide-cone.txt \
  && echo "ok wide cone: a cube of the faces its cone reaches, its size matched" || { echo "FAIL wide cone"; cat wide-cone.txt; fail=1; }

# Shadow volumes: the plan says what they cost and which method each caster got.
"$penumbra" plan --technique volumes --eye in-shadow --size 64x64 --json > volumes.json &&
  python3 -c '
import json, sys
v = json.load(open(sys.argv[1]))["volumes"]
assert v["zfail_casters"] >= 1 and v["silhouette_edges"] > 0 and v["fill_per_pixel"] > 0, v' volumes.json \
  && echo "ok volumes: depth-fail with the eye in a shadow" || { echo "FAIL volumes: no depth-fail with the eye in a shadow"; fail=1; }
# Gooch's soft shadow: K planes (stencil and add passes per plane), the texture, radius 0 = planar.
check gooch --technique gooch --light-radius 0.3 --gooch-planes 4 --size 64x64
check gooch-texture --technique gooch --gooch-method texture --light-radius 0.3 --size 64x64
check gooch-radius-0 --technique gooch --light-radius 0 --size 64x64
python3 -c '
import json, sys
g = json.load(open("gooch.json"))["passes"]
names = [q["name"] for q in g]
assert names == ["camera", "gooch-ground"] + ["gooch-stencil", "gooch-light"] * 4, names
assert all("blend add" in q["state"]["text"] for q in g if q["name"] == "gooch-light"), "gooch-light does not add"
t = json.load(open("gooch-texture.json"))
assert [q["name"] for q in t["passes"]] == ["gooch-texture", "camera"], t["passes"]
r = [x for x in t["resources"] if x["name"] == "gooch-texture"][0]
assert r["sampling"] == "linear" and r["width"] <= 1024, r
z = json.load(open("gooch-radius-0.json"))
p = json.load(open("planar.json"))
assert [q["name"] for q in z["passes"]] == [q["name"] for q in p["passes"]], "radius 0 is not the planar plan"' \
  && echo "ok gooch: planes, texture and radius 0 (the planar passes)" || { echo "FAIL gooch plans"; fail=1; }
if "$penumbra" render --scene "$data/sphere_over_plane.gltf" --technique gooch --light-radius 0.2 --size 64x64 --out gooch.png 2>gooch.err; then
  echo "ok gooch render sphere_over_plane.gltf"
else
  echo "FAIL gooch render sphere_over_plane.gltf: $(cat gooch.err)"; fail=1
fi
# Every glTF scene of the test data renders with shadow volumes.
for f in "$data"/*.gltf "$data"/*.glb; do
  case "$(basename "$f")" in bad_*) continue ;; esac
  if "$penumbra" render --scene "$f" --technique volumes --size 64x64 --out volumes.png 2>/dev/null; then
    echo "ok volumes render $(basename "$f")"
  else
    echo "FAIL volumes render $(basename "$f")"; fail=1
  fi
done

# The second frame of a still scene reuses the map: its pass is skipped, its resource marked reused.
"$penumbra" plan --scene "$data/sphere_over_plane.gltf" --frames 2 --size 64x64 --json > still.json &&
  python3 -c '
import json, sys
p = json.load(open(sys.argv[1]))
m = next(r for r in p["resources"] if r["name"] == "shadow-map")
assert m["reused"] and p["passes"][0]["skipped"], "the still second frame redraws its map"' still.json \
  && echo "ok still: the map is reused" || { echo "FAIL still: the map of a still second frame is not reused"; fail=1; }
# --effects outline: its passes after the technique's, and the stencil uses with disjoint bits.
check outline-planar --technique planar --effects outline --size 64x64
check outline-volumes --technique volumes --effects outline --outline-width 5 --outline-color 00ff00 --size 64x64
check outline-shadowmap --effects outline --size 64x64 --map-size 256
python3 -c '
import json
for name, counter in (("outline-planar", "planar: shadowed ground"), ("outline-volumes", "volumes: shadow count")):
    p = json.load(open(name + ".json"))
    assert [q["name"] for q in p["passes"]][-2:] == ["outline-mark", "outline-draw"], p["passes"]
    uses = {u["name"]: u for u in p["stencil"]}
    assert set(uses) == {counter, "outline: the model'"'"'s pixels"}, uses
    o, c = uses["outline: the model'"'"'s pixels"], uses[counter]
    assert o["read_mask"] == 128 and o["ref_of_1"] == 128 and c["write_mask"] == 127 and c["shift"] == 0, uses
    for q in p["passes"]:
        st = q["state"]["stencil"]
        if st["enabled"]:
            own = o if q["module"] == "outline" else c
            assert st["write_mask"] & ~own["write_mask"] == 0 and st["read_mask"] & ~own["read_mask"] == 0, q["name"]
s = json.load(open("outline-shadowmap.json"))
assert [u["name"] for u in s["stencil"]] == ["outline: the model'"'"'s pixels"], s["stencil"]
assert json.load(open("shadowmap.json"))["stencil"] == [], "a shadow map alone uses no stencil"' \
  && echo "ok outline: the stencil uses" || { echo "FAIL outline: the stencil uses"; fail=1; }
"$penumbra" plan --technique planar --effects outline --size 64x64 | grep -q "outline: the model's pixels (outline): bit 7 (mask 80)" \
  || { echo "FAIL outline: the text plan lists no stencil use"; fail=1; }
# --effects mirror: its six passes after the technique's (and before the outline's), in its own bit.
check mirror-outline --technique volumes --effects mirror,outline --reflectivity 0.3 --size 64x64
python3 -c '
import json
p = json.load(open("mirror-outline.json"))
names = [q["name"] for q in p["passes"]]
assert names[-8:] == ["mirror-mark", "mirror-far", "mirror-depth", "mirror-sky", "mirror-reflect", "mirror-restore",
                      "outline-mark", "outline-draw"], names
uses = {u["name"]: u for u in p["stencil"]}
m = uses["mirror: the mirror'"'"'s pixels"]
for q in p["passes"]:
    if q["module"] == "mirror":
        st = q["state"]["stencil"]
        assert st["enabled"] and st["write_mask"] == m["write_mask"] and st["read_mask"] == m["read_mask"], q["name"]
assert any("without shadows" in n for n in p["notes"]), p["notes"]' \
  && echo "ok mirror: its passes and bit" || { echo "FAIL mirror: its passes and bit"; fail=1; }
# --effects portal: its passes after the mirror's, in its own bit; the other scene's own shadow map
# beside this scene's, whose light frustum stays the plan's.
check portal --effects mirror,portal --size 64x64
check mirror-only --effects mirror --size 64x64
python3 -c '
import json
p = json.load(open("portal.json"))
names = [q["name"] for q in p["passes"]]
assert names[-7:] == ["mirror-restore", "portal-frame", "portal-mark", "portal-far", "portal shadow-map", "portal-scene",
                      "portal-restore"], names
uses = {u["name"]: u for u in p["stencil"]}
o = uses["portal: the opening'"'"'s pixels"]
assert o["write_mask"] & uses["mirror: the mirror'"'"'s pixels"]["write_mask"] == 0, uses
for q in p["passes"]:
    if q["module"] == "portal" and q["name"] != "portal-frame":
        st = q["state"]["stencil"]
        assert st["enabled"] and st["read_mask"] == o["read_mask"], q["name"]
assert {r["name"] for r in p["resources"]} >= {"shadow-map", "portal shadow-map"}, p["resources"]
assert p["light_frustum"] == json.load(open("mirror-only.json"))["light_frustum"]' \
  && echo "ok portal: its passes, bit and map" || { echo "FAIL portal: its passes, bit and map"; fail=1; }
# The text form names every pass too, and bad input is refused as render refuses it.
"$penumbra" plan --technique planar --size 64x64 | grep -q "planar-stencil (planar)" || { echo "FAIL text"; fail=1; }
if "$penumbra" plan --technique volume 2>/dev/null; then echo "FAIL: a bad technique was planned"; fail=1; fi
# render --frames 3 -v: after the ms/frame line, each pass's median GPU time (GL_TIME_ELAPSED_EXT),
# one line per pass of the plan and the total; where `caps` says the context has no timer, one
# line saying so instead. Never a timing check.
"$penumbra" plan --frames 3 --size 64x64 --map-size 256 --json > gpu.json &&
"$penumbra" render --frames 3 -v --size 64x64 --map-size 256 > gpu.out 2> gpu.err &&
"$penumbra" caps > gpu.caps && python3 -c '
import json, re, sys
out = open("gpu.out").read().splitlines()
assert out[0].startswith("3 frames, median "), out
if "GPU timer no" in open("gpu.caps").read():
    assert out[1:] == ["GPU timer: not available on this context (no EXT_disjoint_timer_query)"], out
    print("ok gpu: not available"); sys.exit(0)
assert "GPU timer yes" in open("gpu.caps").read()
assert re.match(r"GPU time per pass \(GL_TIME_ELAPSED_EXT\), median of [1-3] frame\(s\)", out[1]), out
rows = [re.match(r"  (.+?) +([0-9]+\.[0-9]{3}) ms", l) for l in out[2:]]
assert all(rows), out
names = [m.group(1) for m in rows]
want = [q["name"] for q in json.load(open("gpu.json"))["passes"] if not q["skipped"]]
assert names == want + ["total"], (names, want)
assert out[-1].endswith(" ms/frame GPU"), out
print("ok gpu:", ", ".join(f"{m.group(1)} {m.group(2)}" for m in rows))' || { echo "FAIL gpu: render --frames 3 -v's GPU times: $(cat gpu.out gpu.err)"; fail=1; }
exit $fail
