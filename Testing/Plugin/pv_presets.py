"""Run by pvbatch with no X display: a sphere of colour (0.2, 0.5, 1.0) under ParaView's default
light kit, drawn by ParaView's Surface and by the plugin's Phong Surface with its default
(Custom) material and each preset, with SceneAmbient off and on. Prints, per panel, the fraction
of the sphere's pixels with a saturated (255) channel and the median of their brightest channel,
and writes all panels side by side into one picture: columns Surface, Phong Surface with Custom,
Plastic, Metal, Matte; the top row with SceneAmbient off, the bottom row with it on (Surface:
the same both times).

    pv_presets.py PLUGIN OUTPUT.png [SIZE]
"""
import json
import sys

import numpy as np
from paraview.simple import LoadPlugin, Render, SaveScreenshot, Show, Sphere
from pv_scene import dark_render_view
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter

plugin, output = sys.argv[1:3]
size = int(sys.argv[3]) if len(sys.argv) > 3 else 200
LoadPlugin(plugin, remote=False, ns=globals())
view = dark_render_view()
sphere = PolygonNormals(Input=Sphere(ThetaResolution=64, PhiResolution=32), ComputePointNormals=1)
display = Show(sphere, view)
display.DiffuseColor = [0.2, 0.5, 1.0]
display.AmbientColor = [0.2, 0.5, 1.0]
Render(view)  # the first render frames the data; the camera is set after it
view.CameraPosition = [0.0, 0.0, 2.4]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 30.0


def shot(name):
    Render(view)
    path = f"{output}.{name}.png"
    SaveScreenshot(path, view, ImageResolution=[size, size])
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3]


panels, measured = {}, {}
for ambient in (0, 1):
    configurations = [("Surface", "Surface", None)] + [
        (f"Phong Surface {preset}", "Phong Surface", preset)
        for preset in ("Custom", "Plastic", "Metal", "Matte")]
    for name, representation, preset in configurations:
        display.SetRepresentationType(representation)
        if preset is not None:
            display.MaterialPreset = preset
            display.SceneAmbient = ambient
        pixels = shot(f"{len(panels)}")
        background = np.all(pixels == pixels[0, 0], axis=-1)
        sphere_pixels = pixels[~background]
        key = f"{name}, SceneAmbient {'on' if ambient else 'off'}"
        measured[key] = {"clipped": float(np.mean(np.any(sphere_pixels == 255, axis=-1))),
                         "median": float(np.median(sphere_pixels.max(axis=-1)))}
        panels[key] = pixels

rows = [np.concatenate([panels[k] for k in panels if k.endswith(suffix)], axis=1)
        for suffix in ("off", "on")]
picture = np.ascontiguousarray(np.concatenate(rows[::-1], axis=0))  # VTK: bottom row first
image = vtkImageData()
image.SetDimensions(picture.shape[1], picture.shape[0], 1)
image.GetPointData().SetScalars(numpy_to_vtk(picture.reshape(-1, 3), deep=1))
writer = vtkPNGWriter()
writer.SetFileName(output)
writer.SetInputData(image)
writer.Write()
print("measured:", json.dumps(measured))
