#!/usr/bin/env bash
# `penumbra bench --quick` end to end: it must finish and write a well-formed CSV (every row, every
# number parses, percentages in range, each run labelled with its settings), a Markdown table, an
# SVG that parses as XML and a PNG of the plot; never a timing check. Then `penumbra export` and
# `penumbra truth --score` (prose and --json) on the exported file; that the CSV header, the
# Markdown headings and the JSON keys are the score table's (`truth --score-columns`); and the
# bad-input errors. Also `penumbra bench --soft --quick` (the soft methods against the area-light truth).
# usage: bench_quick.sh PENUMBRA WORKDIR SOURCE_DIR
set -uo pipefail
penumbra=$1 work=$2 src=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }

start=$(date +%s)
if "$penumbra" bench --quick --out-dir "$work/bench" \
     --scenes "teapot@0.6,$src/tests/data/bench_easy.gltf" >"$work/bench.out" 2>"$work/bench.err"; then ok
else bad "bench --quick exited $?"; cat "$work/bench.err"; fi
echo "bench --quick took $(( $(date +%s) - start )) s"
grep -q '^\[ *1/' "$work/bench.err" && ok || bad "no progress lines on stderr"

python3 - "$work/bench" <<'PY' && ok || bad "bench outputs are not well-formed"
import csv, struct, sys, xml.etree.ElementTree as ET, zlib
d = sys.argv[1]
every = list(csv.DictReader(open(d + "/results.csv")))
assert {r["section"] for r in every} == {"sweep", "silhouette", "effects", "lights", "budget", "max-error"}, {r["section"] for r in every}
# --max-error 0.1 on each scene frame: every rung of the ladder predicted, scored and timed, the
# same shadow-edge count on each of a frame's rungs; the choice one of them, the cheapest in the
# model's order predicted within 0.1 % where any is, its settings naming the target
err = [r for r in every if r["section"] == "max-error"]
for scene in ("course@0.60", "bench_easy"):
    rungs = [r for r in err if r["scene"] == scene and float(r["max_error_pct"]) == 0]
    assert sorted(int(r["map_size"]) for r in rungs if r["technique"] != "volumes auto") == [128, 256, 512, 1024, 2048, 4096], rungs
    assert len({r["edge_pixels"] for r in rungs}) == 1 and int(rungs[0]["edge_pixels"]) > 0, rungs
    for r in rungs:
        assert float(r["predicted_pct"]) > 0.0 and 0.0 <= float(r["error_pct"]) <= 100.0 and float(r["ms_moving"]) > 0.0, r
    # a larger map is predicted no worse
    maps = sorted((r for r in rungs if r["technique"] != "volumes auto"), key=lambda r: int(r["map_size"]))
    assert all(float(a["predicted_pct"]) >= float(b["predicted_pct"]) for a, b in zip(maps, maps[1:])), maps
    [chosen] = [r for r in err if r["scene"] == scene and float(r["max_error_pct"]) > 0]
    assert float(chosen["max_error_pct"]) == 0.1 and "--max-error 0.1" in chosen["settings"], chosen
    assert (chosen["technique"], chosen["map_size"]) in {(r["technique"], r["map_size"]) for r in rungs}, chosen
    within = [r for r in rungs if float(r["predicted_pct"]) <= 0.1]
    if within: assert float(chosen["predicted_pct"]) <= 0.1, chosen
# --budget-ms 4 and 16 on course@0.60: a hard-filtered map of a power-of-two size the controller
# settled on, or shadow volumes (its top rung), its error scored, the settings naming the budget;
# a larger budget never lower on the ladder
bud = sorted((r for r in every if r["section"] == "budget" and float(r["budget_ms"]) > 0), key=lambda r: float(r["budget_ms"]))
assert [float(r["budget_ms"]) for r in bud] == [4.0, 16.0], bud
# and every rung of its ladder as a fixed setting over the same frames (budget_ms 0): the maps 128
# to 4096 and shadow volumes, each timed and scored once
ladder = [r for r in every if r["section"] == "budget" and float(r["budget_ms"]) == 0]
assert sorted(int(r["map_size"]) for r in ladder if r["technique"] != "volumes auto") == [128, 256, 512, 1024, 2048, 4096], ladder
assert [r["technique"] for r in ladder].count("volumes auto") == 1, ladder
for r in ladder:
    assert "--budget-ms" not in r["settings"] and float(r["ms_moving"]) > 0.0 and 0.0 <= float(r["error_pct"]) <= 100.0, r
