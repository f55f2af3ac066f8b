#!/usr/bin/env bash
# Regenerates the small pictures the documents show (after scripts/build.sh): each step of
# examples/tutorial/ in docs/images/tutorial/ (docs/tutorial.md), and each runnable example in
# docs/images/gallery/GROUP-NAME.png (examples/README.md, README). Animations show their middle frame.
# The tests run it into another folder (docs-images.sh OUT_DIR, HLRSCRIPT=program) and compare.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images}
hlrscript=${HLRSCRIPT:-build/runtime/hlrscript}
mkdir -p "$out/tutorial" "$out/gallery"

# picture SCRIPT TARGET: one frame, 160 × 110 mm at 60 dpi (about 380 × 260 pixels, 10-30 KB); a sheet of
# views (its views are placed in page millimetres) on its own paper with its frame, at 24 dpi.
picture() {
  local frames=() count
  if grep -qE '^(view|views of) ' "$1"; then
    "$hlrscript" "$1" -o "$2" --dpi 24 --line-width 0.5 >/dev/null 2>&1 || { echo "docs-images: $1 failed" >&2; return 1; }
    return
  fi
  count=$("$hlrscript" check "$1" 2>/dev/null | sed -n 's/.*ok: \([0-9]*\) frames\{0,1\} evaluated.*/\1/p')
  [ "${count:-1}" -gt 1 ] && frames=(--frames $((count / 2)))
  "$hlrscript" "$1" "${frames[@]}" -o "$2" --dpi 60 --paper 160x110 --margin 4 --plain --line-width 0.35 \
    >/dev/null 2>&1 || { echo "docs-images: $1 failed" >&2; return 1; }
}

for script in examples/tutorial/*.hls; do
  picture "$script" "$out/tutorial/$(basename "${script%.hls}").png"
done
for script in examples/*/*.hls; do
  case $script in examples/tutorial/*) continue ;; esac
  grep -qE '^(camera|views of) ' "$script" || continue  # solids the views include
  group=$(basename "$(dirname "$script")")
  picture "$script" "$out/gallery/$group-$(basename "${script%.hls}").png"
done
echo "wrote $out/tutorial/*.png and $out/gallery/*.png"
