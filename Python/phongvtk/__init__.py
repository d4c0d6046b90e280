"""PhongVTK: polygon normals by the summed cross-product rule, Phong shading, headless rendering.

The wrapped C++ classes are importable from the package itself::

    from phongvtk import vtkPolygonNormals, vtkHeadlessOSMesaRenderWindow

On VTK before 9.4, importing the package also makes ``vtkRenderWindow()`` headless when there
is no X display (PhongVTK::RenderingHeadless, see vtkHeadlessRenderWindow; environment variable
PHONGVTK_HEADLESS=auto|osmesa|egl|off). VTK 9.4 and later choose their own OSMesa or EGL window.

With PyVista 0.48 or later, ``mesh.phong`` gives PhongVTK's normals, visible area and mapper on a
``pyvista.PolyData`` (see phongvtk.pyvista_accessor).

The command-line interface is ``python3 -m phongvtk`` (render, normals, area, bench, demo; see
phongvtk.cli).
"""

#: The version of PhongVTK (project(VERSION) in the top-level CMakeLists.txt).
__version__ = "0.1.0"

from ._build import HEADLESS, RENDERING
from .vtkPhongVTKFilters import *  # noqa: F401,F403

if RENDERING:  # PHONGVTK_BUILD_RENDERING
    from .vtkPhongVTKRendering import *  # noqa: F401,F403
if HEADLESS:  # PHONGVTK_BUILD_HEADLESS: Linux, VTK before 9.4
    from .vtkPhongVTKRenderingHeadless import *  # noqa: F401,F403

import sys as _sys

# PyVista already imported: the accessor now. Else PyVista imports it at the first `mesh.phong`
# (the entry point in phongvtk's dist-info), and importing phongvtk does not cost PyVista's import.
if "pyvista" in _sys.modules:
    try:
        from . import pyvista_accessor  # noqa: F401
    except (ImportError, AttributeError):  # PyVista before 0.48 has no dataset accessors
        pass
