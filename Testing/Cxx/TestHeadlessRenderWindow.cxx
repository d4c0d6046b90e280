// Headless render windows: both backends, the factory, the window lifecycle and the fallback.
// Images are checked against an independent CPU evaluation of the scene (ray-sphere
// intersection and the lighting formula) and against committed baselines (SSIM).
#include "PhongVTKHeadless.h"
#include "PhongVTKImageRegression.h"
#include "PhongVTKRenderingTestSupport.h"
#include "PhongVTKSkip.h"

#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessOSMesaRenderWindow.h"
#include "vtkHeadlessRenderWindow.h"

#include "vtkActorCollection.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkShaderProperty.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <thread>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
using phongvtk::testing::AddScene;
using phongvtk::testing::Capture;
using phongvtk::testing::Image;
using phongvtk::testing::MatchesBaseline;
using phongvtk::testing::MaxAbsDifference;
using phongvtk::testing::MessageCatcher;
using phongvtk::testing::RenderCounter;

// No test may depend on the machine having an X server.
class Headless : public ::testing::Test
{
protected:
  void SetUp() override
  {
    unsetenv("DISPLAY");
    unsetenv("PHONGVTK_HEADLESS");
  }
};

using HeadlessWindowFactory = std::function<vtkSmartPointer<vtkRenderWindow>()>;

vtkSmartPointer<vtkRenderWindow> NewOSMesa()
{
  return vtkSmartPointer<vtkHeadlessOSMesaRenderWindow>::New();
}
vtkSmartPointer<vtkRenderWindow> NewEGL()
{
  return vtkSmartPointer<vtkHeadlessEGLRenderWindow>::New();
}

Image RenderScene(vtkRenderWindow* window, int width = 240, int height = 180)
{
  AddScene(window, width, height);
  window->Render();
  return Capture(window);
}

// The sphere's surface normal seen through the centre of pixel (px, py) of the scene's camera,
// or false when the ray misses it or grazes it (the cosine between the ray and the normal is
// below `margin`: near the silhouette the mesh's facets and the sphere differ by pixels).
bool SphereNormalAtPixel(
  int px, int py, int width, int height, double normal[3], double margin = 0.3)
{
  const double t = std::tan(15.0 * M_PI / 180.0); // half the 30 degree view angle
  const double aspect = double(width) / height;
  const double d[3] = { ((px + 0.5) / width * 2 - 1) * aspect * t,
    ((py + 0.5) / height * 2 - 1) * t, -1.0 };
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double e[3] = { 0, 0, 4 };
  // |e + s d|^2 = r^2 with r = 0.5
  const double b = 2 * (e[2] * d[2]);
  const double c = e[2] * e[2] - 0.25;
  const double disc = b * b - 4 * dd * c;
  if (disc <= 0)
  {
    return false;
  }
  const double s = (-b - std::sqrt(disc)) / (2 * dd);
  for (int i = 0; i < 3; ++i)
  {
    normal[i] = (e[i] + s * d[i]) / 0.5;
  }
  const double cosine = -(normal[0] * d[0] + normal[1] * d[1] + normal[2] * d[2]) / std::sqrt(dd);
  return cosine > margin;
}

