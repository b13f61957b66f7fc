#!/usr/bin/env bash
# The layering the code promises (docs/architecture.md), checked on the source tree:
#  1. no Technique:: value (a branch on one, or one chosen by its enum) outside the technique
#     modules and their registry (src/plan/techniques/) and the settings and option definitions
#     (src/plan/settings.*, src/plan/option_table.cpp): the planner, the frame shapes, the tools
#     and the examples ask the module (plan/techniques/technique.h), and name a technique as the
#     options do (technique_named, {"technique", "planar"});
#  2. planning (src/plan: penumbra_plan; src/scene, src/scenes, src/shadow: penumbra_scene)
#     includes neither GL nor execution: no GLES, EGL, GLFW or Emscripten header, no gl/ header
#     but the plain values (gl/state.h, gl/caps.h, gl/uniforms.h), nothing of src/render or
#     src/platform;
#  3. no source file over 600 lines.
# Each check runs first on a small tree made to break it (its control: it must fail there), then
# on the repository.
# usage: tests/layering.sh REPO_ROOT
set -euo pipefail
root=${1:?usage: layering.sh REPO_ROOT}

branches() {  # prints each Technique:: value outside the allowed files
  (cd "$1" && grep -rnE '\bTechnique::[A-Za-z]' \
      src tools examples --include='*.cpp' --include='*.h' 2>/dev/null |
   grep -vE '^src/plan/techniques/|^src/plan/settings\.(h|cpp):|^src/plan/option_table\.cpp:' || true)
}
execution_in_planning() {  # prints each GL or execution include in the planning code
  (cd "$1" && grep -rnE '#include[[:space:]]+[<"](GLES2/|GLES3/|EGL/|GLFW/|emscripten|gl/(gl_headers|device|objects|timer|check|entry_points)\.h|render/|platform/)' \
      src/plan src/scene src/scenes src/shadow --include='*.cpp' --include='*.h' 2>/dev/null || true)
}
long_files() {  # prints each source file over 600 lines
  (cd "$1" && find src tools examples tests web shaders_gles2 -type f \
      \( -name '*.cpp' -o -name '*.h' -o -name '*.js' -o -name '*.mjs' -o -name '*.glsl' -o -name '*.vert' -o -name '*.frag' \) \
      -not -path '*/thirdparty/*' -not -path '*/node_modules/*' 2>/dev/null |
   while read -r f; do n=$(wc -l < "$f"); [ "$n" -le 600 ] || echo "$f: $n lines"; done)
}

# Controls: a tree with each kind of breach (and one allowed branch, in a module).
ctl=$(mktemp -d)
trap 'rm -rf "$ctl"' EXIT
mkdir -p "$ctl/src/plan/frames" "$ctl/src/plan/techniques" "$ctl/src/scenes" "$ctl/tools" "$ctl/examples" \
         "$ctl/tests" "$ctl/web" "$ctl/shaders_gles2"
echo 'if (s.technique == render::Technique::Volumes) return;' > "$ctl/tools/bench.cpp"
echo 'switch (t) { case Technique::Planar: break; }' > "$ctl/examples/app.cpp"
echo 's.technique = render::Technique::Gooch;' > "$ctl/tools/gallery.cpp"
echo 'if (s.technique == Technique::Volumes) {}' > "$ctl/src/plan/techniques/volumes.cpp"  # allowed
echo '#include "gl/device.h"' > "$ctl/src/plan/frames/forward.cpp"
echo '#include "render/renderer.h"' > "$ctl/src/scenes/room_scene.cpp"
echo '#include "gl/state.h"' > "$ctl/src/plan/plan.cpp"  # allowed: a plain value
seq 601 > "$ctl/src/plan/long.cpp"
[ "$(branches "$ctl" | wc -l)" -eq 3 ] || { echo "control: the branch check missed a branch or flagged a module:"; branches "$ctl"; exit 1; }
[ "$(execution_in_planning "$ctl" | wc -l)" -eq 2 ] || { echo "control: the include check missed one or flagged a plain value:"; execution_in_planning "$ctl"; exit 1; }
[ -n "$(long_files "$ctl")" ] || { echo "control: the 601-line file was not found"; exit 1; }

fail=0
out=$(branches "$root")
if [ -n "$out" ]; then echo "Technique:: outside its module and the settings (ask the module: plan/techniques/technique.h):"; echo "$out"; fail=1; fi
out=$(execution_in_planning "$root")
if [ -n "$out" ]; then echo "GL or execution in the planning code (plans are made without a context):"; echo "$out"; fail=1; fi
out=$(long_files "$root")
if [ -n "$out" ]; then echo "files over 600 lines:"; echo "$out"; fail=1; fi
[ "$fail" -eq 0 ] && echo "layering: no Technique:: outside the modules and settings, no GL or execution in planning, no file over 600 lines"
exit "$fail"
