#!/usr/bin/env bash
# hlrscript watch: renders, renders again when the script or an included file changes, reports a broken
# script without stopping or touching the output, and recovers. Usage: watch.sh HLRSCRIPT WORKDIR
set -euo pipefail
hlrscript=$(realpath "$1")
work=$2
rm -rf "$work"
mkdir -p "$work"
cd "$work"
printf 'let s = 2\n' > sizes.hls
printf 'include "sizes.hls"\ndraw cube(s)\ncamera c = lookat(eye: (6, -8, 5), target: (0, 0, 0))\n' > scene.hls
"$hlrscript" watch scene.hls -o out.json > log.txt 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
# Waits (up to 20 s) until `test` holds.
wait_for() {
  for _ in $(seq 200); do
    if eval "$1"; then return 0; fi
    sleep 0.1
  done
  echo "timed out waiting for: $1"
  cat log.txt
  exit 1
}
wait_for 'grep -q "watching 2 files" log.txt'
first=$(md5sum < out.json)
sleep 1.1  # a new modification time, on file systems that keep whole seconds
printf 'let s = 3\n' > sizes.hls  # the included file
wait_for 'test "$(md5sum < out.json)" != "$first"'
second=$(md5sum < out.json)
printf 'include "sizes.hls"\ndraw cube(s\n' > scene.hls  # broken: reported, the output kept
wait_for 'grep -q "error" log.txt'
test "$(md5sum < out.json)" = "$second"
kill -0 $pid  # still watching
printf 'include "sizes.hls"\ndraw cube(s + 1)\ncamera c = lookat(eye: (6, -8, 5), target: (0, 0, 0))\n' > scene.hls
wait_for 'test "$(md5sum < out.json)" != "$second"'
grep -c "changed: rendering again" log.txt | grep -qx 3
echo "watch ok"
