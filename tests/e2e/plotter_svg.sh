#!/usr/bin/env bash
# Plotter SVG (--svg plotter) on every example: frame 0 with its hidden layer and its caption in single
# strokes, checked against the JSON of the same frame (--text stroke) by plotter_svg_check.py (our XML reading, Inkscape's --query-all) and drawn by librsvg's
# rsvg-convert; then what selects it: a named plotter makes it the default, --svg document keeps cairo's.
#   plotter_svg.sh HLRSCRIPT EXAMPLES_DIR WORK
set -uo pipefail
hlrscript=$1
examples=$2
work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
export HOME=$work  # Inkscape writes its preferences below HOME

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

count=0
while IFS= read -r script; do
  grep -q '^camera\|^ *camera ' "$script" || continue  # solids-only files the views include
  name=$(basename "${script%.hls}")
  "$hlrscript" "$script" --frames 0 --hidden dashed -o "$name.svg" --svg plotter >/dev/null 2>"$name.err" ||
    { fail "$script -o .svg --svg plotter: $(head -3 "$name.err")"; continue; }
  "$hlrscript" "$script" --frames 0 --hidden dashed -o "$name.json" --text stroke >/dev/null 2>"$name.err" ||
    { fail "$script -o .json: $(head -3 "$name.err")"; continue; }
  python3 "$here/plotter_svg_check.py" "$name.svg" "$name.json" || fail "$script: the plotter SVG disagrees"
  rsvg-convert "$name.svg" -o "$name.png" 2>"$name.err" && [ -s "$name.png" ] ||
    fail "$script: rsvg-convert cannot draw the plotter SVG: $(head -3 "$name.err")"
  count=$((count + 1))
done < <(find "$examples" -name '*.hls' | sort)
[ "$count" -ge 15 ] || fail "only $count examples rendered"

# Occlusion levels as the example asks for them (no --hidden): a layer per pen and level, "N hidden K".
levels=$examples/showcase/occlusion-levels.hls
"$hlrscript" "$levels" -o levels.svg --svg plotter >/dev/null 2>levels.err || fail "levels .svg: $(head -3 levels.err)"
"$hlrscript" "$levels" -o levels.json --text stroke >/dev/null 2>levels.err || fail "levels .json: $(head -3 levels.err)"
python3 "$here/plotter_svg_check.py" levels.svg levels.json || fail "the occlusion levels' plotter SVG disagrees"
grep -q 'inkscape:label="2 hidden 1"' levels.svg || fail "no layer '2 hidden 1' in the occlusion levels' SVG"

# What selects it.
scene=$examples/showcase/pens-and-plotter.hls
"$hlrscript" "$scene" --frames 0 -o named.svg --plotter hp7475a >/dev/null 2>&1 || fail "--plotter with .svg failed"
grep -q 'inkscape:groupmode="layer"' named.svg || fail "a named plotter does not make the SVG a plotter SVG"
"$hlrscript" "$scene" --frames 0 -o doc.svg --plotter hp7475a --svg document >/dev/null 2>&1 || fail "--svg document failed"
grep -q 'inkscape:groupmode' doc.svg && fail "--svg document wrote layers"
gear=$examples/showcase/gear.hls  # names no plotter
"$hlrscript" "$gear" --frames 0 -o plain.svg >/dev/null 2>&1 || fail "the default SVG failed"
grep -q 'inkscape:groupmode' plain.svg && fail "without a plotter the SVG should be cairo's document"
"$hlrscript" "$scene" --frames 0 -o bad.svg --svg inkjet >/dev/null 2>bad.err
[ $? -eq 64 ] && grep -q "svg takes 'plotter' or 'document'" bad.err || fail "--svg inkjet is not a usage error"
[ -e bad.svg ] && fail "--svg inkjet wrote a file"

# Off the page (fitting the drawing, at a scale: framed by the camera it is cut at the frame): an error
# naming --clip, and with --clip the strokes are cut at the page's edge.
"$hlrscript" "$gear" --frames 0 -o big.svg --svg plotter --scale 400 --fit drawing >/dev/null 2>big.err
[ $? -ne 0 ] && grep -q "off the .* page.*--clip" big.err || fail "a drawing larger than the page is not refused"
[ -e big.svg ] && fail "a refused plotter SVG was written"
"$hlrscript" "$gear" --frames 0 -o big.svg --svg plotter --scale 400 --fit drawing --clip >/dev/null 2>&1 || fail "--clip failed"
python3 - big.svg <<'PY' || fail "--clip left points off the page"
import re, sys
text = open(sys.argv[1]).read()
w, h = (float(v) for v in re.search(r'viewBox="0 0 ([0-9.]+) ([0-9.]+)"', text).groups())
pts = [(float(x), float(y)) for x, y in re.findall(r"(-?[0-9.]+),(-?[0-9.]+)", text)]
assert pts and all(0 <= x <= w + 1e-3 and 0 <= y <= h + 1e-3 for x, y in pts), "a point off the page"
PY

echo "$count examples checked, $failures failures"
[ "$failures" -eq 0 ]
