#!/usr/bin/env bash
# The sanitizer pass of CI: one clang build with AddressSanitizer + UndefinedBehaviorSanitizer (and
# libFuzzer's coverage hooks) in build-asan/ serves both the libFuzzer targets and the test suite, so the
# libraries are compiled once. At -O1 with line tables only: the reports keep their file:line, and the
# build takes a fraction of a full debug build's time. Then every fuzz target runs SECONDS (default 25)
# and the suite runs under the sanitizers, less the documents' and tools' checks (CTEST_EXCLUDE), which
# run the same program paths and are checked in the Release pass.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-25}
bash scripts/setup.sh
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DHLR_FUZZ=ON -DHLR_SANITIZE=ON -DHLR_BUILD_TESTS=ON \
  -DHLR_BUILD_BENCH=OFF -DHLR_WERROR=OFF >/dev/null
echo "== fuzzing (libFuzzer, ASan + UBSan), ${seconds} s a target"
FUZZ_BUILD_DIR=build-asan bash scripts/fuzz.sh "$seconds"
echo "== tests (ASan + UBSan)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
ninja -C build-asan
ctest --test-dir build-asan --output-on-failure -j2 -E "${CTEST_EXCLUDE:-^(docs\.|editors\.|cli\.install$|cli\.completion$)}"
