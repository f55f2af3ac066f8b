#!/usr/bin/env bash
# Regenerates runtime/BUILTINS.md from the built-ins' registration tables (after scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
build/runtime/hlrscript help reference > runtime/BUILTINS.md
echo "wrote runtime/BUILTINS.md"
