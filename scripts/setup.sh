#!/usr/bin/env bash
# Installs the Debian 12 packages hlrscript needs to build, test and benchmark. Idempotent: quiet and
# quick when everything is present. --cluster adds a single-node Slurm for scripts/cluster-test.sh.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libcairo2-dev libpng-dev nlohmann-json3-dev tao-pegtl-dev libboost-program-options-dev libtbb-dev zlib1g-dev libdeflate-dev libedit-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libhersheyfont-dev hershey-fonts-data libunistring-dev libgmp-dev libcgal-dev scdoc
  poppler-utils hp2xx librsvg2-bin inkscape tmux parallel python3-ezdxf
  clang libclang-rt-14-dev
)
if [ "${1:-}" = --cluster ]; then packages+=(slurmctld slurmd slurm-client munge); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
