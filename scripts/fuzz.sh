#!/usr/bin/env bash
# Coverage-guided fuzzing (libFuzzer, ASan + UBSan) of every target in tests/fuzz/: builds the fuzz_*
# executables with clang in build-fuzz/, then runs each for SECONDS (default 30) on a copy of its corpus
# (tests/fuzz/corpus/<target>/ is left as it is). FUZZ_JOBS targets run side by side (default 2);
# FUZZ_TARGETS="parser engine" picks some. Fails on any crash, leak, timeout or out-of-memory and prints
# the reproducer; replay one with build-fuzz/tests/fuzz/fuzz_<target> FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
jobs=${FUZZ_JOBS:-2}
read -r -a targets <<<"${FUZZ_TARGETS:-parser evaluator off obj stl_ascii stl_binary albers engine}"
# FUZZ_BUILD_DIR (default build-fuzz) may be a sanitizer build of the tests too (CI's: configured with
# -DHLR_FUZZ=ON -DHLR_SANITIZE=ON and tests on; scripts/sanitize.sh), whose libraries both then share.
build_dir=${FUZZ_BUILD_DIR:-build-fuzz}
work=$build_dir/fuzz-runs

# Inputs longer than the seeds are rarely useful; these leave room for a few mutations beyond them.
declare -A max_len=([parser]=8192 [evaluator]=8192 [off]=4096 [obj]=4096 [stl_ascii]=4096
                    [stl_binary]=4096 [albers]=2048 [engine]=512)
# Keywords spliced in whole by the mutations of the text formats.
declare -A dict=([parser]=hls.dict [evaluator]=hls.dict [off]=mesh.dict [obj]=mesh.dict [stl_ascii]=mesh.dict
                 [albers]=mesh.dict)

bash scripts/setup.sh  # clang and libclang-rt-14-dev among the rest
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build_dir" -G Ninja -DHLR_FUZZ=ON -DHLR_BUILD_TESTS=OFF \
    -DHLR_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
fi
ninja -C "$build_dir" -j "${FUZZ_BUILD_JOBS:-2}" fuzz_all

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0}

# One target: its corpus copied into $work/<target>/corpus, findings into $work/<target>/artifacts/, the
# log in $work/<target>/log, libFuzzer's exit status (0 when nothing was found) in $work/<target>/status.
run_target() {
  local target=$1 dir=$work/$1 status=0 flags=()
  [ -n "${dict[$target]:-}" ] && flags+=(-dict="tests/fuzz/${dict[$target]}")
  "$build_dir/tests/fuzz/fuzz_$target" "${flags[@]}" -max_total_time="$seconds" -max_len="${max_len[$target]}" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$dir/artifacts/" "$dir/corpus" >"$dir/log" 2>&1 ||
    status=$?
  echo "$status" >"$dir/status"
}

echo "fuzzing ${targets[*]} for ${seconds} s each, $jobs at a time"
for target in "${targets[@]}"; do
  [ -x "$build_dir/tests/fuzz/fuzz_$target" ] || { echo "fuzz: no target '$target'" >&2; exit 2; }
  rm -rf "${work:?}/$target"
  mkdir -p "$work/$target/corpus" "$work/$target/artifacts"
  cp -r "tests/fuzz/corpus/$target/." "$work/$target/corpus/"
done
for target in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  run_target "$target" &
done
wait

failed=0
for target in "${targets[@]}"; do
  log=$work/$target/log
  status=$(cat "$work/$target/status" 2>/dev/null || echo "?")
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if [ "$status" = 0 ]; then
    printf '%-11s ok      %10s executions\n' "$target" "${runs:-?}"
    continue
  fi
  failed=1
  printf '%-11s FAILED  (exit %s) log: %s\n' "$target" "$status" "$log"
  grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error:)' "$log" | head -5 | sed 's/^/    /' || true
  for artifact in "$work/$target"/artifacts/*; do
    [ -e "$artifact" ] && echo "    reproducer: $artifact (run: $build_dir/tests/fuzz/fuzz_$target $artifact)"
  done
done
exit "$failed"
