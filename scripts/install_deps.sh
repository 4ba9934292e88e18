#!/usr/bin/env bash
# Installs segmat's build dependencies (Debian 12 packages) when any is missing. Needs root.
# Pictures (segmat_render) need VTK (libvtk9-dev, also pulled in by libpcl-dev) and, with no
# display, Xvfb with Mesa's software OpenGL (xvfb, libgl1-mesa-dri); segmat_batch needs
# python3; the batch report's test opens the report in chromium.
set -euo pipefail
packages=(cmake g++ make libpcl-dev libeigen3-dev libboost-graph-dev libflann-dev libgtest-dev
          libqhull-dev liblz4-dev libvtk9-dev python3 xvfb libgl1-mesa-dri chromium
          python3-dev pybind11-dev python3-numpy python3-pytest python3-open3d)
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
