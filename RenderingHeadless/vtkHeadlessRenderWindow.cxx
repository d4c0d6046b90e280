#include "vtk_glew.h" // before any other OpenGL header

#include "vtkHeadlessRenderWindow.h"

#include "PhongVTKHeadless.h"
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessOSMesaRenderWindow.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkObjectFactoryCollection.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <cstdint>
#include <dlfcn.h>
#include <mutex>
#include <string>
#include <unordered_map>

namespace
{
// The headless window whose context this thread made current last (for PushContext): plain
// values, no destructor. exit() destroys the thread_local objects of the thread that calls it
// before the static ones, and a window kept in a static object makes its context current again
// when it is destroyed: a thread_local vtkWeakPointer was then used after its destruction (VTK
// 9.1's corrupted the heap). A window may be deleted anywhere, on any thread: the record names
// a window only while the window of that serial number is alive (Alive). No weak pointer is
// taken to a window either: VTK clears an object's weak pointers when its count drops to zero,
// before its destructors run (which make the context current to release resources), and one
// taken then was freed twice by VTK 9.1.
struct CurrentRecord
{
  vtkHeadlessRenderWindow* Window;
  std::uint64_t Serial;
};
thread_local CurrentRecord CurrentOnThread = { nullptr, 0 };

// The live headless windows and their serial numbers. Never destroyed: windows in static
// objects outlive every static object made after them.
struct LiveWindows
{
  std::mutex Mutex;
  std::unordered_map<const vtkHeadlessRenderWindow*, std::uint64_t> Serials;
  std::uint64_t Next = 0;
};
LiveWindows& Live()
{
  static LiveWindows* live = new LiveWindows;
  return *live;
}

// `window` while the window of that serial number lives, else null.
vtkHeadlessRenderWindow* Alive(vtkHeadlessRenderWindow* window, std::uint64_t serial)
{
  LiveWindows& live = Live();
  std::lock_guard<std::mutex> lock(live.Mutex);
  const auto found = live.Serials.find(window);
  return found != live.Serials.end() && found->second == serial ? window : nullptr;
}

// A thread that ends with a context current would keep it bound forever (EGL contexts stay
// current to a dead thread): release it when a thread that bound one ends.
struct ThreadContextGuard
{
  bool Bound = false;
  ~ThreadContextGuard()
  {
    if (this->Bound)
    {
      phongvtk::headless::ReleaseThreadContext();
    }
  }
};
thread_local ThreadContextGuard ThreadGuard;

using phongvtk::headless::Window;

vtkHeadlessRenderWindow* NewHeadless(Window kind)
{
  if (kind == Window::EGL)
  {
    return vtkHeadlessEGLRenderWindow::New();
  }
  return vtkHeadlessOSMesaRenderWindow::New();
}

/// The environment's choice, its warning said once.
Window ChosenWindow()
{
  const phongvtk::headless::Choice choice = phongvtk::headless::ChooseWindowFromEnvironment();
  if (!choice.Warning.empty())
  {
    phongvtk::headless::WarnOnce(choice.Warning);
  }
  return choice.Kind;
}

// The interactor of a headless window: VTK's base interactor, which needs no display and whose
// event loop returns at once (there are no events to wait for). VTK's X interactor would
// dereference a missing X display in Initialize() (ParaView's pvpython initialises one per view).
class vtkHeadlessRenderWindowInteractor : public vtkRenderWindowInteractor
{
public:
  static vtkHeadlessRenderWindowInteractor* New()
  {
    auto* interactor = new vtkHeadlessRenderWindowInteractor;
    interactor->InitializeObjectBase();
    return interactor;
  }
  vtkTypeMacro(vtkHeadlessRenderWindowInteractor, vtkRenderWindowInteractor);

protected:
  vtkHeadlessRenderWindowInteractor() = default;
  ~vtkHeadlessRenderWindowInteractor() override = default;

private:
  vtkHeadlessRenderWindowInteractor(const vtkHeadlessRenderWindowInteractor&) = delete;
  void operator=(const vtkHeadlessRenderWindowInteractor&) = delete;
};

// The overrides decline (nullptr) when the environment chooses VTK's own window: vtkObjectFactory
// then asks the factories after this one, and VTK's own answer is what the process would have
// had without PhongVTK.
vtkObject* CreateInteractor()
{
  if (ChosenWindow() == Window::VTKDefault)
  {
    return nullptr;
  }
  return vtkHeadlessRenderWindowInteractor::New();
}

// The override of vtkRenderWindow: a headless window when the environment asks for one.
vtkObject* CreateRenderWindow()
{
  const Window kind = ChosenWindow();
  if (kind == Window::VTKDefault)
  {
    return nullptr;
  }
  return NewHeadless(kind);
}

class vtkHeadlessRenderWindowFactory : public vtkObjectFactory
{
public:
  static vtkHeadlessRenderWindowFactory* New()
  {
    auto* factory = new vtkHeadlessRenderWindowFactory;
    factory->InitializeObjectBase();
    return factory;
  }
  vtkTypeMacro(vtkHeadlessRenderWindowFactory, vtkObjectFactory);
  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override
  {
    return "PhongVTK: headless OpenGL render windows (OSMesa, EGL) when there is no X display";
  }

protected:
  vtkHeadlessRenderWindowFactory()
  {
    this->RegisterOverride("vtkRenderWindow", "vtkHeadlessRenderWindow",
      "headless render window (PHONGVTK_HEADLESS=auto|osmesa|egl|off)", 1, &CreateRenderWindow);
    this->RegisterOverride("vtkRenderWindowInteractor", "vtkHeadlessRenderWindowInteractor",
      "display-free interactor of a headless render window", 1, &CreateInteractor);
  }

private:
  vtkHeadlessRenderWindowFactory(const vtkHeadlessRenderWindowFactory&) = delete;
  void operator=(const vtkHeadlessRenderWindowFactory&) = delete;
};

// The override exists in every process that loads the module: C++ programs (with
// vtk_module_autoinit, which also keeps the library linked under --as-needed, or linking it
// otherwise), Python after `import phongvtk`, ParaView after loading the plugin. It decides
// nothing when it is installed (no probing at load time): the choice is made at each
// vtkRenderWindow::New().
void InstallFactory()
{
  static std::once_flag once;
  std::call_once(once,
    []
    {
      // vtkObjectFactory asks the registered factories in order and takes the first object, and
      // RegisterFactory appends: VTK's RenderingOpenGL2 factory, usually registered first,
      // would always make the X window. This factory is moved to the front of the registry
      // instead; every other factory keeps its place, its overrides and their enable flags.
      vtkHeadlessRenderWindowFactory* factory = vtkHeadlessRenderWindowFactory::New();
      vtkObjectFactory::RegisterFactory(factory); // also creates the registry if needed
      vtkObjectFactoryCollection* registry = vtkObjectFactory::GetRegisteredFactories();
      if (registry->GetNumberOfItems() > 1)
      {
        registry->RemoveItem(factory); // the collection's reference; ours keeps it alive
        registry->InsertItem(-1, factory);
      }
      factory->Delete();
      // The registry now holds an object of this library: the library must stay loaded. Plugin
      // loaders dlopen and dlclose libraries freely (ParaView's tries every library in
      // PV_PLUGIN_PATH, plugin or not), which would leave the registry with a dangling factory.
      Dl_info self;
      if (dladdr(reinterpret_cast<void*>(&InstallFactory), &self) && self.dli_fname)
      {
        dlopen(self.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE); // never closed
      }
    });
}

struct FactoryInstaller
{
  FactoryInstaller() { InstallFactory(); }
};
const FactoryInstaller Installer;
}

