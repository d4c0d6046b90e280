// GL faults are errors, not aborts: a shader program that does not compile or link (a user's
// shader replacement), a window larger than OpenGL can draw, and no OpenGL at all (neither
// OSMesa nor EGL) each give one clear error and draw nothing, and the process goes on. The cases
// that crashed before run in child processes (death tests) so that a crash fails one test, not
// the suite.
#include "PhongVTKHeadless.h"
#include "PhongVTKImageRegression.h"
#include "PhongVTKRenderingTestSupport.h"

#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessOSMesaRenderWindow.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPhongCompositePolyDataMapper.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkShaderProperty.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

namespace
{
using phongvtk::testing::Capture;
using phongvtk::testing::Image;
using phongvtk::testing::MessageCatcher;

constexpr int Width = 240;
constexpr int Height = 180;
// The scene: the broken actor's sphere left of centre, a good Phong sphere right of it.
constexpr int BrokenX = 70;
constexpr int GoodX = 170;
constexpr int Y = 90;
constexpr double Background[3] = { 0.1, 0.2, 0.3 };

// Failures of a child process, printed on its stderr (the parent shows them).
struct Failures
{
  int Count = 0;
  void operator()(const std::string& what)
  {
    std::fprintf(stderr, "FAILED: %s\n", what.c_str());
    ++this->Count;
  }
};

bool IsBackground(const Image& image, int x, int y)
{
  for (int c = 0; c < 3; ++c)
  {
    if (std::abs(image.At(x, y, c) - static_cast<int>(Background[c] * 255 + 0.5)) > 1)
    {
      return false;
    }
  }
  return true;
}

std::string Pixel(const Image& image, int x, int y)
{
  return std::to_string(image.At(x, y, 0)) + "," + std::to_string(image.At(x, y, 1)) + "," +
    std::to_string(image.At(x, y, 2));
}

int Count(const std::vector<std::string>& messages, const std::string& part)
{
  int n = 0;
  for (const std::string& message : messages)
  {
    n += message.find(part) != std::string::npos;
  }
  return n;
}

vtkSmartPointer<vtkPolyDataMapper> SphereMapper(bool composite, double x)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(x, 0, 0);
  sphere->SetRadius(0.4);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  sphere->Update();
  if (!composite)
  {
    auto mapper = vtkSmartPointer<vtkPhongPolyDataMapper>::New();
    mapper->SetInputData(sphere->GetOutput());
    return mapper;
  }
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(1);
  blocks->SetBlock(0, sphere->GetOutput());
  auto mapper = vtkSmartPointer<vtkPhongCompositePolyDataMapper>::New();
  mapper->SetInputDataObject(blocks);
  return mapper;
}

vtkSmartPointer<vtkActor> SphereActor(bool composite, double x)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(SphereMapper(composite, x));
  actor->GetProperty()->SetColor(1.0, 0.3, 0.2);
  actor->GetProperty()->SetInterpolationToPhong();
  return actor;
}

vtkSmartPointer<vtkRenderer> TwoSpheres(vtkRenderWindow* window, vtkActor* broken, vtkActor* good)
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(broken);
  renderer->AddActor(good);
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 4);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(1, 10);
  window->AddRenderer(renderer);
  window->SetSize(Width, Height);
  return renderer;
}

enum class Fault
{
  Compile, // a syntax error in the fragment shader
  Link     // a function declared and called but never defined
};

void Break(vtkActor* actor, Fault fault)
{
  vtkShaderProperty* shaders = actor->GetShaderProperty();
  if (fault == Fault::Compile)
  {
    shaders->AddFragmentShaderReplacement(
      "//VTK::Light::Impl", true, "//VTK::Light::Impl\n  this is not GLSL;\n", false);
  }
  else
  {
    shaders->AddFragmentShaderReplacement(
      "//VTK::Light::Dec", true, "//VTK::Light::Dec\nvec3 phongvtkNeverDefined(vec3 c);\n", false);
    shaders->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
      "//VTK::Light::Impl\n  fragOutput0.rgb = phongvtkNeverDefined(fragOutput0.rgb);\n", false);
  }
}

const char* const Reported = "does not compile or link";

