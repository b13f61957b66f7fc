#!/usr/bin/env bash
# GPU run (2026-11-28 afternoon): HEAD's figures for issue 37's GPU goals, then what a map pass's
# time is made of: 16-bit depth (PENUMBRA_X_DEPTH16), the clear alone (PENUMBRA_X_MAP=nodraw),
# the draws alone (PENUMBRA_X_MAP=noclear). Experimental knobs, not in main.
set -u
cd "$(dirname "$0")"
out=${OUT:-/tmp/out}
mkdir -p "$out"
t0=$(date +%s)
stamp() { echo "$1 at $(( $(date +%s) - t0 )) s" | tee -a "$out/progress.log"; }
tar -xJf penumbra-bundle.tar.xz -C /tmp && stamp unpacked
B=/tmp/penumbra-bundle/run.sh
nvidia-smi --query-gpu=name,driver_version,clocks.current.sm,clocks.max.sm --format=csv > "$out/smi.txt" 2>&1
$B caps > "$out/caps.txt" 2>&1
T="$out/timings.log"
run() { # name, args...; XENV names the experiment's environment
  local name=$1; shift
  echo "== $name: ${XENV:-} $*" >> "$T"
  timeout 40 env ${XENV:-} $B penumbra render --size 1920x1080 --time 0.6 --frames 200 -v --out none "$@" 2>&1 \
    | grep -v "^frame " | grep -v "^settings" | grep -v "^run.sh:" | awk '!seen[$0]++' >> "$T"
}
XENV= run warmup --map-size 4096 --frames 400
for round in 1 2; do
  XENV= run "r$round none" --technique none
  XENV= run "r$round rgba1024" --map-size 1024
  XENV= run "r$round depthtex1024" --map-size 1024 --encoding depthtex
  XENV= run "r$round rgba4096" --map-size 4096
  XENV= run "r$round depthtex4096" --map-size 4096 --encoding depthtex
  XENV=PENUMBRA_X_DEPTH16=1 run "r$round d16 rgba1024" --map-size 1024
  XENV=PENUMBRA_X_DEPTH16=1 run "r$round d16 depthtex1024" --map-size 1024 --encoding depthtex
  XENV=PENUMBRA_X_DEPTH16=1 run "r$round d16 rgba4096" --map-size 4096
  XENV=PENUMBRA_X_DEPTH16=1 run "r$round d16 depthtex4096" --map-size 4096 --encoding depthtex
  XENV=PENUMBRA_X_MAP=nodraw run "r$round clear-only rgba4096" --map-size 4096
  XENV=PENUMBRA_X_MAP=noclear run "r$round draw-only rgba4096" --map-size 4096
  XENV=PENUMBRA_X_MAP=nodraw run "r$round clear-only depthtex4096" --map-size 4096 --encoding depthtex
  XENV=PENUMBRA_X_MAP=noclear run "r$round draw-only depthtex4096" --map-size 4096 --encoding depthtex
  XENV="PENUMBRA_X_MAP=nodraw PENUMBRA_X_DEPTH16=1" run "r$round d16 clear-only depthtex4096" --map-size 4096 --encoding depthtex
  XENV= run "r$round volumes" --technique volumes
  XENV= run "r$round volumes-still" --technique volumes --still
  stamp "timings round $round"
done
XENV= run "rgba2048" --map-size 2048
XENV= run "depthtex2048" --map-size 2048 --encoding depthtex
XENV=PENUMBRA_X_DEPTH16=1 run "d16 depthtex2048" --map-size 2048 --encoding depthtex
XENV= run "volumes-zfail" --technique volumes --volume-method zfail
XENV= run "rgba1024-pcf" --map-size 1024 --filter pcf4x4
XENV= run "none-still" --technique none --still
stamp timings
( cd "$out" && PENUMBRA_OUT=/tmp/ptests timeout 150 $B gl --gtest_filter='-RendererGl.EveryShaderVariantCompilesOnTheContext' > "$out/gl.log" 2>&1; echo "gl rc $?" >> "$out/gl.log" )
stamp gl
( cd "$out" && PENUMBRA_OUT=/tmp/ptests timeout 90 $B extremes > "$out/extremes.log" 2>&1; echo "extremes rc $?" >> "$out/extremes.log" )
stamp extremes
nvidia-smi --query-gpu=clocks.current.sm --format=csv >> "$out/smi.txt" 2>&1
for v in 0 1; do
  if [ $v = 1 ]; then export PENUMBRA_X_DEPTH16=1; fi
  PENUMBRA_OUT=/tmp/pout$v timeout 80 $B bench --scenes teapot@0.6 --size 1920x1080 --maps 1024,2048,4096 --encodings rgba,depthtex --filters hard,pcf4x4 --frames 60 --rounds 1 > "$out/bench$v.log" 2>&1
  cp /tmp/pout$v/bench/results.csv "$out/bench$v-results.csv" 2>/dev/null
  stamp "bench d16=$v"
done
rm -rf "$out/test-output" 2>/dev/null
