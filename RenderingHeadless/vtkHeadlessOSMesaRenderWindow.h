/**
 * @class   vtkHeadlessOSMesaRenderWindow
 * @brief   headless render window on Mesa's OSMesa (llvmpipe), no X server
 *
 * The context is an OpenGL core-profile OSMesa context (libOSMesa.so.8, Debian package
 * libosmesa6, loaded at run time). VTK reaches OpenGL through glvnd, which knows nothing of
 * OSMesa, so the window also makes OSMesa's entry points current in glvnd's libGLdispatch
 * through the interface libGLX and libEGL use (ABI version 1, checked). When OSMesa or that
 * interface is missing, vtkHeadlessRenderWindow::New() and the factory return the EGL window
 * instead with one warning; a vtkHeadlessOSMesaRenderWindow made by name reports the reason as
 * an error when it would render and draws nothing.
 *
 * VTK renders into its own framebuffer objects and readback reads those: the client buffer
 * OSMesa insists on for its window-system framebuffer is never drawn into and stays 1 x 1.
 * Deleting the window on another thread than the one it is current on is safe: the context is
 * destroyed when that thread releases it.
 *
 * @sa vtkHeadlessRenderWindow vtkHeadlessEGLRenderWindow
 */
#ifndef vtkHeadlessOSMesaRenderWindow_h
#define vtkHeadlessOSMesaRenderWindow_h

#include "vtkHeadlessRenderWindow.h"
#include "vtkPhongVTKRenderingHeadlessModule.h" // for export macro

#include <string> // for std::string

struct osmesa_context;

class VTKPHONGVTKRENDERINGHEADLESS_EXPORT vtkHeadlessOSMesaRenderWindow
  : public vtkHeadlessRenderWindow
{
public:
  static vtkHeadlessOSMesaRenderWindow* New();
  vtkTypeMacro(vtkHeadlessOSMesaRenderWindow, vtkHeadlessRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  const char* GetBackendName() override { return "OSMesa"; }

  /**
   * The OSMesaContext, or null before Initialize.
   */
  void* GetGenericContext() override;

  /**
   * Whether OSMesa can be used in this process; when not, `why` (if given) receives the reason.
   */
  static bool IsAvailable(std::string* why = nullptr);

protected:
  vtkHeadlessOSMesaRenderWindow();
  ~vtkHeadlessOSMesaRenderWindow() override;

  bool CreateContext(std::string& problem) override;
  void DestroyContext() override;
  bool BindContext(std::string& problem) override;
  void UnbindContext() override;
  bool IsContextBound() override;

private:
  vtkHeadlessOSMesaRenderWindow(const vtkHeadlessOSMesaRenderWindow&) = delete;
  void operator=(const vtkHeadlessOSMesaRenderWindow&) = delete;

  osmesa_context* Context = nullptr;
};

#endif
