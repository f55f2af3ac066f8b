#!/usr/bin/env bash
# Peak memory (VmHWM, GNU time's %M) of whole runs over 10, 100 and 1000 frames of a small turntable, to
# PDF (one file), JSON (one file) and PNG (a file per frame): the frame pipeline keeps a bounded window
# of frames in flight, so the peak should not grow with the sequence. Usage: bench/pipeline_memory.sh
# [BUILD_DIR] [JOBS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
jobs=${2:-2}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '%-6s %6s %12s %10s\n' device frames peak_kB seconds
for target in long.pdf long.json 'long-{frame:04}.png'; do
  for last in 9 99 999; do
    rm -rf "${out:?}"/*
    stats=$( { /usr/bin/time -f '%M %e' "$build/runtime/hlrscript" bench/scenes/turntable-long.hls \
                 -o "$out/$target" --frames "0-$last" --jobs "$jobs" >/dev/null; } 2>&1 | tail -1)
    printf '%-6s %6d %12s %10s\n' "${target##*.}" $((last + 1)) ${stats}
  done
done
