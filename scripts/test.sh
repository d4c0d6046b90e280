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
cd "$build"
"$PHONGVTK_CTEST" --output-on-failure -j"$(nproc)" "$@"
