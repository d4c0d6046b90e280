#include "PhongVTKHeadless.h"

#include "vtkObjectFactory.h" // for vtkGenericWarningMacro

#include <EGL/egl.h>
#include <GL/glx.h>
#include <GL/osmesa.h>
#include <X11/Xlib.h>

#include <dlfcn.h>

#include <atomic>
#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <thread>

namespace
{
// The part of libglvnd's GLdispatch.h (src/GLdispatch, not installed) that libGLX and libEGL use
// to make a vendor's dispatch table current, at its ABI version 1 (__glDispatchGetABIVersion).
extern "C"
{
  struct GLdispatchTable;
  using GLdispatchGetProcAddress = void* (*)(const char* name, void* param);
  struct GLdispatchThreadState
  {
    int Tag; // which window-system library owns the thread's current context
    void (*ThreadDestroyed)(GLdispatchThreadState*);
    void* Private; // libGLdispatch's own
  };
}
constexpr int GLdispatchTagGLX = 0;
constexpr int GLdispatchTagEGL = 1;
// Ours: neither libGLX nor libEGL takes an OSMesa thread state for its own.
constexpr int GLdispatchTagOSMesa = 0x4f534d41;

thread_local GLdispatchThreadState OSMesaThreadState = { GLdispatchTagOSMesa, nullptr, nullptr };

struct LibraryNames
{
  std::string OSMesa = "libOSMesa.so.8";
  std::string GLDispatch = "libGLdispatch.so.0";
  int RequiredDispatchABI = 1;
};
LibraryNames& Names()
{
  static LibraryNames names;
  return names;
}

std::string Lower(const char* text)
{
  std::string s(text);
  for (char& c : s)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return s;
}

template <typename F>
bool Resolve(void* library, const char* name, F& function, std::string& problem, const char* file)
{
  function = reinterpret_cast<F>(dlsym(library, name));
  if (!function && problem.empty())
  {
    problem = std::string(file) + " has no " + name;
  }
  return function != nullptr;
}
}

namespace phongvtk
{
namespace headless
{

struct OSMesaLibrary::Entry
{
  // libOSMesa
  osmesa_context* (*CreateContextAttribs)(const int*, osmesa_context*) = nullptr;
  unsigned char (*MakeCurrent)(osmesa_context*, void*, unsigned int, int, int) = nullptr;
  void (*DestroyContext)(osmesa_context*) = nullptr;
  osmesa_context* (*GetCurrentContext)() = nullptr;
  void (*(*GetProcAddress)(const char*))() = nullptr;
  // libGLdispatch
  int (*GetABIVersion)() = nullptr;
  void (*Init)() = nullptr;
  int (*NewVendorID)() = nullptr;
  GLdispatchTable* (*CreateTable)(GLdispatchGetProcAddress, void*) = nullptr;
  unsigned char (*DispatchMakeCurrent)(
    GLdispatchThreadState*, GLdispatchTable*, int, const void*) = nullptr;
  void (*LoseCurrent)() = nullptr;
  GLdispatchThreadState* (*GetCurrentThreadState)() = nullptr;

  GLdispatchTable* Table = nullptr;
  int VendorID = 0;

  static void* LookUp(const char* name, void* entry)
  {
    return reinterpret_cast<void*>(static_cast<Entry*>(entry)->GetProcAddress(name));
  }