// One actor's shaders do not build: it draws nothing, the other actor draws, one error says
// so; fixed, it draws again; broken again, it is said again.
int BrokenShaderChild(bool composite, Fault fault, bool egl)
{
  Failures fail;
  vtkSmartPointer<vtkRenderWindow> window = egl
    ? vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkHeadlessEGLRenderWindow>::New())
    : vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkHeadlessOSMesaRenderWindow>::New());
  auto broken = SphereActor(composite, -0.45);
  auto good = SphereActor(composite, 0.45);
  TwoSpheres(window, broken, good);
  Break(broken, fault);

  MessageCatcher messages;
  Image image;
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
    image = Capture(window);
    if (!IsBackground(image, BrokenX, Y))
    {
      fail(
        "frame " + std::to_string(frame) + ": the broken actor drew " + Pixel(image, BrokenX, Y));
    }
    if (IsBackground(image, GoodX, Y))
    {
      fail("frame " + std::to_string(frame) + ": the good actor did not draw");
    }
  }
  if (Count(messages.Errors(), Reported) != 1)
  {
    fail("expected one error saying the program does not build, got " +
      std::to_string(Count(messages.Errors(), Reported)) + " among " +
      std::to_string(messages.Errors().size()) + " errors");
  }

  broken->GetShaderProperty()->ClearAllShaderReplacements();
  window->Render();
  image = Capture(window);
  if (IsBackground(image, BrokenX, Y))
  {
    fail("fixed, the actor still draws nothing");
  }
  const Image good1 = image;

  Break(broken, fault);
  window->Render();
  window->Render();
  image = Capture(window);
  if (!IsBackground(image, BrokenX, Y) || IsBackground(image, GoodX, Y))
  {
    fail("broken again: " + Pixel(image, BrokenX, Y) + " / " + Pixel(image, GoodX, Y));
  }
  if (Count(messages.Errors(), Reported) != 2)
  {
    fail("broken again after it built, it is not said again");
  }
  if (image.At(GoodX, Y, 0) != good1.At(GoodX, Y, 0))
  {
    fail("the good actor changed");
  }
  return fail.Count;
}

class GLFaults : public ::testing::Test
{
protected:
  void SetUp() override
  {
    unsetenv("DISPLAY");
    unsetenv("PHONGVTK_HEADLESS");
    GTEST_FLAG_SET(death_test_style, "threadsafe");
  }
};

// VTK 9.2's own vtkOpenGLPolyDataMapper dies with SIGSEGV on the first frame of each of these.
TEST_F(GLFaults, ShaderThatDoesNotCompileDrawsNothingWithOneError)
{
  EXPECT_EXIT(
    std::exit(BrokenShaderChild(false, Fault::Compile, false)), ::testing::ExitedWithCode(0), "");
}

TEST_F(GLFaults, ShaderThatDoesNotLinkDrawsNothingWithOneError)
{
  EXPECT_EXIT(
    std::exit(BrokenShaderChild(false, Fault::Link, false)), ::testing::ExitedWithCode(0), "");
}

TEST_F(GLFaults, CompositeShaderThatDoesNotCompileDrawsNothingWithOneError)
{
  EXPECT_EXIT(
    std::exit(BrokenShaderChild(true, Fault::Compile, false)), ::testing::ExitedWithCode(0), "");
}

TEST_F(GLFaults, CompositeShaderThatDoesNotLinkDrawsNothingWithOneError)
{
  EXPECT_EXIT(
    std::exit(BrokenShaderChild(true, Fault::Link, false)), ::testing::ExitedWithCode(0), "");
}

TEST_F(GLFaults, ShaderThatDoesNotCompileThroughEGL)
{
  EXPECT_EXIT(
    std::exit(BrokenShaderChild(false, Fault::Compile, true)), ::testing::ExitedWithCode(0), "");
}

//------------------------------------------------------------------------------
// A window larger than OpenGL's largest framebuffer: one error, no GL error from VTK's
// framebuffers, nothing to read; at a size that fits it renders.
int OversizedWindowChild(bool egl)
{
  Failures fail;
  vtkSmartPointer<vtkRenderWindow> window = egl
    ? vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkHeadlessEGLRenderWindow>::New())
    : vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkHeadlessOSMesaRenderWindow>::New());
  auto left = SphereActor(false, -0.45);
  auto right = SphereActor(false, 0.45);
  TwoSpheres(window, left, right);
  MessageCatcher messages;
  window->SetSize(1 << 20, 16);
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  if (messages.Errors().size() != 1 ||
    messages.Errors()[0].find("larger than the largest framebuffer") == std::string::npos)
  {
    fail("expected one error about the size, got " + std::to_string(messages.Errors().size()) +
      (messages.Errors().empty() ? std::string() : ": " + messages.Errors()[0]));
  }
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 9, 9, 1, pixels);
  if (messages.Errors().size() != 2 ||
    messages.Errors()[1].find("Nothing to read") == std::string::npos)
  {
    fail("reading the oversized window did not say there is nothing to read");
  }
  window->SetSize(Width, Height);
  window->Render();
  const Image image = Capture(window);
  if (IsBackground(image, BrokenX, Y) || IsBackground(image, GoodX, Y))
  {
    fail("at a size that fits, the window does not render");
  }
  if (messages.Errors().size() != 2)
  {
    fail("errors after the window fits: " + messages.Errors().back());
  }
  // Too large again: said again.
  window->SetSize(16, 1 << 20);
  window->Render();
  if (messages.Errors().size() != 3)
  {
    fail("too large again, not said again");
  }
  return fail.Count;
}

