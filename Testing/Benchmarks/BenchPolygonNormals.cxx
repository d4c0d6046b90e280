// Google Benchmark of vtkPolygonNormals against VTK's own normal filters, measured side by side
// in one run, with a table of ratios at the end.
//
//   VTK_SMP_BACKEND_IN_USE=STDThread build/bin/PhongVTKBenchPolygonNormals
//       [--benchmark_repetitions=5] [--benchmark_filter=Sphere]
//   scripts/bench-normals.sh      # both SMP backends, then the same from Python
//
// Unless told otherwise, the benchmarks run in random interleaved order, five repetitions each
// (medians), so that PhongVTK and the anchors share the machine's state; the inputs are bare
// geometry, the same as phongvtk.speed's (Python/phongvtk/speed.py).
//
// Meshes: vtkSphereSource 1000 x 1000 (~2,000,000 triangles, float points) and CGAL's bunny
// (75,408 triangles, double points). Anchors: vtkPolyDataNormals with cell normals only, with
// point normals (splitting and consistency off), and vtkTriangleMeshPointNormals. The memory
// floor of cell normals is the bytes the filter must touch divided by the streaming bandwidth
// measured by a copy benchmark in the same run.
#include "vtkPolygonNormals.h"
#include "vtkVisibleArea.h"

#include "PhongVTKBenchmarkMeshes.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMassProperties.h"
#include "vtkPolyDataNormals.h"
#include "vtkSMPTools.h"
#include "vtkTriangleMeshPointNormals.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace
{
struct Mesh
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Data;
};

std::vector<Mesh>& Meshes()
{
  static std::vector<Mesh> meshes;
  return meshes;
}

void RunFilter(benchmark::State& state, vtkPolyDataAlgorithm* filter, vtkPolyData* input)
{
  filter->SetInputData(input);
  for (auto _ : state)
  {
    filter->Modified();
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput());
  }
  state.counters["ns/cell"] = benchmark::Counter(static_cast<double>(input->GetNumberOfCells()),
    benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void PolyDataNormalsCells(benchmark::State& state, vtkPolyData* input)
{
  vtkNew<vtkPolyDataNormals> f;
  f->ComputeCellNormalsOn();
  f->ComputePointNormalsOff();
  f->SplittingOff();
  f->ConsistencyOff();
  RunFilter(state, f, input);
}

void PolyDataNormalsPoints(benchmark::State& state, vtkPolyData* input)
{
  vtkNew<vtkPolyDataNormals> f;
  f->ComputeCellNormalsOff();
  f->ComputePointNormalsOn();
  f->SplittingOff();
  f->ConsistencyOff();
  RunFilter(state, f, input);
}

void TriangleMeshPointNormals(benchmark::State& state, vtkPolyData* input)
{
  vtkNew<vtkTriangleMeshPointNormals> f;
  RunFilter(state, f, input);
}

void PolygonNormals(benchmark::State& state, vtkPolyData* input, int accuracy, bool points,
  bool pieceInvariant = true)
{
  vtkNew<vtkPolygonNormals> f;
  f->SetAccuracy(accuracy);
  f->SetComputeCellNormals(!points);
  f->SetComputePointNormals(points);
  f->SetPieceInvariant(pieceInvariant);
  f->SetConsistency(false); // the polygons as given, no splitting: the normals alone are timed
  f->SetSplitting(false);
  RunFilter(state, f, input);
}

/// vtkVisibleArea toward (1, 2, 2) or from a perspective camera, with or without the edge pass
/// of MaxVisibleArea.
void VisibleArea(
  benchmark::State& state, vtkPolyData* input, int accuracy, bool camera, bool maxArea)
{
  vtkNew<vtkVisibleArea> f;
  f->SetAccuracy(accuracy);
  f->SetViewDirection(1.0, 2.0, 2.0);
  f->SetComputeMaxVisibleArea(maxArea);
  vtkNew<vtkCamera> eye;
  if (camera)
  {
    double b[6];
    input->GetBounds(b);
    eye->SetFocalPoint((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2);
    eye->SetPosition(b[1] + 2 * (b[1] - b[0]), b[3], b[5]);
    f->SetCamera(eye);
  }
  RunFilter(state, f, input);
}

/// VTK's total surface area (triangles), the nearest stock filter.
void MassProperties(benchmark::State& state, vtkPolyData* input)
{
  vtkNew<vtkMassProperties> f;
  f->SetInputData(input);
  for (auto _ : state)
  {
    f->Modified();
    f->Update();
    benchmark::DoNotOptimize(f->GetSurfaceArea());
  }
}

/// Streaming bandwidth: copy of a 256 MiB buffer (read + write bytes per second).
void MemoryCopy(benchmark::State& state)
{
  const std::size_t bytes = std::size_t(256) << 20;
  std::vector<char> a(bytes, 1), b(bytes, 2);
  for (auto _ : state)
  {
    std::memcpy(b.data(), a.data(), bytes);
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<int64_t>(2 * bytes) * state.iterations());
}

/// Bytes vtkPolygonNormals must read and write for cell normals (float output); point normals
/// write 12 bytes a point instead of 12 a cell.
double CellNormalBytes(vtkPolyData* mesh, bool points = false)
{
  vtkCellArray* polys = mesh->GetPolys();
  return static_cast<double>(mesh->GetPoints()->GetData()->GetDataSize()) *
    mesh->GetPoints()->GetData()->GetDataTypeSize() +
    static_cast<double>(polys->GetOffsetsArray()->GetDataSize()) *
    polys->GetOffsetsArray()->GetDataTypeSize() +
    static_cast<double>(polys->GetConnectivityArray()->GetDataSize()) *
    polys->GetConnectivityArray()->GetDataTypeSize() +
    12.0 * static_cast<double>(points ? mesh->GetNumberOfPoints() : mesh->GetNumberOfCells());
}

const char* ModeName(int mode)
{
  static const char* names[] = { "FAST", "DOUBLE", "COMPENSATED", "EXACT" };
  return names[mode];
}

/// Collects the median (or only) real time of every benchmark for the ratio table.
class RatioReporter : public benchmark::ConsoleReporter
{
public:
  std::map<std::string, double> Seconds;
  double Bandwidth = 0.0;

  void ReportRuns(const std::vector<Run>& runs) override
  {
    benchmark::ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs)
    {
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      const bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
      if (!median && !single)
      {
        continue;
      }
      const std::string name = run.run_name.function_name;
      this->Seconds[name] = run.real_accumulated_time / static_cast<double>(run.iterations);
      if (name == "MemoryCopy")
      {
        auto it = run.counters.find("bytes_per_second");
        if (it != run.counters.end())
        {
          this->Bandwidth = it->second;
        }
      }
    }
  }
};
} // namespace