// Compares every third sphere pixel (away from the silhouette) with `expected(n, channel)` in
// 0..1 for the sphere's true normal n there; the mesh's interpolated vertex normals differ from
// the true sphere's by well under 1% (measured: 1.2 LSB at worst on both backends), so 2 LSB
// is the bound.
void ExpectSpherePixels(const Image& image,
  const std::function<double(const double n[3], int channel)>& expected, const char* what)
{
  int checked = 0;
  int worst = 0;
  for (int py = 0; py < image.Height; py += 3)
  {
    for (int px = 0; px < image.Width / 2 + 20; px += 3)
    {
      double n[3];
      if (!SphereNormalAtPixel(px, py, image.Width, image.Height, n))
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        const double value = 255 * expected(n, c);
        worst = std::max(worst, int(std::lround(std::abs(image.At(px, py, c) - value))));
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_LE(worst, 2) << "largest difference from " << what << " over " << checked
                      << " sphere pixels";
}

// Every sphere pixel of the scene shows the diffuse colour times n.l, with VTK's headlight
// shining along the view direction (l = +z): the Lambert term evaluated on the CPU. The corners
// show the background (0.1, 0.2, 0.3): 25.5 -> 25 or 26, 51, 76.5 -> 76 or 77.
void ExpectLambertSphere(const Image& image)
{
  ExpectSpherePixels(
    image, [](const double n[3], int c) { return phongvtk::testing::SphereColour[c] * n[2]; },
    "the Lambert term");
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(image.At(0, 0, c), 255 * phongvtk::testing::SceneBackground[c], 0.5);
    EXPECT_NEAR(image.At(image.Width - 1, image.Height - 1, c),
      255 * phongvtk::testing::SceneBackground[c], 0.5);
  }
}

//------------------------------------------------------------------------------
TEST_F(Headless, OSMesaRendersTheSceneAnalyticallyRight)
{
  auto window = NewOSMesa();
  const Image image = RenderScene(window);
  ASSERT_EQ(image.Width, 240);
  ASSERT_EQ(image.Height, 180);
  ExpectLambertSphere(image);
  EXPECT_TRUE(MatchesBaseline(image, "HeadlessScene"));
}

TEST_F(Headless, EGLRendersTheSceneAnalyticallyRight)
{
  auto window = NewEGL();
  const Image image = RenderScene(window);
  ASSERT_EQ(image.Width, 240);
  ExpectLambertSphere(image);
  EXPECT_TRUE(MatchesBaseline(image, "HeadlessScene"));
}

TEST_F(Headless, BackendsRenderTheSamePixels)
{
  auto osmesa = NewOSMesa();
  auto egl = NewEGL();
  const Image a = RenderScene(osmesa);
  const Image b = RenderScene(egl);
  EXPECT_LE(MaxAbsDifference(a, b), 1);
}

//------------------------------------------------------------------------------
// A vtkOpenGLPolyDataMapper with a fragment-shader replacement: the fragment's colour is its
// view-space normal mapped to [0, 1], checked against the ray-traced sphere normal.
Image RenderNormalShadedScene(vtkRenderWindow* window)
{
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  vtkRenderer* renderer = AddScene(window, 240, 180, mapper);
  auto* sphere = vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(0));
  sphere->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Light::Impl", true,
    "//VTK::Light::Impl\n  gl_FragData[0] = vec4(0.5 * normalVCVSOutput + 0.5, 1.0);\n", false);
  window->Render();
  return Capture(window);
}

// The camera looks down -z with y up: view coordinates are world coordinates.
void ExpectNormalShadedSphere(const Image& image)
{
  ExpectSpherePixels(
    image, [](const double n[3], int c) { return 0.5 * n[c] + 0.5; }, "0.5 n + 0.5");
}

TEST_F(Headless, ShaderReplacementRendersThroughBothBackends)
{
  auto osmesa = NewOSMesa();
  auto egl = NewEGL();
  const Image a = RenderNormalShadedScene(osmesa);
  const Image b = RenderNormalShadedScene(egl);
  ExpectNormalShadedSphere(a);
  ExpectNormalShadedSphere(b);
  EXPECT_LE(MaxAbsDifference(a, b), 1);
  EXPECT_TRUE(MatchesBaseline(a, "HeadlessShaderReplacement"));
}

//------------------------------------------------------------------------------
TEST_F(Headless, FactoryPicksTheHeadlessWindowWithoutADisplay)
{
  const struct
  {
    const char* Request;
    const char* ClassName;
  } cases[] = { { nullptr, "vtkHeadlessOSMesaRenderWindow" },
    { "auto", "vtkHeadlessOSMesaRenderWindow" }, { "osmesa", "vtkHeadlessOSMesaRenderWindow" },
    { "EGL", "vtkHeadlessEGLRenderWindow" } };
  for (const auto& c : cases)
  {
    if (c.Request)
    {
      setenv("PHONGVTK_HEADLESS", c.Request, 1);
    }
    else
    {
      unsetenv("PHONGVTK_HEADLESS");
    }
    vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
    ASSERT_NE(window, nullptr);
    EXPECT_STREQ(window->GetClassName(), c.ClassName)
      << "PHONGVTK_HEADLESS=" << (c.Request ? c.Request : "(unset)");
  }
  // A DISPLAY naming no server is no display.
  setenv("DISPLAY", ":97.0", 1);
  unsetenv("PHONGVTK_HEADLESS");
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  EXPECT_TRUE(window->IsA("vtkHeadlessRenderWindow"));
  // The factory's window renders like one made by name.
  unsetenv("DISPLAY");
  auto reference = NewOSMesa();
  EXPECT_EQ(MaxAbsDifference(RenderScene(window), RenderScene(reference)), 0);
}

