// A C++ program linking PhongVTK::Rendering leaves in every way a program can, with headless
// windows alive, and returns exactly its status: windows rendered and kept in static objects
// (destroyed by exit()), windows leaked, windows never rendered, on both backends and both at
// once. Each case runs in a child process (gtest's death tests: a crash or a heap report fails
// them; CTest's timeout catches a hang). The late teardown ParaView does (windows destroyed
// after this library's static objects) is tested through pvbatch and pvpython in
// Testing/Plugin/test_plugin.py.
#include "PhongVTKRenderingTestSupport.h"

#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessOSMesaRenderWindow.h"

#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

// Under AddressSanitizer (scripts/test.sh --sanitize) these programs leave the process with
// windows, contexts and VTK objects alive on purpose: what is alive at the exit is the test's
// subject, not a leak.
extern "C" const char* __asan_default_options()
{
  return "detect_leaks=0";
}

namespace
{
using phongvtk::testing::AddScene;

vtkSmartPointer<vtkRenderWindow> Rendered(vtkSmartPointer<vtkRenderWindow> window)
{
  AddScene(window, 64, 48);
  window->Render();
  return window;
}

vtkSmartPointer<vtkRenderWindow> OSMesa()
{
  return vtkSmartPointer<vtkHeadlessOSMesaRenderWindow>::New();
}

vtkSmartPointer<vtkRenderWindow> EGL()
{
  return vtkSmartPointer<vtkHeadlessEGLRenderWindow>::New();
}

/// Windows that live until exit() destroys this function's static vector.
void KeepUntilExit(std::vector<vtkSmartPointer<vtkRenderWindow>> windows)
{
  static std::vector<vtkSmartPointer<vtkRenderWindow>> kept;
  kept = std::move(windows);
}

class ProcessExit : public ::testing::Test
{
protected:
  void SetUp() override
  {
    // The "threadsafe" style runs each child from a fresh exec of this program.
    ::testing::FLAGS_gtest_death_test_style = "threadsafe";
    unsetenv("DISPLAY");
  }
};

TEST_F(ProcessExit, RenderedWindowsInStaticObjects)
{
  EXPECT_EXIT(
    {
      KeepUntilExit({ Rendered(OSMesa()), Rendered(EGL()), Rendered(OSMesa()) });
      std::exit(3);
    },
    ::testing::ExitedWithCode(3), "");
  EXPECT_EXIT(
    {
      KeepUntilExit({ Rendered(OSMesa()) });
      std::exit(0);
    },
    ::testing::ExitedWithCode(0), "");
}

TEST_F(ProcessExit, WindowsInStaticsMadeBeforeTheFirstContext)
{
  // Their destructors were registered before Mesa's exit handlers (made with the first context),
  // so exit() runs them after Mesa's: they must make no GL call then.
  EXPECT_EXIT(
    {
      static vtkSmartPointer<vtkRenderWindow> early = OSMesa();
      static vtkSmartPointer<vtkRenderWindow> earlyEGL = EGL();
      Rendered(early);
      Rendered(earlyEGL);
      std::exit(4);
    },
    ::testing::ExitedWithCode(4), "");
}

TEST_F(ProcessExit, LeakedAndNeverRenderedWindows)
{
  EXPECT_EXIT(
    {
      Rendered(OSMesa())->Register(nullptr); // never released
      Rendered(EGL())->Register(nullptr);
      KeepUntilExit({ OSMesa(), EGL() }); // never rendered
      std::exit(5);
    },
    ::testing::ExitedWithCode(5), "");
}

TEST_F(ProcessExit, WindowsDeletedBeforeExit)
{
  EXPECT_EXIT(
    {
      Rendered(OSMesa());
      Rendered(EGL());
      std::exit(7);
    },
    ::testing::ExitedWithCode(7), "");
}
} // namespace
