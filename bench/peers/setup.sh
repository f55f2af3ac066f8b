#!/usr/bin/env bash
# Installs what bench/peers/ needs (Debian 12): OpenCASCADE's development packages (HLRBRep_PolyAlgo,
# the B-rep builders, BRepMesh), Sketch and, optionally, Blender (only blender_lineart.py needs it: its
# Line Art is a peer, README.md; HLR_PEERS_NO_BLENDER=1 leaves it out). Run as root (or through sudo).
# ln (github.com/fogleman/ln) is a Go module that Debian does not package and that cannot be fetched on
# this machine: see README.md.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends \
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev \
  sketch
if [ "${HLR_PEERS_NO_BLENDER:-0}" != 1 ]; then
  # Blender 3.4 (Debian 12) for its Grease Pencil Line Art modifier, ≈ 620 MB installed.
  $SUDO apt-get install -y --no-install-recommends blender
fi
