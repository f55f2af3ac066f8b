#!/usr/bin/env bash
# The REPL in a real terminal (tmux): Tab completion (names, a call's parameters), a continuation line,
# Ctrl-C cancelling it, :show, an error followed by a correct line, history kept across sessions, :help,
# Ctrl-C stopping a long render. Usage: repl_tmux.sh HLRSCRIPT WORKDIR
set -euo pipefail
hlrscript=$(realpath "$1")
work=$2
rm -rf "$work"
mkdir -p "$work"
export XDG_STATE_HOME=$work/state
socket=$work/tmux.sock
session=repl
cleanup() { tmux -S "$socket" kill-server 2>/dev/null || true; }
trap cleanup EXIT

screen() { tmux -S "$socket" capture-pane -t "$session" -p; }
# Waits (up to 20 s) until the pane shows `text`; prints the pane and fails otherwise.
expect() {
  for _ in $(seq 200); do
    if screen | grep -qF -- "$1"; then return 0; fi
    sleep 0.1
  done
  echo "expected to see: $1"
  screen
  exit 1
}
keys() { tmux -S "$socket" send-keys -t "$session" "$@"; }

# A session that outlives the REPL's: a server whose last session ends exits, and a new session asked for
# while it exits fails ("server exited unexpectedly").
tmux -S "$socket" new-session -d -s keep "sleep 600"
tmux -S "$socket" new-session -d -s "$session" -x 100 -y 40 -c "$work" "$hlrscript"
expect "hls>"
keys 'draw cub' Tab
expect "draw cube"
keys '(2)' Enter
expect "scene: 1 objects, 6 faces"
keys 'camera c = lookat(eye: (5, -7, 4), target: (0, 0, 0))' Enter
expect "camera c"
keys 'let q = (1,' Enter
expect "...>"
keys C-c
keys 'q' Enter
expect "unknown name 'q'"
keys 'let q = 1 +* 2' Enter
expect "expected an operand after the operator"
keys 'let q = 40 + 2' Enter
expect "q = 42"
keys ':sh' Tab Enter
expect "camera c, frame 0: 9 visible pieces"
# The picture has the cube's outline: vertical edges drawn in braille (a full left or right dot column).
screen | grep -qF -e '⡇' -e '⢸' || { echo "no braille picture"; screen; exit 1; }
keys ':orbit 30 10' Enter
expect "camera adjusted_c, frame 0"
# :undo takes back the orbit (and only the orbit); a second orbit is saved as the camera drawn.
keys ':undo' Enter
expect "undone: :orbit 30 10"
keys ':orbit 30 10' Enter
expect "camera adjusted_c, frame 0"
keys ':hidden on' Enter
expect "hidden lines dashed"
keys ':save saved.hls' Enter
expect "saved the session to saved.hls (3 inputs)"
grep -q '^camera adjusted_c = adjust(lookat(eye: (5, -7, 4), target: (0, 0, 0)), theta: 30, phi: 10' "$work/saved.hls" ||
  { echo "the orbit is not saved"; cat "$work/saved.hls"; exit 1; }
grep -q '^style hidden dashed$' "$work/saved.hls" || { echo ":hidden on is not saved"; cat "$work/saved.hls"; exit 1; }
"$hlrscript" check "$work/saved.hls" >/dev/null || { echo "the saved script does not run"; exit 1; }
keys C-d
for _ in $(seq 100); do tmux -S "$socket" has-session -t "$session" 2>/dev/null || break; sleep 0.1; done
grep -q 'q\\040=\\04040\\040+\\0402' "$XDG_STATE_HOME/hlrscript/history" || { echo "history not kept"; cat "$XDG_STATE_HOME/hlrscript/history"; exit 1; }

# A second session finds the first one's history: Up brings back its last entry.
tmux -S "$socket" new-session -d -s "$session" -x 100 -y 40 -c "$work" "$hlrscript"
expect "hls>"
keys Up
expect ":save saved.hls"
# Tab inside a call completes the built-in's parameter names; :help shows a built-in's forms.
keys C-u 'let cam = lookat(ey' Tab
expect "lookat(eye:"
keys C-u ':help box' Enter
expect "box(sx, sy, sz) | box(min: p, max: q)"
# Ctrl-C stops a long render; the session stays and keeps what it had.
keys 'for i in 0..6 { for j in 0..6 { draw sphere(1, slices: 300, stacks: 150) at translate(1.2 * i, 1.2 * j, 0.3 * ((i + j) % 3)) } }' Enter
expect "scene: 36 objects"
keys 'camera c = lookat(eye: (3, -14, 8), target: (3, 3, 0))' Enter
expect "camera c"
keys ':show' Enter
sleep 0.5
keys C-c
expect "stopped (Ctrl-C); the session is as it was"
keys ':scene' Enter
expect "cameras: c; frame 0"
keys ':quit' Enter
# The saved script renders.
"$hlrscript" "$work/saved.hls" -o "$work/saved.pdf" >/dev/null
test -s "$work/saved.pdf"
echo "repl session ok"
