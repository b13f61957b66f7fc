#!/usr/bin/env bash
# The layering the code promises (docs/architecture.md), checked on the source tree:
#  1. no branch on a technique (==, != or case on Technique::) outside the technique modules and
#     their registry (src/render/techniques/) and the settings and option definitions
#     (src/render/settings.*, src/render/option_table.cpp): the planner, the frame shapes, the
#     tools and the examples ask the module (render/techniques/technique.h);
#  2. the planning code (src/render/plan*.cpp, frames/, techniques/) includes no GL header;
#  3. no source file over 600 lines.
# Each check runs first on a small tree made to break it (its control: it must fail there), then
# on the repository.
# usage: tests/layering.sh REPO_ROOT
set -euo pipefail
root=${1:?usage: layering.sh REPO_ROOT}

branches() {  # prints each branch on a technique outside the allowed files
  (cd "$1" && grep -rnE '(==|!=)[[:space:]]*(render::)?Technique::|(render::)?Technique::[A-Za-z]+[[:space:]]*(==|!=)|case[[:space:]]+(render::)?Technique::' \
      src tools examples --include='*.cpp' --include='*.h' 2>/dev/null |
   grep -vE '^src/render/techniques/|^src/render/settings\.(h|cpp):|^src/render/option_table\.cpp:' || true)
}
gl_in_planning() {  # prints each GL include in the planning code
  (cd "$1" && grep -nE '#include[[:space:]]+[<"](GLES2/|EGL/|gl/gl_headers\.h|gl/device\.h|gl/objects\.h|gl/timer\.h)' \
      src/render/plan*.cpp src/render/frames/*.cpp src/render/frames/*.h src/render/techniques/*.cpp \
      src/render/techniques/*.h 2>/dev/null || true)
}
long_files() {  # prints each source file over 600 lines
  (cd "$1" && find src tools examples tests web shaders_gles2 -type f \
      \( -name '*.cpp' -o -name '*.h' -o -name '*.js' -o -name '*.mjs' -o -name '*.glsl' -o -name '*.vert' -o -name '*.frag' \) \
      -not -path '*/thirdparty/*' -not -path '*/node_modules/*' 2>/dev/null |
   while read -r f; do n=$(wc -l < "$f"); [ "$n" -le 600 ] || echo "$f: $n lines"; done)
}

# Controls: a tree with one of each.
ctl=$(mktemp -d)
trap 'rm -rf "$ctl"' EXIT
mkdir -p "$ctl/src/render/frames" "$ctl/src/render/techniques" "$ctl/tools" "$ctl/examples" "$ctl/tests" "$ctl/web" "$ctl/shaders_gles2"
echo 'if (s.technique == render::Technique::Volumes) return;' > "$ctl/tools/bench.cpp"
echo 'switch (t) { case Technique::Planar: break; }' > "$ctl/examples/app.cpp"
echo 'if (s.technique == Technique::Volumes) {}' > "$ctl/src/render/techniques/volumes.cpp"  # allowed
echo '#include "gl/device.h"' > "$ctl/src/render/frames/forward.cpp"
seq 601 > "$ctl/src/render/long.cpp"
[ "$(branches "$ctl" | wc -l)" -eq 2 ] || { echo "control: the branch check missed a branch (or flagged a module):"; branches "$ctl"; exit 1; }
[ -n "$(gl_in_planning "$ctl")" ] || { echo "control: the GL include in the planning code was not found"; exit 1; }
[ -n "$(long_files "$ctl")" ] || { echo "control: the 601-line file was not found"; exit 1; }

fail=0
if out=$(branches "$root") && [ -n "$out" ]; then
  echo "branches on a technique outside its module (ask the module: render/techniques/technique.h):"; echo "$out"; fail=1
fi
if out=$(gl_in_planning "$root") && [ -n "$out" ]; then
  echo "GL in the planning code (plans are made without a context):"; echo "$out"; fail=1
fi
if out=$(long_files "$root") && [ -n "$out" ]; then
  echo "files over 600 lines:"; echo "$out"; fail=1
fi
[ "$fail" -eq 0 ] && echo "layering: no technique branch outside the modules, no GL in planning, no file over 600 lines"
exit "$fail"
