#!/usr/bin/env bash
# Bad input to `penumbra render`: one line on stderr that names the problem, a non-zero exit, and
# no output file left behind (not even a partial one). usage: cli_errors.sh PENUMBRA WORKDIR
set -uo pipefail
penumbra=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
printf '{ "asset": {"version": "2.0"}, "meshes": [ ' > broken.gltf
pass=0 fail=0

# expect_error NAME WORD ARGS...: must exit non-zero, print exactly one line containing WORD,
# and leave out.png absent.
expect_error() {
  local name=$1 word=$2; shift 2
  rm -f out.png
  local err rc
  err=$("$penumbra" render --out out.png "$@" 2>&1 >/dev/null); rc=$?
  local lines; lines=$(printf '%s\n' "$err" | grep -c .)
  if [ "$rc" -ne 0 ] && [ "$lines" -eq 1 ] && grep -qi -- "$word" <<<"$err" && [ ! -e out.png ] \
     && ! ls out.png.tmp* >/dev/null 2>&1; then
    pass=$((pass + 1))
  else
    echo "FAIL $name: rc=$rc lines=$lines stderr: $err"; ls; fail=$((fail + 1))
  fi
}

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
expect_error "bad time"          "--time"        --time soon
expect_error "bad bias"          "--bias"        --bias -1
expect_error "zero frames"       "--frames"      --frames 0
expect_error "light-depth planar" "light-depth"  --aov light-depth --technique planar

# A folder that does not exist: named, nothing written.
err=$("$penumbra" render --out nowhere/out.png 2>&1 >/dev/null); rc=$?
if [ "$rc" -ne 0 ] && grep -q nowhere <<<"$err" && [ ! -e nowhere ]; then pass=$((pass + 1)); else echo "FAIL missing folder: $err"; fail=$((fail + 1)); fi

# And the good case writes a PNG whose size is what was asked.
rm -f out.png
if "$penumbra" render --out out.png --size 64x48 --map-size 256 2>/dev/null && [ -s out.png ] \
   && [ "$(head -c 24 out.png | tail -c 8 | od -An -tu1 | tr -s ' ')" = " 0 0 0 64 0 0 0 48" ]; then
  pass=$((pass + 1))
else
  echo "FAIL good render"; fail=$((fail + 1))
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
