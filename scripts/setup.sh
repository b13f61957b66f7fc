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
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: all Debian packages present"
fi

cmake --preset ci >/dev/null
cmake --build --preset ci
echo "setup: built build/penumbra"
