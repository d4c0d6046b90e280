"""Run by pvbatch (or pvpython) with no X display: the plugin's Phong Surface representation
renders through PhongVTK's headless window and SaveScreenshot writes the image.

    pv_render.py PLUGIN OUTPUT.png
"""
import sys

from paraview.simple import LoadPlugin, Render, SaveScreenshot, Show, Sphere
from pv_scene import dark_render_view

LoadPlugin(sys.argv[1], remote=False, ns=globals())  # adds the plugin's proxies here
view = dark_render_view()
sphere = Sphere(ThetaResolution=24, PhiResolution=16, Radius=1.0)
normals = PolygonNormals(Input=sphere, ComputePointNormals=1, Accuracy="Exact")
display = Show(normals, view)
display.SetRepresentationType("Phong Surface")
display.Shading = "Phong"
display.MaterialPreset = "Plastic"
display.DiffuseColor = [0.2, 0.45, 0.9]
view.CameraPosition = [0.0, 0.0, 4.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
Render(view)
SaveScreenshot(sys.argv[2], view, ImageResolution=[240, 180])
print("rendered", sys.argv[2])
