#!/usr/bin/env bash
# The shader lab on the command line (docs/snippets.md): render --snippets draws with a file and
# refuses a bad one (exit status 2, no image); plan --snippets shows the lab's variants; grade
# scores a folder of sample submissions (tests/data/snippets: the answer, each classic mistake,
# broken, hostile; plus a file of megabytes and one of binary bytes made here) into one row each.
# usage: cli_lab.sh PENUMBRA WORKDIR
set -uo pipefail
penumbra=$1 work=$2 data=$(cd "$(dirname "$0")/data/snippets" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail=0
bad() {  # bad NAME WORDS ARGS...: exit status 2, WORDS on stderr, no out.png
  local name=$1 words=$2; shift 2
  rm -f out.png
  "$penumbra" "$@" > /dev/null 2> "$name.err"; local rc=$?
  if [ $rc -ne 2 ]; then echo "FAIL $name: exit $rc, not 2: $(cat "$name.err")"; fail=1; return; fi
  if ! grep -qF -- "$words" "$name.err"; then echo "FAIL $name: no '$words' in: $(cat "$name.err")"; fail=1; return; fi
  if [ -e out.png ]; then echo "FAIL $name: wrote out.png"; fail=1; return; fi
  echo "ok $name: $(head -c 160 "$name.err")"
}
r="render --time 0.6 --size 64x48 --filter pcf4x4 --out out.png"
if "$penumbra" $r --snippets "$data/answer.glsl" && [ -s out.png ]; then echo "ok render --snippets answer.glsl"
else echo "FAIL render --snippets answer.glsl"; fail=1; fi
bad broken "broken.glsl:" $r --snippets "$data/broken.glsl"
bad hostile "hostile_uniform.glsl:2: declares a uniform" $r --snippets "$data/hostile_uniform.glsl"
bad missing "cannot read" $r --snippets "$work/missing.glsl"
bad folder "is a folder" $r --snippets "$data"
bad volumes "the shader lab runs on the shadow map" $r --technique volumes --snippets "$data/answer.glsl"
bad depthtex "not depthtex" $r --encoding depthtex --snippets "$data/answer.glsl"
if "$penumbra" plan --size 64x48 --snippets "$data/no_bias.glsl" | grep -q "LAB"; then echo "ok plan --snippets: LAB variants"
else echo "FAIL plan --snippets: no LAB variant"; fail=1; fi

# grade: the samples, a file of 3 MB and one of binary bytes; a folder named like a file is skipped.
# Each row names the functions the file defines and its verdict; a file that defines none (empty,
# comments, a helper only) is "no-function", never "matches".
mkdir -p class out && cp "$data"/*.glsl class/ && mkdir class/folder.glsl
head -c 3000000 /dev/zero | tr '\0' 'x' > class/huge.glsl
printf 'float f() {\x01\x02 return 1.0; }\n' > class/binary.glsl
if ! "$penumbra" grade class --out out/grades.csv > grade.out 2> grade.err; then
  echo "FAIL grade: $(tail -3 grade.err)"; fail=1
else
  python3 - out/grades.csv <<'PY' || fail=1
import csv, sys
rows = {r["file"]: r for r in csv.DictReader(open(sys.argv[1]))}
fns4 = "packDepth unpackDepth shadowTest offset_lookup"
want = {  # file: (functions, compiles, error (exact, or a prefix ending in '...'), verdict, mistake)
    "answer.glsl": (fns4, "yes", "", "matches", ""),
    "unpack_only.glsl": ("unpackDepth", "yes", "", "matches", ""),
    "two_functions.glsl": ("unpackDepth shadowTest", "yes", "", "mistake", "no-bias"),
    # No function of the sheet written: never a match, though the frame is the answer's (0 pixels).
    "empty.glsl": ("", "yes", "", "no-function", ""),
    "comment_only.glsl": ("", "yes", "", "no-function", ""),
    "helper_only.glsl": ("", "yes", "", "no-function", ""),
    "no_bias.glsl": ("shadowTest", "yes", "", "mistake", "no-bias"),
    "wrong_way.glsl": ("shadowTest", "yes", "", "mistake", "wrong-way"),
    "bias_wrong_side.glsl": ("shadowTest", "yes", "", "mistake", "bias-wrong-side"),
    "eight_bit_threshold.glsl": ("unpackDepth shadowTest", "yes", "", "mistake", "8-bit-threshold"),
    "red_only.glsl": ("unpackDepth", "yes", "", "mistake", "red-only"),
    "unpack_reversed.glsl": ("unpackDepth", "yes", "", "mistake", "unpack-reversed"),
    "detached.glsl": ("shadowTest", "yes", "", "mistake", "detached"),
    "no_texmapscale.glsl": ("offset_lookup", "yes", "", "mistake", "no-texmapscale"),
    "broken.glsl": ("shadowTest", "no", "broken.glsl:...", "error", ""),  # the compiler's words are the implementation's
    "hostile_main.glsl": ("", "no", "hostile_main.glsl:3: defines or names main: the renderer's shader has its own; write only "
                          "the sheet's functions; hostile_main.glsl:4: the name gl_FragColor belongs to the renderer "
                          "(u_, a_, v_, g_, gl_ and penumbra names)", "error", ""),
    "hostile_uniform.glsl": ("", "no", "hostile_uniform.glsl:2: declares a uniform of its own: the lab's functions get what "
                             "they need as parameters (and texmapscale)", "error", ""),
    "hostile_loop.glsl": ("", "no", "hostile_loop.glsl:4: this loop runs more than 16 times (or never ends); the lab's loops "
                          "are short, they run per pixel", "error", ""),
    "hostile_nested.glsl": ("", "no", "hostile_nested.glsl:4: shadowTest does about 4641 steps per call (loop iterations and "
                            "calls); at most 256 are allowed, it runs per pixel", "error", ""),
    "huge.glsl": ("", "no", "huge.glsl: the file holds 3000000 bytes; a snippets file may hold 65536", "error", ""),
    "binary.glsl": ("", "no", "binary.glsl:1: byte 0x01 is not printable ASCII (GLSL ES 1.00 source is ASCII)", "error", ""),
}
mistakes = {}  # name: hint, from the rows that name one
bad = 0
if set(rows) != set(want):
    print("FAIL grade: files", sorted(rows), "want", sorted(want)); sys.exit(1)
if list(next(csv.reader(open(sys.argv[1])))) != ["file", "functions", "compiles", "error", "verdict", "differing_pixels_pct",
                                                  "error_vs_truth_pct", "mistake", "hint"]:
    print("FAIL grade: the CSV's columns"); sys.exit(1)
for f, (functions, compiles, error, verdict, mistake) in want.items():
    r = rows[f]
    ok = r["functions"] == functions and r["compiles"] == compiles and r["verdict"] == verdict and r["mistake"] == mistake and (
        r["error"].startswith(error[:-3]) if error.endswith("...") else r["error"] == error)
    if compiles == "yes":
        ok = ok and float(r["differing_pixels_pct"]) >= 0 and float(r["error_vs_truth_pct"]) >= 0
        if verdict == "matches": ok = ok and float(r["differing_pixels_pct"]) <= 0.1
        elif verdict == "mistake": ok = ok and float(r["differing_pixels_pct"]) > 0.1 and r["hint"] != ""
        # The control of the rule: the frame is the answer's (it alone would read as a match).
        elif verdict == "no-function": ok = ok and float(r["differing_pixels_pct"]) == 0 and \
            r["hint"].startswith("No function of the sheet written")
    else:
        ok = ok and r["differing_pixels_pct"] == "" and r["error_vs_truth_pct"] == ""
    if f == "answer.glsl": ok = ok and float(r["differing_pixels_pct"]) == 0  # the sheet's answer to 0 pixels
    if f == "wrong_way.glsl": ok = ok and r["hint"].startswith("The comparison the wrong way round")
    print(("ok" if ok else "FAIL") + " grade row " + f + ": " + ",".join(r.values())[:200])
    bad += not ok
sys.exit(1 if bad else 0)
PY
  [ -s out/grades.html ] && grep -q "answer.glsl" out/grades.html && [ -s out/grades_files/1_frame.png ] ||
    { echo "FAIL grade: no report or thumbnails"; fail=1; }
  # The report's verdict per function, where a file defines several: two_functions.glsl's
  # unpackDepth matches and its shadowTest is no-bias; the answer's four each match. The control:
  # unpack_only.glsl, one function, has none (its row is its verdict).
  python3 - out/grades.html <<'PY' || fail=1
import re, sys
rows = {}
for tr in re.findall(r"<tr><td>([^<]*)</td>(.*?)</tr>", open(sys.argv[1]).read()):
    rows[tr[0]] = re.findall(r"<li><code>(\w+)</code> alone: ([^<]*)</li>", tr[1])
want = {
    "two_functions.glsl": [("unpackDepth", "matches the sheet's answer"), ("shadowTest", "the classic mistake no-bias")],
    "answer.glsl": [(f, "matches the sheet's answer") for f in ("packDepth", "unpackDepth", "shadowTest", "offset_lookup")],
    "unpack_only.glsl": [],
    "no_bias.glsl": [],
}
bad = 0
for f, each in want.items():
    ok = rows.get(f) == each
    print(("ok" if ok else "FAIL") + f" report's verdicts per function of {f}: {rows.get(f)}")
    bad += not ok
sys.exit(1 if bad else 0)
PY
fi
# grade's bad input: exit status 2 and nothing written.
mkdir -p empty
rm -rf out2 && mkdir out2
for args in "empty --out out2/g.csv" "nowhere --out out2/g.csv" "class --out missing/g.csv" "class --out out2/g.txt" \
            "class --out out2/g.csv --encoding depthtex" "class --out out2/g.csv --filter pcss" "class --out out2/g.csv --size 8x8"; do
  "$penumbra" grade $args > /dev/null 2> g.err; rc=$?
  if [ $rc -ne 2 ] || [ -n "$(ls out2)" ]; then echo "FAIL grade $args: exit $rc, wrote: $(ls out2) $(cat g.err)"; fail=1
  else echo "ok grade $args: $(cat g.err)"; fi
done
exit $fail