TEST_F(GLFaults, OversizedOSMesaWindowSaysSoOnceAndRendersWhenItFits)
{
  EXPECT_EXIT(std::exit(OversizedWindowChild(false)), ::testing::ExitedWithCode(0), "");
}

TEST_F(GLFaults, OversizedEGLWindowSaysSoOnceAndRendersWhenItFits)
{
  EXPECT_EXIT(std::exit(OversizedWindowChild(true)), ::testing::ExitedWithCode(0), "");
}

//------------------------------------------------------------------------------
// Neither OSMesa (a library name that does not exist) nor EGL (glvnd finds no vendor): the
// factory's window says why once, renders nothing, reads nothing, and the process goes on.
int NoOpenGLChild()
{
  Failures fail;
  phongvtk::headless::SetOSMesaLibrariesForTesting(
    "libOSMesa-not-installed.so.8", "libGLdispatch.so.0", 1);
  setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/phongvtk-no-vendor.json", 1);
  MessageCatcher messages;
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  auto left = SphereActor(false, -0.45);
  auto right = SphereActor(true, 0.45);
  TwoSpheres(window, left, right);
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  if (Count(messages.Warnings(), "cannot load libOSMesa-not-installed.so.8") != 1)
  {
    fail("no single warning that OSMesa is missing");
  }
  if (messages.Errors().size() != 1 ||
    messages.Errors()[0].find("no OpenGL context") == std::string::npos ||
    messages.Errors()[0].find("EGL") == std::string::npos)
  {
    fail("expected one error saying EGL gives no context, got " +
      std::to_string(messages.Errors().size()) +
      (messages.Errors().empty() ? std::string() : ": " + messages.Errors()[0]));
  }
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 9, 9, 1, pixels);
  if (Count(messages.Errors(), "Nothing to read") != 1)
  {
    fail("reading said nothing");
  }
  return fail.Count;
}

TEST_F(GLFaults, NeitherOSMesaNorEGLIsAnErrorNotACrash)
{
  EXPECT_EXIT(std::exit(NoOpenGLChild()), ::testing::ExitedWithCode(0), "");
}

//------------------------------------------------------------------------------
// A context that cannot be made current: an EGL context is current on the thread that rendered
// last, and EGL refuses it to another thread (EGL_BAD_ACCESS). The other thread's render is one
// error and draws nothing; the first thread renders on.
int ContextCurrentElsewhereChild()
{
  Failures fail;
  auto window = vtkSmartPointer<vtkHeadlessEGLRenderWindow>::New();
  auto left = SphereActor(false, -0.45);
  auto right = SphereActor(false, 0.45);
  TwoSpheres(window, left, right);
  MessageCatcher messages;
  window->Render();
  const Image before = Capture(window);
  if (IsBackground(before, BrokenX, Y))
  {
    fail("the first render drew nothing");
  }
  std::thread other(
    [&]
    {
      for (int frame = 0; frame < 3; ++frame)
      {
        window->Render();
      }
    });
  other.join();
  if (Count(messages.Errors(), "cannot make the context current") != 1)
  {
    fail("expected one error saying the context cannot be made current, got " +
      std::to_string(messages.Errors().size()) + " errors" +
      (messages.Errors().empty() ? std::string() : ": " + messages.Errors()[0]));
  }
  window->Render();
  const Image after = Capture(window);
  if (after.Pixels != before.Pixels)
  {
    fail("the first thread's frame changed");
  }
  return fail.Count;
}

TEST_F(GLFaults, ContextCurrentOnAnotherThreadIsAnErrorNotACrash)
{
  EXPECT_EXIT(std::exit(ContextCurrentElsewhereChild()), ::testing::ExitedWithCode(0), "");
}
}
