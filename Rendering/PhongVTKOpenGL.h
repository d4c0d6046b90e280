// OpenGL's declarations as the VTK in use loads GL: through GLEW up to VTK 9.3 (vtk_glew.h,
// module VTK::glew), through glad from 9.4 (vtk_glad.h, VTK::glad). Include it before any other
// OpenGL header. Private to PhongVTK::Rendering.
#ifndef PhongVTKOpenGL_h
#define PhongVTKOpenGL_h

#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#endif
// VTK-HeaderTest-Exclude: PhongVTKOpenGL.h
