#!/usr/bin/env bash
# The test command: installs, builds, checks formatting and runs the whole suite through CTest.
#
#   scripts/test.sh [CTEST ARGS...]              the suite (build/)
#   scripts/test.sh --sanitize [CTEST ARGS...]   the modules and the C++ tests built with
#                                                AddressSanitizer + UndefinedBehaviorSanitizer
#                                                (build-sanitize/; Testing/Sanitizers/)
#   scripts/test.sh --clang [CTEST ARGS...]      the Filters module and its C++ tests built with
#                                                Debian's Clang (build-clang/; Testing/Clang/)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ "${1:-}" = "--sanitize" ]; then
  shift
  exec "$here/Testing/Sanitizers/run.sh" "$@"
fi
if [ "${1:-}" = "--clang" ]; then
  shift
  exec "$here/Testing/Clang/run.sh" "$@"
fi
. "$here/scripts/common.sh"
"$here/scripts/build.sh"
"$here/scripts/check-format.sh"
# ParaView's flavour installs every prerequisite of every test: a skip there is a failure.
if command -v pvbatch >/dev/null; then
  export PHONGVTK_NO_SKIPS="${PHONGVTK_NO_SKIPS-1}"
fi
build="${PHONGVTK_BUILD_DIR:-$here/build}"
# The PyVista accessor's test (Python.PyVista) runs in a virtual environment of Debian's Python
# that sees Debian's VTK or ParaView (system site packages) and has PyVista from PyPI. CMake asks
# for it, with the pip steps, where the VTK is one PyVista supports (Testing/Python).
if [ -f "$build/pyvista-venv.wanted" ]; then
  mapfile -t steps <"$build/pyvista-venv.wanted"
  if ! phongvtk_pypi_venv "$build/pyvista-venv" --system-site-packages "${steps[@]}"; then
    echo "phongvtk: the PyVista accessor is NOT tested: PyVista could not be installed from PyPI" >&2
  fi
fi
cd "$build"
"$PHONGVTK_CTEST" --output-on-failure -j"$(nproc)" "$@"
