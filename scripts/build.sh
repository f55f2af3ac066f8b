#!/usr/bin/env bash
# Configures and builds into build/ (Release) what README's first command runs: the program (its library
# modules are read from stdlib/modules/) and its manual page. scripts/test.sh builds everything else
# (tests, benchmarks, fuzz replays). Extra arguments go to cmake, e.g. -DHLR_WERROR=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
targets=(hlrscript)
ninja -C build -t targets all | grep -q '^hlrscript_man:' && targets+=(hlrscript_man)
ninja -C build "${targets[@]}"
