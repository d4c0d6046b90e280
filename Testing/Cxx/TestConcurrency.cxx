// Concurrency: independent pipelines (vtkPolygonNormals feeding vtkPhongPolyDataMapper in a
// headless window of their own) on two threads at once give the same bits as one after the
// other, on either backend and on both together; a filter made, run and deleted on one thread
// while another thread renders leaves that thread's frames bitwise unchanged. Each pipeline
// owns everything it touches (sources, filters, mapper, window), as VTK asks of threads.
#include "PhongVTKImageRegression.h"
#include "PhongVTKRenderingTestSupport.h"

#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessOSMesaRenderWindow.h"
#include "vtkPhongPolyDataMapper.h"
#include "vtkPolygonNormals.h"
#include "vtkSMPTools.h"
#include "vtkSuperquadricSource.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

namespace
{
using phongvtk::testing::Capture;
using phongvtk::testing::Image;
using phongvtk::testing::MessageCatcher;

enum class Backend
{
  OSMesa,
  EGL
};

// What one pipeline draws: a superquadric (creases and smooth patches) with split, auto-oriented
// EXACT normals, in Phong shading, seen from `Frames` camera positions.
struct Pipeline
{
  int Seed = 0; // shapes the superquadric and the material
  Backend Window = Backend::OSMesa;
  static constexpr int Frames = 6;

  std::vector<Image> Run() const
  {
    vtkNew<vtkSuperquadricSource> shape;
    shape->SetThetaResolution(160 + 16 * this->Seed);
    shape->SetPhiResolution(120 + 8 * this->Seed);
    shape->SetThetaRoundness(0.3 + 0.2 * this->Seed);
    shape->SetPhiRoundness(0.6);
    shape->ToroidalOff();
    vtkNew<vtkPolygonNormals> normals;
    normals->SetInputConnection(shape->GetOutputPort());
    normals->SetAccuracy(vtkPolygonNormals::EXACT);
    normals->ComputePointNormalsOn();
    normals->SplittingOn();
    normals->AutoOrientNormalsOn();
    vtkNew<vtkPhongPolyDataMapper> mapper;
    mapper->SetInputConnection(normals->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetInterpolationToPhong();
    actor->GetProperty()->SetColor(0.9, 0.5 + 0.1 * this->Seed, 0.3);
    actor->GetProperty()->SetSpecular(0.4);
    actor->GetProperty()->SetSpecularPower(20);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    renderer->SetBackground(0.1, 0.2, 0.3);
    vtkSmartPointer<vtkRenderWindow> window = this->Window == Backend::EGL
      ? vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkHeadlessEGLRenderWindow>::New())
      : vtkSmartPointer<vtkRenderWindow>(vtkSmartPointer<vtkHeadlessOSMesaRenderWindow>::New());
    window->AddRenderer(renderer);
    window->SetSize(160, 120);
    renderer->ResetCamera();
    std::vector<Image> frames;
    for (int frame = 0; frame < Frames; ++frame)
    {
      renderer->GetActiveCamera()->Azimuth(25);
      renderer->GetActiveCamera()->Elevation(10);
      renderer->ResetCameraClippingRange();
      window->Render();
      frames.push_back(Capture(window));
    }
    return frames;
  }
};

bool Same(const std::vector<Image>& a, const std::vector<Image>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (a[i].Width != b[i].Width || a[i].Height != b[i].Height || a[i].Pixels != b[i].Pixels)
    {
      return false;
    }
  }
  return true;
}

// The frames of a pipeline show something beside the background (the test would otherwise
// compare two blank images).
bool Drawn(const std::vector<Image>& frames)
{
  for (const Image& image : frames)
  {
    const unsigned char centre = image.At(image.Width / 2, image.Height / 2, 0);
    if (std::abs(centre - 26) <= 2)
    {
      return false;
    }
  }
  return !frames.empty();
}

// The two windows' backends and VTK's SMP backend (the filters' threads inside each pipeline).
using Configuration = std::tuple<Backend, Backend, std::string>;

class Concurrency : public ::testing::TestWithParam<Configuration>
{
protected:
  void SetUp() override
  {
    unsetenv("DISPLAY");
    unsetenv("PHONGVTK_HEADLESS");
    this->Previous = vtkSMPTools::GetBackend();
    ASSERT_TRUE(vtkSMPTools::SetBackend(std::get<2>(GetParam()).c_str()));
  }
  void TearDown() override { vtkSMPTools::SetBackend(this->Previous.c_str()); }
  std::string Previous;
};