TEST_F(Headless, FactoryLeavesVTKAloneWhenAskedTo)
{
  setenv("PHONGVTK_HEADLESS", "off", 1);
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  ASSERT_NE(window, nullptr);
  // Debian's VTK: the GLX window of RenderingOpenGL2 (made here, not rendered: no X server).
  EXPECT_STREQ(window->GetClassName(), "vtkXOpenGLRenderWindow");
}

TEST_F(Headless, HeadlessNewFollowsTheRequestEvenWhenOff)
{
  setenv("PHONGVTK_HEADLESS", "egl", 1);
  vtkSmartPointer<vtkHeadlessRenderWindow> egl = vtkSmartPointer<vtkHeadlessRenderWindow>::New();
  EXPECT_STREQ(egl->GetBackendName(), "EGL");
  setenv("PHONGVTK_HEADLESS", "off", 1);
  vtkSmartPointer<vtkHeadlessRenderWindow> osmesa = vtkSmartPointer<vtkHeadlessRenderWindow>::New();
  EXPECT_STREQ(osmesa->GetBackendName(), "OSMesa");
}

TEST_F(Headless, AnUnknownRequestIsAutoWithAWarning)
{
  MessageCatcher messages;
  setenv("PHONGVTK_HEADLESS", "vulkan", 1);
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  EXPECT_STREQ(window->GetClassName(), "vtkHeadlessOSMesaRenderWindow");
  ASSERT_EQ(messages.Warnings().size(), 1u);
  EXPECT_NE(messages.Warnings()[0].find("PHONGVTK_HEADLESS='vulkan'"), std::string::npos);
}

//------------------------------------------------------------------------------
// The policy, every branch, without needing a machine that lacks a display or a library.
TEST(HeadlessPolicy, ChoosesTheWindowFromRequestDisplayAndOSMesa)
{
  using phongvtk::headless::ChooseWindow;
  using phongvtk::headless::Request;
  using phongvtk::headless::Window;
  const std::string missing = "cannot load libOSMesa.so.8";
  EXPECT_EQ(ChooseWindow(Request::Auto, true, "").Kind, Window::VTKDefault);
  EXPECT_EQ(ChooseWindow(Request::Auto, true, missing).Kind, Window::VTKDefault);
  EXPECT_EQ(ChooseWindow(Request::Auto, false, "").Kind, Window::OSMesa);
  EXPECT_TRUE(ChooseWindow(Request::Auto, false, "").Warning.empty());
  const auto fallback = ChooseWindow(Request::Auto, false, missing);
  EXPECT_EQ(fallback.Kind, Window::EGL);
  EXPECT_NE(fallback.Warning.find(missing), std::string::npos);
  EXPECT_NE(fallback.Warning.find("EGL"), std::string::npos);
  EXPECT_EQ(ChooseWindow(Request::OSMesa, true, "").Kind, Window::OSMesa);
  EXPECT_EQ(ChooseWindow(Request::OSMesa, true, missing).Kind, Window::EGL);
  EXPECT_FALSE(ChooseWindow(Request::OSMesa, true, missing).Warning.empty());
  EXPECT_EQ(ChooseWindow(Request::EGL, true, "").Kind, Window::EGL);
  EXPECT_EQ(ChooseWindow(Request::EGL, false, missing).Kind, Window::EGL);
  EXPECT_TRUE(ChooseWindow(Request::EGL, false, missing).Warning.empty());
  EXPECT_EQ(ChooseWindow(Request::Off, false, "").Kind, Window::VTKDefault);
  EXPECT_EQ(ChooseWindow(Request::Off, false, missing).Kind, Window::VTKDefault);
}

