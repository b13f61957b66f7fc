#!/usr/bin/env bash
# Bad input to `penumbra`: one line on stderr (valid UTF-8) that names the problem, the exact exit
# status (2 for every bad input, an unwritable output included; 1 only for a failure while
# rendering; never a signal), and nothing written: no output file, not even a partial one or an
# empty folder. usage: cli_errors.sh PENUMBRA WORKDIR
set -uo pipefail
penumbra=$1 work=$2
data=$(cd "$(dirname "${BASH_SOURCE[0]}")/data" && pwd) || exit 1
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
printf '{ "asset": {"version": "2.0"}, "meshes": [ ' > broken.gltf
touch afile                  # a regular file: a path under it fails with ENOTDIR
printf 'not a png' > broken.png
"$penumbra" render --size 32x16 --out wide.png >/dev/null 2>&1 || { echo "setup: cannot render wide.png"; exit 1; }
mkdir adir.png adir.gltf     # existing folders named like the outputs
nonutf8=$(printf 'a\xff.gltf')
cp "$data/sphere_over_plane.gltf" "$nonutf8"
pass=0 fail=0
runner=()  # what runs penumbra: nothing, or setpriv for the read-only folder as root
have_truth=0
"$penumbra" truth --help >/dev/null 2>&1 && have_truth=1

