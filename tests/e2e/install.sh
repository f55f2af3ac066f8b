#!/usr/bin/env bash
# Install and package: `cmake --install` into a prefix, the prefix moved elsewhere, and the moved program
# renders a script that includes a library module from any folder (it finds ../share/hlrscript/modules
# beside itself, not the source tree); HLRSCRIPT_STDLIB still overrides. Then `cpack -G DEB`: the package
# holds the same files under /usr and depends on the shared libraries the program links (libedit and
# Boost's are linked in), cairo (loaded when first drawn with) and the font data.
#   install.sh BUILD_DIR WORK
set -uo pipefail
build=$1
work=$2
rm -rf "$work"
mkdir -p "$work/elsewhere"

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

cmake --install "$build" --prefix "$work/first" >"$work/install.log" 2>&1 || { cat "$work/install.log"; exit 1; }
mv "$work/first" "$work/moved"
program=$work/moved/bin/hlrscript
[ -x "$program" ] || fail "no bin/hlrscript installed"
[ -f "$work/moved/share/hlrscript/modules/gears.hls" ] || fail "the library modules are not installed"
[ -f "$work/moved/share/doc/hlrscript/examples/showcase/workshop.hls" ] || fail "the examples are not installed"
[ -f "$work/moved/share/man/man1/hlrscript.1" ] || fail "the manual page is not installed"
[ -f "$work/moved/share/bash-completion/completions/hlrscript" ] || fail "the bash completion is not installed"
[ -f "$work/moved/share/zsh/vendor-completions/_hlrscript" ] || fail "the zsh completion is not installed"

"$program" --version >"$work/version.txt" 2>&1 || fail "--version failed"
grep -qx "library modules: $work/moved/share/hlrscript/modules" "$work/version.txt" ||
  fail "the moved program does not use its own modules: $(cat "$work/version.txt")"

cd "$work/elsewhere" || exit 1
cat >gears.hls <<'HLS'
include "std/gears.hls"
draw gear(12, 1, 2, bore: 3)
camera main = lookat(eye: (20, -25, 18), target: (0, 0, 0))
HLS
"$program" gears.hls -o gears.pdf >out.txt 2>&1 || fail "the moved program cannot render a script with a library module: $(cat out.txt)"
pdfinfo gears.pdf >/dev/null 2>&1 || fail "no readable gears.pdf"

# HLRSCRIPT_STDLIB still wins: an empty folder has no gears.hls.
mkdir -p empty
HLRSCRIPT_STDLIB=$PWD/empty "$program" gears.hls -o other.pdf >err.txt 2>&1 && fail "HLRSCRIPT_STDLIB was ignored"
grep -q "empty" err.txt || fail "the error does not name the HLRSCRIPT_STDLIB folder: $(cat err.txt)"

# The Debian package.
(cd "$build" && cpack -G DEB -B "$work/deb" >"$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; fail "cpack -G DEB failed"; }
deb=$(ls "$work"/deb/hlrscript_*.deb 2>/dev/null | head -1)
if [ -z "$deb" ]; then
  fail "no .deb written"
else
  depends=$(dpkg-deb -f "$deb" Depends)
  for lib in libcairo2 libtbb libstdc++6 hershey-fonts-data; do
    [[ $depends == *"$lib"* ]] || fail "the package does not depend on $lib: $depends"
  done
  dpkg-deb -x "$deb" "$work/unpacked"
  [ -x "$work/unpacked/usr/bin/hlrscript" ] || fail "the package has no /usr/bin/hlrscript"
  [ -f "$work/unpacked/usr/share/hlrscript/modules/gears.hls" ] || fail "the package has no modules"
  [ -f "$work/unpacked/usr/share/man/man1/hlrscript.1" ] || fail "the package has no manual page"
  # Unpacked anywhere, it too finds its own modules.
  "$work/unpacked/usr/bin/hlrscript" gears.hls -o unpacked.pdf >out.txt 2>&1 ||
    fail "the unpacked program cannot render: $(cat out.txt)"
fi

echo "$failures failures"
[ "$failures" -eq 0 ]
