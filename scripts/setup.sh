#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine for penumbra and builds it: installs the Debian packages the
# build, the headless GL context and the tests need (only what is missing), then configures and
# builds the native tree in build/. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake g++ ninja-build pkg-config python3       # build
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri  # headless GLES2 on Mesa llvmpipe
  libglm-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libcli11-dev  # maths, scenes, PNG, CLI
  libgtest-dev libbenchmark-dev glslang-tools    # tests and shader validation
  libembree-dev                                  # the ray-traced ground truth (penumbra bench / truth)
  librsvg2-dev fonts-dejavu-core                 # the bench plots' PNGs: the SVG rendered by librsvg, in DejaVu Sans
  libglfw3-dev xvfb xauth x11-utils              # the desktop app, and its tests on a virtual X server (xwininfo reads the title)
  emscripten chromium nodejs                     # the web pages, and their tests in headless Chromium
  clang libclang-rt-14-dev                       # the libFuzzer targets (preset fuzz, tests/fuzz) with ASan + UBSan
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Debian packages npm apart from nodejs; other nodejs builds bring their own.
command -v npm >/dev/null 2>&1 || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
else
  echo "setup: all Debian packages present"
fi

# playwright-core (drives /usr/bin/chromium; no browser download), pngjs and three (the three.js
# side by side, tools/threejs_compare.mjs) for the browser tests, codemirror (the shader lab's
# editor, which the web build copies into the site) and google-closure-compiler (the web build
# minifies the pages' scripts with it), as package-lock.json pins them.
if [ ! -d node_modules/playwright-core ] || [ ! -d node_modules/three ] || [ ! -d node_modules/codemirror ] ||
   [ ! -d node_modules/google-closure-compiler ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "setup: npm ci (playwright-core, pngjs, three, codemirror, google-closure-compiler)"
  npm ci --no-audit --no-fund --loglevel=error
fi

cmake --preset ci >/dev/null
cmake --build --preset ci
echo "setup: built build/penumbra and build/penumbra-desktop"
# The exercise pages (Emscripten, WebGL 1): build-web/site, served by scripts/serve.sh.
cmake --preset web >/dev/null
cmake --build --preset web
echo "setup: built build-web/site"
