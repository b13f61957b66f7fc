#!/usr/bin/env bash
# Approves the golden images that the GL tests wrote as NAME.actual.png: copies each over
# tests/golden/NAME.png. Look at every actual (and its diff) before you run this, and say in the
# commit why the goldens changed.
# usage: tools/approve_goldens.sh [BUILD_DIR] [NAME ...]   (default build dir: build; default: all)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}; shift || true
src="$root/$build/test-output/golden"
[ -d "$src" ] || { echo "no $src: run the GL tests first (ctest --test-dir $build -L gl)"; exit 1; }
shopt -s nullglob
actuals=("$src"/*.actual.png)
[ ${#actuals[@]} -gt 0 ] || { echo "nothing to approve in $src"; exit 0; }
for f in "${actuals[@]}"; do
  name=$(basename "$f" .actual.png)
  if [ $# -gt 0 ] && ! printf '%s\n' "$@" | grep -qx "$name"; then continue; fi
  cp "$f" "$root/tests/golden/$name.png"
  rm -f "$f" "$src/$name.diff.png"
  echo "approved $name"
done
