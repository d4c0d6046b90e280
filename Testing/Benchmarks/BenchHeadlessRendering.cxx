// Google Benchmark of the headless render windows: first-frame and frame times of 1,000,000
// triangles at 1024 x 1024 per backend, side by side in one run, with VTK's own (GLX) window under
// Xvfb as the anchor when an X server is reachable. scripts/bench-headless.sh starts Xvfb when it
// is installed and runs this program:
//
//   scripts/bench-headless.sh [--benchmark_repetitions=5]
//
// First frame: window creation to the first finished frame (context, shader compilation, upload
// of the mesh); the window is destroyed outside the timing. Frame: the camera turns by one degree
// and the scene is drawn and finished (glFinish). Frame+readback adds vtkWindowToImageFilter.
// All backends are Mesa llvmpipe on the CPU (LP_NUM_THREADS sets its threads).
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessOSMesaRenderWindow.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include "PhongVTKMedianReporter.h"
#include <X11/Xlib.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

namespace
{
constexpr int Size = 1024;

// vtkSphereSource makes 2 theta (phi - 2) triangles: 1000 x 502 gives 1,000,000.
vtkPolyData* Mesh()
{
  static vtkSmartPointer<vtkPolyData> mesh = []
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(1000);
    sphere->SetPhiResolution(502);
    sphere->Update();
    vtkSmartPointer<vtkPolyData> out = sphere->GetOutput();
    return out;
  }();
  return mesh;
}

using WindowMaker = std::function<vtkSmartPointer<vtkRenderWindow>()>;

vtkSmartPointer<vtkRenderer> AddScene(vtkRenderWindow* window)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(Mesh());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  renderer->ResetCamera();
  window->AddRenderer(renderer);
  window->SetSize(Size, Size);
  return renderer;
}

void FirstFrame(benchmark::State& state, const WindowMaker& make)
{
  for (auto _ : state)
  {
    const auto start = std::chrono::steady_clock::now();
    vtkSmartPointer<vtkRenderWindow> window = make();
    AddScene(window);
    window->Render();
    window->WaitForCompletion();
    const auto stop = std::chrono::steady_clock::now();
    state.SetIterationTime(std::chrono::duration<double>(stop - start).count());
  }
  state.counters["triangles"] = static_cast<double>(Mesh()->GetNumberOfCells());
}

void Frame(benchmark::State& state, const WindowMaker& make, bool readBack)
{
  vtkSmartPointer<vtkRenderWindow> window = make();
  vtkRenderer* renderer = AddScene(window);
  window->Render();
  window->WaitForCompletion();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ShouldRerenderOff();
  for (auto _ : state)
  {
    const auto start = std::chrono::steady_clock::now();
    renderer->GetActiveCamera()->Azimuth(1.0);
    window->Render();
    if (readBack)
    {
      grab->Modified();
      grab->Update();
    }
    window->WaitForCompletion();
    const auto stop = std::chrono::steady_clock::now();
    state.SetIterationTime(std::chrono::duration<double>(stop - start).count());
  }
  state.SetLabel(
    std::string(window->GetClassName()) + " MSAA=" + std::to_string(window->GetMultiSamples()));
}

// Whether an X server is reachable. The connection stays open for the whole run: an X server
// resets when its last client leaves and refuses connections while it does.
bool XServerReachable()
{
  const char* name = std::getenv("DISPLAY");
  static Display* held = name && *name ? XOpenDisplay(name) : nullptr;
  return held != nullptr;
}

// VTK's own window (the factory left alone): as VTK makes it (on screen, multisampled as VTK's
// global default says), or doing the headless windows' work (off screen, no multisampling).
vtkSmartPointer<vtkRenderWindow> NewVTKWindow(bool sameWork)
{
  setenv("PHONGVTK_HEADLESS", "off", 1);
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  if (sameWork)
  {
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
  }
  return window;
}

}

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  std::map<std::string, WindowMaker> backends;
  backends["OSMesa"] = []
  {
    return vtkSmartPointer<vtkHeadlessOSMesaRenderWindow>::New();
  };
  backends["EGL"] = []
  {
    return vtkSmartPointer<vtkHeadlessEGLRenderWindow>::New();
  };
  const bool xvfb = XServerReachable();
  if (xvfb)
  {
    backends["Xvfb.GLX"] = []
    {
      return NewVTKWindow(false);
    };
    backends["Xvfb.GLX.SameWork"] = []
    {
      return NewVTKWindow(true);
    };
  }
  else
  {
    std::printf("No X server reachable (DISPLAY): VTK's own window is not measured. "
                "scripts/bench-headless.sh starts Xvfb when it is installed.\n");
  }
  Mesh();
  for (const auto& backend : backends)
  {
    const WindowMaker make = backend.second;
    benchmark::RegisterBenchmark(
      ("FirstFrame/" + backend.first).c_str(), [make](benchmark::State& s) { FirstFrame(s, make); })
      ->Unit(benchmark::kMillisecond)
      ->UseManualTime()
      ->Iterations(3);
    benchmark::RegisterBenchmark(
      ("Frame/" + backend.first).c_str(), [make](benchmark::State& s) { Frame(s, make, false); })
      ->Unit(benchmark::kMillisecond)
      ->UseManualTime()
      ->MinTime(2.0);
    benchmark::RegisterBenchmark(("FrameReadback/" + backend.first).c_str(),
      [make](benchmark::State& s) { Frame(s, make, true); })
      ->Unit(benchmark::kMillisecond)
      ->UseManualTime()
      ->MinTime(2.0);
  }
  phongvtk::benchmarks::MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  const char* threads = std::getenv("LP_NUM_THREADS");
  std::printf("\n%lld triangles at %d x %d, llvmpipe threads %s. Medians when repeated; "
              "ratios: anchor time / backend time (higher is faster).\n",
    static_cast<long long>(Mesh()->GetNumberOfCells()), Size, Size,
    threads ? threads : "(Mesa's default: one per core)");
  // Anchors: VTK's window as VTK makes it, and VTK's window doing the same work.
  const std::string anchor = xvfb ? "Xvfb.GLX" : "OSMesa";
  const std::string sameWork = xvfb ? "Xvfb.GLX.SameWork" : "OSMesa";
  auto seconds = [&](const std::string& name)
  {
    auto it = reporter.Seconds.find(name);
    return it == reporter.Seconds.end() ? 0.0 : it->second;
  };
  std::printf("%-20s %14s %10s %14s %10s %12s %12s\n", "window", "first frame ms", "frame ms",
    "frame+read ms", "frame fps", ("vs " + anchor).c_str(), ("vs " + sameWork).c_str());
  for (const auto& backend : backends)
  {
    const std::string& b = backend.first;
    const double first = seconds("FirstFrame/" + b);
    const double frame = seconds("Frame/" + b);
    const double read = seconds("FrameReadback/" + b);
    const double anchorFrame = seconds("Frame/" + anchor);
    const double sameWorkFrame = seconds("Frame/" + sameWork);
    std::printf("%-20s %14.1f %10.1f %14.1f %10.1f %11.2fx %11.2fx\n", b.c_str(), 1e3 * first,
      1e3 * frame, 1e3 * read, frame > 0 ? 1.0 / frame : 0.0, frame > 0 ? anchorFrame / frame : 0.0,
      frame > 0 ? sameWorkFrame / frame : 0.0);
  }
  benchmark::Shutdown();
  return 0;
}
