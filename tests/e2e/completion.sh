#!/usr/bin/env bash
# Shell completion (completions/hlrscript.bash) as bash runs it: options (taken from --help), the values
# of the options that take words, device extensions after -o, plotter profiles (--list-plotters) and the
# camera names of the script on the line (--list-cameras). zsh's file is checked for syntax when zsh is here.
#   completion.sh HLRSCRIPT SOURCE_DIR WORK
set -uo pipefail
hlrscript=$1
source_dir=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
# shellcheck source=/dev/null
source "$source_dir/completions/hlrscript.bash"

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# complete WORD... : COMPREPLY for the last word, as bash would ask with the cursor at its end.
complete_line() {
  COMP_WORDS=("$hlrscript" "$@")
  COMP_CWORD=$(($# ))
  COMPREPLY=()
  _hlrscript
  printf '%s\n' "${COMPREPLY[@]}" | sort
}
expect_has() {  # expect_has WANTED WORD...
  local wanted=$1
  shift
  complete_line "$@" | grep -qx -- "$wanted" || fail "completing '$*' does not offer '$wanted': $(complete_line "$@" | tr '\n' ' ')"
}
expect_lacks() {
  local unwanted=$1
  shift
  complete_line "$@" | grep -qx -- "$unwanted" && fail "completing '$*' offers '$unwanted'"
  return 0
}

cat >views.hls <<'HLS'
draw cube(1)
camera front = lookat(eye: (0, -5, 1), target: (0, 0, 0))
camera top_down = ortho(eye: (0, 0, 5), target: (0, 0, 0), up: (0, 1, 0), height: 3)
HLS
touch notes.txt old.pdf

# Every option --help lists, and only options.
while read -r option; do expect_has "$option" "--${option:2:2}"; done < <(
  "$hlrscript" --help | grep -E '^ +-' | grep -oE -- '--[a-z][a-z-]*' | sort -u)
expect_has --list-cameras --list
expect_has --plotter --plo
expect_lacks --wrap --w  # from --help's examples, not an option

# Values.
expect_has front views.hls --camera ""
expect_has top_down views.hls --camera t
expect_lacks front --camera ""  # no script on the line: no cameras to offer
for p in hp7475a roland-dxy generic grbl-servo grbl-z; do expect_has "$p" views.hls --plotter ""; done
expect_has dashed views.hls --hidden d
expect_has 16 views.hls --levels 1
expect_lacks 17 views.hls --levels 1
expect_has plotter views.hls --svg p
expect_has outline views.hls --text o
expect_has optimized --pen-order o
expect_has A4 --paper A
expect_has faces= --limit f

# Files: scripts first, device files after -o, commands as the first word.
expect_has views.hls v
expect_lacks notes.txt n
expect_has check ch
expect_has old.pdf views.hls -o o
expect_lacks notes.txt views.hls -o n
expect_has scene.gcode views.hls -o scene

# zsh's completion file parses.
if command -v zsh >/dev/null; then
  zsh -n "$source_dir/completions/_hlrscript" || fail "completions/_hlrscript does not parse"
fi

echo "$failures failures"
[ "$failures" -eq 0 ]