# expect STATUS NAME WORD ARGS...: `penumbra ARGS` must exit with exactly STATUS, print exactly one
# line on stderr, valid UTF-8, containing WORD (a fixed string), and leave the folder as it was.
expect() {
  local status=$1 name=$2 word=$3; shift 3
  local before after err rc lines
  before=$(find . | LC_ALL=C sort)
  err=$("${runner[@]}" "$penumbra" "$@" 2>&1 >/dev/null); rc=$?
  after=$(find . | LC_ALL=C sort)
  lines=$(printf '%s\n' "$err" | grep -c '')
  if [ "$rc" -eq "$status" ] && [ "$lines" -eq 1 ] && grep -qiF -- "$word" <<<"$err" \
     && printf '%s' "$err" | iconv -f UTF-8 -t UTF-8 >/dev/null 2>&1 && [ "$before" = "$after" ]; then
    pass=$((pass + 1))
  else
    echo "FAIL $name: rc=$rc (want $status) lines=$lines stderr: $err"
    [ "$before" = "$after" ] || { echo "  the folder changed:"; diff <(echo "$before") <(echo "$after"); }
    fail=$((fail + 1))
  fi
  # Whatever a failed case left, the next starts clean.
  rm -rf out.png out.png.tmp* nowhere newdir ./*.probe* 2>/dev/null
}

# `penumbra render --out out.png ARGS`: bad input, exit status 2.
expect_error() { local name=$1 word=$2; shift 2; expect 2 "$name" "$word" render --out out.png "$@"; }

expect_error "missing file"      "no_such.gltf"  --scene no_such.gltf
expect_error "malformed file"    "broken.gltf"   --scene broken.gltf
expect_error "unknown option"    "--colour"      --colour red
expect_error "unknown encoding"  "r16"           --encoding r16
expect_error "unknown filter"    "pcf8x8"        --filter pcf8x8
expect_error "unknown aov"       "aov"           --aov normals
expect_error "unknown technique" "technique"     --technique volume
expect_error "zero size"         "--size"        --size 0x512
expect_error "bad size"          "--size"        --size 512
expect_error "huge size"         "maximum"       --size 100000x64
expect_error "zero map size"     "--map-size"    --map-size 0
expect_error "huge map size"     "[1, 65536]"    --map-size 100000
expect_error "bad time"          "--time"        --time soon
expect_error "bad bias"          "--bias"        --bias -1
expect_error "zero frames"       "--frames"      --frames 0
expect_error "light-depth planar" "light-depth"  --aov light-depth --technique planar
# Numbers: finite and in range, the option, the value and the rule named.
expect_error "time nan"          "--time: must be a finite number in [-1000000, 1000000], got 'nan'" --time nan
expect_error "time inf"          "--time: must be a finite number" --time inf
expect_error "time too far"      "--time: must lie in [-1000000, 1000000], got '1e300'" --time 1e300
expect_error "light radius inf"  "--light-radius: must be a finite number in [0, 1000000], got 'inf'" --light-radius inf
expect_error "frames too many"   "--frames: must lie in [1, 10000], got '100000'" --frames 100000
expect 2 "effects unknown"        "--effects: unknown value 'window'" render --effects outline,window --size 16x16
expect 2 "reflectivity range"     "--reflectivity: must lie in [0, 1]" render --effects mirror --reflectivity 1.5 --size 16x16
expect 2 "portal without one"     "the scene has no portal" render --effects portal --scene "$data/sphere_over_plane.gltf" --size 16x16 --out p.png
expect 2 "effects twice"          "'outline' twice"   plan --effects outline,outline
expect 2 "cascades unknown"       "--cascades: unknown value '5' (1, 2, 3, 4, cube, auto)" plan --cascades 5
expect 2 "cascade split range"    "--cascade-split: must lie in [0, 1]" plan --cascade-split 2
expect 2 "cascade blend range"    "--cascade-blend: must lie in [0, 0.5]" render --cascade-blend 0.6 --size 16x16
expect 2 "cascades aov planar"    "--aov cascades: needs --technique shadowmap" render --aov cascades --technique planar
expect 2 "cascades bench soft"    "--cascades: not with --soft" bench --cascades --soft
expect 2 "cascades bench scenes"  "bench --cascades: one scene" bench --cascades --scenes a.gltf,b.gltf
expect 2 "outline width small"    "--outline-width: must lie in [0.5, 32]" render --effects outline --outline-width 0.1
expect 2 "outline width word"     "--outline-width: not a number" plan --outline-width wide
expect 2 "outline colour form"    "--outline-color: expected six hex digits" render --outline-color 1,0,0 --size 16x16
expect 2 "plan frames too many"  "--frames: must lie in [1, 10000]" plan --frames 100000
expect 2 "gallery time nan"      "--time: must be a finite number" gallery --out-dir newdir --time nan

# An option without its value is named, not the word after it (CLI11 said "The following argument
# was not expected: 0.5"); a negative number is a value, not an option (the control).
expect 2 "scene without value"   "penumbra: error: --scene: needs a value (got the option --time instead)" render --scene --time 0.5
expect 2 "time without value"    "--time: needs a value (it is the last argument)" render --time
expect 2 "time= empty"           "--time: needs a value (nothing after its '=')" render --time=
expect 2 "encoding '' empty"     "--encoding: needs a value: r8, rgba, depthtex" render --encoding ''
expect 2 "grade out"             "--out: needs a value (got the option --size instead)" grade "$data" --out --size 64x48
expect 2 "negative is a value"   "--bias: must lie in [0, 1], got '-0.5'" render --bias -0.5
expect 2 "negative time"         "--frames: must lie in [1, 10000]" render --time -0.5 --frames 0
# Every option that takes a value, of every subcommand (as each --help lists them: a name and a
# type), named when it is the last word and when another option follows it: exactly that one line,
# exit status 2, and the folder as it was (checked once around the loop: expect's per-case look
# at the folder made this loop alone take minutes).
subcommands=$("$penumbra" --help | awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }')
valued=0 loop_bad=0
before=$(find . | LC_ALL=C sort)
for sub in $subcommands; do
  for opt in $("$penumbra" "$sub" --help | sed -n 's/^  \(-[a-zA-Z],\)\{0,1\}\(--[a-z0-9-]*\) [A-Z][A-Z_:]*\( .*\)\{0,1\}$/\2/p'); do
    for next in "" --scene; do
      want="penumbra: error: $opt: needs a value (got the option --scene instead) (see penumbra --help)"
      [ -z "$next" ] && want="penumbra: error: $opt: needs a value (it is the last argument) (see penumbra --help)"
      err=$("$penumbra" "$sub" "$opt" $next 2>&1 >/dev/null); rc=$?
      if [ "$rc" -ne 2 ] || [ "$err" != "$want" ]; then
        echo "FAIL $sub $opt $next: rc=$rc stderr: $err"; loop_bad=$((loop_bad + 1))
      fi
    done
    valued=$((valued + 1))
  done
done
[ "$before" = "$(find . | LC_ALL=C sort)" ] || { echo "FAIL the options without values changed the folder"; loop_bad=$((loop_bad + 1)); }
# The control of the loop: it found the commands and their options (render's alone take 40).
if [ "$loop_bad" -eq 0 ] && [ "$valued" -ge 100 ] && grep -qw grade <<<"$subcommands"; then pass=$((pass + 1))
else echo "FAIL the options that take a value: $loop_bad failed, $valued found in: $subcommands"; fail=$((fail + 1)); fi
echo "options that take a value, each without it: $valued"

# A folder that does not exist: named, nothing written (not the folder either).
expect 2 "missing folder"        "folder nowhere does not exist" render --out nowhere/out.png
# Unwritable outputs are bad input too (2), with the system's reason, found before any rendering.
# The tests may run as root, for whom chmod does not stop a write: then the read-only folder is
# tried as user nobody (setpriv) where that can run penumbra here, and skipped where it cannot.
# Every user gets a path under a regular file (ENOTDIR), under /proc (nothing can be created
# there, not even by root) and an existing folder as the output file (EISDIR).
mkdir ro && chmod 555 ro
if [ "$(id -u)" -eq 0 ]; then
  runner=(setpriv --reuid=65534 --regid=65534 --clear-groups)
  { "${runner[@]}" "$penumbra" --help && "${runner[@]}" test -r . -a -x .; } >/dev/null 2>&1 || { runner=(); echo "note: root without a way to run as nobody: read-only folder not tried"; }
fi
if [ "$(id -u)" -ne 0 ] || [ "${#runner[@]}" -gt 0 ]; then
  expect 2 "read-only folder"    "--out ro/out.png: cannot write in folder ro (Permission denied)" render --out ro/out.png --size 16x16
  expect 2 "read-only out-dir"   "--out ro/shaders: cannot create (Permission denied)" shaders --out ro/shaders
  expect 2 "read-only export"    "Permission denied" export --out ro/x.gltf
fi
runner=()
expect 2 "out under a file"      "Not a directory"   render --out afile/out.png --size 16x16
expect 2 "out under /proc"       "--out /proc/penumbra-cli-test.png: cannot write" render --out /proc/penumbra-cli-test.png --size 16x16
expect 2 "out is a folder"       "--out adir.png: cannot write (Is a directory)" render --out adir.png --size 16x16
expect 2 "export out is a folder" "Is a directory"   export --out adir.gltf
expect 2 "export out under /proc" "/proc"            export --out /proc/penumbra-cli-test.gltf
expect 2 "export out extension"  "must end in .gltf" export --out x.png
expect 2 "shaders under /proc"   "--out /proc/penumbra-cli-test"  shaders --out /proc/penumbra-cli-test
expect 2 "gallery under a file"  "--out-dir afile/g: cannot create" gallery --out-dir afile/g --size 16x16
# A newline in a name stays one line (\n); so does a byte that is not UTF-8 (\xFF).
expect 2 "newline in --out"      'no\nwhere'         render --out "$(printf 'no\nwhere')/out.png"
expect 2 "newline in --scene"    'new\nline'         render --scene "$(printf 'new\nline.gltf')"
expect 2 "newline in a value"    "--encoding: unknown value 'r\\n8'" render --encoding "$(printf 'r\n8')"
expect 2 "missing non-UTF-8 scene" 'b\xFF.gltf'      render --scene "$(printf 'b\xff.gltf')"
expect 2 "newline in CLI11's error" 'Could not convert: --frames = 1\n2' bench --frames "$(printf '1\n2')" --out-dir newdir
expect 2 "newline in a subcommand" "unknown subcommand 'sub\ncmd'" "$(printf 'sub\ncmd')"
# Subcommands.
expect 2 "unknown subcommand"    "unknown subcommand 'frobnicate' (expected one of render, plan, gallery" frobnicate
expect 2 "no subcommand"         "a subcommand is required" 
expect 2 "export time nan"       "--time: must be a finite number" export --time nan --out x.gltf
expect 2 "export size"           "--size: width and height must be at most 16384" export --size 100000x10 --out x.gltf
expect 2 "mipmaps size"          "--size: 96 is not a power of two" mipmaps --size 96 --out-dir newdir
expect 2 "mipmaps size 0"        "--size: 0 is not a power of two" mipmaps --size 0 --out-dir newdir
expect 2 "mipmaps missing png"   "--source: nothere.png"  mipmaps --source nothere.png --out-dir newdir
expect 2 "mipmaps not a png"     "expected marble, normals or a FILE.png" mipmaps --source "$data/textured_quad.gltf" --out-dir newdir
expect 2 "mipmaps broken png"    "--source: broken.png"   mipmaps --source broken.png --out-dir newdir
expect 2 "mipmaps not square"    "wide.png is 32x16: a mip chain here is square" mipmaps --source wide.png --out-dir newdir
expect 2 "mipmaps filter"        "--filter: blur not in {box,normal,auto}" mipmaps --filter blur --out-dir newdir
expect 2 "mipmaps out-dir"       "--out-dir afile/m: cannot create" mipmaps --size 16 --out-dir afile/m

if [ "$have_truth" -eq 1 ]; then
  # truth checks every option before it creates its folder or does any work.
  expect 2 "truth huge size"     "--size: width and height must be at most 16384 (the maximum), got '100000x100000'" \
    truth --size 100000x100000 --out-dir newdir
  expect 2 "truth time nan"      "--time: must be a finite number" truth --time nan --out-dir newdir
  expect 2 "truth light radius"  "--light-radius: must be a finite number in [0, 1000000], got 'inf'" \
    truth --light-radius inf --out-dir newdir
  expect 2 "truth soft samples"  "--soft-samples: must lie in [0, 16384], got '100000'" truth --soft-samples 100000 --out-dir newdir
  expect 2 "truth blend-shadows" "--blend-shadows: unknown value 'maybe' (off, on)" truth --blend-shadows maybe --out-dir newdir
  expect 2 "truth negative soft" "--soft-samples: must lie in [0, 16384], got '-1'" truth --soft-samples -1 --out-dir newdir
  expect 2 "truth out-dir /proc" "--out-dir /proc/penumbra-cli-test: cannot create" \
    truth --size 16x16 --out-dir /proc/penumbra-cli-test
  expect 2 "truth out-dir file"  "--out-dir afile" truth --size 16x16 --out-dir afile
  expect 2 "bench frames -5"     "--frames: must lie in [1, 10000], got '-5'" bench --frames -5 --out-dir newdir
  expect 2 "bench frames huge"   "--frames: must lie in [1, 10000], got '100000'" bench --frames 100000 --out-dir newdir
  expect 2 "bench rounds"        "--rounds: must lie in [1, 100], got '0'" bench --rounds 0 --out-dir newdir
  expect 2 "bench soft samples"  "--soft-samples: must lie in [0, 16384]" bench --soft-samples 100000 --out-dir newdir
  expect 2 "bench scene time"    "--scenes: 'teapot@nan'" bench --scenes teapot@nan --out-dir newdir
  expect 2 "bench out-dir file"  "--out-dir afile/b: cannot create" bench --from-csv none.csv --out-dir afile/b
fi

# The good cases. A non-UTF-8 scene path works: export writes valid JSON naming it escaped, and
# the file loads back (rendered from it); no "null" (a number JSON cannot hold) in it.
rm -f out.png
if "$penumbra" render --out out.png --size 64x48 --map-size 256 2>/dev/null && [ -s out.png ] \
   && [ "$(head -c 24 out.png | tail -c 8 | od -An -tu1 | tr -s ' ')" = " 0 0 0 64 0 0 0 48" ]; then
  pass=$((pass + 1))
else
  echo "FAIL good render"; fail=$((fail + 1))
fi
rm -f out.png
for t in 0 0.6 7.25; do
  if "$penumbra" export --time "$t" --out course.gltf >/dev/null 2>&1 && ! grep -q null course.gltf \
     && "$penumbra" render --scene course.gltf --size 32x32 --map-size 256 --out back.png 2>/dev/null && [ -s back.png ]; then
    pass=$((pass + 1))
  else
    echo "FAIL export at t = $t does not load back"; fail=$((fail + 1))
  fi
  rm -f course.gltf back.png
done
if "$penumbra" export --scene "$nonutf8" --out nonutf8.gltf >/dev/null 2>&1 \
   && python3 -c 'import json,sys; json.load(open(sys.argv[1], encoding="utf-8"))' nonutf8.gltf \
   && grep -qF 'a\\xFF.gltf' nonutf8.gltf \
   && "$penumbra" render --scene nonutf8.gltf --size 32x32 --map-size 256 --out back.png 2>/dev/null && [ -s back.png ]; then
  pass=$((pass + 1))
else
  echo "FAIL export of a non-UTF-8 scene path"; fail=$((fail + 1))
fi
rm -f nonutf8.gltf back.png
if "$penumbra" render --scene "$nonutf8" --size 32x32 --map-size 256 --aov visibility --out vis.png 2>/dev/null; then
  pass=$((pass + 1))
else
  echo "FAIL render of a non-UTF-8 scene path"; fail=$((fail + 1))
fi
if [ "$have_truth" -eq 1 ]; then
  if "$penumbra" truth --scene "$nonutf8" --size 32x32 --out-dir truth --score vis.png --json 2>/dev/null > score.json \
     && python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["scene"] == "a\\xFF.gltf"' score.json; then
    pass=$((pass + 1))
  else
    echo "FAIL truth --json of a non-UTF-8 scene path"; fail=$((fail + 1))
  fi
fi
# --allow-outside PATH reaches the loader: a buffer in a sibling folder loads with it.
mkdir -p outside/scene outside/shared
python3 - "$data/sphere_over_plane.gltf" <<'PY'
import base64, json, sys
g = json.load(open(sys.argv[1]))
b = g["buffers"][0]
open("outside/shared/data.bin", "wb").write(base64.b64decode(b["uri"].split(",", 1)[1]))
b["uri"] = "../shared/data.bin"
json.dump(g, open("outside/scene/s.gltf", "w"))
PY
if "$penumbra" render --scene outside/scene/s.gltf --allow-outside outside/shared --size 16x16 --map-size 64 --out outside.png 2>/dev/null \
   && [ -s outside.png ] && "$penumbra" plan --scene outside/scene/s.gltf --allow-outside outside/shared --size 16x16 >/dev/null 2>&1 \
   && "$penumbra" export --scene outside/scene/s.gltf --allow-outside outside/shared --out outside.gltf >/dev/null 2>&1; then
  pass=$((pass + 1))
else
  echo "FAIL --allow-outside"; fail=$((fail + 1))
fi
# --allow-outside is taken by every command that takes --scene (the loader enforces it).
for cmd in render plan gallery export truth bench; do
  [ "$have_truth" -eq 0 ] && { [ "$cmd" = truth ] || [ "$cmd" = bench ]; } && continue
  if "$penumbra" "$cmd" --help 2>/dev/null | grep -q -- "--allow-outside"; then
    pass=$((pass + 1))
  else
    echo "FAIL $cmd --help has no --allow-outside"; fail=$((fail + 1))
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
