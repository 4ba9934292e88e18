#!/usr/bin/env bash
# Installs segmat's build dependencies (Debian 12 packages) when any is missing. Needs root.
# Extra packages may be named as arguments: scripts/test.sh adds what the optional parts and
# their tests need (see SEGMAT_TEST_PACKAGES there).
set -euo pipefail
packages=(cmake g++ make libpcl-dev libeigen3-dev libboost-graph-dev libflann-dev libgtest-dev
          libqhull-dev liblz4-dev
          clang libclang-rt-14-dev "$@") # clang: the libFuzzer targets of scripts/fuzz.sh
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "segmat: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "segmat: missing packages (${missing[*]}); run as root or install them first" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
