#!/usr/bin/env bash
# Scenes at scale through the language (issue 17): generated cities of BOXES boxes (bench/city_script.py,
# each box a `solid` block of literal coordinates), for each size the script's size, `check` (parse and
# evaluate) time and peak memory, and a whole HPGL render's hidden-line and plan times (--stats), time and
# peak memory, per input face; then the growth figures: hidden-line time per face and plan time per visible
# piece, each beside log2 of its count (the n log n test: the ratio column should stay flat).
#   bench/scale_bench.sh [BUILD_DIR] [BOXES ...]      (default sizes: 4000 16000 64000)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(4000 16000 64000)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
growth=$out/growth
printf '| %7s | %7s | %9s | %16s | %9s | %10s | %8s | %16s | %9s |\n' boxes faces "script MB" "check s (MB/s)" \
  "check MB" "hidden ms" "plan ms" "end to end s" "peak B/face"
printf '|%s:|%s:|%s:|%s:|%s:|%s:|%s:|%s:|%s:|\n' --------- --------- ----------- ------------------ ----------- ------------ ---------- ------------------ -----------
for boxes in "${sizes[@]}"; do
  script=$out/city-$boxes.hls
  python3 bench/city_script.py "$boxes" >"$script"
  faces=$((boxes * 6))
  bytes=$(stat -c %s "$script")
  read -r check_s check_kb < <({ /usr/bin/time -f '%e %M' "$build/runtime/hlrscript" check "$script" >/dev/null; } 2>&1 | tail -1)
  "$build/runtime/hlrscript" "$script" -o "$out/city.hpgl" --stats -q 2>"$out/stats" >/dev/null
  hidden=$(sed -n 's/.*hidden-line \([0-9.]*\) ms.*/\1/p' "$out/stats" | head -1)
  plan=$(sed -n 's/.*planned in \([0-9.]*\) ms.*/\1/p' "$out/stats" | head -1)
  pieces=$(sed -n 's/.* \([0-9]*\) visible pieces.*/\1/p' "$out/stats" | head -1)
  echo "$boxes $faces $hidden $pieces $plan" >>"$growth"
  read -r run_s run_kb < <({ /usr/bin/time -f '%e %M' "$build/runtime/hlrscript" "$script" -o "$out/city.hpgl" -q >/dev/null; } 2>&1 | tail -1)
  printf '| %7d | %7d | %9.1f | %8s (%5.1f) | %9.0f | %10s | %8s | %16s | %9.0f |\n' "$boxes" "$faces" \
    "$(echo "$bytes / 1000000" | bc -l)" "$check_s" "$(echo "$bytes / 1000000 / ($check_s + 0.001)" | bc -l)" \
    "$(echo "$check_kb / 1024" | bc -l)" "$hidden" "$plan" "$run_s" "$(echo "$run_kb * 1024 / $faces" | bc -l)"
done
echo
printf '| %7s | %14s | %19s | %14s | %15s | %20s |\n' boxes "hidden µs/face" "÷ log2 faces (ns)" \
  "visible pieces" "plan µs/piece" "÷ log2 pieces (ns)"
printf '|%s:|%s:|%s:|%s:|%s:|%s:|\n' --------- ---------------- --------------------- ---------------- \
  ----------------- ----------------------
while read -r boxes faces hidden pieces plan; do
  printf '| %7d | %14.3f | %19.1f | %14d | %15.3f | %20.1f |\n' "$boxes" \
    "$(echo "$hidden * 1000 / $faces" | bc -l)" "$(echo "$hidden * 1000000 / $faces / (l($faces) / l(2))" | bc -l)" \
    "$pieces" "$(echo "$plan * 1000 / $pieces" | bc -l)" "$(echo "$plan * 1000000 / $pieces / (l($pieces) / l(2))" | bc -l)"
done <"$growth"