int main(int argc, char** argv)
{
  // Interleaved repetitions unless the command line says otherwise.
  std::vector<char*> args(argv, argv + argc);
  auto given = [&](const char* flag)
  {
    return std::any_of(args.begin(), args.end(),
      [flag](const char* a) { return std::strncmp(a, flag, std::strlen(flag)) == 0; });
  };
  static char interleave[] = "--benchmark_enable_random_interleaving=true";
  static char repetitions[] = "--benchmark_repetitions=5";
  static char aggregates[] = "--benchmark_report_aggregates_only=true";
  if (!given("--benchmark_enable_random_interleaving"))
  {
    args.push_back(interleave);
  }
  if (!given("--benchmark_repetitions"))
  {
    args.push_back(repetitions);
  }
  if (!given("--benchmark_report_aggregates_only"))
  {
    args.push_back(aggregates);
  }
  int count = static_cast<int>(args.size());
  args.push_back(nullptr);
  benchmark::Initialize(&count, args.data());
  Meshes().push_back({ "Sphere2M", phongvtk_bench::Sphere(1000) });
  if (auto bunny = phongvtk_bench::CGALMesh("bunny00.off"))
  {
    Meshes().push_back({ "Bunny", bunny });
  }

  benchmark::RegisterBenchmark("MemoryCopy", MemoryCopy)->Unit(benchmark::kMillisecond);
  for (const Mesh& mesh : Meshes())
  {
    vtkPolyData* data = mesh.Data;
    auto reg = [&](const std::string& name, auto fn)
    {
      benchmark::RegisterBenchmark((mesh.Name + "/" + name).c_str(), fn)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    };
    reg("vtkPolyDataNormals.Cells", [data](benchmark::State& s) { PolyDataNormalsCells(s, data); });
    reg(
      "vtkPolyDataNormals.Points", [data](benchmark::State& s) { PolyDataNormalsPoints(s, data); });
    reg("vtkTriangleMeshPointNormals",
      [data](benchmark::State& s) { TriangleMeshPointNormals(s, data); });
    for (int mode = vtkPolygonNormals::FAST; mode <= vtkPolygonNormals::EXACT; ++mode)
    {
      reg(std::string("PolygonNormals.Cells.") + ModeName(mode),
        [data, mode](benchmark::State& s) { PolygonNormals(s, data, mode, false); });
      reg(std::string("PolygonNormals.Points.") + ModeName(mode),
        [data, mode](benchmark::State& s) { PolygonNormals(s, data, mode, true); });
      reg(std::string("PolygonNormals.PointsInCellOrder.") + ModeName(mode),
        [data, mode](benchmark::State& s) { PolygonNormals(s, data, mode, true, false); });
      reg(std::string("VisibleArea.Direction.") + ModeName(mode),
        [data, mode](benchmark::State& s) { VisibleArea(s, data, mode, false, false); });
      reg(std::string("VisibleArea.Camera.") + ModeName(mode),
        [data, mode](benchmark::State& s) { VisibleArea(s, data, mode, true, false); });
    }
    reg("VisibleArea.Direction.DOUBLE+MaxVisibleArea",
      [data](benchmark::State& s) { VisibleArea(s, data, vtkVisibleArea::DOUBLE, false, true); });
    reg("vtkMassProperties", [data](benchmark::State& s) { MassProperties(s, data); });
  }

  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  std::printf("\nSMP backend %s, %d threads. Ratios: anchor time / PhongVTK time (higher is "
              "faster), medians when repeated.\n",
    vtkSMPTools::GetBackend(), vtkSMPTools::GetEstimatedNumberOfThreads());
  auto seconds = [&](const std::string& name)
  {
    auto it = reporter.Seconds.find(name);
    return it == reporter.Seconds.end() ? 0.0 : it->second;
  };
  for (const Mesh& mesh : Meshes())
  {
    const std::string m = mesh.Name + "/";
    const double cellsAnchor = seconds(m + "vtkPolyDataNormals.Cells");
    const double pointsAnchor = seconds(m + "vtkPolyDataNormals.Points");
    const double triangleAnchor = seconds(m + "vtkTriangleMeshPointNormals");
    const double floor =
      reporter.Bandwidth > 0 ? CellNormalBytes(mesh.Data) / reporter.Bandwidth : 0.0;
    const double pointFloor =
      reporter.Bandwidth > 0 ? CellNormalBytes(mesh.Data, true) / reporter.Bandwidth : 0.0;
    std::printf("\n%s: %lld cells; vtkPolyDataNormals cells %.1f ms, points %.1f ms; "
                "vtkTriangleMeshPointNormals %.1f ms; memory floor cells %.2f ms, points %.2f ms\n",
      mesh.Name.c_str(), static_cast<long long>(mesh.Data->GetNumberOfCells()), 1e3 * cellsAnchor,
      1e3 * pointsAnchor, 1e3 * triangleAnchor, 1e3 * floor, 1e3 * pointFloor);
    std::printf("%-12s %10s %12s %10s | %10s %12s %14s %10s | %14s %12s\n", "mode", "cells ms",
      "vs PDN cells", "x floor", "points ms", "vs PDN points", "vs TriMeshPN", "x floor",
      "cell order ms", "invariant x");
    for (int mode = vtkPolygonNormals::FAST; mode <= vtkPolygonNormals::EXACT; ++mode)
    {
      const double cells = seconds(m + "PolygonNormals.Cells." + ModeName(mode));
      const double points = seconds(m + "PolygonNormals.Points." + ModeName(mode));
      const double cellOrder = seconds(m + "PolygonNormals.PointsInCellOrder." + ModeName(mode));
      if (cells <= 0 || points <= 0 || cellOrder <= 0)
      {
        continue;
      }
      std::printf("%-12s %10.2f %11.1fx %9.2fx | %10.2f %12.1fx %13.1fx %9.2fx | %14.2f %11.2fx\n",
        ModeName(mode), 1e3 * cells, cellsAnchor / cells, floor > 0 ? cells / floor : 0.0,
        1e3 * points, pointsAnchor / points, triangleAnchor / points,
        pointFloor > 0 ? points / pointFloor : 0.0, 1e3 * cellOrder, points / cellOrder);
    }
  }
  for (const Mesh& mesh : Meshes())
  {
    const std::string m = mesh.Name + "/";
    const double normals = seconds(m + "PolygonNormals.Cells.DOUBLE");
    const double mass = seconds(m + "vtkMassProperties");
    const double edges = seconds(m + "VisibleArea.Direction.DOUBLE+MaxVisibleArea") -
      seconds(m + "VisibleArea.Direction.DOUBLE");
    std::printf("\n%s vtkVisibleArea (ratio = time / anchor; anchors: PolygonNormals DOUBLE cells "
                "%.2f ms, vtkMassProperties %.2f ms; MaxVisibleArea's edge pass adds %.2f ms)\n",
      mesh.Name.c_str(), 1e3 * normals, 1e3 * mass, 1e3 * edges);
    std::printf("%-12s %12s %10s %10s | %12s %10s\n", "mode", "direction ms", "/normals", "/mass",
      "camera ms", "/normals");
    for (int mode = vtkPolygonNormals::FAST; mode <= vtkPolygonNormals::EXACT; ++mode)
    {
      const double direction = seconds(m + "VisibleArea.Direction." + ModeName(mode));
      const double camera = seconds(m + "VisibleArea.Camera." + ModeName(mode));
      if (direction <= 0 || camera <= 0 || normals <= 0 || mass <= 0)
      {
        continue;
      }
      std::printf("%-12s %12.2f %9.2fx %9.2fx | %12.2f %9.2fx\n", ModeName(mode), 1e3 * direction,
        direction / normals, direction / mass, 1e3 * camera, camera / normals);
    }
  }
  benchmark::Shutdown();
  return 0;
}