// VTK's module autoinit (the module IMPLEMENTS VTK::RenderingCore).
VTKPHONGVTKRENDERINGHEADLESS_EXPORT void vtkPhongVTKRenderingHeadless_AutoInit_Construct()
{
  InstallFactory();
}

//------------------------------------------------------------------------------
vtkHeadlessRenderWindow* vtkHeadlessRenderWindow::New()
{
  std::string invalid;
  phongvtk::headless::Request request =
    phongvtk::headless::ParseRequest(std::getenv("PHONGVTK_HEADLESS"), &invalid);
  if (!invalid.empty())
  {
    phongvtk::headless::WarnOnce(invalid);
  }
  if (request == phongvtk::headless::Request::Off)
  {
    request = phongvtk::headless::Request::Auto; // asked for by name: headless in any case
  }
  std::string osmesaProblem;
  if (request != phongvtk::headless::Request::EGL)
  {
    phongvtk::headless::OSMesaLibrary::Get(&osmesaProblem);
  }
  const phongvtk::headless::Choice choice =
    phongvtk::headless::ChooseWindow(request, false, osmesaProblem);
  if (!choice.Warning.empty())
  {
    phongvtk::headless::WarnOnce(choice.Warning);
  }
  return NewHeadless(choice.Kind);
}

//------------------------------------------------------------------------------
vtkHeadlessRenderWindow::vtkHeadlessRenderWindow()
{
  this->ShowWindow = false;
  this->UseOffScreenBuffers = true;
  // Reproducible images: the same scene gives the same pixels on every run and backend.
  this->MultiSamples = 0;
  this->ScreenSize[0] = this->ScreenSize[1] = 0;
  LiveWindows& live = Live();
  std::lock_guard<std::mutex> lock(live.Mutex);
  this->Serial = ++live.Next;
  live.Serials[this] = this->Serial;
}

