#!/usr/bin/env bash
# The main job, from a fresh clone: installs and builds what is missing (scripts/build.sh), then
# renders CGAL's bunny decimated to 2,000 triangles and whole, in flat, Gouraud and Phong shading,
# into phongvtk-demo.png in the current directory, and prints the normals ladder (speed and error
# of each accuracy mode against exact arithmetic) and the shading error against tessellation
# (against the exact sphere). Extra arguments go to `phongvtk demo` (see --help).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/build.sh" >&2
build="${PHONGVTK_BUILD_DIR:-$here/build}"
exec "$build/bin/phongvtk" demo "$@"
