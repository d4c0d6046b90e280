"""Run by pvbatch: values that mean nothing are errors in the log naming the value, and leave
the previous value in place; nothing crashes."""
import sys

import phongvtk  # noqa: F401  (the filters' Python classes, for GetClientSideObject)

from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, Render, Show, Sphere)

LoadPlugin(sys.argv[1], remote=False, ns=globals())  # adds the plugin's proxies here
normals = PolygonNormals(Input=Sphere())
normals.Accuracy = "Compensated"
normals.UpdatePipeline()
normals.GetProperty("Accuracy").SetData(7)  # bypasses the Python-side enumeration check
normals.UpdatePipeline()
assert normals.GetClientSideObject().GetAccuracy() == 2
view = GetActiveViewOrCreate("RenderView")
display = Show(normals, view)
display.SetRepresentationType("Phong Surface")
display.SpecularPower = 40.0
display.SpecularPower = -5.0
display.Specular = float("nan")
display.GetProperty("Shading").SetData(9)
Render(view)
print("bad values handled")
