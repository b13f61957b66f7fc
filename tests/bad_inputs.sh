#!/usr/bin/env bash
# The hostile-input corpus against `penumbra render`, `export` and `truth`: every file in
# tests/data/bad/expected.tsv (written by tests/data/make_bad.py) must end each command with its
# exact exit status and, on stderr, one line holding its message fragment; a refused input
# leaves no output behind. Then what git cannot hold, made here: a FIFO, a device, a folder and a
# socket given as the scene or named by a buffer's uri, and a symbolic link out of the folder.
# No command may take longer than 30 s (a hang) or die of a signal, and each runs under an
# address-space cap of CAP_KIB (ulimit -v; 4 GiB in the release build, none under the sanitizers):
# no bad input may need more.
# usage: bad_inputs.sh PENUMBRA DATA_DIR WORKDIR [CAP_KIB]
set -uo pipefail
penumbra=$1 data=$2 work=$3 cap=${4:-0}
[ "$cap" -gt 0 ] || cap=unlimited
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
have_truth=0
"$penumbra" truth --help >/dev/null 2>&1 && have_truth=1
pass=0 fail=0

# check LABEL STATUS FRAGMENT CMD...: run CMD (in a fresh out/ folder), compare.
check() {
  local label=$1 want=$2 fragment=$3; shift 3
  rm -rf out && mkdir out
  local err rc
  err=$( (ulimit -v "$cap" && timeout 30 "$@") 2>&1 >/dev/null); rc=$?
  local lines; lines=$(printf '%s' "$err" | grep -c '^penumbra: error')
  local ok=1
  [ "$rc" -eq "$want" ] || ok=0
  grep -qF -- "$fragment" <<<"$err" || ok=0
  if [ "$want" -ne 0 ]; then
    [ "$lines" -eq 1 ] || ok=0
    [ -z "$(ls -A out)" ] || ok=0   # nothing written, not even a temporary file
  fi
  if [ "$ok" -eq 1 ]; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1))
    echo "FAIL $label: exit $rc (want $want), expected '$fragment' in:"
    printf '%s\n' "$err" | head -5
    ls -A out | head -3
  fi
}

# on_scene LABEL STATUS FRAGMENT SCENE [OPTIONS...]: the three commands on one scene.
on_scene() {
  local label=$1 want=$2 fragment=$3 scene=$4; shift 4
  check "render $label" "$want" "$fragment" "$penumbra" render --scene "$scene" --size 32x32 --map-size 64 --out out/a.png "$@"
  check "export $label" "$want" "$fragment" "$penumbra" export --scene "$scene" --out out/a.gltf "$@"
  if [ "$have_truth" -eq 1 ]; then
    check "truth $label" "$want" "$fragment" "$penumbra" truth --scene "$scene" --size 16x16 --out-dir out/truth "$@"
  fi
}

cases=0
while IFS=$'\t' read -r file status fragment; do
  case "$file" in '#'*|'') continue ;; esac
  cases=$((cases + 1))
  on_scene "$file" "$status" "$fragment" "$data/bad/$file"
done < "$data/bad/expected.tsv"
[ "$cases" -gt 30 ] || { echo "FAIL: only $cases cases read from $data/bad/expected.tsv"; fail=$((fail + 1)); }

# Not regular files, as the scene: refused at once, never opened for a blocking read.
mkfifo fifo.gltf
on_scene "a FIFO as the scene" 2 "fifo.gltf: is a FIFO, not a regular file" fifo.gltf
ln -s /dev/zero zero.gltf
on_scene "a device as the scene" 2 "zero.gltf: is a character device, not a regular file" zero.gltf
mkdir folder.gltf
on_scene "a folder as the scene" 2 "folder.gltf: is a folder, not a regular file" folder.gltf

# ... and as a buffer's uri, inside the scene's folder.
mkdir -p scene
cp "$data/bad/buffer_is_folder.gltf" scene/base.gltf
uri_case() {  # uri_case LABEL URI FRAGMENT [OPTIONS...]
  local label=$1 uri=$2 fragment=$3; shift 3
  sed 's#"uri": "\."#"uri": "'"$uri"'"#' scene/base.gltf > scene/uri.gltf
  on_scene "$label" 2 "$fragment" scene/uri.gltf "$@"
}
mkfifo scene/fifo.bin
uri_case "a FIFO as a buffer" "fifo.bin" "buffers[0].uri 'fifo.bin' is not a regular file"
ln -s /dev/zero scene/zero.bin  # the link resolves to /dev/zero: outside the folder before anything else
uri_case "a device as a buffer" "zero.bin" "buffers[0].uri 'zero.bin' is outside the scene's folder"
# --allow-outside lets the link through the folder check, not past the regular-file one.
uri_case "a device as a buffer, /dev allowed" "zero.bin" "buffers[0].uri 'zero.bin' is not a regular file" --allow-outside /dev
mkdir scene/sub
uri_case "a folder as a buffer" "sub" "buffers[0].uri 'sub' is not a regular file"
ln -s /etc/passwd scene/link.bin
uri_case "a symbolic link out of the folder" "link.bin" "buffers[0].uri 'link.bin' is outside the scene's folder"
# Allowed, /etc/passwd is read as a buffer and fails as one (its size is not the buffer's).
uri_case "a file outside, allowed" "link.bin" "File size mismatch" --allow-outside /etc

# A name with a newline and bytes that are not UTF-8: one line, escaped.
cp "$data/bad/version_3.gltf" "$work/two"$'\n'"lines.gltf"
on_scene "a newline in the name" 2 'two\nlines.gltf: asset.version' "$work/two"$'\n'"lines.gltf"
cp "$data/bad/version_3.gltf" "$work/latin1-"$'\xe9'".gltf"
on_scene "a name that is not UTF-8" 2 'latin1-\xE9.gltf: asset.version' "$work/latin1-"$'\xe9'".gltf"

echo "$pass passed, $fail failed ($cases corpus files)"
[ "$fail" -eq 0 ]
