#!/usr/bin/env bash
# GNU parallel runs the landing as three jobs, each taking its share with --shard auto/3 (K from
# PARALLEL_SEQ); together they write byte for byte the files one unsharded run writes.
# Usage: shards_parallel.sh HLRSCRIPT EXAMPLES_DIR WORKDIR
set -euo pipefail
hlrscript=$(realpath "$1")
landing=$(realpath "$2")/desens/landing.hls
work=$3
rm -rf "$work"
mkdir -p "$work/one" "$work/shards/1" "$work/shards/2" "$work/shards/3" "$work/merged"
command -v parallel >/dev/null || { echo "GNU parallel is missing: run scripts/setup.sh"; exit 1; }

"$hlrscript" "$landing" -o "$work/one/f-{frame:03}.svg" -q >/dev/null 2>&1
# -N0: each job gets no argument, only its sequence number (PARALLEL_SEQ, and {#} in the command: 1, 2, 3);
# each writes into its own directory, so the test sees what each one did.
parallel --will-cite -N0 -j 3 "$hlrscript" "$landing" -o "'$work/shards/{#}/f-{frame:03}.svg'" -q --shard auto/3 \
  ::: 1 2 3 2>/dev/null
count=$(find "$work/one" -name '*.svg' | wc -l)
[ "$count" -eq 48 ] || { echo "the unsharded run wrote $count files, expected 48"; exit 1; }
for k in 1 2 3; do
  n=$(find "$work/shards/$k" -name '*.svg' | wc -l)
  [ "$n" -eq 16 ] || { echo "job $k wrote $n files, expected its 16"; exit 1; }
  cp "$work/shards/$k"/*.svg "$work/merged/"
done
# Job 2 of 3 has frames 1, 4, 7, ...
[ -f "$work/shards/2/f-001.svg" ] && [ -f "$work/shards/2/f-046.svg" ] || { echo "job 2 lacks its frames"; exit 1; }
diff -r "$work/one" "$work/merged" || { echo "the shards differ from the unsharded run"; exit 1; }
echo "3 GNU parallel shards = the unsharded run: $count files"
