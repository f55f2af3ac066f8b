#!/usr/bin/env bash
# The manual page (docs/hlrscript.1.scd, built by scdoc) keeps up with the program: every option --help
# lists, every exit code --help names and every environment variable the sources read are in it, and man
# (or groff) formats it without a warning.
#   man_page.sh HLRSCRIPT SOURCE_DIR MAN_PAGE
set -uo pipefail
hlrscript=$1
source_dir=$2
page=$3
[ -s "$page" ] || { echo "no manual page at $page (is scdoc installed? bash scripts/setup.sh)"; exit 1; }
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
# roff escapes '-' as '\-'; read the words back as text.
text=$(sed 's/\\-/-/g; s/\\f[BIRP]//g' "$page")
while read -r option; do
  grep -qF -- "$option" <<<"$text" || fail "the manual page lacks $option"
done < <("$hlrscript" --help | grep -E '^ +-' | grep -oE -- '--[a-z][a-z-]*' | sort -u)
while read -r code; do
  grep -qxF -- "$code" <<<"$text" || fail "the manual page lacks exit status $code"
done < <("$hlrscript" --help | sed -n '/^exit codes/,$p' | grep -oE '\b[0-9]{1,3}\b' | sort -u)
while read -r name; do
  grep -qF -- "$name" <<<"$text" || fail "the manual page lacks the environment variable $name"
done < <(grep -rhoE 'getenv\("[A-Z_]+"\)' "$source_dir/runtime" "$source_dir/core" | sed 's/getenv("//; s/")//' | sort -u)
if command -v groff >/dev/null; then
  warnings=$(groff -k -man -Tutf8 -ww -z "$page" 2>&1)  # -k: the page is UTF-8
  [ -z "$warnings" ] || fail "groff warns: $warnings"
fi
echo "$failures failures"
[ "$failures" -eq 0 ]
