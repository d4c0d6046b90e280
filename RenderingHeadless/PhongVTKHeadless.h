/**
 * Private to PhongVTK::RenderingHeadless: the policy that picks a render window, and the libraries
 * the headless backends load at run time.
 *
 * The policy (ParseRequest, ChooseWindow) is a pure function of its inputs so that every branch
 * is tested without the machine having to lack a display or a library. The loaders look the
 * libraries up once per process and say why a backend cannot be used instead of failing later
 * inside a GL call.
 */
#ifndef PhongVTKHeadless_h
#define PhongVTKHeadless_h

#include "vtkPhongVTKRenderingHeadlessModule.h" // for the export macro

#include <string>

struct osmesa_context;

namespace phongvtk
{
namespace headless
{

/// What the environment variable PHONGVTK_HEADLESS asks for.
enum class Request
{
  Auto,   ///< headless only without an X display; OSMesa, else EGL (unset or empty variable)
  OSMesa, ///< always headless, OSMesa (EGL when OSMesa cannot be used)
  EGL,    ///< always headless, EGL
  Off     ///< leave VTK's own window alone
};

/// The render window vtkRenderWindow::New() returns.
enum class Window
{
  VTKDefault, ///< whatever VTK's other factories make (the X window on Debian)
  OSMesa,
  EGL
};

struct Choice
{
  Window Kind = Window::VTKDefault;
  /// Non-empty when the choice is a fallback the user did not ask for: say it once per process.
  std::string Warning;
};

/// PHONGVTK_HEADLESS's value (case-insensitive); null or empty is Auto. An unknown value is Auto
/// and `*invalid` receives a message naming it.
VTKPHONGVTKRENDERINGHEADLESS_EXPORT Request ParseRequest(const char* value, std::string* invalid);

/// The window for a request. `osmesaProblem` is empty when OSMesa can be used, otherwise why not.
VTKPHONGVTKRENDERINGHEADLESS_EXPORT Choice ChooseWindow(
  Request request, bool xDisplayAvailable, const std::string& osmesaProblem);

/// The choice for this process now: PHONGVTK_HEADLESS, the X display, OSMesa's availability.
VTKPHONGVTKRENDERINGHEADLESS_EXPORT Choice ChooseWindowFromEnvironment();

/// Whether DISPLAY names an X server that accepts a connection (probed once per DISPLAY value).
VTKPHONGVTKRENDERINGHEADLESS_EXPORT bool XDisplayAvailable();

/**
 * Whether the process is ending: this library's static objects are being destroyed (exit(), or
 * the library unloaded). Windows destroyed after that (ParaView keeps its views in a static of
 * libvtkRemotingCore, which exit() destroys after a plugin's statics: pvbatch after sys.exit())
 * leave their contexts to the process's end: the GL libraries loaded after ParaView's have been
 * finalised by then, and the registries of contexts would be gone.
 */
VTKPHONGVTKRENDERINGHEADLESS_EXPORT bool ProcessEnding();

/// Makes ProcessEnding() true also from the first of exit()'s handlers that runs after Mesa's
/// (registered once, when a headless context has been created).
VTKPHONGVTKRENDERINGHEADLESS_EXPORT void WatchForTheEnd();

/// Releases the OpenGL context current on this thread, whichever library made it current (OSMesa
/// through PhongVTK, EGL, GLX); nothing when none is. Native state only: no window object needs
/// to be alive. glvnd lets one window-system library at a time have a context current on a
/// thread, so binding a context of another library needs this first.
VTKPHONGVTKRENDERINGHEADLESS_EXPORT void ReleaseThreadContext();

/// Whether a PhongVTK headless context (OSMesa through PhongVTK, or EGL) is current on this thread.
VTKPHONGVTKRENDERINGHEADLESS_EXPORT bool HeadlessContextIsCurrent();

/**
 * Makes VTK's calls to glewInit() (vtkOpenGLRenderWindow::OpenGLInitContext) succeed when a
 * headless context is current, so that windows of any class sharing a PhongVTK headless context
 * (ParaView's per-view windows in pvbatch) initialise as they would on a GLX context. Debian's
 * GLEW is a GLX build: with a non-GLX context current, glewInit() loads every entry point and
 * then reports GLEW_ERROR_NO_GLX_DISPLAY. Done once per process, by rewriting the import slot of
 * glewInit in VTK's OpenGL library; false, with the reason in `*problem`, when there is none.
 */
VTKPHONGVTKRENDERINGHEADLESS_EXPORT bool RouteVTKGlewInit(std::string* problem);

/// Emits `message` as a VTK warning the first time it is seen in this process.
VTKPHONGVTKRENDERINGHEADLESS_EXPORT void WarnOnce(const std::string& message);

/**
 * Mesa's OSMesa and glvnd's dispatch, loaded once per process.
 *
 * VTK calls OpenGL through glvnd (libGL/libGLdispatch): a call reaches whichever vendor libGLX
 * or libEGL made current on the thread. An OSMesa context is invisible to glvnd, so Bind() also
 * makes OSMesa's entry points current in libGLdispatch through the interface libGLX and libEGL
 * use themselves (__glDispatchMakeCurrent, ABI version 1). That interface is private to glvnd,
 * hence the version check: anything else and OSMesa is reported unusable.
 */
class VTKPHONGVTKRENDERINGHEADLESS_EXPORT OSMesaLibrary
{
public:
  /// The library, or null with the reason in `*problem`.
  static const OSMesaLibrary* Get(std::string* problem);
  /// The library if an earlier Get() loaded it, else null (never loads).
  static const OSMesaLibrary* IfLoaded();

  /// A core-profile (>= 3.2) RGBA context without depth or stencil in its own framebuffer: VTK
  /// renders into framebuffer objects. Null with a reason on failure.
  osmesa_context* CreateContext(std::string* problem) const;
  /// Destroys the context, or, when it is current on another thread, as soon as that thread
  /// releases it (Mesa would otherwise leave that thread pointing at freed memory).
  void DestroyContext(osmesa_context* context) const;

  /// Makes `context` current on this thread and routes glvnd's dispatch to it. The caller has
  /// released any other context first. Fails for a context current on another thread.
  bool Bind(osmesa_context* context, std::string* problem) const;
  /// Releases the thread's OSMesa context and glvnd's dispatch to it, if they are current.
  void Unbind() const;
  /// Makes no GL dispatch table current on this thread if OSMesa's is (libGLdispatch alone; no
  /// call into libOSMesa): at the process's end, when Mesa may be finalised.
  void LoseDispatchIfOwned() const;
  /// Whether `context` is current on this thread and glvnd dispatches to it.
  bool IsBound(osmesa_context* context) const;
  /// Whether glvnd dispatches to some OSMesa context on this thread.
  bool OwnsThreadDispatch() const;

  struct Entry;

private:
  OSMesaLibrary() = default;
  const Entry* E = nullptr;
};

/// Testing hook: the library names and the glvnd ABI version OSMesaLibrary::Get() will require.
/// Only effective before the first Get() in the process.
VTKPHONGVTKRENDERINGHEADLESS_EXPORT void SetOSMesaLibrariesForTesting(
  const char* osmesa, const char* glDispatch, int requiredDispatchABI);

}
}

#endif
// VTK-HeaderTest-Exclude: PhongVTKHeadless.h
