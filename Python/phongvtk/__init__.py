"""PhongVTK: polygon normals by the summed cross-product rule, Phong shading, headless rendering.

The wrapped C++ classes are importable from the package itself::

    from phongvtk import vtkPolygonNormals, vtkHeadlessOSMesaRenderWindow

Importing the package also makes ``vtkRenderWindow()`` headless when there is no X display
(see vtkHeadlessRenderWindow; environment variable PHONGVTK_HEADLESS=auto|osmesa|egl|off).
"""

from .vtkPhongVTKFilters import *  # noqa: F401,F403
from .vtkPhongVTKRendering import *  # noqa: F401,F403
