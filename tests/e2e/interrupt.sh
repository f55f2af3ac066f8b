#!/usr/bin/env bash
# A long render stopped by a signal, as a user and a scheduler stop it: Ctrl-C in a real terminal (tmux),
# where the progress line shows, and SIGTERM from outside with stderr not a terminal, where it does not.
# Either way: exit 130, a line naming the frames done and the --frames that renders the rest, only
# complete files left (each equal to the same frame rendered alone), and the rest rendered by that
# --frames makes the whole sequence, byte for byte.
# Usage: interrupt.sh HLRSCRIPT SOURCE_DIR WORKDIR
set -euo pipefail
hlrscript=$(realpath "$1")
scene=$(realpath "$2")/bench/scenes/turntable-long.hls
work=$3
rm -rf "$work"
mkdir -p "$work"
command -v tmux >/dev/null || { echo "tmux is missing: run scripts/setup.sh"; exit 1; }
last=143  # frames 0-143 of the turntable, ≈ 20 ms each on one thread: long enough to stop on the way
render=("$hlrscript" "$scene" --frames "0-$last" --jobs 1)
mkdir -p "$work/whole"
"${render[@]}" -o "$work/whole/f-{frame:03}.png" -q >/dev/null 2>&1

wait_for_files() {  # wait_for_files DIR N: until N frames are written (staged as .f-NNN.png.tmp-PID until the end)
  for _ in $(seq 600); do
    [ "$(find "$1" -name '*.png*' 2>/dev/null | wc -l)" -ge "$2" ] && return 0
    sleep 0.1
  done
  echo "no $2 frames in $1 within 60 s"
  exit 1
}

check_stopped() {  # check_stopped DIR STATUS STDERR_FILE: what a stopped run must leave
  local dir=$1 status=$2 err=$3 kept first
  [ "$status" -eq 130 ] || { echo "exit status $status, expected 130"; cat "$err"; exit 1; }
  kept=$(find "$dir" -name 'f-*.png' | wc -l)
  grep -q "interrupted after $kept of $((last + 1)) frames" "$err" || { echo "no line naming the $kept frames done:"; cat "$err"; exit 1; }
  [ "$kept" -lt $((last + 1)) ] || { echo "the run finished before the signal: nothing was tested"; exit 1; }
  [ "$(find "$dir" ! -name 'f-*.png' ! -type d | wc -l)" -eq 0 ] || { echo "left over:"; ls -la "$dir"; exit 1; }
  for f in "$dir"/f-*.png; do
    cmp -s "$f" "$work/whole/$(basename "$f")" || { echo "$f is not the complete frame"; exit 1; }
  done
  first=$(grep -o -- '--frames [0-9]*-[0-9]*' "$err" | head -1) || { echo "no --frames hint:"; cat "$err"; exit 1; }
  # shellcheck disable=SC2086 # the hint is two words
  "$hlrscript" "$scene" $first --jobs 1 -o "$dir/f-{frame:03}.png" -q >/dev/null 2>&1
  diff -r "$work/whole" "$dir" >/dev/null || { echo "the kept frames and the hinted rest are not the sequence"; exit 1; }
}

# Ctrl-C in a terminal (stderr to a file, to read the closing line whole). Each part has a session of its
# own, all left open until the end: killing the server's last session makes it exit, and a new session
# asked for while it exits fails ("server exited unexpectedly").
mkdir -p "$work/tty"
session=interrupt-tty
socket=$work/tmux.socket  # a server of its own, so other tests' sessions are never touched
tm() { tmux -S "$socket" "$@"; }
tm new-session -d -s "$session" -x 160 -y 20 \
  "cd '$work/tty' && '${render[0]}' '$scene' --frames 0-$last --jobs 1 -o 'f-{frame:03}.png' 2>'$work/tty.err'; echo \$? > '$work/tty.status'; sleep 60"
trap 'tm kill-server 2>/dev/null || true' EXIT
wait_for_files "$work/tty" 3
tm send-keys -t "$session" C-c
for _ in $(seq 300); do [ -s "$work/tty.status" ] && break; sleep 0.1; done
[ -s "$work/tty.status" ] || { echo "Ctrl-C did not stop the render within 30 s"; exit 1; }
check_stopped "$work/tty" "$(cat "$work/tty.status")" "$work/tty.err"

# The progress line, on a terminal's stderr.
mkdir -p "$work/progress"
session=interrupt-progress
tm new-session -d -s "$session" -x 160 -y 20 \
  "cd '$work/progress' && '${render[0]}' '$scene' --frames 0-$last --jobs 1 -o 'f-{frame:03}.png'; echo status \$?; sleep 60"
progress="frame [0-9]+/$((last + 1)), [0-9.]+ frames/s, [0-9]+ s left"
for _ in $(seq 300); do tm capture-pane -p -t "$session" | grep -Eq "$progress" && break; sleep 0.1; done
tm capture-pane -p -t "$session" | grep -Eq "$progress" ||
  { echo "no progress line on the terminal:"; tm capture-pane -p -t "$session"; exit 1; }
tm send-keys -t "$session" C-c
for _ in $(seq 300); do tm capture-pane -p -t "$session" | grep -q '^status' && break; sleep 0.1; done
tm capture-pane -p -t "$session" | grep -q '^status 130' || { echo "Ctrl-C on the terminal: no exit 130"; tm capture-pane -p -t "$session"; exit 1; }

# SIGTERM, as Slurm and Kubernetes send it, with stderr a file: no progress line there.
mkdir -p "$work/term"
"${render[@]}" -o "$work/term/f-{frame:03}.png" 2>"$work/term.err" >/dev/null &
pid=$!
wait_for_files "$work/term" 3
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
check_stopped "$work/term" "$status" "$work/term.err"
if grep -q 'frames/s' "$work/term.err"; then echo "a progress line went to a file"; exit 1; fi
echo "Ctrl-C in a terminal and SIGTERM: exit 130, only complete frames kept, the hinted rest completes the sequence"
