#!/usr/bin/env bash
# desktop.*: penumbra-desktop opens a real window (GLFW, GLES 2 through EGL) on a virtual X server
# (Xvfb, Mesa llvmpipe), renders some frames, writes a screenshot and exits 0; the screenshot must
# have the window's size and not be blank.
# usage: run_desktop.sh PENUMBRA_DESKTOP OUT_DIR NAME EXPECTED_WxH [app options...]
set -euo pipefail
app=$1 out=$2 name=$3 size=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
shot="$out/$name.png"
rm -f "$shot"
log="$out/$name.log"
# 24-bit screen: the default 8-bit one offers no RGB888 EGL config.
if ! xvfb-run -a -s "-screen 0 1280x1024x24" "$app" --frames 30 --screenshot "$shot" "$@" >"$log" 2>&1; then
  echo "desktop $name: penumbra-desktop failed:"; cat "$log"; exit 1
fi
grep -q "GLFW .* window, GLES 2 through EGL" "$log" || { echo "desktop $name: no window reported:"; cat "$log"; exit 1; }
grep -q "^30 frames" "$log" || { echo "desktop $name: did not render 30 frames:"; cat "$log"; exit 1; }
python3 "$here/check_png.py" "$shot" "$size"
grep -E "^(window resized|wrote|30 frames)" "$log"
