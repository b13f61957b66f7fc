#!/usr/bin/env bash
# One relocatable tarball of the built `penumbra` and the GL and extremes test binaries, with their
# non-system shared libraries, the test data and goldens, and a run.sh that runs them from wherever
# the tarball is unpacked (docs/gpu.md: on the GPU machine). Nothing is built here: run it after
# `cmake --build build --target penumbra_cli penumbra_gl_tests penumbra_extremes_tests`.
# usage: scripts/bundle.sh [BUILD_DIR] [OUT.tar.xz]   (default build, BUILD_DIR/penumbra-bundle.tar.xz)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-$build/penumbra-bundle.tar.xz}
bins=("$build/penumbra" "$build/tests/penumbra_gl_tests" "$build/tests/penumbra_extremes_tests")
for b in "${bins[@]}"; do
  [ -x "$b" ] || { echo "bundle: $b is missing: build penumbra_cli, penumbra_gl_tests and penumbra_extremes_tests first" >&2; exit 2; }
done

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
root=$stage/penumbra-bundle
mkdir -p "$root/bin" "$root/lib/glvnd" "$root/tests"
# Without their debug information (-g: 200 MB of the 230), as the release binaries were carried.
for b in "${bins[@]}"; do strip --strip-debug -o "$root/bin/$(basename "$b")" "$b"; done

# Every ldd dependency but the C and C++ runtimes and the loader (the GPU machine has its own,
# as every Linux does). glvnd's dispatchers (libEGL.so.1, libGLESv2.so.2, libGLdispatch.so.0) go
# to lib/glvnd: vendor-neutral, they load the vendor's EGL named by the glvnd JSON files
# (__EGL_VENDOR_LIBRARY_FILENAMES); run.sh uses them only where the system has none. No vendor
# library (Mesa's libEGL_mesa, NVIDIA's libEGL_nvidia) is shipped: the machine's own is used.
system='^(linux-vdso|ld-linux|libc|libm|libgcc_s|libstdc\+\+|libdl|libpthread|librt)\.so'
glvnd='^(libEGL|libGLESv2|libGLdispatch)\.so'
ldd "${bins[@]}" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' | sort -u | while read -r name path; do
  if [[ $name =~ $system ]]; then continue; fi
  if [[ $name =~ $glvnd ]]; then cp -L "$path" "$root/lib/glvnd/$name"; else cp -L "$path" "$root/lib/$name"; fi
done
# A library the binaries need that ldd could not find would fail there too: stop here instead.
if ldd "${bins[@]}" | grep -q "not found"; then
  echo "bundle: unresolved libraries:" >&2; ldd "${bins[@]}" | grep "not found" >&2; exit 1
fi

cp -r tests/data tests/golden "$root/tests/"
git rev-parse --short HEAD > "$root/COMMIT" 2>/dev/null || echo unknown > "$root/COMMIT"
git diff --quiet HEAD -- 2>/dev/null || echo "(built from a working tree with uncommitted changes)" >> "$root/COMMIT"

cat > "$root/run.sh" <<'RUN'
#!/usr/bin/env bash
# Runs the bundle's binaries from wherever it was unpacked (docs/gpu.md).
# usage: run.sh caps [ARGS]          penumbra caps (the GPU, EGL and its devices)
#        run.sh gl [GTEST ARGS]      the GL ring (penumbra_gl_tests), e.g. --gtest_filter='Course/*'
#        run.sh extremes [GTEST ARGS] the extremes ring (penumbra_extremes_tests)
#        run.sh bench [ARGS]         penumbra bench (default: the course at t = 0.6, 1280x720, maps 512-4096)
#        run.sh penumbra ARGS        any penumbra command
# Environment: PENUMBRA_OUT (default ./penumbra-out: test outputs, bench results; the tests run in
# it), PENUMBRA_EGL_DEVICE=N (an EGL device of `run.sh caps`' list), PENUMBRA_GLVND=bundle|system
# (whose libEGL.so.1/libGLESv2.so.2 dispatchers; default: the system's where it has them).
# Where /usr/local/nvidia holds NVIDIA's driver (as on the GPU machine) and
# __EGL_VENDOR_LIBRARY_FILENAMES is not set, it is set to NVIDIA's glvnd JSON there.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
nvidia=/usr/local/nvidia
libs=$here/lib
if [ -d "$nvidia/lib64" ]; then libs=$libs:$nvidia/lib64; fi
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -f "$nvidia/share/glvnd/egl_vendor.d/10_nvidia.json" ]; then
  export __EGL_VENDOR_LIBRARY_FILENAMES=$nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
fi
has_system_glvnd() {
  local l
  for l in libEGL.so.1 libGLESv2.so.2 libGLdispatch.so.0; do
    /sbin/ldconfig -p 2>/dev/null | grep -qE "^[[:space:]]*$l " && continue
    [ -e "$nvidia/lib64/$l" ] && continue
    return 1
  done
}
case ${PENUMBRA_GLVND:-auto} in
  bundle) libs=$libs:$here/lib/glvnd ;;
  system) ;;
  *) has_system_glvnd || libs=$libs:$here/lib/glvnd ;;
esac
export LD_LIBRARY_PATH=$libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export PENUMBRA_TEST_DATA=${PENUMBRA_TEST_DATA:-$here/tests/data}
export PENUMBRA_GOLDEN_DIR=${PENUMBRA_GOLDEN_DIR:-$here/tests/golden}
out=${PENUMBRA_OUT:-$PWD/penumbra-out}
mkdir -p "$out"
out=$(cd "$out" && pwd)
export PENUMBRA_TEST_OUT=${PENUMBRA_TEST_OUT:-$out/test-output}
echo "run.sh: bundle of $(head -1 "$here/COMMIT"); LD_LIBRARY_PATH=$LD_LIBRARY_PATH;" \
     "__EGL_VENDOR_LIBRARY_FILENAMES=${__EGL_VENDOR_LIBRARY_FILENAMES:-(unset)}; output in $out" >&2
what=${1:-}
[ $# -gt 0 ] && shift
case $what in
  caps) exec "$here/bin/penumbra" caps "$@" ;;
  gl) cd "$out" && exec "$here/bin/penumbra_gl_tests" "$@" ;;
  extremes) cd "$out" && exec "$here/bin/penumbra_extremes_tests" "$@" ;;
  bench)
    [ $# -gt 0 ] || set -- --scenes teapot@0.6 --size 1280x720 --maps 512,1024,2048,4096
    exec "$here/bin/penumbra" bench --out-dir "$out/bench" "$@" ;;
  penumbra) exec "$here/bin/penumbra" "$@" ;;
  *) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
esac
RUN
chmod +x "$root/run.sh"

mkdir -p "$(dirname "$out")"
XZ_OPT=${XZ_OPT:--6 -T2} tar -C "$stage" -cJf "$out.tmp" penumbra-bundle
mv "$out.tmp" "$out"
echo "bundle: $out ($(du -h "$out" | cut -f1); $(ls "$root/lib" "$root/lib/glvnd" | grep -c '\.so') libraries; unpack it, then penumbra-bundle/run.sh caps)"
