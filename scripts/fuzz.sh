#!/usr/bin/env bash
# Long fuzzing runs: scripts/fuzz.sh TARGET [SECONDS | -runs=N] [more libFuzzer flags]
#   TARGET  gltf (the glTF / GLB loader from memory), options (the option parser) or query (the
#           pages' URL query on a CourseApp); see docs/reliability.md.
#   SECONDS how long (default 600); -runs=N instead stops after N executions.
# Builds the preset "fuzz" (build-fuzz/, clang with libFuzzer, ASan + UBSan), then runs the target
# on its corpus (build-fuzz/fuzz/corpus/TARGET, kept between runs) and seeds with its dictionary,
# and prints executions, exec/s, coverage (cov: edges, ft: features), the corpus and where crashes
# went (build-fuzz/fuzz/crashes/TARGET/). Reproduce one: build-fuzz/tests/fuzz/fuzz_TARGET FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ]; then
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
target=$1
shift
limit=(-max_total_time=600)
if [ $# -gt 0 ]; then
  case "$1" in
    -runs=*) limit=("$1"); shift ;;
    *[!0-9]*) ;;
    *) limit=(-max_total_time="$1"); shift ;;
  esac
fi
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
start=$(date +%s)
set +e
bash tests/fuzz/run.sh build-fuzz "$target" "${limit[@]}" "$@"
rc=$?
set -e
secs=$(( $(date +%s) - start ))
execs=$(grep -E '^#[0-9]+' "$(ls -t build-fuzz/fuzz/logs/"$target"-*.log | head -n 1)" | tail -n 1 | sed -E 's/^#([0-9]+).*/\1/')
[ -n "$execs" ] && [ "$secs" -gt 0 ] && echo "fuzz_$target: $execs executions in $secs s: $(( execs / secs )) exec/s"
exit $rc
