#!/usr/bin/env bash
# Install the Debian 12 packages this project needs, only those missing.
set -euo pipefail

packages=(
  liggghts libliggghts-dev        # LIGGGHTS 3.8: the DEM engine we extend
  libopenmpi-dev openmpi-bin      # MPI (LIGGGHTS is built against Open MPI)
  libeigen3-dev                   # small dense linear algebra in the cores
  libcgal-dev                     # regular triangulation of the 3D membrane's packing
  cmake g++ make libgtest-dev     # build and unit tests
  python3 python3-numpy python3-scipy python3-matplotlib   # post-processing and test driver
  python3-vtk9                    # the VTK files (.vtp, .vtk) read with VTK's own readers
  xvfb xauth                      # a display for VTK's off-screen rendering (scripts/render_paraview.py)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
