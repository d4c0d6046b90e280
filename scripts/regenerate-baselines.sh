#!/usr/bin/env bash
# (Re)generates image baselines deliberately: runs the chosen rendering tests with
# PHONGVTK_REGENERATE_BASELINES=1, which makes every image comparison write the rendered image as
# Testing/Data/Baseline/<Name>.png instead of comparing. The tests' other checks (analytic pixel
# values, backend agreement) still run: a baseline from a failing run is not one to commit.
# Look at every image it lists before committing it.
#
#   scripts/regenerate-baselines.sh                # every test labelled "rendering"
#   scripts/regenerate-baselines.sh 'ShaderRepl'   # only tests whose name matches (ctest -R)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PHONGVTK_BUILD_DIR:-$here/build}"
"$here/scripts/build.sh"
cd "$build"
args=(-L rendering --output-on-failure)
if [ $# -gt 0 ]; then
  args+=(-R "$1")
fi
PHONGVTK_REGENERATE_BASELINES=1 /usr/bin/ctest "${args[@]}"
echo "phongvtk: baselines now in Testing/Data/Baseline (review before committing):"
git -C "$here" status --short -- Testing/Data/Baseline