  std::string Load()
  {
    const LibraryNames& names = Names();
    void* osmesa = dlopen(names.OSMesa.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!osmesa)
    {
      return "cannot load " + names.OSMesa + " (" + dlerror() + "; Debian package libosmesa6)";
    }
    std::string problem;
    const char* file = names.OSMesa.c_str();
    Resolve(osmesa, "OSMesaCreateContextAttribs", this->CreateContextAttribs, problem, file);
    Resolve(osmesa, "OSMesaMakeCurrent", this->MakeCurrent, problem, file);
    Resolve(osmesa, "OSMesaDestroyContext", this->DestroyContext, problem, file);
    Resolve(osmesa, "OSMesaGetCurrentContext", this->GetCurrentContext, problem, file);
    Resolve(osmesa, "OSMesaGetProcAddress", this->GetProcAddress, problem, file);
    if (!problem.empty())
    {
      return problem;
    }

    // glvnd's libGL (which VTK's GLEW links) has already loaded it: this is the same instance.
    void* dispatch = dlopen(names.GLDispatch.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!dispatch)
    {
      return "cannot load glvnd's " + names.GLDispatch + " (" + dlerror() + ")";
    }
    file = names.GLDispatch.c_str();
    if (!Resolve(dispatch, "__glDispatchGetABIVersion", this->GetABIVersion, problem, file))
    {
      return problem;
    }
    const int abi = this->GetABIVersion();
    if (abi != names.RequiredDispatchABI)
    {
      return "glvnd's " + names.GLDispatch + " has dispatch ABI version " + std::to_string(abi) +
        "; PhongVTK carries OSMesa into version " + std::to_string(names.RequiredDispatchABI) +
        " only";
    }
    Resolve(dispatch, "__glDispatchInit", this->Init, problem, file);
    Resolve(dispatch, "__glDispatchNewVendorID", this->NewVendorID, problem, file);
    Resolve(dispatch, "__glDispatchCreateTable", this->CreateTable, problem, file);
    Resolve(dispatch, "__glDispatchMakeCurrent", this->DispatchMakeCurrent, problem, file);
    Resolve(dispatch, "__glDispatchLoseCurrent", this->LoseCurrent, problem, file);
    Resolve(
      dispatch, "__glDispatchGetCurrentThreadState", this->GetCurrentThreadState, problem, file);
    if (!problem.empty())
    {
      return problem;
    }
    this->Init();
    this->VendorID = this->NewVendorID();
    // OSMesaGetProcAddress hands out Mesa's own dispatch stubs, which follow whichever OSMesa
    // context is current: one table serves every OSMesa context of the process.
    this->Table = this->CreateTable(&Entry::LookUp, this);
    if (!this->Table)
    {
      return "libGLdispatch could not create a dispatch table for OSMesa";
    }
    return std::string();
  }
};

//------------------------------------------------------------------------------
Request ParseRequest(const char* value, std::string* invalid)
{
  if (!value || !*value)
  {
    return Request::Auto;
  }
  const std::string v = Lower(value);
  if (v == "auto")
  {
    return Request::Auto;
  }
  if (v == "osmesa")
  {
    return Request::OSMesa;
  }
  if (v == "egl")
  {
    return Request::EGL;
  }
  if (v == "off")
  {
    return Request::Off;
  }
  if (invalid)
  {
    *invalid = std::string("PHONGVTK_HEADLESS='") + value +
      "' is not one of auto, osmesa, egl, off: using auto";
  }
  return Request::Auto;
}

//------------------------------------------------------------------------------
Choice ChooseWindow(Request request, bool xDisplayAvailable, const std::string& osmesaProblem)
{
  Choice choice;
  switch (request)
  {
    case Request::Off:
      choice.Kind = Window::VTKDefault;
      break;
    case Request::EGL:
      choice.Kind = Window::EGL;
      break;
    case Request::Auto:
      if (xDisplayAvailable)
      {
        choice.Kind = Window::VTKDefault;
        break;
      }
      // no display: as for OSMesa
      VTK_FALLTHROUGH;
    case Request::OSMesa:
      if (osmesaProblem.empty())
      {
        choice.Kind = Window::OSMesa;
      }
      else
      {
        choice.Kind = Window::EGL;
        choice.Warning = "PhongVTK: OSMesa cannot be used: " + osmesaProblem +
          ". Rendering headless through EGL (surfaceless Mesa) instead.";
      }
      break;
  }
  return choice;
}

//------------------------------------------------------------------------------
Choice ChooseWindowFromEnvironment()
{
  std::string invalid;
  const Request request = ParseRequest(std::getenv("PHONGVTK_HEADLESS"), &invalid);
  if (!invalid.empty())
  {
    WarnOnce(invalid);
  }
  const bool display = request == Request::Auto && XDisplayAvailable();
  std::string osmesaProblem;
  if (!display && (request == Request::Auto || request == Request::OSMesa))
  {
    OSMesaLibrary::Get(&osmesaProblem);
  }
  return ChooseWindow(request, display, osmesaProblem);
}

//------------------------------------------------------------------------------
bool XDisplayAvailable()
{
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name)
  {
    return false;
  }
  static std::mutex mutex;
  static std::string probed;
  static bool available = false;
  std::lock_guard<std::mutex> lock(mutex);
  if (probed != name)
  {
    // A DISPLAY left over from a session that is gone is common on build machines: only a
    // server that accepts a connection counts.
    Display* display = XOpenDisplay(name);
    available = display != nullptr;
    if (display)
    {
      XCloseDisplay(display);
    }
    probed = name;
  }
  return available;
}

//------------------------------------------------------------------------------
void ReleaseThreadContext()
{
  if (const OSMesaLibrary* osmesa = OSMesaLibrary::IfLoaded())
  {
    osmesa->Unbind();
  }
  // libEGL and libGLX answer only for a context they made current themselves.
  if (eglGetCurrentContext() != EGL_NO_CONTEXT)
  {
    eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (glXGetCurrentContext())
  {
    glXMakeCurrent(glXGetCurrentDisplay(), None, nullptr);
  }
}

//------------------------------------------------------------------------------
void WarnOnce(const std::string& message)
{
  static std::mutex mutex;
  static std::set<std::string> said;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (!said.insert(message).second)
    {
      return;
    }
  }
  vtkGenericWarningMacro(<< message);
}

//------------------------------------------------------------------------------
namespace
{
std::atomic<const OSMesaLibrary*> LoadedLibrary{ nullptr };
}

//------------------------------------------------------------------------------
const OSMesaLibrary* OSMesaLibrary::IfLoaded()
{
  return LoadedLibrary.load();
}

//------------------------------------------------------------------------------
const OSMesaLibrary* OSMesaLibrary::Get(std::string* problem)
{
  static std::once_flag once;
  static Entry entry;
  static std::string loadProblem;
  static OSMesaLibrary library;
  std::call_once(once,
    []
    {
      loadProblem = entry.Load();
      library.E = &entry;
      if (loadProblem.empty())
      {
        LoadedLibrary.store(&library);
      }
    });
  if (!loadProblem.empty())
  {
    if (problem)
    {
      *problem = loadProblem;
    }
    return nullptr;
  }
  return &library;
}

//------------------------------------------------------------------------------
osmesa_context* OSMesaLibrary::CreateContext(std::string* problem) const
{
  // VTK needs OpenGL 3.2 core; llvmpipe gives the highest core version it has.
  static const int attributes[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
    OSMESA_STENCIL_BITS, 0, OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
    OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 2, 0 };
  osmesa_context* context = this->E->CreateContextAttribs(attributes, nullptr);
  if (!context && problem)
  {
    *problem = "OSMesaCreateContextAttribs could not create an OpenGL 3.2 core context";
  }
  if (context)
  {
    WatchForTheEnd();
  }
  return context;
}

//------------------------------------------------------------------------------
namespace
{
// Which thread has each OSMesa context current. Mesa keeps a pointer to a thread's current
// context: destroying it while it is current on another thread would leave that thread pointing
// at freed memory (its next OpenGL or OSMesa call crashes). Such a context is orphaned instead
// and destroyed when its thread releases it (next MakeCurrent, ReleaseCurrent or thread end).
struct Bindings
{
  std::mutex Mutex;
  std::map<osmesa_context*, std::thread::id> BoundOn;
  std::set<osmesa_context*> Orphans;
  // Each context's window-system framebuffer: 1 x 1 RGBA, never drawn into (VTK renders into
  // framebuffer objects), yet written when a context is released. It lives as long as the
  // context, which may outlive its window (an orphan).
  std::map<osmesa_context*, std::unique_ptr<unsigned char[]>> ClientBuffers;
};

// Made once and never destroyed: a window may be destroyed after this library's statics are
// (see ProcessEnding). As a static object, pvbatch's sys.exit() freed ClientBuffers' nodes twice.
Bindings& TheBindings()
{
  static Bindings* bindings = new Bindings;
  return *bindings;
}

void DestroyNow(void (*destroy)(osmesa_context*), osmesa_context* context)
{
  destroy(context);
  Bindings& b = TheBindings();
  std::lock_guard<std::mutex> lock(b.Mutex);
  b.ClientBuffers.erase(context);
}
}

//------------------------------------------------------------------------------
void OSMesaLibrary::DestroyContext(osmesa_context* context) const
{
  if (!context)
  {
    return;
  }
  {
    Bindings& b = TheBindings();
    std::lock_guard<std::mutex> lock(b.Mutex);
    auto it = b.BoundOn.find(context);
    if (it != b.BoundOn.end() && it->second != std::this_thread::get_id())
    {
      b.Orphans.insert(context);
      return;
    }
  }
  if (this->E->GetCurrentContext() == context)
  {
    this->Unbind();
  }
  DestroyNow(this->E->DestroyContext, context);
}

//------------------------------------------------------------------------------
bool OSMesaLibrary::Bind(osmesa_context* context, std::string* problem) const
{
  GLdispatchThreadState* current = this->E->GetCurrentThreadState();
  if (current && current != &OSMesaThreadState)
  {
    *problem = std::string("another OpenGL context (") +
      (current->Tag == GLdispatchTagGLX      ? "GLX"
          : current->Tag == GLdispatchTagEGL ? "EGL"
                                             : "unknown API") +
      ") is current on this thread";
    return false;
  }
  void* buffer = nullptr;
  Bindings& b = TheBindings();
  {
    std::lock_guard<std::mutex> lock(b.Mutex);
    auto it = b.BoundOn.find(context);
    if (it != b.BoundOn.end() && it->second != std::this_thread::get_id())
    {
      *problem = "the context is current on another thread (ReleaseCurrent it there first)";
      return false;
    }
    std::unique_ptr<unsigned char[]>& pixel = b.ClientBuffers[context];
    if (!pixel)
    {
      pixel.reset(new unsigned char[4]());
    }
    buffer = pixel.get();
  }
  osmesa_context* previous = this->E->GetCurrentContext();
  if (!this->E->MakeCurrent(context, buffer, GL_UNSIGNED_BYTE, 1, 1))
  {
    *problem = "OSMesaMakeCurrent failed";
    return false;
  }
  {
    std::lock_guard<std::mutex> lock(b.Mutex);
    if (previous && previous != context)
    {
      b.BoundOn.erase(previous);
    }
    b.BoundOn[context] = std::this_thread::get_id();
  }
  if (!current &&
    !this->E->DispatchMakeCurrent(&OSMesaThreadState, this->E->Table, this->E->VendorID, nullptr))
  {
    this->E->MakeCurrent(nullptr, nullptr, 0, 0, 0);
    *problem = "libGLdispatch refused to make OSMesa's dispatch table current";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void OSMesaLibrary::Unbind() const
{
  if (osmesa_context* current = this->E->GetCurrentContext())
  {
    this->E->MakeCurrent(nullptr, nullptr, 0, 0, 0);
    bool orphan = false;
    {
      Bindings& b = TheBindings();
      std::lock_guard<std::mutex> lock(b.Mutex);
      b.BoundOn.erase(current);
      orphan = b.Orphans.erase(current) > 0;
    }
    if (orphan)
    {
      DestroyNow(this->E->DestroyContext, current);
    }
  }
  if (this->OwnsThreadDispatch())
  {
    this->E->LoseCurrent();
  }
}

//------------------------------------------------------------------------------
bool OSMesaLibrary::IsBound(osmesa_context* context) const
{
  return context && this->E->GetCurrentContext() == context && this->OwnsThreadDispatch();
}

//------------------------------------------------------------------------------
bool OSMesaLibrary::OwnsThreadDispatch() const
{
  return this->E->GetCurrentThreadState() == &OSMesaThreadState;
}

//------------------------------------------------------------------------------
namespace
{
std::atomic<bool> Ending{ false };

void MarkEnding()
{
  Ending.store(true);
  if (const OSMesaLibrary* library = LoadedLibrary.load())
  {
    library->LoseDispatchIfOwned();
  }
}

// Its destructor runs with this library's other static objects, before the static objects of
// the libraries loaded before this one (ParaView's process module, which destroys the views and
// their windows). From then on the headless windows make no GL or window-system call, and the
// thread's GL dispatch (libGLdispatch, still alive) no longer points into libOSMesa.
struct EndWatch
{
  ~EndWatch() { MarkEnding(); }
} TheEndWatch;
}

//------------------------------------------------------------------------------
void WatchForTheEnd()
{
  // Exit handlers run in the reverse order of their registration: registered once the first
  // context exists (after Mesa registered its own), this one runs before Mesa's, so that a
  // window kept in a static object made between this library's loading and the first context
  // (a static of the program, a function-local static) is not torn down by GL calls into a
  // finalised Mesa.
  static std::once_flag once;
  std::call_once(once, [] { std::atexit(MarkEnding); });
}

//------------------------------------------------------------------------------
bool ProcessEnding()
{
  return Ending.load();
}

//------------------------------------------------------------------------------
void OSMesaLibrary::LoseDispatchIfOwned() const
{
  if (this->OwnsThreadDispatch())
  {
    this->E->LoseCurrent();
  }
}

//------------------------------------------------------------------------------
void SetOSMesaLibrariesForTesting(
  const char* osmesa, const char* glDispatch, int requiredDispatchABI)
{
  LibraryNames& names = Names();
  names.OSMesa = osmesa;
  names.GLDispatch = glDispatch;
  names.RequiredDispatchABI = requiredDispatchABI;
}

}
}
