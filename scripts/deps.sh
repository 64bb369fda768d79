#!/usr/bin/env bash
# Installs the Debian 12 packages t2 needs (as root), or prints the exact apt-get line and stops.
set -euo pipefail
packages=(
  cmake g++ make ninja-build ccache pkg-config git ca-certificates
  libgtest-dev libgmock-dev libbenchmark-dev libfmt-dev libcairo2-dev libgmp-dev zlib1g-dev
  doxygen pandoc libjs-katex librsvg2-bin fonts-dejavu-core
  clang libclang-rt-14-dev bubblewrap zip unzip
  libcgal-dev libboost-dev libcli11-dev nlohmann-json3-dev libseccomp-dev libqhull-dev libnanoflann-dev libgeos-dev
  chromium
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
line="apt-get install -y --no-install-recommends ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "t2 needs these Debian packages; as root, run:" >&2
  echo "  apt-get update && $line" >&2
  exit 1
fi
echo "installing: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
