/**
 * @class   vtkHeadlessEGLRenderWindow
 * @brief   headless render window on EGL's surfaceless platform (Mesa llvmpipe), no X server
 *
 * The context is an OpenGL core-profile EGL context on Mesa's surfaceless platform
 * (EGL_MESA_platform_surfaceless, through glvnd's libEGL): no window, no pixel buffer and no
 * window-system framebuffer at all. VTK renders into its own framebuffer objects
 * (UseOffScreenBuffers) and readback reads those. The EGL display is shared by every window of
 * the process and initialised once.
 *
 * @sa vtkHeadlessRenderWindow vtkHeadlessOSMesaRenderWindow
 */
#ifndef vtkHeadlessEGLRenderWindow_h
#define vtkHeadlessEGLRenderWindow_h

#include "vtkHeadlessRenderWindow.h"
#include "vtkPhongVTKRenderingHeadlessModule.h" // for export macro

#include <string> // for std::string

class VTKPHONGVTKRENDERINGHEADLESS_EXPORT vtkHeadlessEGLRenderWindow
  : public vtkHeadlessRenderWindow
{
public:
  static vtkHeadlessEGLRenderWindow* New();
  vtkTypeMacro(vtkHeadlessEGLRenderWindow, vtkHeadlessRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  const char* GetBackendName() override { return "EGL"; }

  ///@{
  /**
   * The EGLContext and the EGLDisplay, or null before Initialize.
   */
  void* GetGenericContext() override { return this->Context; }
  void* GetGenericDisplayId() override;
  ///@}

  /**
   * Whether EGL's surfaceless platform can be used in this process; when not, `why` (if given)
   * receives the reason.
   */
  static bool IsAvailable(std::string* why = nullptr);

protected:
  vtkHeadlessEGLRenderWindow();
  ~vtkHeadlessEGLRenderWindow() override;

  bool CreateContext(std::string& problem) override;
  void DestroyContext() override;
  bool BindContext(std::string& problem) override;
  void UnbindContext() override;
  bool IsContextBound() override;

private:
  vtkHeadlessEGLRenderWindow(const vtkHeadlessEGLRenderWindow&) = delete;
  void operator=(const vtkHeadlessEGLRenderWindow&) = delete;

  void* Context = nullptr; // EGLContext
};

#endif
