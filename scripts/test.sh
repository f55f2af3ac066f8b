#!/usr/bin/env bash
# Builds (warnings as errors) and runs the whole test suite. BUILD_DIR and extra cmake arguments may be
# given, e.g. BUILD_DIR=build-asan scripts/test.sh -DHLR_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo;
# CTEST_EXCLUDE, a ctest -E pattern, leaves tests out (CI's sanitizer pass skips the documents' checks).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
bash scripts/setup.sh
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHLR_WERROR=ON "$@" >/dev/null
ninja -C "$build_dir"
exclude=()
[ -n "${CTEST_EXCLUDE:-}" ] && exclude=(-E "$CTEST_EXCLUDE")
ctest --test-dir "$build_dir" --output-on-failure -j2 "${exclude[@]}"