//------------------------------------------------------------------------------
vtkHeadlessRenderWindow::~vtkHeadlessRenderWindow()
{
  // The backend's destructor has destroyed the context (Finalize): renderers only let go.
  vtkCollectionSimpleIterator it;
  this->Renderers->InitTraversal(it);
  while (vtkRenderer* renderer = this->Renderers->GetNextRenderer(it))
  {
    renderer->SetRenderWindow(nullptr);
  }
  LiveWindows& live = Live();
  std::lock_guard<std::mutex> lock(live.Mutex);
  live.Serials.erase(this);
}

//------------------------------------------------------------------------------
bool vtkHeadlessRenderWindow::EnsureContext()
{
  if (!this->Initialized || !this->HasContext())
  {
    this->Initialize();
  }
  return this->Initialized && this->HasContext();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::ReportContextProblem(const std::string& problem)
{
  // A scene renders many times: say each distinct problem once, not once a frame.
  if (problem != this->ContextProblem)
  {
    this->ContextProblem = problem;
    vtkErrorMacro(<< this->GetBackendName() << " render window: " << problem);
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Initialize()
{
  if (!this->HasContext())
  {
    std::string problem;
    if (!this->CreateContext(problem))
    {
      this->ReportContextProblem("no OpenGL context: " + problem);
      return;
    }
    this->RebindPending = true;
    // Windows of other classes may share this context (ParaView's per-view windows do).
    std::string routeProblem;
    if (!phongvtk::headless::RouteVTKGlewInit(&routeProblem))
    {
      phongvtk::headless::WarnOnce(
        "Windows sharing a headless context will report GLEW errors: " + routeProblem);
    }
  }
  if (!this->Initialized)
  {
    this->MakeCurrent();
    if (!this->IsCurrent())
    {
      return; // MakeCurrent said why
    }
    this->OpenGLInit();
    if (this->Initialized)
    {
      this->ContextProblem.clear();
    }
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Finalize()
{
  this->DestroyWindow();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::WindowRemap()
{
  this->Finalize();
  this->Initialize();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::CreateAWindow()
{
  this->Initialize();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::DestroyWindow()
{
  // At the process's end (phongvtk::headless::ProcessEnding) the context is left to the exit:
  // no GL call is made and no context destroyed with libraries that are already finalised.
  if (this->HasContext() && !phongvtk::headless::ProcessEnding())
  {
    this->MakeCurrent();
    if (this->IsCurrent())
    {
      // Textures, buffers and programs of the window, its renderers and their props.
      this->ReleaseGraphicsResources(this);
    }
    this->ReleaseCurrent();
    this->DestroyContext();
  }
  this->Initialized = false;
  this->Mapped = 0;
  delete[] this->Capabilities;
  this->Capabilities = nullptr;
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Render()
{
  if (!this->EnsureContext())
  {
    return; // the reason has been reported; nothing to draw with
  }
  this->MakeCurrent();
  if (!this->IsCurrent())
  {
    return; // MakeCurrent said why: no GL call may reach another context, or none
  }
  if (!this->SizeFits(true))
  {
    return; // VTK's framebuffers would fail with a GL error each
  }
  this->Superclass::Render();
  this->ReleaseForGLXWindows();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Start()
{
  if (!this->EnsureContext())
  {
    return;
  }
  this->MakeCurrent();
  if (!this->IsCurrent() || !this->SizeFits(true))
  {
    return;
  }
  this->Superclass::Start();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::Frame()
{
  if (!this->Initialized)
  {
    return;
  }
  this->MakeCurrent();
  // Copies the rendered frame to the display framebuffer, which readback reads; there is no
  // window-system buffer to blit to (UseOffScreenBuffers).
  this->Superclass::Frame();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::MakeCurrent()
{
  if (!this->HasContext() || phongvtk::headless::ProcessEnding())
  {
    return; // no context, or none to be made current any more (GL calls then do nothing)
  }
  // VTK calls this many times a frame: cheap when nothing changed.
  if (!this->RebindPending && this->IsContextBound())
  {
    this->RecordCurrent();
    return;
  }
  // Whatever is current on this thread, whoever made it so.
  phongvtk::headless::ReleaseThreadContext();
  std::string problem;
  if (!this->BindContext(problem))
  {
    this->ReportContextProblem("cannot make the context current: " + problem);
    return;
  }
  this->RecordCurrent();
  ThreadGuard.Bound = true;
  this->RebindPending = false;
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::RecordCurrent()
{
  CurrentOnThread = { this, this->Serial };
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::ReleaseCurrent()
{
  if (this->HasContext() && !phongvtk::headless::ProcessEnding() && this->IsContextBound())
  {
    this->UnbindContext();
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::ReleaseForGLXWindows()
{
  if (phongvtk::headless::XDisplayAvailable())
  {
    this->ReleaseCurrent();
  }
}

//------------------------------------------------------------------------------
bool vtkHeadlessRenderWindow::IsCurrent()
{
  return this->HasContext() && !phongvtk::headless::ProcessEnding() && this->IsContextBound();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::SetForceMakeCurrent()
{
  this->RebindPending = true;
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::PushContext()
{
  vtkHeadlessRenderWindow* previous = Alive(CurrentOnThread.Window, CurrentOnThread.Serial);
  previous = previous && previous->IsCurrent() ? previous : nullptr;
  this->ContextStack.emplace_back(previous, previous ? CurrentOnThread.Serial : 0);
  if (previous != this)
  {
    this->MakeCurrent();
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::PopContext()
{
  if (this->ContextStack.empty())
  {
    return;
  }
  // Null also when the window that was current has been deleted since.
  vtkHeadlessRenderWindow* previous =
    Alive(this->ContextStack.back().first, this->ContextStack.back().second);
  this->ContextStack.pop_back();
  if (previous == this)
  {
    return;
  }
  if (previous)
  {
    previous->MakeCurrent();
  }
  else
  {
    this->ReleaseCurrent();
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::SetUseOffScreenBuffers(bool)
{
  // A surfaceless context has no window-system framebuffer to show anything in.
  this->UseOffScreenBuffers = true;
}

//------------------------------------------------------------------------------
int* vtkHeadlessRenderWindow::GetScreenSize()
{
  this->ScreenSize[0] = this->Size[0];
  this->ScreenSize[1] = this->Size[1];
  return this->ScreenSize;
}

//------------------------------------------------------------------------------
bool vtkHeadlessRenderWindow::WindowFramebufferBound()
{
  if (!this->Initialized || !this->HasContext())
  {
    return false;
  }
  this->MakeCurrent();
  GLint binding = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &binding);
  return binding == 0;
}

//------------------------------------------------------------------------------
bool vtkHeadlessRenderWindow::SizeFits(bool report)
{
  const int largest = this->LargestFramebuffer;
  if (largest <= 0 || (this->Size[0] <= largest && this->Size[1] <= largest))
  {
    this->SizeReported = false;
    return true;
  }
  // Once until the window renders again.
  if (report && !this->SizeReported)
  {
    this->SizeReported = true;
    vtkErrorMacro(<< this->GetBackendName() << " render window: a window of " << this->Size[0]
                  << " x " << this->Size[1]
                  << " pixels is larger than the largest framebuffer this OpenGL draws (" << largest
                  << " pixels a side): nothing rendered.");
  }
  return false;
}

//------------------------------------------------------------------------------
int vtkHeadlessRenderWindow::GetColorBufferSizes(int* rgba)
{
  if (rgba && this->WindowFramebufferBound())
  {
    rgba[0] = rgba[1] = rgba[2] = rgba[3] = 8;
    return 32;
  }
  return this->Superclass::GetColorBufferSizes(rgba);
}

//------------------------------------------------------------------------------
int vtkHeadlessRenderWindow::GetDepthBufferSize()
{
  if (this->WindowFramebufferBound())
  {
    return 32;
  }
  return this->Superclass::GetDepthBufferSize();
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::OpenGLInitContext()
{
  this->ContextCreationTime.Modified();
  if (this->Initialized)
  {
    return;
  }
  const GLenum result = glewInit();
  // Debian's GLEW is a GLX build: glewInit() loads every OpenGL entry point (through glvnd, which
  // routes them to whichever context is current) and then looks for the current GLX display,
  // which a headless context never has.
  this->GlewInitValid = result == GLEW_OK;
#ifdef GLEW_ERROR_NO_GLX_DISPLAY
  this->GlewInitValid = this->GlewInitValid || result == GLEW_ERROR_NO_GLX_DISPLAY;
#endif
  if (!this->GlewInitValid)
  {
    this->ReportContextProblem(std::string("GLEW could not be initialized: ") +
      reinterpret_cast<const char*>(glewGetErrorString(result)));
    return;
  }
  if (!GLEW_VERSION_3_2)
  {
    this->GlewInitValid = false;
    const GLubyte* version = glGetString(GL_VERSION);
    this->ReportContextProblem(std::string("VTK needs OpenGL 3.2, the context has ") +
      (version ? reinterpret_cast<const char*>(version) : "none"));
    return;
  }
  this->Initialized = true;

  // The largest framebuffer VTK can make: its colour and depth attachments are textures or
  // renderbuffers, drawn through a viewport.
  GLint texture = 0;
  GLint renderbuffer = 0;
  GLint viewport[2] = { 0, 0 };
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  this->LargestFramebuffer =
    glGetError() == GL_NO_ERROR ? std::min({ texture, renderbuffer, viewport[0], viewport[1] }) : 0;

  // As vtkOpenGLRenderWindow does once per context: the line widths the implementation draws.
  GLfloat range[2] = { 1.0f, 1.0f };
  this->MaximumHardwareLineWidth = 1.0;
  glGetFloatv(
    this->LineSmoothing ? GL_SMOOTH_LINE_WIDTH_RANGE : GL_ALIASED_LINE_WIDTH_RANGE, range);
  if (glGetError() == GL_NO_ERROR)
  {
    this->MaximumHardwareLineWidth = range[1];
  }
}

//------------------------------------------------------------------------------
int vtkHeadlessRenderWindow::ReadPixels(
  const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right)
{
  if (!this->Initialized || !this->HasContext())
  {
    vtkErrorMacro(<< "Nothing to read: the window has not rendered (no OpenGL context).");
    return VTK_ERROR;
  }
  if (!this->SizeFits(false))
  {
    vtkErrorMacro(<< "Nothing to read: the window has not rendered (larger than the largest "
                  << "framebuffer this OpenGL draws, " << this->LargestFramebuffer
                  << " pixels a side).");
    return VTK_ERROR;
  }
  const int result = this->Superclass::ReadPixels(rect, front, glFormat, glType, data, right);
  this->ReleaseForGLXWindows();
  return result;
}

//------------------------------------------------------------------------------
void vtkHeadlessRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << this->GetBackendName() << "\n";
  os << indent << "HasContext: " << (this->HasContext() ? "yes" : "no") << "\n";
  os << indent << "RebindPending: " << (this->RebindPending ? "yes" : "no") << "\n";
  os << indent
     << "ContextProblem: " << (this->ContextProblem.empty() ? "(none)" : this->ContextProblem)
     << "\n";
  os << indent << "ContextStack depth: " << this->ContextStack.size() << "\n";
}
