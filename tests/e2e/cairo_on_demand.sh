#!/usr/bin/env bash
# cairo is loaded only when a picture is drawn with it (core/device/formats/cairo_library.hpp): the engine
# does not link it, a PDF or JSON run never loads it, a PNG run does, and a PNG run that cannot load it
# says what to install, exits non-zero and writes nothing.
#   cairo_on_demand.sh HLRSCRIPT WORK
set -uo pipefail
hlrscript=$1
source "$(dirname "${BASH_SOURCE[0]}")/checks.sh" "$2"
engine="$(dirname "$hlrscript")/hlrscript-engine"
cat >scene.hls <<'HLS'
draw box(1, 1, 1)
camera main = lookat(eye: (3, -4, 2), target: (0, 0, 0), fov: 30)
HLS
if ldd "$engine" | grep -q libcairo; then fail "the engine links cairo"; fi
# Which libraries a run loads, from the dynamic loader's own trace.
loads_cairo() {
  LD_DEBUG=files LD_DEBUG_OUTPUT="$work/trace" "$hlrscript" "$@" >/dev/null 2>&1
  grep -q "file=libcairo.so.2" "$work"/trace.*  # not through a pipe: grep -q leaving early fails `cat`
  local found=$?
  rm -f "$work"/trace.*
  return $found
}
for out in scene.pdf scene.json scene.hpgl; do
  if loads_cairo scene.hls -o "$out"; then fail "writing $out loaded cairo"; fi
  [ -s "$out" ] || fail "no $out written"
done
loads_cairo scene.hls -o scene.png || fail "writing scene.png did not load cairo"
[ -s scene.png ] || fail "no scene.png written"
# A library that cannot be loaded: an empty file by cairo's name, found first.
mkdir -p broken
: >broken/libcairo.so.2
rm -f missing.png
LD_LIBRARY_PATH="$work/broken" "$hlrscript" scene.hls -o missing.png >out.txt 2>err.txt
status=$?
[ "$status" -ne 0 ] || fail "a PNG run without cairo exited 0"
grep -q "cannot load cairo (libcairo.so.2)" err.txt || fail "no message naming cairo: $(cat err.txt)"
grep -q "apt-get install libcairo2" err.txt || fail "the message does not say what to install"
[ ! -e missing.png ] || fail "missing.png was written"
LD_LIBRARY_PATH="$work/broken" "$hlrscript" scene.hls -o fine.pdf >/dev/null 2>&1 || fail "a PDF run needed cairo"
[ -s fine.pdf ] || fail "no fine.pdf without cairo"
[ "$failures" -eq 0 ] && echo "cairo on demand: all checks passed"
exit $((failures > 0))
