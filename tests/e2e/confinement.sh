#!/usr/bin/env bash
# What a script can touch (README, "What a script can touch"): every escape route a downloaded script
# could take is refused with exit 77 before the file is read or written, and never quotes the file;
# --allow-path and --out-dir open exactly what they name; -o, typed by the user, writes anywhere.
#   confinement.sh HLRSCRIPT WORK
set -uo pipefail
hlrscript=$1
work=$2
rm -rf "$work" "$work.log"
mkdir -p "$work/project/sub" "$work/elsewhere" "$work.log"
out=$work.log/out.txt err=$work.log/err.txt
cd "$work/project" || exit 1

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

secret='the-secret-line-of-elsewhere'
printf '%s\n' "$secret" >../elsewhere/secret.hls
printf 'let shared = box(1, 1, 1)\n' >../elsewhere/shared.hls
printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' >../elsewhere/tet.off
printf 'OFF\n%s\n' "$secret" >../elsewhere/secret.off
ln -s ../elsewhere link               # a folder link out of the project
ln -s ../elsewhere/secret.hls alias.hls  # a file link out of the project
printf '%s\n' "$secret" >notes.txt
camera='camera c = lookat(eye: (3, -4, 2), target: (0, 0, 0), fov: 30)'

# expect NAME EXIT MESSAGE SCRIPT [ARGS...]: runs SCRIPT (its text) as t.hls; checks the exit status, that
# its output holds MESSAGE (and a caret under the script's line for a refusal), never the secret, and that
# a failed run changed no file anywhere.
expect() {
  local name=$1 status=$2 message=$3 text=$4
  shift 4
  printf '%s\n%s\n' "$text" "$camera" >t.hls
  local before after code
  before=$(find "$work" | sort)
  "$hlrscript" t.hls "$@" >"$out" 2>"$err"
  code=$?
  after=$(find "$work" | sort)
  [ "$code" = "$status" ] || fail "$name: exit $code, expected $status ($(cat "$err"))"
  grep -qF -- "$message" "$out" "$err" || fail "$name: the output lacks '$message': $(cat "$out" "$err")"
  if [ "$status" = 77 ] || [ "$status" = 65 ]; then
    grep -q '\^' "$err" || fail "$name: no caret under the script's line: $(cat "$err")"
  fi
  if [ "$status" != 0 ]; then
    [ "$before" = "$after" ] || fail "$name: files changed: $(diff <(echo "$before") <(echo "$after"))"
  fi
  if grep -qF "$secret" "$out" "$err"; then fail "$name: the refused file was quoted"; fi
}

# ---- reading: include ----
expect include-parent 77 "cannot include '../elsewhere/secret.hls': it is outside the folders" \
  'include "../elsewhere/secret.hls"'
expect include-parent-hint 77 "run it with --allow-path $work/elsewhere" 'include "../elsewhere/secret.hls"'
expect include-absolute 77 "cannot include '$work/elsewhere/secret.hls'" "include \"$work/elsewhere/secret.hls\""
expect include-folder-link 77 "cannot include 'link/secret.hls': it is outside" 'include "link/secret.hls"'
expect include-file-link 77 "cannot include 'alias.hls': it is outside" 'include "alias.hls"'
expect include-library-escape 77 "it is outside the folders" \
  "include \"std/../../../../../../../../../..$work/elsewhere/secret.hls\""
expect include-non-script 65 "include reads hlrscript scripts (.hls) only" 'include "notes.txt"'
expect include-missing-outside 77 "it is outside the folders" 'include "../elsewhere/no-such.hls"'

# ---- reading: import ----
expect import-parent 77 "cannot import '../elsewhere/tet.off': it is outside" 'draw import("../elsewhere/tet.off")'
expect import-absolute 77 "cannot import '$work/elsewhere/tet.off'" "draw import(\"$work/elsewhere/tet.off\")"
expect import-folder-link 77 "cannot import 'link/secret.off': it is outside" 'draw import("link/secret.off")'

# ---- --allow-path opens the folder it names, and only that ----
expect allow-include 0 "wrote" 'include "link/shared.hls"
draw shared' -o "$work/allowed.pdf" --allow-path ../elsewhere
expect allow-import 0 "wrote" 'draw import("../elsewhere/tet.off")' -o "$work/allowed.pdf" --allow-path "$work/elsewhere"
expect allow-other 77 "it is outside" 'draw import("../elsewhere/tet.off")' --allow-path sub
expect allow-missing 64 "--allow-path no-such-folder: no such folder" 'draw box(1, 1, 1)' --allow-path no-such-folder

# ---- writing: the script's output statement ----
expect output-parent 77 "output '../escaped.pdf': it is outside the folder a script's outputs go to" \
  'draw box(1, 1, 1)
output "../escaped.pdf"'
expect output-absolute 77 "output '$work/escaped.svg': it is outside" "draw box(1, 1, 1)
output \"$work/escaped.svg\""
expect output-folder-link 77 "output 'link/escaped.svg': it is outside" 'draw box(1, 1, 1)
output "link/escaped.svg"'
expect output-hint 77 "name the file on the command line: -o ../escaped.pdf" 'draw box(1, 1, 1)
output "../escaped.pdf"'
expect output-below 0 "wrote sub/inside.svg" 'draw box(1, 1, 1)
output "sub/inside.svg"'
[ -s sub/inside.svg ] || fail "output-below: sub/inside.svg not written"
expect out-dir 0 "wrote" 'draw box(1, 1, 1)
output "moved.svg"' --out-dir ../elsewhere
[ -s ../elsewhere/moved.svg ] || fail "out-dir: ../elsewhere/moved.svg not written"
[ ! -e moved.svg ] || fail "out-dir: moved.svg written in the working directory too"
expect out-dir-escape 77 "it is outside the folder a script's outputs go to ($work/project/sub, from --out-dir)" \
  'draw box(1, 1, 1)
output "../escaped.svg"' --out-dir sub
# -o is the user's own choice: any path.
expect cli-output 0 "wrote ../cli.svg" 'draw box(1, 1, 1)
output "../escaped.pdf"' -o ../cli.svg
[ -s ../cli.svg ] || fail "cli-output: ../cli.svg not written"
for f in "$work/escaped.pdf" "$work/escaped.svg" "$work/elsewhere/escaped.svg" "$work/project/escaped.svg"; do
  [ ! -e "$f" ] || fail "$f was written"
done

if [ "$failures" -gt 0 ]; then
  echo "$failures failures"
  exit 1
fi
rm -rf "$work.log"
echo "confinement: every escape route refused, every allowed path works"
