#!/usr/bin/env bash
# Outputs that fail while they are written: every command that writes files, on each hostile
# output (a full disk: the file a symbolic link to /dev/full; a read-only folder; a folder where
# the file should go), must end with exit status 2 and one error line on stderr naming the path
# and the system's reason, and leave no partial or temporary file (the link still a link to
# /dev/full, the folder still an empty folder). Also standard output on a full disk.
# usage: cli_write_errors.sh PENUMBRA WORKDIR
set -uo pipefail
penumbra=$(realpath -- "$1") work=$2
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd) || exit 1
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
pass=0 fail=0 runs=0
have_truth=0
"$penumbra" truth --help >/dev/null 2>&1 && have_truth=1

# The read-only folder. Tests and CI run as root, whom chmod does not stop: where this machine
# allows a mount namespace (unshare -m), each command runs in its own, with ro/ bind-mounted
# read-only over itself (EROFS, "Read-only file system"); nothing outside that command sees the
# mount. Otherwise a user who is not root gets chmod 555 (EACCES), and root /sys, where even root
# cannot create a file (EACCES, or EROFS where /sys is mounted read-only). The reason expected is
# the one touch gets there.
mkdir ro
ro=ro
ro_wrap=(unshare -m sh -c 'mount --bind "$0" "$0" && mount -o remount,bind,ro "$0" && exec "$@"' "$PWD/ro")
# probe: why a new file cannot be made in $ro (the system's reason as touch prints it), or "".
probe() { "${ro_wrap[@]}" touch "$ro/probe" 2>&1 | sed -n "s/.*: //p" | tail -1; rm -f "$ro/probe" 2>/dev/null; }
ro_reason=$(probe)
if [ "$ro_reason" != "Read-only file system" ]; then
  ro_wrap=()
  if [ "$(id -u)" -ne 0 ]; then chmod 555 ro; else ro=/sys; fi
  ro_reason=$(probe)
  echo "note: no read-only mount here: the read-only folder is $ro (${ro_reason:-writable: not tried})"
fi

# The state of PATH, to compare before and after: its type, and where a link points.
state() { if [ -e "$1" ] || [ -L "$1" ]; then stat -c '%F %N' -- "$1"; [ -d "$1" ] && ls -A -- "$1"; else echo absent; fi; }

# expect NAME PATH REASON WHERE CMD...: CMD must exit with exactly 2, end stderr with its one error
# line (progress lines may come before it), which holds PATH and "(REASON)", leave PATH as it was (WHERE: the folder whose listing must not
# change at all, or "" where the command may have written other files whole before failing), and
# leave no temporary file anywhere under the working folder.
expect() {
  local name=$1 path=$2 reason=$3 where=$4; shift 4
  local before after listed=""
  before=$(state "$path")
  [ -n "$where" ] && listed=$(find "$where" -printf '%p %y %l\n' | LC_ALL=C sort)
  local err rc errors line ok=1 why=""
  err=$(timeout 300 "$@" 2>&1 >/dev/null); rc=$?
  errors=$(grep -c '^penumbra: error: ' <<<"$err")
  line=$(tail -1 <<<"$err")
  [ "$rc" -eq 2 ] || { ok=0; why+=" exit $rc (want 2);"; }
  [ "$errors" -eq 1 ] || { ok=0; why+=" $errors error lines (want 1, the last);"; }
  grep -qF -- "$path" <<<"$line" || { ok=0; why+=" the path is not named;"; }
  grep -qF -- "($reason)" <<<"$line" || { ok=0; why+=" the reason ($reason) is not given;"; }
  after=$(state "$path")
  [ "$before" = "$after" ] || { ok=0; why+=" $path changed: $(tr '\n' ' ' <<<"$after");"; }
  if [ -n "$where" ] && [ "$listed" != "$(find "$where" -printf '%p %y %l\n' | LC_ALL=C sort)" ]; then
    ok=0; why+=" something was written in $where;"
  fi
  local left; left=$(find . \( -name '*.tmp*' -o -name '*.probe*' \) -print | head -3 | tr '\n' ' ')
  [ -z "$left" ] || { ok=0; why+=" left behind: $left;"; }
  if [ "$ok" -eq 1 ]; then
    pass=$((pass + 1))
  else
    echo "FAIL $name:$why stderr: $(head -3 <<<"$err")"
    fail=$((fail + 1))
  fi
  find . \( -name '*.tmp*' -o -name '*.probe*' \) -exec rm -rf {} + 2>/dev/null
}

