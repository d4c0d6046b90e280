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
 * OSMesa draws into a client memory buffer of the window's size; VTK renders into its own
 * framebuffer objects and readback reads those.
 *
 * @sa vtkHeadlessRenderWindow vtkHeadlessEGLRenderWindow
 */
#ifndef vtkHeadlessOSMesaRenderWindow_h
#define vtkHeadlessOSMesaRenderWindow_h

#include "vtkHeadlessRenderWindow.h"
#include "vtkPhongVTKRenderingModule.h" // for export macro

#include <string> // for std::string
#include <vector> // for std::vector

struct osmesa_context;

class VTKPHONGVTKRENDERING_EXPORT vtkHeadlessOSMesaRenderWindow : public vtkHeadlessRenderWindow
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
  void ResizeContextBuffer(int width, int height) override;

private:
  vtkHeadlessOSMesaRenderWindow(const vtkHeadlessOSMesaRenderWindow&) = delete;
  void operator=(const vtkHeadlessOSMesaRenderWindow&) = delete;

  osmesa_context* Context = nullptr;
  std::vector<unsigned char> Buffer; // OSMesa's window-system framebuffer (RGBA)
  int BufferSize[2] = { 0, 0 };
};

#endif
