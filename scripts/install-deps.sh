#!/usr/bin/env bash
# Installs the Debian 12 packages rotlie needs (idempotent: already-installed packages are skipped).
set -euo pipefail

packages=(
  g++ cmake make pkg-config git
  libginac-dev libcln-dev        # symbolic side: lie/, bch/, solver/
  libeigen3-dev libgsl-dev       # numeric side
  libboost-dev libboost-test-dev # Boost.Math headers, Boost.Test
  libcli11-dev nlohmann-json3-dev
  libbenchmark-dev               # bench/
  gnuplot-nox                    # report figures
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
