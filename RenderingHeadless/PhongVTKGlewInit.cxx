// VTK's vtkOpenGLRenderWindow::OpenGLInitContext() calls glewInit(), which with Debian's GLEW (a
// GLX build) loads every OpenGL entry point and then fails with GLEW_ERROR_NO_GLX_DISPLAY when the
// current context is not a GLX one. PhongVTK's own windows accept that answer (vtkHeadlessRender-
// Window::OpenGLInitContext), but windows of other classes that share a headless context cannot:
// ParaView's pvbatch renders every view in such a window, which then never counts as initialised
// and logs "GLEW could not be initialized" at every frame. The fix belongs in VTK (glewContextInit
// for non-GLX contexts); until then PhongVTK routes VTK's call to glewInit() through a function
// that gives that answer the meaning VTK needs when a PhongVTK headless context is current, by
// rewriting the one import slot of glewInit in VTK's OpenGL library (PhongVTKImportSlots.h).
// Nothing else is touched: any other result, any other context, any other caller sees GLEW's own
// answer.
#include "PhongVTKHeadless.h"
#include "PhongVTKImportSlots.h"

#include "vtk_glew.h"

#include <EGL/egl.h>

#include <dlfcn.h>

#include <mutex>

namespace
{
using GlewInitFunction = GLenum (*)();
GlewInitFunction GlewInit = nullptr; // GLEW's own glewInit

GLenum GlewInitAcceptingHeadlessContexts()
{
  const GLenum result = GlewInit();
#ifdef GLEW_ERROR_NO_GLX_DISPLAY
  if (result == GLEW_ERROR_NO_GLX_DISPLAY && phongvtk::headless::HeadlessContextIsCurrent())
  {
    return GLEW_OK; // every entry point is loaded; only the GLX extension query was skipped
  }
#endif
  return result;
}

}

namespace phongvtk
{
namespace headless
{

//------------------------------------------------------------------------------
bool HeadlessContextIsCurrent()
{
  const OSMesaLibrary* osmesa = OSMesaLibrary::IfLoaded();
  return (osmesa && osmesa->OwnsThreadDispatch()) || eglGetCurrentContext() != EGL_NO_CONTEXT;
}

//------------------------------------------------------------------------------
bool RouteVTKGlewInit(std::string* problem)
{
  static std::once_flag once;
  static int slots = 0;
  static std::string why;
  std::call_once(once,
    []
    {
      GlewInit = reinterpret_cast<GlewInitFunction>(dlsym(RTLD_DEFAULT, "glewInit"));
      if (!GlewInit)
      {
        why = "glewInit is not loaded";
        return;
      }
      slots = phongvtk::RouteImport("libvtkRenderingOpenGL2", "glewInit",
        reinterpret_cast<void*>(&GlewInitAcceptingHeadlessContexts), &why);
    });
  if (problem)
  {
    *problem = why;
  }
  return slots > 0;
}

}
}
