#!/usr/bin/env bash
# A screenshot of the ParaView client (the GUI) with PhongVTK's plugin loaded, a sphere through
# Polygon Normals drawn as Phong Surface with the Plastic preset, on a private Xvfb server.
#   scripts/paraview-screenshot.sh PLUGIN OUTPUT.png
# Needs paraview, Xvfb, xwd (x11-apps) and ImageMagick's convert (scripts/docs-pictures.sh
# installs the last two).
set -euo pipefail
plugin=$1
output=$2
work=$(mktemp -d)
trap 'kill "${viewer:-}" "${server:-}" 2>/dev/null || true; rm -rf "$work"' EXIT
cat >"$work/scene.py" <<PY
from paraview.simple import *
LoadPlugin("$plugin", remote=False, ns=globals())
normals = PolygonNormals(Input=Sphere(ThetaResolution=48, PhiResolution=24), ComputePointNormals=1,
                         Accuracy="Exact")
display = Show(normals)
display.SetRepresentationType("Phong Surface")
display.MaterialPreset = "Plastic"
display.DiffuseColor = [0.2, 0.5, 1.0]
SetActiveSource(normals)
Render()
PY
Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"$work/display" &
server=$!
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
export DISPLAY=":$(cat "$work/display")"
paraview --script="$work/scene.py" >"$work/paraview.log" 2>&1 &
viewer=$!
sleep "${PHONGVTK_SCREENSHOT_WAIT:-25}"
xwd -root -silent >"$work/screen.xwd"
/usr/bin/convert "xwd:$work/screen.xwd" -trim +repage "$output"  # the black beyond the window
echo "wrote $output" >&2