TEST_P(Concurrency, TwoPipelinesOnTwoThreadsGiveTheBitsOfOneAfterTheOther)
{
  const Pipeline a{ 0, std::get<0>(GetParam()) };
  const Pipeline b{ 1, std::get<1>(GetParam()) };
  MessageCatcher messages;
  const std::vector<Image> aAlone = a.Run();
  const std::vector<Image> bAlone = b.Run();
  ASSERT_TRUE(Drawn(aAlone));
  ASSERT_TRUE(Drawn(bAlone));
  ASSERT_FALSE(Same(aAlone, bAlone));
  using Clock = std::chrono::steady_clock;
  int overlapping = 0;
  for (int round = 0; round < 3; ++round)
  {
    std::vector<Image> aTogether, bTogether;
    Clock::time_point aStart, aEnd, bStart, bEnd;
    std::thread first(
      [&]
      {
        aStart = Clock::now();
        aTogether = a.Run();
        aEnd = Clock::now();
      });
    std::thread second(
      [&]
      {
        bStart = Clock::now();
        bTogether = b.Run();
        bEnd = Clock::now();
      });
    first.join();
    second.join();
    overlapping += std::max(aStart, bStart) < std::min(aEnd, bEnd);
    EXPECT_TRUE(Same(aAlone, aTogether)) << "round " << round;
    EXPECT_TRUE(Same(bAlone, bTogether)) << "round " << round;
  }
  // The pipelines really ran at the same time (else the test would show nothing).
  EXPECT_GT(overlapping, 0);
  EXPECT_TRUE(messages.Errors().empty()) << messages.Errors()[0];
  EXPECT_TRUE(messages.Warnings().empty()) << messages.Warnings()[0];
}

INSTANTIATE_TEST_SUITE_P(Backends, Concurrency,
  ::testing::Values(Configuration{ Backend::OSMesa, Backend::OSMesa, "Sequential" },
    Configuration{ Backend::EGL, Backend::EGL, "Sequential" },
    Configuration{ Backend::OSMesa, Backend::EGL, "Sequential" },
    Configuration{ Backend::OSMesa, Backend::EGL, "STDThread" }),
  [](const ::testing::TestParamInfo<Configuration>& info)
  {
    auto name = [](Backend b)
    {
      return b == Backend::EGL ? std::string("EGL") : "OSMesa";
    };
    return name(std::get<0>(info.param)) + "And" + name(std::get<1>(info.param)) +
      std::get<2>(info.param);
  });

// One thread renders its pipeline again and again while the other makes, runs and deletes
// filters and windows of its own: the renders are bitwise those of a quiet process.
TEST(ConcurrencyDeletion, FiltersDeletedWhileAnotherThreadRendersLeaveItsFramesUnchanged)
{
  unsetenv("DISPLAY");
  unsetenv("PHONGVTK_HEADLESS");
  MessageCatcher messages;
  const Pipeline rendered{ 0, Backend::OSMesa };
  const std::vector<Image> quiet = rendered.Run();
  ASSERT_TRUE(Drawn(quiet));
  std::atomic<bool> rendering{ true };
  std::atomic<int> different{ 0 };
  std::atomic<int> renders{ 0 };
  std::thread renderer(
    [&]
    {
      for (int round = 0; round < 4; ++round)
      {
        different += !Same(quiet, rendered.Run());
        ++renders;
      }
      rendering = false;
    });
  int deleted = 0;
  while (rendering || deleted < 8)
  {
    // A filter alone, deleted as soon as it has run...
    {
      vtkNew<vtkSuperquadricSource> shape;
      shape->SetThetaResolution(64);
      shape->SetPhiResolution(48);
      auto normals = vtkSmartPointer<vtkPolygonNormals>::New();
      normals->SetInputConnection(shape->GetOutputPort());
      normals->ComputePointNormalsOn();
      normals->SplittingOn();
      normals->Update();
      EXPECT_GT(normals->GetOutput()->GetNumberOfPoints(), 0);
    }
    // ...and every other time a whole pipeline with its window, deleted after one frame.
    if (deleted % 2 == 1)
    {
      const Pipeline other{ 2, deleted % 4 == 1 ? Backend::EGL : Backend::OSMesa };
      EXPECT_TRUE(Drawn(other.Run()));
    }
    ++deleted;
  }
  renderer.join();
  EXPECT_EQ(renders, 4);
  EXPECT_EQ(different, 0);
  EXPECT_TRUE(messages.Errors().empty()) << messages.Errors()[0];
}
}
