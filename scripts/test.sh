#!/usr/bin/env bash
# The test command: installs, builds, checks formatting and runs the whole suite through CTest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/build.sh"
"$here/scripts/check-format.sh"
build="${PHONGVTK_BUILD_DIR:-$here/build}"
cd "$build"
ctest --output-on-failure -j"$(nproc)" "$@"