TEST(HeadlessPolicy, ParsesTheEnvironmentVariable)
{
  using phongvtk::headless::ParseRequest;
  using phongvtk::headless::Request;
  std::string invalid;
  EXPECT_EQ(ParseRequest(nullptr, &invalid), Request::Auto);
  EXPECT_EQ(ParseRequest("", &invalid), Request::Auto);
  EXPECT_EQ(ParseRequest("auto", &invalid), Request::Auto);
  EXPECT_EQ(ParseRequest("OSMesa", &invalid), Request::OSMesa);
  EXPECT_EQ(ParseRequest("egl", &invalid), Request::EGL);
  EXPECT_EQ(ParseRequest("Off", &invalid), Request::Off);
  EXPECT_TRUE(invalid.empty());
  EXPECT_EQ(ParseRequest("glx", &invalid), Request::Auto);
  EXPECT_NE(invalid.find("'glx'"), std::string::npos);
}

//------------------------------------------------------------------------------
// The lifecycle of a window, for both backends.
class HeadlessLifecycle
  : public Headless
  , public ::testing::WithParamInterface<const char*>
{
protected:
  vtkSmartPointer<vtkRenderWindow> NewWindow()
  {
    return std::string(this->GetParam()) == "EGL" ? NewEGL() : NewOSMesa();
  }
};

TEST_P(HeadlessLifecycle, MultisamplingIsOffByDefault)
{
  EXPECT_EQ(this->NewWindow()->GetMultiSamples(), 0);
}

TEST_P(HeadlessLifecycle, SeveralWindowsAtOnce)
{
  // Three windows of different sizes and backgrounds, both backends among them, rendered in
  // turns: each shows what it shows alone.
  auto a = this->NewWindow();
  auto b = NewOSMesa();
  auto c = NewEGL();
  vtkRenderer* ra = AddScene(a, 240, 180);
  vtkRenderer* rb = AddScene(b, 160, 120);
  vtkRenderer* rc = AddScene(c, 200, 100);
  rb->SetBackground(0.8, 0.8, 0.8);
  rc->GetActiveCamera()->Azimuth(40);
  for (int round = 0; round < 3; ++round)
  {
    a->Render();
    b->Render();
    c->Render();
  }
  const Image ia = Capture(a);
  const Image ib = Capture(b);
  const Image ic = Capture(c);
  ExpectLambertSphere(ia);

  auto alone = this->NewWindow();
  vtkRenderer* r = AddScene(alone, 160, 120);
  r->SetBackground(0.8, 0.8, 0.8);
  alone->Render();
  EXPECT_LE(MaxAbsDifference(ib, Capture(alone)), 1);
  auto alone2 = this->NewWindow();
  AddScene(alone2, 200, 100)->GetActiveCamera()->Azimuth(40);
  alone2->Render();
  EXPECT_LE(MaxAbsDifference(ic, Capture(alone2)), 1);
  EXPECT_EQ(ib.Width, 160);
  EXPECT_EQ(ic.Height, 100);
}

TEST_P(HeadlessLifecycle, Resize)
{
  auto window = this->NewWindow();
  AddScene(window, 240, 180);
  window->Render();
  window->SetSize(120, 90);
  window->Render();
  const Image small = Capture(window);
  ASSERT_EQ(small.Width, 120);
  ASSERT_EQ(small.Height, 90);
  auto fresh = this->NewWindow();
  EXPECT_LE(MaxAbsDifference(small, RenderScene(fresh, 120, 90)), 1);
  // and back up, larger than it started
  window->SetSize(300, 225);
  window->Render();
  const Image large = Capture(window);
  ASSERT_EQ(large.Width, 300);
  auto fresh2 = this->NewWindow();
  EXPECT_LE(MaxAbsDifference(large, RenderScene(fresh2, 300, 225)), 1);
}