rung = lambda r: 1 << 20 if r["technique"] == "volumes auto" else int(r["map_size"])
for r in bud:
    assert r["scene"] == "course@0.60" and "--budget-ms %g" % float(r["budget_ms"]) in r["settings"], r
    if r["technique"] == "volumes auto":
        assert r["map_size"] == "0" and "--technique volumes" in r["settings"], r
    else:
        assert r["filter"] == "hard" and r["encoding"] in ("depthtex", "rgba"), r
        m = int(r["map_size"]); assert 128 <= m <= 4096 and m & (m - 1) == 0 and "--map-size %d" % m in r["settings"], r
    assert 0.0 <= float(r["error_pct"]) <= 100.0 and int(r["valid_pixels"]) > 1000 and float(r["ms_moving"]) > 0.0, r
assert rung(bud[0]) <= rung(bud[1]), bud
rows = [r for r in every if r["section"] == "sweep"]
sil = [r for r in every if r["section"] == "silhouette"]
# 2 scenes x (3 encodings x 3 filters x (2 maps + map auto) + rgba hard and pcf4x4 at map 1024 as before issue 9
# + volumes auto, zpass, zfail + none + planar)
assert len(rows) == 2 * (3 * 3 * 3 + 2 + 3 + 2), len(rows)
volumes = [r for r in rows if r["technique"].startswith("volumes ")]
assert sorted({r["technique"] for r in volumes}) == ["volumes auto", "volumes zfail", "volumes zpass"], volumes
for r in volumes:
    assert "--technique volumes" in r["settings"] and "--volume-method " + r["technique"][8:] in r["settings"], r
    assert r["map_size"] == "0" and r["shadow_map_bytes"] == "0" and r["texel_use_pct"] == "", r
    assert int(r["silhouette_edges"]) > 0 and int(r["volume_triangles"]) > 0 and float(r["fill_per_pixel"]) > 0.0, r
    casters = int(r["zpass_casters"]) + int(r["zfail_casters"])
    assert casters > 0, r
    if r["technique"] == "volumes zpass": assert r["zfail_casters"] == "0", r
    if r["technique"] == "volumes zfail": assert r["zpass_casters"] == "0", r
# the silhouette sweep: a sphere of 8 ... 128 segments, volumes (auto) and rgba hard 1024, each scored
assert len(sil) == 5 * 2, len(sil)
assert sorted({(r["technique"], r["map_size"]) for r in sil}) == [("rgba hard", "1024"), ("volumes auto", "0")], sil
vs = sorted((r for r in sil if r["technique"] == "volumes auto"), key=lambda r: int(r["segments"]))
assert [int(r["segments"]) for r in vs] == [8, 16, 32, 64, 128], vs
edges = [int(r["silhouette_edges"]) for r in vs]
assert all(a < b for a, b in zip(edges, edges[1:])) and edges[0] >= 8, edges
for r in sil:
    assert r["scene"] == "sphere-" + r["segments"] and int(r["valid_pixels"]) > 1000, r
    assert 0.0 <= float(r["error_pct"]) <= 100.0 and float(r["ms_moving"]) >= 0.0, r
    if r["technique"] == "volumes auto": assert float(r["fill_per_pixel"]) > 0.0, r
    else: assert r["silhouette_edges"] == "" and int(r["shadow_map_bytes"]) >= 1024 ** 2, r
# the stencil effects on course@0.60: none, each alone and all three, under the default technique and volumes
# (and the --post passes under the default technique: timed, not scored)
post = [r for r in every if r["section"] == "effects" and r["post"] != "none"]
eff = [r for r in every if r["section"] == "effects" and r["post"] == "none"]
sets = ["none", "outline", "mirror", "portal", "outline,mirror,portal"]
assert sorted((r["technique"], r["effects"]) for r in eff) == sorted((t, e) for t in ("rgba hard", "volumes auto") for e in sets), eff
assert sorted(r["post"] for r in post) == ["bloom:0.6", "blur:12", "blur:4", "shadow-blur:6"], post
map_bytes = {r["technique"]: int(r["shadow_map_bytes"]) for r in eff if r["effects"] == "none"}
for r in post:
    assert r["technique"] == "rgba hard" and r["effects"] == "none" and "--post " + r["post"] in r["settings"], r
    assert int(r["valid_pixels"]) == 0 and r["effect_error_pct"] == "" and float(r["ms_moving"]) > 0.0, r
    assert int(r["shadow_map_bytes"]) > map_bytes["rgba hard"], r  # the post targets counted beside the map
