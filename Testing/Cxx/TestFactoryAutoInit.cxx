// A program that uses only VTK's own API: no PhongVTK symbol is referenced, so with the linker's
// --as-needed (Debian's default) the module is loaded only through vtk_module_autoinit. Plain
// vtkRenderWindow::New() must still return the headless window without a display, and the
// module must not have switched off the overrides of VTK's own factories.
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkObjectFactoryCollection.h"
#include "vtkOverrideInformation.h"
#include "vtkOverrideInformationCollection.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

TEST(FactoryAutoInit, PlainVTKProgramGetsTheHeadlessWindow)
{
  unsetenv("DISPLAY");
  unsetenv("PHONGVTK_HEADLESS");
  vtkNew<vtkRenderWindow> window;
  EXPECT_TRUE(window->IsA("vtkHeadlessRenderWindow")) << window->GetClassName();
}

// Loading the module must leave every other factory as it was: its overrides of vtkRenderWindow
// (VTK's RenderingOpenGL2 factory) and vtkRenderWindowInteractor (RenderingUI's) still enabled,
// and the headless factory ahead of them in the registry, so that it answers first and declines
// (PHONGVTK_HEADLESS=off) to VTK's own window and interactor.
TEST(FactoryAutoInit, OtherFactoriesKeepTheirOverrides)
{
  for (const char* className : { "vtkRenderWindow", "vtkRenderWindowInteractor" })
  {
    int others = 0;
    vtkNew<vtkOverrideInformationCollection> overrides;
    vtkObjectFactory::GetOverrideInformation(className, overrides);
    vtkCollectionSimpleIterator it;
    overrides->InitTraversal(it);
    while (vtkOverrideInformation* info = overrides->GetNextOverrideInformation(it))
    {
      vtkObjectFactory* factory = info->GetObjectFactory();
      if (std::string(factory->GetClassName()) != "vtkHeadlessRenderWindowFactory")
      {
        ++others;
        EXPECT_TRUE(factory->GetEnableFlag(className, info->GetClassOverrideWithName()))
          << factory->GetClassName() << " " << info->GetClassOverrideWithName();
      }
    }
    EXPECT_GE(others, 1) << "no other factory overrides " << className;
  }

  vtkObjectFactoryCollection* registry = vtkObjectFactory::GetRegisteredFactories();
  vtkCollectionSimpleIterator it;
  registry->InitTraversal(it);
  vtkObjectFactory* first = registry->GetNextObjectFactory(it);
  ASSERT_NE(first, nullptr);
  EXPECT_STREQ(first->GetClassName(), "vtkHeadlessRenderWindowFactory");
}

TEST(FactoryAutoInit, OffGivesVTKsOwnWindowAndInteractor)
{
  setenv("PHONGVTK_HEADLESS", "off", 1);
  vtkSmartPointer<vtkObject> window =
    vtkSmartPointer<vtkObject>::Take(vtkObjectFactory::CreateInstance("vtkRenderWindow"));
  vtkSmartPointer<vtkObject> interactor =
    vtkSmartPointer<vtkObject>::Take(vtkObjectFactory::CreateInstance("vtkRenderWindowInteractor"));
  unsetenv("PHONGVTK_HEADLESS");
  ASSERT_NE(window, nullptr);
  EXPECT_FALSE(window->IsA("vtkHeadlessRenderWindow")) << window->GetClassName();
  EXPECT_TRUE(window->IsA("vtkOpenGLRenderWindow")) << window->GetClassName();
  ASSERT_NE(interactor, nullptr);
  EXPECT_STRNE(interactor->GetClassName(), "vtkHeadlessRenderWindowInteractor");
  EXPECT_STRNE(interactor->GetClassName(), "vtkRenderWindowInteractor"); // RenderingUI's own
}
