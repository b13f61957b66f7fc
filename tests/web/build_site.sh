#!/usr/bin/env bash
# web.build (the fixture of every web.* test): configures the "web" preset if needed and builds
# build-web/site (nothing to do when it is up to date; scripts/test.sh builds it first anyway).
set -euo pipefail
cd "$(dirname "$0")/../.."
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
[ -f build-web/build.ninja ] || cmake --preset web >/dev/null
cmake --build --preset web