TEST_P(HeadlessLifecycle, FinalizeAndInitializeAgain)
{
  auto window = this->NewWindow();
  const Image before = RenderScene(window);
  auto* headless = vtkHeadlessRenderWindow::SafeDownCast(window);
  ASSERT_NE(headless, nullptr);
  EXPECT_TRUE(headless->HasContext());
  for (int i = 0; i < 3; ++i)
  {
    window->Finalize();
    EXPECT_FALSE(headless->HasContext());
    window->Render();
    EXPECT_TRUE(headless->HasContext());
    EXPECT_EQ(MaxAbsDifference(before, Capture(window)), 0) << "after re-initialisation " << i;
  }
  window->Finalize();
  headless->Initialize();
  EXPECT_TRUE(headless->HasContext());
  window->Render();
  EXPECT_EQ(MaxAbsDifference(before, Capture(window)), 0);
}

TEST_P(HeadlessLifecycle, DeleteAndRecreate)
{
  Image first;
  for (int i = 0; i < 25; ++i)
  {
    auto window = this->NewWindow();
    const Image image = RenderScene(window);
    if (i == 0)
    {
      first = image;
    }
    ASSERT_EQ(MaxAbsDifference(first, image), 0) << "window " << i;
  }
}

long ResidentKiB()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind("VmRSS:", 0) == 0)
    {
      return std::atol(line.c_str() + 6);
    }
  }
  return 0;
}

TEST_P(HeadlessLifecycle, ThousandsOfFrames)
{
  auto window = this->NewWindow();
  vtkRenderer* renderer = AddScene(window, 96, 72);
  window->Render();
  const Image start = Capture(window);
  long residentAfterWarmUp = 0;
  for (int frame = 1; frame <= 2000; ++frame)
  {
    renderer->GetActiveCamera()->Azimuth(0.18); // a full turn over 2000 frames
    window->Render();
    if (frame == 200)
    {
      residentAfterWarmUp = ResidentKiB();
    }
  }
  // The camera is back where it started, and so are the pixels.
  const Image end = Capture(window);
  EXPECT_LE(MaxAbsDifference(start, end), 1);
  // No per-frame leak: 1800 frames add less than 16 MiB (a leak of 10 KB a frame would show).
  EXPECT_LT(ResidentKiB() - residentAfterWarmUp, 16 * 1024);
}

TEST_P(HeadlessLifecycle, ReadbackDoesNotRenderAgain)
{
  auto window = this->NewWindow();
  AddScene(window);
  RenderCounter counter(window);
  window->Render();
  ASSERT_EQ(counter.Renders(), 1);
  const Image first = Capture(window); // vtkWindowToImageFilter without re-render
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 239, 179, 1, pixels);
  EXPECT_EQ(counter.Renders(), 1);
  ExpectLambertSphere(first);
  ASSERT_EQ(pixels->GetNumberOfTuples(), 240 * 180);
  for (vtkIdType i = 0; i < pixels->GetNumberOfValues(); ++i)
  {
    ASSERT_EQ(pixels->GetValue(i), first.Pixels[i]) << "value " << i;
  }
  // The filter's default re-renders exactly once and reads the same frame.
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  EXPECT_EQ(counter.Renders(), 2);
  EXPECT_EQ(MaxAbsDifference(first, phongvtk::testing::FromImageData(grab->GetOutput())), 0);
}

TEST_P(HeadlessLifecycle, PushAndPopSurviveADeletedWindow)
{
  auto window = this->NewWindow();
  auto* a = vtkHeadlessRenderWindow::SafeDownCast(window);
  const Image expected = RenderScene(a);
  vtkSmartPointer<vtkRenderWindow> held = this->NewWindow();
  vtkHeadlessRenderWindow* b = vtkHeadlessRenderWindow::SafeDownCast(held);
  AddScene(b);
  b->Render();
  // b is current when a pushes; b goes away before a pops.
  b->MakeCurrent();
  a->PushContext();
  held = nullptr; // deletes b
  a->PopContext();
  a->Render();
  EXPECT_EQ(MaxAbsDifference(expected, Capture(a)), 0);
}

TEST_P(HeadlessLifecycle, DeletedOnAnotherThread)
{
  vtkSmartPointer<vtkRenderWindow> a = this->NewWindow();
  RenderScene(a);
  std::thread([&a] { a = nullptr; }).join(); // the last reference goes on the other thread
  auto b = this->NewWindow();
  ExpectLambertSphere(RenderScene(b));
}

