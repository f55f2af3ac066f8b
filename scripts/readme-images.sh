#!/usr/bin/env bash
# Regenerates the pictures README shows (after scripts/build.sh): the landing's frames 0, 11, 23, 35
# and 47 — the approach and the thesis's Carrier (2)-(5) — as small PNGs in docs/images/.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p docs/images
build/runtime/hlrscript examples/desens/landing.hls -o 'docs/images/landing-{frame:02}.png' \
  --frames 0,11,23,35,47 --dpi 100 --paper 100x100 --margin 2 --plain --line-width 0.3 -q >/dev/null 2>&1
echo "wrote docs/images/landing-{00,11,23,35,47}.png"
