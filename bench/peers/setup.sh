#!/usr/bin/env bash
# Installs what bench/peers/ needs (Debian 12): OpenCASCADE's development packages (HLRBRep_PolyAlgo,
# the B-rep builders, BRepMesh) and Sketch. Run as root (or through sudo). ln (github.com/fogleman/ln)
# is a Go module that Debian does not package and that cannot be fetched on this machine: see README.md.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends \
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev \
  sketch