TEST_P(HeadlessLifecycle, AThreadThatEndsReleasesItsContext)
{
  // A worker renders and ends without releasing: the window renders on the main thread after.
  auto window = this->NewWindow();
  AddScene(window);
  std::thread([&window] { window->Render(); }).join();
  MessageCatcher messages;
  window->Render();
  ExpectLambertSphere(Capture(window));
  EXPECT_TRUE(messages.Errors().empty()) << messages.Errors()[0];
}

TEST_P(HeadlessLifecycle, HandedToAnotherThreadAfterReleaseCurrent)
{
  auto window = this->NewWindow();
  const Image expected = RenderScene(window);
  window->ReleaseCurrent();
  Image there;
  std::thread(
    [&]
    {
      window->Render();
      there = Capture(window);
      window->ReleaseCurrent();
    })
    .join();
  EXPECT_EQ(MaxAbsDifference(expected, there), 0);
}

INSTANTIATE_TEST_SUITE_P(Backends, HeadlessLifecycle, ::testing::Values("OSMesa", "EGL"),
  [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

//------------------------------------------------------------------------------
// With an X server (Xvfb, started here when installed): `auto` keeps VTK's own window, and GLX and
// headless windows take turns on one thread.
class Xvfb
{
public:
  Xvfb()
  {
    if (access("/usr/bin/Xvfb", X_OK) != 0)
    {
      return;
    }
    // The server picks a free display itself and writes its number to the pipe once it accepts
    // connections (-displayfd): tests running in parallel never race for the same display.
    int ready[2];
    if (pipe(ready) != 0)
    {
      return;
    }
    this->Pid = fork();
    if (this->Pid == 0)
    {
      close(ready[0]);
      const std::string fd = std::to_string(ready[1]);
      // -noreset: a server resets when its last client leaves and refuses connections meanwhile
      execl("/usr/bin/Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-noreset", "-nolisten", "tcp",
        "-screen", "0", "640x480x24", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(ready[1]);
    std::string number;
    pollfd wait = { ready[0], POLLIN, 0 };
    char c = 0;
    // Until the newline, EOF (the server exited) or 10 s without a word.
    while (this->Pid > 0 && poll(&wait, 1, 10000) == 1 && read(ready[0], &c, 1) == 1 && c != '\n')
    {
      number += c;
    }
    close(ready[0]);
    if (c == '\n' && !number.empty())
    {
      this->Display = ":" + number;
    }
  }
  ~Xvfb()
  {
    if (this->Pid > 0)
    {
      kill(this->Pid, SIGTERM);
      waitpid(this->Pid, nullptr, 0);
    }
  }
  Xvfb(const Xvfb&) = delete;
  void operator=(const Xvfb&) = delete;
  std::string Display;

private:
  pid_t Pid = -1;
};

class WithXServer : public ::testing::Test
{
protected:
  void SetUp() override
  {
    unsetenv("PHONGVTK_HEADLESS");
    if (this->Server.Display.empty())
    {
      PHONGVTK_SKIP() << "Xvfb is not installed (Debian package xvfb)";
    }
    setenv("DISPLAY", this->Server.Display.c_str(), 1);
  }
  void TearDown() override { unsetenv("DISPLAY"); }
  Xvfb Server;
};

TEST_F(WithXServer, AutoKeepsVTKsOwnWindow)
{
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  EXPECT_STREQ(window->GetClassName(), "vtkXOpenGLRenderWindow");
  setenv("PHONGVTK_HEADLESS", "osmesa", 1);
  window = vtkSmartPointer<vtkRenderWindow>::New();
  EXPECT_STREQ(window->GetClassName(), "vtkHeadlessOSMesaRenderWindow");
}

TEST_F(WithXServer, GLXAndHeadlessWindowsTakeTurnsOnOneThread)
{
  vtkSmartPointer<vtkRenderWindow> x = vtkSmartPointer<vtkRenderWindow>::New();
  ASSERT_STREQ(x->GetClassName(), "vtkXOpenGLRenderWindow");
  x->SetOffScreenRendering(1);
  x->SetMultiSamples(0);
  auto osmesa = NewOSMesa();
  auto egl = NewEGL();
  AddScene(x);
  AddScene(osmesa);
  AddScene(egl);
  MessageCatcher messages;
  for (int round = 0; round < 2; ++round)
  {
    for (vtkRenderWindow* window : { static_cast<vtkRenderWindow*>(x), osmesa.Get(), egl.Get() })
    {
      window->Render();
      SCOPED_TRACE(std::string(window->GetClassName()) + " round " + std::to_string(round));
      ExpectLambertSphere(Capture(window));
    }
  }
  EXPECT_TRUE(messages.Errors().empty()) << messages.Errors()[0];
}

//------------------------------------------------------------------------------
// The fallback when OSMesa cannot be used. OSMesa is looked up once per process, so each case
// runs in a child process of its own (a death test re-running this binary).
int FallbackChild(const char* osmesa, int abi, const char* expectedReason)
{
  phongvtk::headless::SetOSMesaLibrariesForTesting(osmesa, "libGLdispatch.so.0", abi);
  unsetenv("DISPLAY");
  unsetenv("PHONGVTK_HEADLESS");
  int failures = 0;
  auto fail = [&failures](const std::string& what)
  {
    std::fprintf(stderr, "FAILED: %s\n", what.c_str());
    ++failures;
  };
  MessageCatcher messages;
  vtkSmartPointer<vtkRenderWindow> first = vtkSmartPointer<vtkRenderWindow>::New();
  vtkSmartPointer<vtkRenderWindow> second = vtkSmartPointer<vtkRenderWindow>::New();
  if (!first->IsA("vtkHeadlessEGLRenderWindow") || !second->IsA("vtkHeadlessEGLRenderWindow"))
  {
    fail(std::string("the factory made ") + first->GetClassName());
  }
  if (messages.Warnings().size() != 1)
  {
    fail("expected one warning, got " + std::to_string(messages.Warnings().size()));
  }
  else if (messages.Warnings()[0].find(expectedReason) == std::string::npos ||
    messages.Warnings()[0].find("EGL") == std::string::npos)
  {
    fail("the warning does not say why and what instead: " + messages.Warnings()[0]);
  }
  // The fallback renders the scene.
  const Image image = RenderScene(first);
  if (image.Width != 240 || std::abs(image.At(120, 90, 0) - 255) > 2)
  {
    fail("the EGL fallback did not render the scene");
  }
  // vtkHeadlessRenderWindow::New() falls back the same way, without a second warning.
  vtkSmartPointer<vtkHeadlessRenderWindow> named = vtkSmartPointer<vtkHeadlessRenderWindow>::New();
  if (std::string(named->GetBackendName()) != "EGL" || messages.Warnings().size() != 1)
  {
    fail("vtkHeadlessRenderWindow::New() did not fall back quietly");
  }
  // An OSMesa window made by name reports the reason once and renders nothing, no crash.
  vtkSmartPointer<vtkRenderWindow> byName = NewOSMesa();
  AddScene(byName);
  for (int i = 0; i < 3; ++i)
  {
    byName->Render();
  }
  vtkNew<vtkUnsignedCharArray> pixels;
  byName->GetPixelData(0, 0, 9, 9, 1, pixels);
  if (messages.Errors().empty() || messages.Errors()[0].find(expectedReason) == std::string::npos)
  {
    fail("the OSMesa window did not report why it cannot render");
  }
  if (messages.Errors().size() != 2) // the context, once; the readback of nothing
  {
    fail("expected two errors, got " + std::to_string(messages.Errors().size()));
  }
  return failures;
}

TEST(HeadlessFallback, MissingOSMesaFallsBackToEGLWithOneWarning)
{
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(std::exit(FallbackChild(
                "libOSMesa-not-installed.so.8", 1, "cannot load libOSMesa-not-installed.so.8")),
    ::testing::ExitedWithCode(0), "");
}

TEST(HeadlessFallback, DispatchABIMismatchFallsBackToEGLWithOneWarning)
{
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(std::exit(FallbackChild("libOSMesa.so.8", 2, "dispatch ABI version 1")),
    ::testing::ExitedWithCode(0), "");
}
}
