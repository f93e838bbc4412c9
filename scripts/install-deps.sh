#!/usr/bin/env bash
# Installs the Debian 12 packages shockfield needs to build, test and compare against its peers.
# Only missing packages are installed; running it twice does nothing the second time.
set -euo pipefail
packages=(
  build-essential cmake pkg-config git
  libeigen3-dev libtomlplusplus-dev libcli11-dev libfmt-dev libfftw3-dev libhdf5-dev libomp-dev
  libgtest-dev libgmock-dev libbenchmark-dev libnanoflann-dev libcgal-dev zlib1g-dev
  lammps python3-numpy python3-scipy python3-skimage python3-matplotlib python3-ase python3-vtk9 python3-h5py python3-mdanalysis
  pybind11-dev python3-pybind11 python3-dev
  libopenmpi-dev openmpi-bin
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
