#!/usr/bin/env bash
# What each output device costs a frame (issue 16): every device renders the same turntable on one
# thread with --stats, and the table gives, per device, the mean encode time and bytes a frame (what the
# device does after the hidden lines and the pen plan), the whole run's time and peak memory (GNU time),
# and for reference the mean hidden-line and pen-plan times of the same frames.
#   bench/device_bench.sh [BUILD_DIR] [SCENE.hls ...]
# Default scenes: the fandisk turntable (bench/cgal_meshes.sh fetches the mesh into bench/data) and the
# 100k-face torus turntable.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
  [ -f bench/data/fandisk_large.off ] || bash bench/cgal_meshes.sh >/dev/null
  scenes=(bench/scenes/turntable-fandisk.hls bench/scenes/turntable-100k.hls)
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mean() { awk -v key="$1" '{ for (i = 1; i <= NF; ++i) if ($i == key) { s += $(i + 2); n++ } } END { printf "%.1f", n ? s / n : 0 }'; }
mean_bytes() { awk '{ for (i = 1; i <= NF; ++i) if ($i == "encoded") { gsub(/[(]/, "", $(i + 4)); s += $(i + 4); n++ } } END { printf "%.0f", n ? s / n / 1024 : 0 }'; }
for scene in "${scenes[@]}"; do
  echo "$scene, one thread:"
  printf '| %-17s | %13s | %14s | %9s | %9s | %11s | %7s |\n' device "encode ms/frame" "KB/frame" "run s" "peak MB" "hidden ms" "plan ms"
  printf '|%s|%s:|%s:|%s:|%s:|%s:|%s:|\n' ------------------- --------------- ---------------- ----------- ----------- ------------- ---------
  for target in 'f-{frame:02}.hpgl' 'f-{frame:02}.gcode' 'all.pdf' 'f-{frame:02}.svg' 'p-{frame:02}.svg --svg plotter' \
                'f-{frame:02}.png' 'all.json' 'all.jsonl' 'some.json --json strokes,stats'; do
    rm -rf "${out:?}"/*
    read -r name extra <<<"$target"
    # shellcheck disable=SC2086 # extra options are words
    "$build/runtime/hlrscript" "$scene" --allow-path bench/data -o "$out/$name" $extra --jobs 1 --stats -q \
      2>"$out/stats" >/dev/null
    # shellcheck disable=SC2086
    time_line=$( { /usr/bin/time -f '%e %M' "$build/runtime/hlrscript" "$scene" --allow-path bench/data \
                     -o "$out/$name" $extra --jobs 1 -q >/dev/null; } 2>&1 | tail -1)
    read -r seconds peak_kb <<<"$time_line"
    label=${name##*.}${extra:+ ${extra}}
    printf '| %-17s | %14s | %14s | %9s | %9.0f | %11s | %7s |\n' "$label" \
      "$(grep -- '->' "$out/stats" | mean encoded)" "$(grep -- '->' "$out/stats" | mean_bytes)" "$seconds" \
      "$(echo "$peak_kb / 1024" | bc -l)" "$(grep 'hidden-line' "$out/stats" | awk '{for(i=1;i<=NF;i++) if($i=="hidden-line"){s+=$(i+1);n++}} END{printf "%.1f", s/n}')" \
      "$(grep -- '->' "$out/stats" | mean planned)"
  done
  echo
done
