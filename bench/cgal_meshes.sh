#!/usr/bin/env bash
# Fetches the CGAL demo meshes issue 12 measured — the Stanford bunny (bunny00.off, 75 408 triangles,
# 2.6 MB) and fandisk (fandisk_large.off, 31 682 triangles, 1.3 MB) — from Debian's libcgal-demo package
# (downloaded, not installed) into DIR (default bench/data, which git ignores).
#   bash bench/cgal_meshes.sh [DIR]
#   HLR_IMPORT_FILES=bench/data/bunny00.off:bench/data/fandisk_large.off build/bench/import_bench \
#     --benchmark_filter=File
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-bench/data}
mkdir -p "$dir"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && apt-get download libcgal-demo >/dev/null)
dpkg-deb -x "$work"/libcgal-demo_*.deb "$work/x"
tar -xzf "$work/x/usr/share/doc/libcgal-dev/data.tar.gz" -C "$work" data/meshes/bunny00.off data/meshes/fandisk_large.off
cp "$work/data/meshes/bunny00.off" "$work/data/meshes/fandisk_large.off" "$dir/"
echo "cgal_meshes: $dir/bunny00.off, $dir/fandisk_large.off"
