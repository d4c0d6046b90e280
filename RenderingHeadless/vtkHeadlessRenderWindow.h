/**
 * @class   vtkHeadlessRenderWindow
 * @brief   an OpenGL render window that needs no X server: OSMesa or EGL (surfaceless Mesa)
 *
 * Debian's VTK is built for GLX only: without an X display vtkRenderWindow fails ("bad X server
 * connection"). A headless window renders into VTK's own framebuffer objects through a context
 * of one of two backends, each its own class:
 * - vtkHeadlessOSMesaRenderWindow: Mesa's off-screen library (the default);
 * - vtkHeadlessEGLRenderWindow: EGL on Mesa's surfaceless platform.
 * Both are llvmpipe on the CPU and render a scene to the same pixels.
 *
 * Everything else is a vtkOpenGLRenderWindow: several windows at once (each MakeCurrent switches
 * the thread's context, across backends too), SetSize, Finalize and re-Initialize, readback with
 * vtkWindowToImageFilter or GetPixelData (from the last frame; reading renders nothing), use
 * from another thread after ReleaseCurrent (a thread that ends releases what it had current).
 * When an X server is reachable a headless window releases its context after each Render and
 * readback, so that VTK's GLX windows on the same thread can make theirs current (glvnd allows
 * one window-system library at a time per thread).
 * Multisampling is off by default so that images are reproducible; ShowWindow is ignored and
 * UseOffScreenBuffers stays on: there is no screen.
 *
 * The module overrides vtkRenderWindow in VTK's object factory as soon as it is loaded (a C++
 * program that links it, `import phongvtk` in Python, the ParaView plugin). What
 * vtkRenderWindow::New() returns follows the environment variable PHONGVTK_HEADLESS:
 * - `auto` (or unset): VTK's own window when DISPLAY names a reachable X server, else headless:
 *   OSMesa, or EGL when OSMesa cannot be used here (one warning says why);
 * - `osmesa`: always headless, OSMesa (EGL with the warning when OSMesa cannot be used);
 * - `egl`: always headless, EGL;
 * - `off`: the factory leaves VTK alone.
 * vtkHeadlessRenderWindow::New() returns a headless window by the same rule, display or not.
 *
 * A window whose context cannot be created reports the reason once as an error and renders
 * nothing; it never aborts the program.
 *
 * @sa vtkHeadlessOSMesaRenderWindow vtkHeadlessEGLRenderWindow vtkOpenGLRenderWindow
 */
#ifndef vtkHeadlessRenderWindow_h
#define vtkHeadlessRenderWindow_h

#include "vtkOpenGLRenderWindow.h"
#include "vtkPhongVTKRenderingHeadlessModule.h" // for export macro

#include <cstdint> // for std::uint64_t
#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

class VTKPHONGVTKRENDERINGHEADLESS_EXPORT vtkHeadlessRenderWindow : public vtkOpenGLRenderWindow
{
public:
  /**
   * A headless window: OSMesa, or EGL when PHONGVTK_HEADLESS=egl or OSMesa cannot be used.
   */
  static vtkHeadlessRenderWindow* New();
  vtkTypeMacro(vtkHeadlessRenderWindow, vtkOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The backend's name: "OSMesa" or "EGL".
   */
  virtual const char* GetBackendName() = 0;

  /**
   * Whether the window has a context (it is created by Initialize or the first Render).
   */
  bool HasContext() { return this->GetGenericContext() != nullptr; }

  ///@{
  /**
   * Create (Initialize) or destroy (Finalize) the context and every OpenGL resource of the
   * window. Symmetric: the pair may be repeated, and the next Render re-initialises.
   */
  void Initialize() override;
  void Finalize() override;
  void WindowRemap() override;
  ///@}

  void Render() override;
  void Start() override;
  void Frame() override;

  ///@{
  /**
   * Make the window's context current on this thread (releasing another headless window's),
   * release it, or ask whether it is current.
   */
  void MakeCurrent() override;
  void ReleaseCurrent() override;
  bool IsCurrent() override;
  void SetForceMakeCurrent() override;
  void PushContext() override;
  void PopContext() override;
  ///@}

  /**
   * There is no screen: the off-screen buffers are always used (the setting is ignored).
   */
  void SetUseOffScreenBuffers(bool) override;

  /**
   * The size of the screen a headless window does not have: its own size.
   */
  int* GetScreenSize() VTK_SIZEHINT(2) override;

  vtkTypeBool GetEventPending() override { return 0; }
  vtkTypeBool IsDirect() override { return 1; }

  /**
   * A headless window always creates its own context.
   */
  bool InitializeFromCurrentContext() override { return false; }

  ///@{
  /**
   * Bit depths of what the window renders into. With the window-system framebuffer bound (which
   * a surfaceless context does not have) they are those of VTK's framebuffer objects: RGBA8 and
   * a 32-bit depth buffer.
   */
  int GetColorBufferSizes(int* rgba) override;
  int GetDepthBufferSize() override;
  ///@}

protected:
  vtkHeadlessRenderWindow();
  ~vtkHeadlessRenderWindow() override;

  void CreateAWindow() override;
  void DestroyWindow() override;

  /**
   * VTK's initialisation of a new context, accepting that the system GLEW (a GLX build) finds no
   * GLX display after it has loaded every OpenGL entry point.
   */
  void OpenGLInitContext() override;

  int ReadPixels(
    const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right = 0) override;

  ///@{
  /**
   * The backend. CreateContext and BindContext return false with the reason in `problem`.
   * BindContext is called with no other headless window current on the thread.
   */
  virtual bool CreateContext(std::string& problem) = 0;
  virtual void DestroyContext() = 0;
  virtual bool BindContext(std::string& problem) = 0;
  virtual void UnbindContext() = 0;
  virtual bool IsContextBound() = 0;
  ///@}

  /**
   * The next MakeCurrent binds the context again even if it is current (a new buffer, say).
   */
  bool RebindPending = true;

private:
  vtkHeadlessRenderWindow(const vtkHeadlessRenderWindow&) = delete;
  void operator=(const vtkHeadlessRenderWindow&) = delete;

  // Creates the context and initialises OpenGL when needed; false when there is none.
  bool EnsureContext();
  // Reports a problem as an error unless it is the one reported last.
  void ReportContextProblem(const std::string& problem);
  // Whether the window-system framebuffer (never rendered into) is bound for drawing.
  bool WindowFramebufferBound();
  // Whether OpenGL can draw a framebuffer of the window's size; when not, reports it once.
  bool SizeFits(bool report);

  // Remembers this window as the thread's current one (for PushContext).
  void RecordCurrent();
  // With an X server reachable, VTK's GLX windows may share the thread: glvnd lets them bind
  // their context only when no other window-system library has one current.
  void ReleaseForGLXWindows();

  std::string ContextProblem;
  int LargestFramebuffer = 0; // pixels a side; 0 until the context is initialised
  bool SizeReported = false;  // the window's size was reported too large
  // The windows current before each PushContext, with their serial numbers (no weak pointers:
  // see CurrentOnThread in the .cxx).
  std::vector<std::pair<vtkHeadlessRenderWindow*, std::uint64_t>> ContextStack;
  std::uint64_t Serial = 0; // tells this window from a later one at the same address
  int ScreenSize[2];
};

#endif
