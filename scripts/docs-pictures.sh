#!/usr/bin/env bash
# Regenerates the pictures and tables of README.md and docs/ in docs/images/, after building
# (scripts/build.sh). Quote numbers from one run of this script; the machine should be idle.
#   demo.png, demo-tables.txt      the main job: build/bin/phongvtk demo (Sequential, as users call it)
#   trade-table.txt                build/bin/PhongVTKTradeTable: the extended normals ladder
#   python-speed.txt               phongvtk bench --speed: against VTK's filters, both backends
#   benchmark-normals.txt          scripts/bench-normals.sh cxx: the same in C++, both backends
#   normals-ladder.png, shading-error-vs-tessellation.png   phongvtk bench --plot-dir
#   paraview-presets.png           Testing/Plugin/pv_presets.py under pvbatch (ParaView flavour)
#   paraview-plugin.png            the ParaView client under Xvfb (ParaView flavour; installs
#                                  x11-apps and imagemagick for the screenshot when missing)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/build.sh" >&2
build="${PHONGVTK_BUILD_DIR:-$here/build}"
images="$here/docs/images"
mkdir -p "$images"
cd "$images"
say() { echo "docs-pictures: $*" >&2; }

say "the main job"
"$build/bin/phongvtk" demo -q -o demo.png | grep -v '^picture: ' >demo-tables.txt
say "the extended trade table"
"$build/bin/PhongVTKTradeTable" >trade-table.txt
say "speed from Python, both backends"
"$build/bin/phongvtk" bench --speed >python-speed.txt 2>/dev/null
say "the same in C++, both backends (a few minutes)"
PHONGVTK_BUILD_DIR="$build" "$here/scripts/bench-normals.sh" cxx >benchmark-normals.txt
say "plots"
"$build/bin/phongvtk" bench -q --plot-dir . >/dev/null

plugin="$( (ls "$build"/lib/paraview-*/plugins/PhongVTK/PhongVTK.so 2>/dev/null || true) | head -n 1)"
if [ -f "$plugin" ] && command -v pvbatch >/dev/null; then
  say "ParaView presets"
  env -u DISPLAY pvbatch "$here/Testing/Plugin/pv_presets.py" "$plugin" "$images/paraview-presets.png" 200 \
    >/dev/null
  rm -f "$images"/paraview-presets.png.*.png
  say "the ParaView client under Xvfb"
  missing=()
  command -v xwd >/dev/null || missing+=(x11-apps)
  dpkg-query -W -f='${Status}' imagemagick 2>/dev/null | grep -q "ok installed" || missing+=(imagemagick)
  if [ ${#missing[@]} -gt 0 ]; then
    sudo=(); [ "$(id -u)" -ne 0 ] && sudo=(sudo)
    "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
  fi
  "$here/scripts/paraview-screenshot.sh" "$plugin" "$images/paraview-plugin.png"
fi
ls -l "$images" >&2
