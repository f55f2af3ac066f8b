#!/usr/bin/env bash
# hlrscript is a launcher (runtime/cli/launcher.cpp) that executes the engine beside it: the output and the
# exit status are the engine's, every argument reaches it as given, a user's own glibc.malloc.hugetlb
# setting is kept, and without its engine it says what is missing and what to do (exit status 127).
#   launcher.sh HLRSCRIPT SOURCE_DIR WORK
set -uo pipefail
hlrscript=$1
source_dir=$2
source "$(dirname "${BASH_SOURCE[0]}")/checks.sh" "$3"
engine="$(dirname "$hlrscript")/hlrscript-engine"
[ -x "$engine" ] || fail "no engine beside $hlrscript"

# The same as the engine run directly: a good script, a broken one, a missing file with a space in its name.
cp "$source_dir/examples/tutorial/01-a-solid.hls" good.hls || fail "no examples/tutorial/01-a-solid.hls"
"$hlrscript" check good.hls >/dev/null 2>&1 || fail "check good.hls did not pass"
printf 'draw box((0,0,0), (1,1,1)\n' >broken.hls
for args in "check good.hls" "check broken.hls" "--version"; do
  # shellcheck disable=SC2086
  "$hlrscript" $args >launcher.out 2>launcher.err
  launcher_status=$?
  # shellcheck disable=SC2086
  "$engine" $args >engine.out 2>engine.err
  engine_status=$?
  [ "$launcher_status" = "$engine_status" ] || fail "$args: exit status $launcher_status, the engine's $engine_status"
  cmp -s launcher.out engine.out || fail "$args: standard output differs from the engine's"
  cmp -s launcher.err engine.err || fail "$args: standard error differs from the engine's"
done
"$hlrscript" check "no such file.hls" 2>launcher.err
status=$?
[ "$status" = 66 ] || fail "a missing script: exit status $status, not 66"
grep -qF "cannot read 'no such file.hls'" launcher.err || fail "the name with a space did not reach the engine whole"

# A user's own hugetlb setting, and other tunables, are kept and the program still runs.
GLIBC_TUNABLES=glibc.malloc.hugetlb=0 "$hlrscript" check good.hls >/dev/null 2>&1 ||
  fail "GLIBC_TUNABLES=glibc.malloc.hugetlb=0: the program did not run"
GLIBC_TUNABLES=glibc.malloc.tcache_count=0 "$hlrscript" check good.hls >/dev/null 2>&1 ||
  fail "GLIBC_TUNABLES with another tunable: the program did not run"

# Without its engine: what is missing, what to do, status 127, nothing else run.
mkdir alone
cp "$hlrscript" alone/hlrscript
alone/hlrscript check good.hls >alone.out 2>alone.err
status=$?
[ "$status" = 127 ] || fail "without the engine: exit status $status, not 127"
grep -qF "the engine is missing" alone.err || fail "without the engine: no message saying so"
grep -qF "reinstall hlrscript" alone.err || fail "without the engine: no hint"
[ ! -s alone.out ] || fail "without the engine: something was printed on standard output"

if [ "$failures" -gt 0 ]; then
  echo "$failures launcher check(s) failed"
  exit 1
fi
echo "launcher: ok"
