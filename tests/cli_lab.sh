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
mkdir -p class out && cp "$data"/*.glsl class/ && mkdir class/folder.glsl
head -c 3000000 /dev/zero | tr '\0' 'x' > class/huge.glsl
printf 'float f() {\x01\x02 return 1.0; }\n' > class/binary.glsl
if ! "$penumbra" grade class --out out/grades.csv > grade.out 2> grade.err; then
  echo "FAIL grade: $(tail -3 grade.err)"; fail=1
else
  python3 - out/grades.csv <<'PY' || fail=1
import csv, sys
rows = {r["file"]: r for r in csv.DictReader(open(sys.argv[1]))}
want = {  # file: (compiles, error (exact, or a prefix ending in '...'), mistake)
    "answer.glsl": ("yes", "", ""),
    "unpack_only.glsl": ("yes", "", ""),
    "no_bias.glsl": ("yes", "", "no-bias"),
    "eight_bit_threshold.glsl": ("yes", "", "8-bit-threshold"),
    "red_only.glsl": ("yes", "", "red-only"),
    "detached.glsl": ("yes", "", "detached"),
    "no_texmapscale.glsl": ("yes", "", "no-texmapscale"),
    "broken.glsl": ("no", "broken.glsl:...", ""),  # the compiler's words are the implementation's
    "hostile_main.glsl": ("no", "hostile_main.glsl:3: defines or names main: the renderer's shader has its own; write only "
                          "the sheet's functions; hostile_main.glsl:4: the name gl_FragColor belongs to the renderer "
                          "(u_, a_, v_, g_, gl_ and penumbra names)", ""),
    "hostile_uniform.glsl": ("no", "hostile_uniform.glsl:2: declares a uniform of its own: the lab's functions get what "
                             "they need as parameters (and texmapscale)", ""),
    "hostile_loop.glsl": ("no", "hostile_loop.glsl:4: this loop runs more than 16 times (or never ends); the lab's loops "
                          "are short, they run per pixel", ""),
    "hostile_nested.glsl": ("no", "hostile_nested.glsl:4: shadowTest does about 4641 steps per call (loop iterations and "
                            "calls); at most 256 are allowed, it runs per pixel", ""),
    "huge.glsl": ("no", "huge.glsl: the file holds 3000000 bytes; a snippets file may hold 65536", ""),
    "binary.glsl": ("no", "binary.glsl:1: byte 0x01 is not printable ASCII (GLSL ES 1.00 source is ASCII)", ""),
}
bad = 0
if set(rows) != set(want):
    print("FAIL grade: files", sorted(rows), "want", sorted(want)); sys.exit(1)
for f, (compiles, error, mistake) in want.items():
    r = rows[f]
    ok = r["compiles"] == compiles and r["mistake"] == mistake and (
        r["error"].startswith(error[:-3]) if error.endswith("...") else r["error"] == error)
    if compiles == "yes":
        ok = ok and float(r["differing_pixels_pct"]) >= 0 and float(r["error_vs_truth_pct"]) >= 0
        if not mistake: ok = ok and float(r["differing_pixels_pct"]) <= 0.1
        else: ok = ok and float(r["differing_pixels_pct"]) > 0.1
    else:
        ok = ok and r["differing_pixels_pct"] == "" and r["error_vs_truth_pct"] == ""
    print(("ok" if ok else "FAIL") + " grade row " + f + ": " + ",".join(r.values())[:200])
    bad += not ok
sys.exit(1 if bad else 0)
PY
  [ -s out/grades.html ] && grep -q "answer.glsl" out/grades.html && [ -s out/grades_files/1_frame.png ] ||
    { echo "FAIL grade: no report or thumbnails"; fail=1; }
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
