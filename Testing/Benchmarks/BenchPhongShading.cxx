// Google Benchmark of vtkPhongPolyDataMapper, side by side in one run, headless (Mesa llvmpipe):
//
// 1. Frame time against VTK's stock mapper (the anchor) and against the general (unspecialised)
//    Phong shader, at 1024 x 1024: a 1,000,000-triangle sphere (vertex-bound) and an 8,192-triangle
//    sphere filling the window (fragment-bound); each with VTK's default scene (headlight, diffuse
//    only: ambient and specular drop out) and with every term present (ambient, diffuse,
//    specular).
// 2. The accuracy/tessellation table (--table, after the benchmarks): a sphere at increasing
//    tessellation rendered flat, Gouraud and Phong, RMS and max error in LSB against the model
//    evaluated on the exact sphere (PhongVTKPhongReference.h, pixels away from the silhouette),
//    and the frame time of each.
//
//   PhongVTKBenchPhongShading [--benchmark_repetitions=5] [--table]
#include "PhongVTKPhongReference.h"
#include "vtkPhongPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include "PhongVTKMedianReporter.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

using namespace phongvtk::testing;

namespace
{
constexpr int Size = 1024;

vtkPolyData* Mesh(bool large)
{
  static vtkSmartPointer<vtkPolyData> big = SphereMesh(1000, 502);
  static vtkSmartPointer<vtkPolyData> small = SphereMesh(64, 66);
  return large ? big.Get() : small.Get();
}

enum class Mapper
{
  Stock,
  General,
  Phong,
  Gouraud,
  Flat
};

struct Bench
{
  vtkSmartPointer<vtkRenderWindow> Window = vtkSmartPointer<vtkRenderWindow>::New();
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
};

void Setup(Bench& bench, Mapper kind, vtkPolyData* mesh, bool allTerms, bool fill)
{
  vtkSmartPointer<vtkOpenGLPolyDataMapper> mapper;
  if (kind == Mapper::Stock)
  {
    mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
  }
  else
  {
    auto phong = vtkSmartPointer<vtkPhongPolyDataMapper>::New();
    phong->SetSpecializeShaders(kind != Mapper::General);
    mapper = phong;
  }
  mapper->SetInputData(mesh);
  bench.Actor->SetMapper(mapper);
  vtkProperty* p = bench.Actor->GetProperty();
  p->SetInterpolation(kind == Mapper::Flat ? VTK_FLAT
      : kind == Mapper::Gouraud            ? VTK_GOURAUD
                                           : VTK_PHONG);
  if (allTerms)
  {
    Apply(WarmMaterial(), p);
  }
  bench.Renderer->AddActor(bench.Actor);
  vtkCamera* camera = bench.Renderer->GetActiveCamera();
  camera->SetPosition(0, 0, fill ? 0.9 : 4);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewAngle(30);
  bench.Renderer->ResetCameraClippingRange();
  bench.Window->AddRenderer(bench.Renderer);
  bench.Window->SetSize(Size, Size);
  bench.Window->Render();
  bench.Window->WaitForCompletion();
}

void Frame(benchmark::State& state, Mapper kind, bool large, bool allTerms)
{
  Bench bench;
  Setup(bench, kind, Mesh(large), allTerms, !large);
  for (auto _ : state)
  {
    const auto start = std::chrono::steady_clock::now();
    bench.Renderer->GetActiveCamera()->Azimuth(1.0);
    bench.Window->Render();
    bench.Window->WaitForCompletion();
    const auto stop = std::chrono::steady_clock::now();
    state.SetIterationTime(std::chrono::duration<double>(stop - start).count());
  }
  state.counters["triangles"] = static_cast<double>(Mesh(large)->GetNumberOfCells());
}

const char* MapperName(Mapper kind)
{
  const char* names[] = { "Stock", "General", "Phong", "Gouraud", "Flat" };
  return names[static_cast<int>(kind)];
}

// Median frame time of `frames` frames of an already drawn scene, in ms.
double MedianFrameMs(vtkRenderWindow* window, vtkRenderer* renderer, int frames)
{
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    renderer->GetActiveCamera()->Azimuth(0.5);
    window->Render();
    window->WaitForCompletion();
    ms.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

// The tessellation table: for each mode, error against the exact sphere and frame time.
void TessellationTable()
{
  const int size = 512;
  SceneSpec scene;
  LightSpec key;
  key.Position = { -1, 1, 2 };
  LightSpec fill;
  fill.Position = { 1.5, -0.5, 1 };
  fill.Diffuse = { 0.3, 0.4, 0.8 };
  fill.Specular = { 0.3, 0.4, 0.8 };
  scene.Lights = { key, fill };
  scene.RendererAmbient = { 0.2, 0.2, 0.2 };
  const MaterialSpec material = WarmMaterial();
  CameraSpec camera;
  camera.Position = { 0, 0, 2.2 };
  const Reference truth = AnalyticSphere(scene, material, camera, { 0, 0, 0 }, 0.5, size, size);

  struct Row
  {
    int Triangles;
    double RMS[3], Max[3], Ms[3];
  };
  std::vector<Row> rows;
  const int resolutions[][2] = { { 8, 6 }, { 16, 10 }, { 32, 18 }, { 64, 34 }, { 128, 66 },
    { 256, 130 }, { 512, 258 }, { 1024, 514 } };
  for (const auto& res : resolutions)
  {
    auto mesh = SphereMesh(res[0], res[1]);
    Row row{ static_cast<int>(mesh->GetNumberOfCells()), {}, {}, {} };
    int column = 0;
    for (int interpolation : { VTK_FLAT, VTK_GOURAUD, VTK_PHONG })
    {
      vtkNew<vtkPhongPolyDataMapper> mapper;
      mapper->SetInputData(mesh);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      Apply(material, actor->GetProperty());
      actor->GetProperty()->SetInterpolation(interpolation);
      vtkNew<vtkRenderer> renderer;
      renderer->AddActor(actor);
      Apply(scene, camera, renderer);
      vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
      window->AddRenderer(renderer);
      window->SetSize(size, size);
      window->Render();
      const Agreement a = Compare(Capture(window), truth);
      row.RMS[column] = a.RMS;
      row.Max[column] = a.Max;
      row.Ms[column] = MedianFrameMs(window, renderer, 15);
      ++column;
    }
    rows.push_back(row);
  }

  std::printf("\nError against the exact sphere (RMS / max LSB over %d x %d pixels away from the "
              "silhouette) and frame time (median of 15, ms), two coloured lights, all terms:\n",
    size, size);
  std::printf("%10s  %16s %16s %16s  %8s %8s %8s\n", "triangles", "flat rms/max", "gouraud rms/max",
    "phong rms/max", "flat ms", "gour ms", "phong ms");
  for (const Row& r : rows)
  {
    std::printf("%10d  %7.2f / %6.1f %7.2f / %6.1f %7.2f / %6.1f  %8.1f %8.1f %8.1f\n", r.Triangles,
      r.RMS[0], r.Max[0], r.RMS[1], r.Max[1], r.RMS[2], r.Max[2], r.Ms[0], r.Ms[1], r.Ms[2]);
  }
  const char* names[] = { "flat", "gouraud", "phong" };
  for (int m = 0; m < 3; ++m)
  {
    const auto first =
      std::find_if(rows.begin(), rows.end(), [m](const Row& r) { return r.RMS[m] <= 1.0; });
    if (first == rows.end())
    {
      std::printf(
        "%-8s never reaches 1 LSB RMS up to %d triangles\n", names[m], rows.back().Triangles);
    }
    else
    {
      std::printf("%-8s reaches 1 LSB RMS at %d triangles\n", names[m], first->Triangles);
    }
  }
  // Phong at N triangles against flat at about N^2 triangles.
  for (const Row& r : rows)
  {
    const double n2 = double(r.Triangles) * r.Triangles;
    const auto flat =
      std::find_if(rows.begin(), rows.end(), [n2](const Row& q) { return q.Triangles >= n2; });
    if (flat != rows.end())
    {
      std::printf("phong at %d triangles: RMS %.2f LSB; flat at %d (>= N^2): RMS %.2f LSB\n",
        r.Triangles, r.RMS[2], flat->Triangles, flat->RMS[0]);
    }
  }
}

}

int main(int argc, char** argv)
{
  bool table = false;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--table") == 0)
    {
      table = true;
    }
    else
    {
      args.push_back(argv[i]);
    }
  }
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  for (bool large : { true, false })
  {
    for (bool allTerms : { false, true })
    {
      for (Mapper kind :
        { Mapper::Stock, Mapper::General, Mapper::Phong, Mapper::Gouraud, Mapper::Flat })
      {
        const std::string name = std::string(large ? "Mesh1M" : "Fill8K") +
          (allTerms ? ".AllTerms." : ".DiffuseOnly.") + MapperName(kind);
        benchmark::RegisterBenchmark(name.c_str(), Frame, kind, large, allTerms)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond)
          ->MinTime(1.0);
      }
    }
  }
  phongvtk::benchmarks::MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  std::printf("\nFrame time at %d x %d (medians when repeated), ratio = time / stock time "
              "(lower is faster):\n",
    Size, Size);
  std::printf(
    "%-24s %10s %10s %10s %10s %10s\n", "scene", "stock ms", "general", "phong", "gouraud", "flat");
  for (const char* scene :
    { "Mesh1M.DiffuseOnly", "Mesh1M.AllTerms", "Fill8K.DiffuseOnly", "Fill8K.AllTerms" })
  {
    auto seconds = [&](const char* mapper)
    {
      const auto it = reporter.Seconds.find(std::string(scene) + "." + mapper);
      return it == reporter.Seconds.end() ? 0.0 : it->second;
    };
    const double stock = seconds("Stock");
    if (stock <= 0)
    {
      continue;
    }
    std::printf("%-24s %10.1f", scene, 1e3 * stock);
    for (const char* mapper : { "General", "Phong", "Gouraud", "Flat" })
    {
      std::printf(" %9.2fx", seconds(mapper) / stock);
    }
    std::printf("\n");
  }
  if (table)
  {
    TessellationTable();
  }
  return 0;
}