for r in eff:
    assert r["scene"] == "course@0.60" and "--effects " + r["effects"] in r["settings"], r
    assert 0.0 <= float(r["error_pct"]) <= 100.0 and float(r["ms_moving"]) >= 0.0 and float(r["ms_still"]) >= 0.0, r
    shows = "mirror" in r["effects"] or "portal" in r["effects"]
    # the mirror's and the opening's pixels scored alone where there are any
    assert (int(r["effect_valid_pixels"]) > 50) == shows, r
    if shows: assert 0.0 <= float(r["effect_error_pct"]) <= 100.0, r
    else: assert r["effect_error_pct"] == "", r
    # the mirror does not reflect the portal: those pixels, and only those, are left out
    assert (int(r["not_modelled_pixels"]) > 0) == ("mirror" in r["effects"] and "portal" in r["effects"]), r
# forward against deferred: 0, 8 and 64 lights, each shading; the shadow is the main light's in
# both (the same error up to the rare pixels where the shadow test flips), the G-buffer's bytes
# counted (deferred's targets more), the settings naming both options
lit = [r for r in every if r["section"] == "lights"]
assert sorted((int(r["lights"]), r["shading"]) for r in lit) == sorted((n, s) for n in (0, 8, 64) for s in ("forward", "deferred")), lit
lby = {(int(r["lights"]), r["shading"]): r for r in lit}
for n in (0, 8, 64):
    f, g = lby[(n, "forward")], lby[(n, "deferred")]
    assert abs(float(f["error_pct"]) - float(g["error_pct"])) < 0.05, (f, g)
    assert int(g["shadow_map_bytes"]) > int(f["shadow_map_bytes"]), (f, g)
    assert "--shading deferred" in g["settings"] and "--lights %d" % n in g["settings"], g
    assert float(f["ms_moving"]) > 0 and float(g["ms_moving"]) > 0
by = {(r["technique"], r["effects"]): r for r in eff}
# the outline is not in the visibility AOV: the frame under it is scored, the same as without it
assert by[("rgba hard", "outline")]["error_pct"] == by[("rgba hard", "none")]["error_pct"]
# volumes leave the reflection unshadowed (documented): the mirror's pixels lose its shadows
assert float(by[("volumes auto", "mirror")]["effect_false_lit_pct"]) > float(by[("rgba hard", "mirror")]["effect_false_lit_pct"])
before = [r for r in rows if r["technique"].endswith(" (before)")]
assert sorted({r["technique"] for r in before}) == ["rgba hard (before)", "rgba pcf4x4 (before)"], before
for r in before:
    assert r["map_size"] == "1024" and "--bias sheet" in r["settings"] and "--light-fit scene" in r["settings"], r
    assert "--map-faces both" in r["settings"] and "--pcf-kernel full" in r["settings"], r
volumes_names = {r["technique"] for r in volumes}
for r in rows:
    for k in ("false_shadow_pct", "false_lit_pct", "error_pct", "mae_pct", "truth_shadowed_pct"):
        v = float(r[k]); assert 0.0 <= v <= 100.0, (k, v)
    assert abs(float(r["false_shadow_pct"]) + float(r["false_lit_pct"]) - float(r["error_pct"])) < 1e-3
    assert int(r["valid_pixels"]) > 1000
    for k in ("ms_moving", "ms_still", "ms_shadow_pass", "ms_camera_pass"):
        assert float(r[k]) >= 0.0
    assert r["settings"].startswith("--scene ") and "--technique " in r["settings"]
    if r["technique"] in volumes_names: pass
    elif r["technique"] not in ("none", "planar"):
        assert int(r["shadow_map_bytes"]) >= int(r["map_size"]) ** 2, r
        assert int(r["redrawn_moving"]) == int(r["frames"]) and int(r["redrawn_still"]) == 0, r
        assert 0.0 < float(r["texel_use_pct"]) <= 100.0, r
        assert r["silhouette_edges"] == "", r
    else:
        assert r["texel_use_pct"] == "" and r["silhouette_edges"] == "", r
