#!/usr/bin/env bash
# The documents' pictures are current: scripts/docs-images.sh run again into WORK draws every tutorial
# step and every example as docs/images/tutorial/ and docs/images/gallery/ show them (png_diff.py: same
# size, within a few antialiased pixels), and no step or example lacks its picture.
#   docs_images.sh HLRSCRIPT SOURCE_DIR WORK
set -uo pipefail
hlrscript=$1
source=$2
work=$3
rm -rf "$work"
HLRSCRIPT=$hlrscript bash "$source/scripts/docs-images.sh" "$work" >/dev/null || exit 1
failures=0
count=0
for set in tutorial gallery; do
  for made in "$work/$set"/*.png; do
    count=$((count + 1))
    kept=$source/docs/images/$set/$(basename "$made")
    if [ ! -f "$kept" ]; then
      echo "docs/images/$set/$(basename "$made") is missing: run scripts/docs-images.sh"
      failures=$((failures + 1))
      continue
    fi
    python3 "$(dirname "$0")/png_diff.py" "$kept" "$made" || failures=$((failures + 1))
  done
done
echo "$count pictures, $failures missing or out of date"
[ "$count" -ge 30 ] && [ "$failures" -eq 0 ]
