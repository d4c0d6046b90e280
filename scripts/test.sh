#!/usr/bin/env bash
# The test command: installs, builds, checks formatting and runs the whole suite through CTest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/build.sh"
"$here/scripts/check-format.sh"
# ParaView's flavour installs every prerequisite of every test: a skip there is a failure.
if command -v pvbatch >/dev/null; then
  export PHONGVTK_NO_SKIPS="${PHONGVTK_NO_SKIPS-1}"
fi
build="${PHONGVTK_BUILD_DIR:-$here/build}"
cd "$build"
ctest --output-on-failure -j"$(nproc)" "$@"
