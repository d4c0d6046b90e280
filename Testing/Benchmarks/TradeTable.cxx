// PhongVTKTradeTable: the extended normals ladder (the main job prints the Python one,
// scripts/demo.sh). Computes the cell normals of real and hard inputs in every
// accuracy mode of vtkPolygonNormals and prints what each mode costs (ns per polygon, median of
// several runs) and what it buys (worst and median error against exact rational arithmetic, in
// ulps of the output precision and in radians).
//
//   PhongVTKTradeTable [--mesh file.off] [--runs N] [--quick]
#include "vtkPolygonNormals.h"

#include "PhongVTKBenchmarkMeshes.h"
#include "PhongVTKExactReference.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace
{
struct InputClass
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Mesh;
};

struct Reference
{
  std::vector<std::array<mpf_class, 3>> Normals;
  std::vector<bool> Zero; // exact area vector is zero
};

Reference ComputeReference(vtkPolyData* mesh)
{
  Reference ref;
  vtkCellArray* polys = mesh->GetPolys();
  const vtkIdType n = polys->GetNumberOfCells();
  ref.Normals.resize(n);
  ref.Zero.resize(n);
  vtkNew<vtkIdList> ids;
  std::vector<phongvtk_test::Point> polygon;
  for (vtkIdType c = 0; c < n; ++c)
  {
    polys->GetCellAtId(c, ids);
    polygon.resize(ids->GetNumberOfIds());
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      mesh->GetPoint(ids->GetId(i), polygon[i].data());
    }
    const auto w = phongvtk_test::ComputeExactAreaVector(polygon);
    ref.Zero[c] = w.IsZero();
    ref.Normals[c] = phongvtk_test::ReferenceNormal(w);
  }
  return ref;
}

const char* ModeName(int mode)
{
  static const char* names[] = { "FAST", "DOUBLE", "COMPENSATED", "EXACT" };
  return names[mode];
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

/// Median seconds of one Update() of each filter: every filter is warmed up (allocation, first
/// touch), then each sample times a batch of runs of that filter long enough to measure, and the
/// filters take turns starting with a different one each round, so that the machine's drift and
/// noise fall on all of them alike and the ranking is the real one.
std::vector<double> InterleavedMedians(
  std::vector<vtkSmartPointer<vtkPolygonNormals>>& filters, int runs)
{
  auto time = [](vtkPolygonNormals* filter, int count)
  {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < count; ++k)
    {
      filter->Modified();
      filter->Update();
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / count;
  };
  const std::size_t n = filters.size();
  std::vector<int> batches(n, 1);
  for (int round = 0; round < 2; ++round) // the first allocates; the second is a run's cost
  {
    for (std::size_t f = 0; f < n; ++f)
    {
      const double once = time(filters[f], 1);
      batches[f] = std::max(1, static_cast<int>(std::ceil(0.02 / std::max(once, 1e-9))));
    }
  }
  std::vector<std::vector<double>> times(n);
  for (int r = 0; r < runs; ++r)
  {
    for (std::size_t k = 0; k < n; ++k)
    {
      const std::size_t f = (k + static_cast<std::size_t>(r)) % n;
      times[f].push_back(time(filters[f], batches[f]));
    }
  }
  std::vector<double> medians;
  for (auto& t : times)
  {
    medians.push_back(Median(t));
  }
  return medians;
}

/// Prints one row; returns false when EXACT breaks its promise (a normal more than 1 ulp off,
/// or zero where the exact area vector is not, or the reverse), so the smoke run fails then.
bool Row(const InputClass& input, const Reference& ref, int mode, vtkPolygonNormals* filter,
  double seconds)
{
  // FAST is a float mode: its errors are counted in float ulps; the others in double ulps.
  const bool single = mode == vtkPolygonNormals::FAST;
  vtkDataArray* normals = filter->GetOutput()->GetCellData()->GetNormals();
  const vtkIdType n = static_cast<vtkIdType>(ref.Normals.size());
  std::vector<double> ulps, angles;
  ulps.reserve(n);
  angles.reserve(n);
  vtkIdType zeroMismatch = 0;
  for (vtkIdType c = 0; c < n; ++c)
  {
    double v[3];
    normals->GetTuple(c, v);
    const bool isZero = v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
    if (ref.Zero[c] || isZero)
    {
      zeroMismatch += (ref.Zero[c] != isZero);
      continue;
    }
    ulps.push_back(single ? phongvtk_test::NormalUlpError<float>(v, ref.Normals[c])
                          : phongvtk_test::NormalUlpError<double>(v, ref.Normals[c]));
    angles.push_back(phongvtk_test::AngleError(v, ref.Normals[c]));
  }
  const double worstUlp = ulps.empty() ? 0.0 : *std::max_element(ulps.begin(), ulps.end());
  const double worstAngle = angles.empty() ? 0.0 : *std::max_element(angles.begin(), angles.end());
  std::printf("| %-22s | %-11s | %9.1f | %10.3g %-4s | %10.3g | %10.2e | %10.2e | %9lld |\n",
    input.Name.c_str(), ModeName(mode), 1e9 * seconds / static_cast<double>(n), worstUlp,
    single ? "(f)" : "(d)", Median(ulps), worstAngle, Median(angles),
    static_cast<long long>(zeroMismatch));
  return mode != vtkPolygonNormals::EXACT || (worstUlp <= 1.0 && zeroMismatch == 0);
}
} // namespace

