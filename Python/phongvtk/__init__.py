"""PhongVTK: polygon normals by the summed cross-product rule, Phong shading, headless rendering.

The wrapped C++ classes are importable from the package itself::

    from phongvtk import vtkPolygonNormals, vtkHeadlessOSMesaRenderWindow

Importing the package also makes ``vtkRenderWindow()`` headless when there is no X display
(see vtkHeadlessRenderWindow; environment variable PHONGVTK_HEADLESS=auto|osmesa|egl|off).

The command-line interface is ``python3 -m phongvtk`` (render, normals, area, bench, demo; see
phongvtk.cli).
"""

#: The version of PhongVTK (project(VERSION) in the top-level CMakeLists.txt).
__version__ = "0.1.0"

from ._build import RENDERING
from .vtkPhongVTKFilters import *  # noqa: F401,F403

if RENDERING:  # built against VTK 9.1/9.2 (PHONGVTK_BUILD_RENDERING)
    from .vtkPhongVTKRendering import *  # noqa: F401,F403
