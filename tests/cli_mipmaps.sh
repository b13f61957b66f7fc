#!/usr/bin/env bash
# `penumbra mipmaps` end to end: both paths and both sources, a PNG read back as the source; every
# run exits 0, says the rendered chain is within 1 level of the CPU's on every level and writes
# each level of the three chains, index.html and mipmaps.csv. usage: cli_mipmaps.sh PENUMBRA WORKDIR
set -euo pipefail
penumbra=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail=0
run() {  # NAME ARGS...
  local name=$1; shift
  local out
  if ! out=$("$penumbra" mipmaps --repeat 1 "$@" 2>&1); then echo "FAIL $name: exit status"; echo "$out"; fail=1; return; fi
  grep -qE "rendered against the CPU: within [01] level" <<<"$out" || { echo "FAIL $name: not within 1 level"; echo "$out"; fail=1; }
  echo "$out" | sed -n 2p
}
run normals-levels --source normals --size 64 --path levels --out-dir a
run marble-textures --source marble --size 32 --path textures --out-dir b
run png-box --source a/rendered-0.png --filter box --out-dir c
for f in a/index.html a/mipmaps.csv a/rendered-6.png a/generated-6.png a/cpu-6.png b/rendered-5.png c/cpu-6.png; do
  [ -s "$f" ] || { echo "FAIL missing $f"; fail=1; }
done
[ "$(wc -l < a/mipmaps.csv)" -eq 8 ] || { echo "FAIL a/mipmaps.csv: want a header and 7 levels"; fail=1; }
grep -q "path levels" a/index.html || { echo "FAIL index.html names no path"; fail=1; }
[ "$fail" -eq 0 ] && echo "cli_mipmaps: all passed"
exit "$fail"
