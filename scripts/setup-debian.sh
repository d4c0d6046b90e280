#!/usr/bin/env bash
# Installs the Debian 12 or 13 packages PhongVTK builds, tests and runs with. Idempotent and quick
# when everything is already installed; uses sudo when not run as root.
# PHONGVTK_FLAVOUR=paraview installs ParaView's SDK (5.11 on Debian 12, 5.13 on Debian 13);
# PHONGVTK_FLAVOUR=vtk installs Debian's plain VTK instead (9.1 on Debian 12, 9.3 on Debian 13;
# python3-vtk9 and python3-paraview conflict: one flavour a root). Unset: the flavour already
# installed, ParaView on a machine that has neither.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$here/scripts/common.sh"
phongvtk_debian_clang
clang="$PHONGVTK_CLANG_VERSION"

installed() {
  dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"
}
if [ -z "${PHONGVTK_FLAVOUR:-}" ]; then
  PHONGVTK_FLAVOUR=paraview
  if installed python3-vtk9 && ! installed python3-paraview; then
    PHONGVTK_FLAVOUR=vtk
  fi
fi

case "$PHONGVTK_FLAVOUR" in
  paraview)
    # ParaView's SDK (VTK 9.2 inside 5.11, 9.3 inside 5.13) and the -dev packages its CMake config
    # looks for; paraview-dev depends on none of them. Found by configuring in a debootstrap
    # minbase root (../shared/tools/fresh-debian-check): without libfreetype-dev the configure
    # stops in VTK-targets.cmake (Freetype::Freetype), without libjpeg-dev/libtiff-dev it reports
    # them missing for VTK::IOImage; 5.13's looks for GLEW (libglew-dev, below).
    flavour=(paraview-dev python3-paraview python3-dev libopenmpi-dev libdouble-conversion-dev
      libutfcpp-dev liblz4-dev liblzma-dev zlib1g-dev libpugixml-dev libjsoncpp-dev
      libeigen3-dev libfreetype-dev libjpeg-dev libtiff-dev libpng-dev)
    other=python3-vtk9
    ;;
  vtk)
    # VTK 9.1 or 9.3 (its -dev package depends on most of what its CMake config looks for)
    flavour=(libvtk9-dev python3-vtk9 python3-dev)
    other=python3-paraview
    ;;
  *)
    echo "phongvtk: PHONGVTK_FLAVOUR must be paraview or vtk, not '$PHONGVTK_FLAVOUR'" >&2
    exit 2
    ;;
esac

packages=(
  # toolchain (ccache: scripts/build.sh); Debian's Clang builds the Filters a second time
  # (Testing/Clang)
  g++ cmake ninja-build ccache clang-format "clang-$clang"
  "${flavour[@]}"
  # headless rendering: OSMesa and EGL (Mesa llvmpipe), no X server
  libosmesa6-dev libegl-dev libgl-dev libx11-dev libglew-dev
  # VTK's XML parser on the system's expat (RenderingHeadless/PhongVTKExpatDeferral.cxx)
  libexpat1-dev
  # an X server for the tests that check coexistence with VTK's own GLX window
  xvfb
  # exact arithmetic (EXACT fallback, test reference), tests, benchmarks
  libgmp-dev libgtest-dev libbenchmark-dev python3-pytest python3-numpy
  # virtual environments: the format check's clang-format 14 where Debian's is another version
  python3-venv
  # LLVM's FuzzedDataProvider.h: the fuzz targets' input decoding (Testing/Fuzz)
  "libclang-rt-$clang-dev"
  # the plugin's distributed test (mpiexec pvbatch)
  openmpi-bin
  # the command line's benchmark plots (python3 -m phongvtk bench)
  python3-matplotlib
  # real meshes nobody here wrote (CGAL's sample data)
  libcgal-demo
)

# apt-get -y would remove the other flavour to make room; refuse instead.
if installed "$other"; then
  echo "phongvtk: $other (the other flavour) is installed;" \
    "PHONGVTK_FLAVOUR=$PHONGVTK_FLAVOUR needs a machine or root without it" >&2
  exit 2
fi

missing=()
for p in "${packages[@]}"; do
  if ! installed "$p"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo=()
if [ "$(id -u)" -ne 0 ]; then
  sudo=(sudo)
fi
echo "phongvtk: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
