#include "vtkHeadlessEGLRenderWindow.h"

#include "PhongVTKHeadless.h"

#include "vtkObjectFactory.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <mutex>
#include <sstream>

vtkStandardNewMacro(vtkHeadlessEGLRenderWindow);

namespace
{
struct SurfacelessDisplay
{
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLConfig Config = nullptr; // null: EGL_KHR_no_config_context
  std::string Problem;
};

std::string EGLError(const char* call)
{
  std::ostringstream message;
  message << call << " failed (EGL error 0x" << std::hex << eglGetError() << ")";
  return message.str();
}

bool HasExtension(const char* extensions, const std::string& name)
{
  std::istringstream words(extensions ? extensions : "");
  std::string word;
  while (words >> word)
  {
    if (word == name)
    {
      return true;
    }
  }
  return false;
}

// One display for the process, initialised once and never terminated: eglTerminate would pull
// the display from under every other window.
const SurfacelessDisplay& Surfaceless()
{
  static SurfacelessDisplay surfaceless;
  static std::once_flag once;
  std::call_once(once,
    []
    {
      SurfacelessDisplay& s = surfaceless;
      const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
      if (!HasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
      {
        s.Problem = "EGL has no EGL_MESA_platform_surfaceless (Debian package libegl-mesa0)";
        return;
      }
      s.Display =
        eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (s.Display == EGL_NO_DISPLAY)
      {
        s.Problem = EGLError("eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA)");
        return;
      }
      EGLint major = 0;
      EGLint minor = 0;
      if (!eglInitialize(s.Display, &major, &minor))
      {
        s.Problem = EGLError("eglInitialize");
        s.Display = EGL_NO_DISPLAY;
        return;
      }
      const char* extensions = eglQueryString(s.Display, EGL_EXTENSIONS);
      if (!HasExtension(extensions, "EGL_KHR_surfaceless_context"))
      {
        s.Problem = "the EGL display has no EGL_KHR_surfaceless_context";
        return;
      }
      if (!HasExtension(extensions, "EGL_KHR_no_config_context"))
      {
        const EGLint attributes[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
        EGLint count = 0;
        if (!eglChooseConfig(s.Display, attributes, &s.Config, 1, &count) || count < 1)
        {
          s.Problem = "no EGL configuration renders desktop OpenGL";
        }
      }
    });
  return surfaceless;
}
}

//------------------------------------------------------------------------------
vtkHeadlessEGLRenderWindow::vtkHeadlessEGLRenderWindow() = default;

//------------------------------------------------------------------------------
vtkHeadlessEGLRenderWindow::~vtkHeadlessEGLRenderWindow()
{
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLRenderWindow::IsAvailable(std::string* why)
{
  const SurfacelessDisplay& surfaceless = Surfaceless();
  if (!surfaceless.Problem.empty() && why)
  {
    *why = surfaceless.Problem;
  }
  return surfaceless.Problem.empty();
}

//------------------------------------------------------------------------------
void* vtkHeadlessEGLRenderWindow::GetGenericDisplayId()
{
  return this->Context ? Surfaceless().Display : nullptr;
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLRenderWindow::CreateContext(std::string& problem)
{
  const SurfacelessDisplay& surfaceless = Surfaceless();
  if (!surfaceless.Problem.empty())
  {
    problem = surfaceless.Problem;
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API))
  {
    problem = EGLError("eglBindAPI(EGL_OPENGL_API)");
    return false;
  }
  // VTK needs OpenGL 3.2 core; llvmpipe gives the highest core version it has.
  const EGLint attributes[] = { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2,
    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
  EGLContext context =
    eglCreateContext(surfaceless.Display, surfaceless.Config, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT)
  {
    problem = EGLError("eglCreateContext (OpenGL 3.2 core)");
    return false;
  }
  this->Context = context;
  phongvtk::headless::WatchForTheEnd();
  return true;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::DestroyContext()
{
  if (this->Context)
  {
    if (this->IsContextBound())
    {
      this->UnbindContext();
    }
    eglDestroyContext(Surfaceless().Display, this->Context);
    this->Context = nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLRenderWindow::BindContext(std::string& problem)
{
  if (!eglMakeCurrent(Surfaceless().Display, EGL_NO_SURFACE, EGL_NO_SURFACE, this->Context))
  {
    problem = EGLError("eglMakeCurrent (surfaceless)");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::UnbindContext()
{
  eglMakeCurrent(Surfaceless().Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLRenderWindow::IsContextBound()
{
  return this->Context && eglGetCurrentContext() == this->Context;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: " << this->Context << "\n";
  os << indent << "Display: " << this->GetGenericDisplayId() << "\n";
}
