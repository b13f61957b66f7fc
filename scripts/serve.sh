#!/usr/bin/env bash
# Serves the exercise pages (build-web/site: the pages, each with its module NAME.js, NAME.wasm) on 127.0.0.1
# and prints the index page's URL; Ctrl+C stops it. Builds the site first when it is missing.
# usage: scripts/serve.sh [PORT]   (default 8000)
set -euo pipefail
cd "$(dirname "$0")/.."
port=${1:-8000}
site=build-web/site
if [ ! -f "$site/w09p1.wasm" ]; then
  echo "serve: building $site first (cmake --preset web && cmake --build --preset web)"
  cmake --preset web >/dev/null
  cmake --build --preset web
fi
echo "serve: http://127.0.0.1:$port/index.html  (serving $site; Ctrl+C stops)"
exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site"