# One file: --out FILE (render, export).
file_cases() {
  local cmd=$1 ext=$2; shift 2
  mkdir -p "$cmd" && ln -sfn /dev/full "$cmd/full.$ext" && mkdir -p "$cmd/dir.$ext"
  expect "$cmd to /dev/full" "$cmd/full.$ext" "No space left on device" "$cmd" \
    "$penumbra" "$cmd" "$@" --out "$cmd/full.$ext"
  expect "$cmd to a folder" "$cmd/dir.$ext" "Is a directory" "$cmd" "$penumbra" "$cmd" "$@" --out "$cmd/dir.$ext"
  [ -n "$ro_reason" ] &&
    expect "$cmd to a read-only folder" "$ro/x.$ext" "$ro_reason" "" "${ro_wrap[@]}" "$penumbra" "$cmd" "$@" --out "$ro/x.$ext"
}

# A folder of files (OPTION DIR): first a good run, which must write FILE (NAME: FILE itself, or
# "first": the file it wrote first), then FILE made a link to /dev/full, then a folder.
folder_cases() {
  local cmd=$1 option=$2 file=$3; shift 3
  local good="$cmd-good" n=$((++runs))
  if ! "$penumbra" "$cmd" "$@" "$option" "$good" >/dev/null 2>&1; then
    echo "FAIL $cmd: the good run failed: $("$penumbra" "$cmd" "$@" "$option" "$good" 2>&1 >/dev/null | tail -1)"
    fail=$((fail + 1)); return
  fi
  [ "$file" = first ] && file=$(ls -1tr "$good" | head -1)
  if [ -z "$file" ] || [ ! -s "$good/$file" ]; then
    echo "FAIL $cmd: the good run wrote no ${file:-file} in $good"; fail=$((fail + 1)); return
  fi
  rm -rf "$good"
  mkdir -p "full$n" "dir$n/$file" && ln -s /dev/full "full$n/$file"
  expect "$cmd: $file to /dev/full" "full$n/$file" "No space left on device" "" \
    "$penumbra" "$cmd" "$@" "$option" "full$n"
  expect "$cmd: $file a folder" "dir$n/$file" "Is a directory" "" "$penumbra" "$cmd" "$@" "$option" "dir$n"
  [ -n "$ro_reason" ] &&
    expect "$cmd: a read-only folder" "$option $ro:" "$ro_reason" "" "${ro_wrap[@]}" "$penumbra" "$cmd" "$@" "$option" "$ro"
}

file_cases render png --size 16x16 --map-size 64
file_cases export gltf
folder_cases shaders --out first
folder_cases mipmaps --out-dir index.html --size 16
folder_cases gallery --out-dir first --size 16x16 --map-size 64
if [ "$have_truth" -eq 1 ]; then
  folder_cases truth --out-dir visibility.png --size 16x16
  folder_cases bench --out-dir results.md --from-csv "$root/results/bench/results.csv"
  folder_cases bench --out-dir tradeoff.png --from-csv "$root/results/bench/results.csv"
fi

# Standard output on a full disk: the same (main() flushes and checks it).
err=$("$penumbra" plan --json 2>&1 >/dev/full); rc=$?
if [ "$rc" -eq 2 ] && grep -qF "standard output (No space left on device)" <<<"$err"; then
  pass=$((pass + 1))
else
  echo "FAIL plan --json to /dev/full: exit $rc, stderr: $err"; fail=$((fail + 1))
fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
