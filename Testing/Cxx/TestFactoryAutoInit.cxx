// A program that uses only VTK's own API: no PhongVTK symbol is referenced, so with the linker's
// --as-needed (Debian's default) the module is loaded only through vtk_module_autoinit. Plain
// vtkRenderWindow::New() must still return the headless window without a display.
#include "vtkNew.h"
#include "vtkRenderWindow.h"

#include <gtest/gtest.h>

#include <cstdlib>

TEST(FactoryAutoInit, PlainVTKProgramGetsTheHeadlessWindow)
{
  unsetenv("DISPLAY");
  unsetenv("PHONGVTK_HEADLESS");
  vtkNew<vtkRenderWindow> window;
  EXPECT_TRUE(window->IsA("vtkHeadlessRenderWindow")) << window->GetClassName();
}
