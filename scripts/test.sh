#!/usr/bin/env bash
# The test command: builds with warnings as errors and runs every test ring (unit, GL on headless
# EGL, shader validation, command line, the desktop app under Xvfb, the web pages in headless
# Chromium), then the fuzz targets for 20 s each (clang, libFuzzer with ASan + UBSan: the glTF
# loader, the option parser, the pages' URL query; docs/reliability.md), then the unit and GL tests
# again under ASan + UBSan.
# Set PENUMBRA_SKIP_FUZZ=1 to skip the fuzz runs, PENUMBRA_SKIP_ASAN=1 to skip the sanitizer pass.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
cmake --preset ci >/dev/null
cmake --build --preset ci
# The npm packages first: the web build copies the shader lab's editor from node_modules/codemirror
# and minifies the pages' scripts with node_modules/google-closure-compiler.
{ [ -d node_modules/playwright-core ] && [ -d node_modules/three ] && [ -d node_modules/codemirror ] &&
  [ -d node_modules/google-closure-compiler ]; } ||
  npm ci --no-audit --no-fund --loglevel=error
# The web pages once (Emscripten; prints each page's payload); the web.* tests load build-web/site.
cmake --preset web >/dev/null
cmake --build --preset web
ctest --preset ci
if [ "${PENUMBRA_SKIP_FUZZ:-0}" != 1 ]; then
  echo "== the fuzz targets, 20 s each (build-fuzz; scripts/fuzz.sh for long runs) =="
  cmake --preset fuzz >/dev/null
  cmake --build --preset fuzz
  ctest --preset fuzz
fi
if [ "${PENUMBRA_SKIP_ASAN:-0}" != 1 ]; then
  echo "== again under AddressSanitizer + UndefinedBehaviorSanitizer (Debug, per-call GL checks) =="
  cmake --preset asan >/dev/null
  # Only what the pass runs (tests/CMakeLists.txt, penumbra_asan_tests): not the extremes ring or
  # the desktop app. The preset compiles with clang and precompiled headers, the quicker of what
  # was timed (docs/testing.md).
  cmake --build --preset asan --target penumbra_asan_tests
  # Mesa's own allocations outlive the process on purpose; leaks are checked in our code by
  # the RAII types, not by LeakSanitizer.
  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 ctest --preset asan
fi
echo "tests finished in $(( $(date +%s) - start )) s"