int main(int argc, char** argv)
{
  std::string meshPath = phongvtk_test::CGALMeshPath("bunny00.off");
  int runs = 7;
  vtkIdType synthetic = 50000;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc)
    {
      meshPath = argv[++i];
    }
    else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc)
    {
      runs = std::max(1, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--quick"))
    {
      runs = 1;
      synthetic = 2000;
    }
    else
    {
      std::printf("usage: %s [--mesh file.off] [--runs N] [--quick]\n"
                  "Prints the speed/accuracy trade of vtkPolygonNormals' accuracy modes.\n",
        argv[0]);
      return std::strcmp(argv[i], "--help") ? 2 : 0;
    }
  }
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = phongvtk_test::ReadOFF(meshPath, &error);
  if (!mesh)
  {
    std::fprintf(
      stderr, "PhongVTKTradeTable: cannot read %s: %s\n", meshPath.c_str(), error.c_str());
    return 1;
  }
  const std::string base = meshPath.substr(meshPath.find_last_of('/') + 1);
  std::vector<InputClass> inputs = {
    { "ordinary: " + base, mesh },
    { "far offset 1e12", phongvtk_bench::Transformed(mesh, 0, 1e12) },
    { "needles, aspect 1e12", phongvtk_bench::Needles(synthetic) },
    { "tiny scale 2^-1000", phongvtk_bench::Transformed(mesh, -1000, 0.0) },
    { "huge scale 2^1000", phongvtk_bench::Transformed(mesh, 1000, 0.0) },
    { "non-planar hexagons", phongvtk_bench::NonPlanar(synthetic) },
  };
  std::printf("vtkPolygonNormals speed/accuracy trade (%s: %lld polygons; SMP backend %s, %d "
              "threads; time = median of %d interleaved, warmed-up samples)\n"
              "Errors against exact rational arithmetic; ulps of the output precision "
              "((f) float, (d) double), largest component.\n\n",
    base.c_str(), static_cast<long long>(mesh->GetNumberOfPolys()), vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads(), runs);
  std::printf("| %-22s | %-11s | %9s | %15s | %10s | %10s | %10s | %9s |\n", "input", "mode",
    "ns/poly", "worst ulp", "median ulp", "worst rad", "median rad", "zero err");
  std::printf("|%s|%s|%s|%s|%s|%s|%s|%s|\n", std::string(24, '-').c_str(),
    std::string(13, '-').c_str(), std::string(11, '-').c_str(), std::string(17, '-').c_str(),
    std::string(12, '-').c_str(), std::string(12, '-').c_str(), std::string(12, '-').c_str(),
    std::string(11, '-').c_str());
  std::vector<std::string> broken;
  for (const InputClass& input : inputs)
  {
    const Reference ref = ComputeReference(input.Mesh);
    std::vector<vtkSmartPointer<vtkPolygonNormals>> filters;
    for (int mode = vtkPolygonNormals::FAST; mode <= vtkPolygonNormals::EXACT; ++mode)
    {
      auto filter = vtkSmartPointer<vtkPolygonNormals>::New();
      filter->SetInputData(input.Mesh);
      filter->SetAccuracy(mode);
      filter->SetComputeCellNormals(true); // the cell normals of the polygons as given
      filter->SetComputePointNormals(false);
      filter->SetConsistency(false);
      filter->SetOutputPrecision(mode == vtkPolygonNormals::FAST ? vtkAlgorithm::SINGLE_PRECISION
                                                                 : vtkAlgorithm::DOUBLE_PRECISION);
      filters.push_back(filter);
    }
    const std::vector<double> seconds = InterleavedMedians(filters, runs);
    for (int mode = vtkPolygonNormals::FAST; mode <= vtkPolygonNormals::EXACT; ++mode)
    {
      if (!Row(input, ref, mode, filters[mode], seconds[mode]))
      {
        broken.push_back(input.Name);
      }
    }
  }
  std::printf("\nzero err: polygons whose normal is zero while the exact area vector is not, or "
              "the reverse.\n");
  for (const std::string& name : broken)
  {
    std::fprintf(stderr, "EXACT is not faithful on '%s'\n", name.c_str());
  }
  return broken.empty() ? 0 : 1;
}
