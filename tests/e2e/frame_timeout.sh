#!/usr/bin/env bash
# --frame-timeout: a frame that runs out of time is an error at the script's line, in the evaluation and
# in the hidden lines alike, names the option, and writes nothing. (The column where a runaway loop is
# caught depends on when the clock runs out, so the message is checked, not the column.)
#   frame_timeout.sh HLRSCRIPT WORK
set -uo pipefail
hlrscript=$1
source "$(dirname "${BASH_SOURCE[0]}")/checks.sh" "$2"
check() {  # NAME MESSAGE LINE SCRIPT ARGS...
  local name=$1 message=$2 line=$3 text=$4
  shift 4
  printf '%s\n' "$text" >t.hls
  "$hlrscript" t.hls "$@" 2>err.txt >/dev/null
  local code=$?
  [ "$code" = 65 ] || fail "$name: exit $code, expected 65: $(cat err.txt)"
  grep -qF -- "$message" err.txt || fail "$name: stderr lacks '$message': $(cat err.txt)"
  grep -q "^t.hls:$line:[0-9]*: error: " err.txt || fail "$name: not located at line $line: $(cat err.txt)"
  [ ! -e t.svg ] || fail "$name: t.svg was written"
  rm -f err.txt t.svg
}
# The runaway line comes first: on a loaded machine even `camera c = orbit()` can take a millisecond.
check evaluation "the frame took longer than --frame-timeout 0.001 s while evaluating the script" 1 \
  'let xs = [sqrt(i) * 2 for i in 0..2000000]
camera c = orbit()
draw box(1, 1, 1)' --frame-timeout 0.001 -o t.svg
check hidden-lines "the frame took longer than --frame-timeout 0.001 s in the hidden lines" 1 \
  'camera c = orbit()
draw sphere(1, 400, 200)' --frame-timeout 0.001 -o t.svg
check in-a-frame "(in frame 2)" 3 \
  'animate frames 4
camera c = orbit()
let xs = [sqrt(i) * 2 for i in 0..(1 + 2000000 * max(0, 1 - abs(frame - 2)))]
draw box(1, 1, 1)' --frame-timeout 0.2 -o 'f-{frame}.svg' --jobs 1
[ -s f-0.svg ] && [ -s f-1.svg ] && [ ! -e f-2.svg ] && [ ! -e f-3.svg ] ||
  fail "in-a-frame: expected f-0.svg and f-1.svg only: $(ls)"
# Generous enough, the same scenes render.
printf 'camera c = orbit()\ndraw sphere(1, 40, 20)\n' >ok.hls
"$hlrscript" ok.hls -o ok.svg --frame-timeout 60 >/dev/null 2>&1 || fail "a 60 s budget stopped a small frame"
[ -s ok.svg ] || fail "ok.svg not written"
if [ "$failures" -gt 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "frame timeout: evaluation and hidden lines stop at the deadline with a located error"
