#!/usr/bin/env bash
# Runs one libFuzzer target of a built fuzz tree: run.sh BUILD_DIR TARGET [libFuzzer flags...]
# (ctest's fuzz.* pass -max_total_time=30; scripts/fuzz.sh builds first and passes its own).
# TARGET: gltf, options, query or snippets. The corpus grows in BUILD_DIR/fuzz/corpus/TARGET (seeds in
# BUILD_DIR/fuzz/seeds/TARGET are read, never written); a crash, leak or timeout is written to
# BUILD_DIR/fuzz/crashes/TARGET/ and fails the run; the log is BUILD_DIR/fuzz/logs/TARGET-*.log.
set -euo pipefail
build=$(cd "$1" && pwd)
target=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
case "$target" in
  gltf) dict=$here/gltf.dict; max_len=8192 ;;
  options) dict=$here/options.dict; max_len=1024 ;;
  query) dict=$here/options.dict; max_len=9000 ;;  # past examples/query.h's kMaxQueryBytes
  snippets) dict=$here/snippets.dict; max_len=4096 ;;
  *) echo "run.sh: unknown target '$target' (gltf, options, query, snippets)" >&2; exit 2 ;;
esac
bin=$build/tests/fuzz/fuzz_$target
[ -x "$bin" ] || { echo "run.sh: $bin not built (cmake --build --preset fuzz)" >&2; exit 2; }
fuzz=$build/fuzz
mkdir -p "$fuzz/corpus/$target" "$fuzz/crashes/$target" "$fuzz/logs" "$fuzz/seeds/$target"
log=$fuzz/logs/$target-$(date -u +%Y%m%dT%H%M%SZ).log
# The scene's folder is empty (fuzz_gltf passes no base folder); the run's own folder is the
# crashes' folder, so a stray relative path would land there, not in the source tree.
cd "$fuzz/crashes/$target"
set +e
ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1} \
UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
"$bin" -dict="$dict" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
  -artifact_prefix="$fuzz/crashes/$target/" -print_final_stats=1 "$@" \
  "$fuzz/corpus/$target" "$fuzz/seeds/$target" >"$log" 2>&1
rc=$?
set -e
# The summary: libFuzzer's last status line (execs, cov: edges, ft: features, corp: units/bytes),
# its final stats, and what went to the crashes' folder.
grep -E '^#[0-9]+' "$log" | tail -n 1 || true
grep -E '^stat::' "$log" || true
echo "corpus: $(find "$fuzz/corpus/$target" -type f | wc -l) files in $fuzz/corpus/$target"
crashes=$(find "$fuzz/crashes/$target" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'slow-unit-*' \) | wc -l)
echo "crashes: $crashes files in $fuzz/crashes/$target/; log: $log"
if [ $rc -ne 0 ]; then
  echo "fuzz_$target failed (exit $rc); the end of its log:" >&2
  tail -n 60 "$log" >&2
fi
exit $rc
