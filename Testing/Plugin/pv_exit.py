"""Run by pvbatch or pvpython with no X display: loads the plugin, renders a Phong Surface
through PhongVTK's headless window, then leaves as ENDING says, with the view still alive.

    pv_exit.py PLUGIN ENDING      (ENDING: end, exit0, exit3, raise)
"""
import sys

from paraview.simple import LoadPlugin, Render, Show, Sphere
from pv_scene import dark_render_view

LoadPlugin(sys.argv[1], remote=False, ns=globals())  # adds the plugin's proxies here
view = dark_render_view()
display = Show(PolygonNormals(Input=Sphere(), ComputePointNormals=1), view)
display.SetRepresentationType("Phong Surface")
Render(view)
ending = sys.argv[2]
print("rendered; leaving by", ending, flush=True)
if ending == "exit0":
    sys.exit(0)
if ending == "exit3":
    sys.exit(3)
if ending == "raise":
    raise RuntimeError("a batch script failing")