md = open(d + "/results.md").read()
assert md.startswith("# penumbra bench") and "| technique |" in md and "## The course scene, map 1024" in md
assert "## Texel use" in md
assert "## Shadow volumes against the shadow map (rgba hard, map 1024)" in md and "| course@0.60 | volumes auto |" in md
assert "## Shadow volumes as the silhouette grows" in md and "| 128 | 16128 |" in md
assert "## The defaults against the settings before issue 9" in md and "| rgba hard | 1024 |" in md
assert "## The stencil effects and the post passes on course@0.60" in md and "| volumes auto | outline,mirror,portal | none |" in md
assert "| rgba hard | none | shadow-blur:6 | - |" in md
assert "## Forward against deferred shading on course@0.60" in md and "| 64 |" in md
assert "## The time budget (--budget-ms)" in md and "| budget ms | chosen | map |" in md
assert "The ladder's rungs over the same frames:" in md
assert "## The error target (--max-error)" in md and "| scene | target % | chosen | map | predicted % |" in md
assert "The model rung by rung" in md and "Measured over predicted, over" in md
lsvg = ET.parse(d + "/lights.svg").getroot()
assert "deferred" in [t.text for t in lsvg.iter("{http://www.w3.org/2000/svg}text")]
assert open(d + "/lights.png", "rb").read()[:8] == b"\x89PNG\r\n\x1a\n"
svg = ET.parse(d + "/tradeoff.svg").getroot()
assert svg.tag.endswith("svg") and len(svg.findall(".//{http://www.w3.org/2000/svg}polyline")) > 0
texts = [t.text for t in svg.iter("{http://www.w3.org/2000/svg}text")]
assert "shadow volumes" in texts and "volumes auto" in texts and "volumes zfail" in texts, texts
titles = [t.text for t in svg.iter("{http://www.w3.org/2000/svg}title")]
assert any(t.startswith("volumes zpass:") and "silhouette edges" in t for t in titles), titles
png = open(d + "/tradeoff.png", "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n"
w, h = struct.unpack(">II", png[16:24]); assert w >= 400 and h >= 300, (w, h)
print("outputs well-formed:", len(rows), "rows")
PY

# --from-csv: the same tables again from the rows, the silhouette sweep's and the effects' included.
if "$penumbra" bench --from-csv "$work/bench/results.csv" --out-dir "$work/again" >/dev/null 2>"$work/again.err" &&
   grep -q "^## Shadow volumes as the silhouette grows" "$work/again/results.md" &&
   grep -q "^## Shadow volumes against the shadow map" "$work/again/results.md" &&
   cmp -s <(sed -n '/^## The stencil effects/,/^$/p' "$work/bench/results.md") \
          <(sed -n '/^## The stencil effects/,/^$/p' "$work/again/results.md") &&
   grep -q "^| rgba hard | mirror |" "$work/again/results.md" &&
   cmp -s <(sed -n '/^## Forward against deferred/,/^$/p' "$work/bench/results.md") \
          <(sed -n '/^## Forward against deferred/,/^$/p' "$work/again/results.md") &&
   cmp -s <(sed -n '/^## The time budget/,/^$/p' "$work/bench/results.md") \
          <(sed -n '/^## The time budget/,/^$/p' "$work/again/results.md") &&
   cmp -s <(sed -n '/^| scene | target %/,/^$/p' "$work/bench/results.md") \
          <(sed -n '/^| scene | target %/,/^$/p' "$work/again/results.md") &&
   grep -q '^| scene | target %' "$work/again/results.md" &&
   cmp -s <(sed -n '/^| segments/,/^$/p' "$work/bench/results.md" | awk -F'|' 'NF > 4 {print $2 $3 $(NF-3) $(NF-2) $(NF-1)}') \
          <(sed -n '/^| segments/,/^$/p' "$work/again/results.md" | awk -F'|' 'NF > 4 {print $2 $3 $(NF-3) $(NF-2) $(NF-1)}'); then ok
else bad "bench --from-csv lost the volumes' or the effects' tables: $(cat "$work/again.err")"; fi
cmp -s "$work/bench/results.csv" "$work/again/results.csv" && ok || bad "bench --from-csv does not write the same CSV back"

# The GPU time (EXT_disjoint_timer_query) beside ms/frame: every row has it where `caps` says the
# context has a timer (a non-negative figure, each timed pass named), none where it has not; the
# table, or the line saying it is not available. Never a timing check.
"$penumbra" caps >"$work/caps.txt" 2>/dev/null
python3 - "$work/bench" "$work/caps.txt" <<'PY' && ok || bad "the GPU columns are wrong"
import csv, sys
d, caps = sys.argv[1], open(sys.argv[2]).read()
rows = list(csv.DictReader(open(d + "/results.csv")))
md = open(d + "/results.md").read()
assert "## GPU time per frame and per pass (GL_TIME_ELAPSED_EXT)" in md
if "GPU timer no" in caps:
    assert all(r["gpu_ms_moving"] == "" and r["gpu_ms_per_pass"] == "" for r in rows)
    assert "GPU timer: not available on this context" in md
    print("GPU timer: not available"); sys.exit(0)
assert "GPU timer yes" in caps, caps
assert "| technique | map | ms/frame moving | GPU ms moving | ms/frame still | GPU ms still | GPU ms per pass (moving) |" in md
# The budget's rows are the wall times its controller saw (budget_bench.cpp), the error target's
# rungs short wall-time runs beside their predictions (error_bench.cpp): no GPU columns.
assert all(r["gpu_ms_moving"] == "" for r in rows if r["section"] in ("budget", "max-error"))
for r in (r for r in rows if r["section"] not in ("budget", "max-error")):
    assert float(r["gpu_ms_moving"]) >= 0.0 and float(r["gpu_ms_still"]) >= 0.0, r
    names = [p.split(": ")[0] for p in r["gpu_ms_per_pass"].split("; ")]
    assert all(names) and all(float(p.split(": ")[1]) >= 0.0 for p in r["gpu_ms_per_pass"].split("; ")), r
    if r["section"] == "sweep": assert "camera" in names, r
    if r["section"] == "sweep" and r["map_size"] != "0": assert "shadow-map" in names, r
print("GPU columns:", len(rows), "rows")
PY

# `penumbra bench --soft --quick`: the soft methods against the area-light truth (course scene,
# 128x128, radius 0.15 of the scene): every row there, numbers in range, and what must hold
# whatever the timings: Heckbert-Herf's error falls from 4 to 64 samples (and with N along the
# convergence rows), PCSS beats the hard shadow and PCF 4x4 against the soft truth.
start=$(date +%s)
if "$penumbra" bench --soft --quick --out-dir "$work/soft" >"$work/soft.out" 2>"$work/soft.err"; then ok
else bad "bench --soft --quick exited $?"; cat "$work/soft.err"; fi
echo "bench --soft --quick took $(( $(date +%s) - start )) s"
python3 - "$work/soft" <<'PY' && ok || bad "bench --soft outputs are wrong"
import csv, struct, sys, xml.etree.ElementTree as ET
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/soft.csv")))
sweep = {r["method"]: r for r in rows if r["section"] == "sweep"}
conv = sorted((r for r in rows if r["section"] == "convergence"), key=lambda r: int(r["samples"]))
want = {"hard", "pcf4x4", "pcss 16/16", "pcss 16/16 mean", "hh 4", "hh 16", "hh 64", "hh 16 interleaved", "hh 64 interleaved", "shadow-blur 4"}
assert want <= set(sweep), sorted(sweep)
assert set(sweep) - want <= {"gooch"}, sorted(sweep)
for r in rows:
    assert r["scene"] == "course@0.60" and r["light"] == "point" and r["radius_fraction"] == "0.15", r
    assert float(r["light_radius"]) > 0.0 and "--light-radius " in r["settings"], r
    assert int(r["valid_pixels"]) > 1000 and 100 < int(r["penumbra_pixels"]) < int(r["valid_pixels"]), r
    for k in ("mae_area_light_pct", "mae_penumbra_pct", "mae_pct"):
        assert 0.0 <= float(r[k]) <= 100.0, (k, r)
    # the penumbra holds the error: its mean is at least the whole image's
    assert float(r["mae_penumbra_pct"]) >= float(r["mae_area_light_pct"]), r
    if r["section"] == "sweep": assert float(r["ms_per_frame"]) > 0.0 and int(r["frames"]) >= 2, r
    else: assert r["ms_per_frame"] == "", r
for m, r in sweep.items():
    if m.startswith("hh "): assert "--area-samples " + m[3:].split()[0] + " " in r["settings"], r
    if m.endswith(" interleaved"): assert "--area-interleave 2" in r["settings"], r
    if m.startswith("pcss"): assert "--filter pcss" in r["settings"] and "--pcss-taps 16" in r["settings"], r
    if m.startswith("pcss"): assert ("--pcss-blockers " + ("mean" if m.endswith("mean") else "layered")) in r["settings"], r
    if m.startswith("shadow-blur"): assert "--post shadow-blur:4" in r["settings"] and r["family"] == "screen blur", r
e = {m: float(r["mae_area_light_pct"]) for m, r in sweep.items()}
assert e["hh 4"] > e["hh 16"] > e["hh 64"], e
assert e["pcss 16/16"] < e["hard"] and e["pcss 16/16"] < e["pcf4x4"], e
assert e["shadow-blur 4"] < e["hard"], e  # blurring the hard edge moves it towards the penumbra
assert [int(r["samples"]) for r in conv] == [1, 2, 4, 8, 16, 32, 64], conv
ce = [float(r["mae_area_light_pct"]) for r in conv]
assert ce[-1] < 0.5 * ce[0] and ce[2] > ce[-1], ce
assert abs(ce[0] - e["hard"]) < 1e-3  # one sample: the light's centre, the hard shadow
md = open(d + "/soft.md").read()
assert md.startswith("# penumbra bench --soft") and "## Mean over the scenes, per light radius" in md
assert "## Heckbert-Herf's convergence on course@0.60" in md and "## The issue's goals" in md
for name in ("soft", "soft_convergence"):
    svg = ET.parse(d + "/" + name + ".svg").getroot(); assert svg.tag.endswith("svg")
    png = open(d + "/" + name + ".png", "rb").read(); assert png[:8] == b"\x89PNG\r\n\x1a\n"
print("bench --soft --quick:", ", ".join(f"{m} {v:.2f} %" for m, v in sorted(e.items(), key=lambda x: x[1])))
PY
expect_error_soft() { local err rc; err=$("$penumbra" "$@" 2>&1 >/dev/null); rc=$?
  if [ "$rc" -eq 2 ] && [ "$(grep -c . <<<"$err")" -eq 1 ]; then ok; else bad "$*: rc=$rc: $err"; fi; }
expect_error_soft bench --soft --quick --radii 1.5 --out-dir "$work/s2"

# export -> render and truth on the exported file -> score.
if "$penumbra" export --scene teapot --time 0.6 --out "$work/course.gltf" >/dev/null; then ok; else bad "export failed"; fi
grep -q '"KHR_lights_punctual"' "$work/course.gltf" && grep -q 'data:image/png;base64' "$work/course.gltf" && ok || bad "export lacks the light or the marble"
if "$penumbra" render --scene "$work/course.gltf" --size 96x96 --aov visibility --out "$work/vis.png" 2>/dev/null &&
   out=$("$penumbra" truth --scene "$work/course.gltf" --size 96x96 --out-dir "$work/truth" --score "$work/vis.png") &&
   grep -q "score of .*error [0-9.]* %" <<<"$out" && [ -s "$work/truth/errors.png" ] && [ -s "$work/truth/mask.png" ]; then ok
else bad "truth --score on the exported scene: $out"; fi
if "$penumbra" truth --score-columns >"$work/columns.json" &&
   "$penumbra" truth --scene "$work/course.gltf" --size 96x96 --out-dir "$work/truth" --score "$work/vis.png" --json \
     >"$work/score.json" 2>"$work/score.err"; then ok
else bad "truth --score-columns / --score --json failed: $(cat "$work/score.err")"; fi
python3 - "$work" <<'PY' && ok || bad "the CSV, the Markdown or the JSON do not follow the score table"
import json, sys
d = sys.argv[1]
cols = json.load(open(d + "/columns.json"))
keys = [c["key"] for c in cols]
assert keys[:3] == ["valid_pixels", "truth_shadowed_pct", "false_shadow_pct"], keys
# the JSON: one object, the frame then one key per column in the table's order, null only where optional
text = open(d + "/score.json").read()
assert text.count("\n") == 1, "stdout holds more than the JSON object"
j = json.loads(text)
assert list(j) == ["scene", "time", "width", "height"] + keys, list(j)
assert j["scene"].endswith("course.gltf") and j["width"] == 96 and j["height"] == 96
for c in cols:
    v = j[c["key"]]
    assert v is not None or c["optional"], c["key"]
    if v is not None and c["key"].endswith("_pct"): assert 0.0 <= v <= 100.0, (c["key"], v)
assert isinstance(j["valid_pixels"], int) and j["valid_pixels"] > 0
assert j["mae_area_light_pct"] is None  # no --soft-samples
assert abs(j["false_shadow_pct"] + j["false_lit_pct"] - j["error_pct"]) < 1e-3
# the CSV: the score columns, contiguous and in order, between map_size and ms_moving
header = open(d + "/bench/results.csv").readline().strip().split(",")
i = header.index("map_size")
assert header[i + 1:i + 1 + len(keys)] == keys and header[i + 1 + len(keys)] == "ms_moving", header
# the Markdown: every table's score headings, in order
md = open(d + "/bench/results.md").read()
headings = " | ".join(c["heading"] for c in cols if c["table_digits"] >= 0)
assert "| technique | map | " + headings + " | ms/frame moving |" in md
assert "| technique | " + headings + " | ms/frame moving |" in md
print("score columns:", ", ".join(keys))
PY

# Bad input: one line, exit 2, no file.
expect_error() {
  local what=$1; shift
  local err rc; err=$("$penumbra" "$@" 2>&1 >/dev/null); rc=$?
  if [ "$rc" -eq 2 ] && [ "$(grep -c . <<<"$err")" -eq 1 ]; then ok; else bad "$what: rc=$rc: $err"; fi
}
expect_error "export to .png" export --out "$work/x.png"
expect_error "export, missing folder" export --out "$work/nope/x.gltf"
expect_error "export, missing scene" export --scene "$work/none.gltf" --out "$work/x.gltf"
expect_error "bench, unknown encoding" bench --quick --encodings r16 --out-dir "$work/b2"
expect_error "bench, bad scene time" bench --quick --scenes teapot@soon --out-dir "$work/b2"
expect_error "truth, bad size" truth --size 0x5 --out-dir "$work/t2"
expect_error "truth, --json without --score" truth --json --out-dir "$work/t2"
[ ! -e "$work/x.gltf" ] && [ ! -e "$work/x.png" ] && ok || bad "a failed export left a file"

# A quick run with no --out-dir writes under out/, never over the committed results/bench (issue 56).
# --from-csv rebuilds the table from the run above, so this costs no rendering; the control is the
# same command with --out-dir results/bench, which must write there (else the check could not fail).
mkdir -p "$work/cwd/results/bench" && echo committed >"$work/cwd/results/bench/results.md"
if (cd "$work/cwd" && "$penumbra" bench --quick --from-csv "$work/bench/results.csv" >/dev/null 2>&1); then ok
else bad "bench --quick --from-csv exited $?"; fi
[ -s "$work/cwd/out/bench-quick/results.md" ] && ok || bad "bench --quick wrote no out/bench-quick/results.md"
[ "$(cat "$work/cwd/results/bench/results.md")" = committed ] && [ "$(ls "$work/cwd/results/bench")" = results.md ] && ok \
  || bad "bench --quick wrote into results/bench: $(ls "$work/cwd/results/bench")"
(cd "$work/cwd" && "$penumbra" bench --quick --from-csv "$work/bench/results.csv" --out-dir results/bench >/dev/null 2>&1)
[ "$(cat "$work/cwd/results/bench/results.md")" != committed ] && ok || bad "control: --out-dir results/bench wrote nothing there"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
