#!/usr/bin/env bash
# The heap on transparent huge pages (runtime/base/allocator_policy.hpp): a process calling
# heap_on_huge_pages() starts again once with glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES (unless the
# host takes back freed memory, heap_pages.hpp), keeps what the user set there, leaves a hugetlb setting
# of the user's alone and never restarts twice; under AddressSanitizer it does nothing. The heap warmer
# (heap_warmer.hpp) faults in the huge page past the heap's use, which stays cold without it (and under
# AddressSanitizer, where it does nothing). Then hlrscript itself: a REPL's own environment
# (/proc/PID/environ).
# usage: allocator_policy.sh PROBE HLRSCRIPT WORKDIR SANITIZED(0|1)
set -euo pipefail
probe=$1 hlrscript=$2 work=$3 sanitized=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "allocator_policy: $*" >&2; exit 1; }

# check GIVEN EXPECTED STARTS: the probe run with GLIBC_TUNABLES=GIVEN (unset when empty).
check() {
  local given=$1 expected=$2 starts=$3 seen count
  if [ -n "$given" ]; then
    seen=$(GLIBC_TUNABLES=$given "$probe" 2>"$work/err")
  else
    seen=$(env -u GLIBC_TUNABLES "$probe" 2>"$work/err")
  fi
  count=$(grep -c '^start$' "$work/err")
  [ "$seen" = "$expected" ] || fail "GLIBC_TUNABLES='$given' became '$seen', expected '$expected'"
  [ "$count" = "$starts" ] || fail "GLIBC_TUNABLES='$given': $count starts, expected $starts"
}

# warmth MODE EXPECTED: the probe's last line with `warm` or `cold`.
warmth() {
  local seen
  seen=$("$probe" "$1" 2>/dev/null | tail -n 1)
  [ "$seen" = "$2" ] || fail "probe $1: the page past the heap's use is $seen, expected $2"
}

if [ "$sanitized" = 1 ]; then
  warmth warm cold
  check "" "" 1
  check "glibc.malloc.arena_max=4" "glibc.malloc.arena_max=4" 1
  echo "allocator_policy: sanitized build, environment left alone"
  exit 0
fi
# On a virtual machine whose virtio balloon reports free pages to the host (device id 5, feature bit 5),
# the heap stays on small pages (runtime/base/heap_pages.hpp): the engine does not start again, and
# hlrscript says so in the environment it starts the engine with.
reporting=0
for dev in /sys/bus/virtio/devices/*; do
  [ "$(cat "$dev/device" 2>/dev/null)" = 0x0005 ] || continue
  [ "$(cut -c6 "$dev/features" 2>/dev/null)" = 1 ] && reporting=1
done
if [ "$reporting" = 1 ]; then
  echo "allocator_policy: the host takes back freed memory: small pages expected"
  check "" "" 1
  check "glibc.malloc.arena_max=4" "glibc.malloc.arena_max=4" 1
  launched="glibc.malloc.hugetlb=0"
else
  check "" "glibc.malloc.hugetlb=1" 2
  check "glibc.malloc.arena_max=4" "glibc.malloc.arena_max=4:glibc.malloc.hugetlb=1" 2
  launched="glibc.malloc.hugetlb=1"
fi
check "glibc.malloc.hugetlb=0" "glibc.malloc.hugetlb=0" 1
check "glibc.malloc.hugetlb=1" "glibc.malloc.hugetlb=1" 1
warmth cold cold
if [ "$(uname -r | awk -F. '{print ($1 > 5 || ($1 == 5 && $2 >= 14))}')" = 1 ]; then
  warmth warm warmed
else
  echo "allocator_policy: kernel $(uname -r) cannot populate pages (MADV_POPULATE_WRITE, 5.14): warmer not checked"
fi

# hlrscript calls it: a REPL, once it has answered a line, runs with the setting.
fifo="$work/in" out="$work/out"
mkfifo "$fifo"
env -u GLIBC_TUNABLES "$hlrscript" repl <"$fifo" >"$out" 2>&1 &
pid=$!
exec 3>"$fifo"
echo "6 * 7" >&3
for _ in $(seq 200); do
  grep -q 42 "$out" && break
  sleep 0.05
done
grep -q 42 "$out" || fail "the REPL did not answer: $(cat "$out")"
seen=$(tr '\0' '\n' <"/proc/$pid/environ" | sed -n 's/^GLIBC_TUNABLES=//p')
echo ":quit" >&3
exec 3>&-
wait "$pid" || true
[ "$seen" = "$launched" ] || fail "hlrscript runs with GLIBC_TUNABLES='$seen', expected '$launched'"
echo "allocator_policy: ok"
