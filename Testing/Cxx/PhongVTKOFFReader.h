/**
 * @file PhongVTKOFFReader.h
 * @brief A small reader of ASCII OFF meshes (the format of CGAL's sample data) for the tests and
 * benchmarks.
 *
 * Understood: the header keyword `OFF` with the optional prefixes of Geomview's family (`ST`, `C`,
 * `N`, e.g. `COFF`, `NOFF`, `STCNOFF`), the counts `vertices faces edges` on the header line or on
 * the next one, comments from `#` to the end of a line, blank lines anywhere, one vertex per line
 * (x y z, then anything: normals, colours, texture coordinates are ignored) and one face per line
 * (`n i0 ... i(n-1)`, optionally followed by a colour). Coordinates are read as doubles, so the
 * points are exactly the decimal values of the file rounded once. Every face becomes one polygon,
 * in file order: cell id = face index. Not understood (an error): `4OFF`, `nOFF` and binary OFF.
 */
#ifndef PhongVTKOFFReader_h
#define PhongVTKOFFReader_h

#include "PhongVTKSkip.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace phongvtk_test
{
namespace detail
{
/// Reads the next line that is not empty once its comment is removed; counts lines for messages.
class OFFLines
{
public:
  explicit OFFLines(std::istream& in)
    : In(in)
  {
  }

  bool Next(std::string& line)
  {
    while (std::getline(this->In, line))
    {
      ++this->Number;
      const auto hash = line.find('#');
      if (hash != std::string::npos)
      {
        line.erase(hash);
      }
      if (line.find_first_not_of(" \t\r\f\v") != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }

  long long LineNumber() const { return this->Number; }

private:
  std::istream& In;
  long long Number = 0;
};

/// Splits a line into whitespace-separated tokens.
inline std::vector<std::string> Tokens(const std::string& line)
{
  std::vector<std::string> tokens;
  std::istringstream words(line);
  std::string word;
  while (words >> word)
  {
    tokens.push_back(word);
  }
  return tokens;
}

/// A whole token as a double (strtod: correctly rounded, so subnormals, inf and nan are read too).
inline bool ParseDouble(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end != token.c_str() && *end == '\0';
}

/// A whole token as a non-negative integer.
inline bool ParseCount(const std::string& token, long long& value)
{
  if (token.empty() || token[0] == '-' || token[0] == '+')
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(token.c_str(), &end, 10);
  return *end == '\0' && errno != ERANGE;
}

/// True when `keyword` is OFF with any of the optional prefixes ST, C, N (in that order).
inline bool IsOFFKeyword(const std::string& keyword, std::string& unsupported)
{
  std::string k = keyword;
  if (k.size() < 3 || k.compare(k.size() - 3, 3, "OFF") != 0)
  {
    return false;
  }
  k.erase(k.size() - 3);
  for (const char* prefix : { "ST", "C", "N" })
  {
    const std::string p(prefix);
    if (k.compare(0, p.size(), p) == 0)
    {
      k.erase(0, p.size());
    }
  }
  if (!k.empty())
  {
    unsupported = "the header '" + keyword + "' (4D or n-dimensional OFF) is not supported";
  }
  return true;
}
} // namespace detail

/**
 * Reads the ASCII OFF file at `path` into a vtkPolyData with double points and one polygon per
 * face. Returns nullptr when the file is missing or not a valid OFF file; `error` (if given) then
 * says why, with the line number.
 */
inline vtkSmartPointer<vtkPolyData> ReadOFF(const std::string& path, std::string* error = nullptr)
{
  auto fail = [&](const std::string& why) -> vtkSmartPointer<vtkPolyData>
  {
    if (error)
    {
      *error = "ReadOFF: " + why;
    }
    return nullptr;
  };
  std::ifstream file(path, std::ios::binary);
  if (!file)
  {
    return fail("cannot open '" + path + "'");
  }
  detail::OFFLines lines(file);
  auto where = [&]()
  {
    return path + ":" + std::to_string(lines.LineNumber()) + ": ";
  };

  std::string line;
  if (!lines.Next(line))
  {
    return fail(path + ": empty or unreadable file, expected the OFF header");
  }
  std::vector<std::string> tokens = detail::Tokens(line);
  std::string unsupported;
  if (!detail::IsOFFKeyword(tokens[0], unsupported))
  {
    return fail(where() + "expected the OFF header, found '" + tokens[0] + "'");
  }
  if (!unsupported.empty())
  {
    return fail(where() + unsupported);
  }
  tokens.erase(tokens.begin());
  if (!tokens.empty() && tokens[0] == "BINARY")
  {
    return fail(where() + "binary OFF is not supported");
  }
  if (tokens.empty())
  {
    if (!lines.Next(line))
    {
      return fail(where() + "missing the counts 'vertices faces edges'");
    }
    tokens = detail::Tokens(line);
  }
  long long numPoints = 0, numFaces = 0, numEdges = 0;
  if (tokens.size() < 2 || tokens.size() > 3 || !detail::ParseCount(tokens[0], numPoints) ||
    !detail::ParseCount(tokens[1], numFaces) ||
    (tokens.size() == 3 && !detail::ParseCount(tokens[2], numEdges)))
  {
    return fail(where() + "expected the counts 'vertices faces edges', found '" + line + "'");
  }

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(numPoints);
  for (long long i = 0; i < numPoints; ++i)
  {
    if (!lines.Next(line))
    {
      return fail(path + ": unexpected end of file after " + std::to_string(i) + " of " +
        std::to_string(numPoints) + " vertices");
    }
    tokens = detail::Tokens(line);
    double xyz[3];
    if (tokens.size() < 3 || !detail::ParseDouble(tokens[0], xyz[0]) ||
      !detail::ParseDouble(tokens[1], xyz[1]) || !detail::ParseDouble(tokens[2], xyz[2]))
    {
      return fail(where() + "expected the coordinates 'x y z' of vertex " + std::to_string(i) +
        ", found '" + line + "'");
    }
    coordinates->SetTypedTuple(i, xyz);
  }

  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfTuples(numFaces + 1);
  offsets->SetValue(0, 0);
  connectivity->Allocate(3 * numFaces);
  for (long long f = 0; f < numFaces; ++f)
  {
    if (!lines.Next(line))
    {
      return fail(path + ": unexpected end of file after " + std::to_string(f) + " of " +
        std::to_string(numFaces) + " faces");
    }
    tokens = detail::Tokens(line);
    long long n = 0;
    if (tokens.empty() || !detail::ParseCount(tokens[0], n) ||
      static_cast<long long>(tokens.size()) < n + 1)
    {
      return fail(where() + "expected face " + std::to_string(f) +
        " as 'n i0 ... i(n-1)', found '" + line + "'");
    }
    for (long long k = 1; k <= n; ++k)
    {
      long long id = 0;
      if (!detail::ParseCount(tokens[k], id) || id >= numPoints)
      {
        return fail(where() + "face " + std::to_string(f) + " has the vertex index '" + tokens[k] +
          "', not in [0, " + std::to_string(numPoints) + ")");
      }
      connectivity->InsertNextValue(static_cast<vtkIdType>(id));
    }
    offsets->SetValue(f + 1, connectivity->GetNumberOfTuples());
  }

  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

#ifdef PHONGVTK_CGAL_MESHES
/// Path of one of CGAL's sample meshes (Debian's libcgal-demo, unpacked at configure time).
inline std::string CGALMeshPath(const std::string& name)
{
  return std::string(PHONGVTK_CGAL_MESHES) + "/" + name;
}

inline bool HaveCGALMeshes()
{
  return std::ifstream(CGALMeshPath("bunny00.off")).good();
}

/// Skips the current GoogleTest test when the CGAL sample meshes are not there.
#define PHONGVTK_SKIP_WITHOUT_CGAL_MESHES()                                                        \
  do                                                                                               \
  {                                                                                                \
    if (!phongvtk_test::HaveCGALMeshes())                                                          \
    {                                                                                              \
      PHONGVTK_SKIP() << "CGAL sample meshes not found in " PHONGVTK_CGAL_MESHES                   \
                         " (install Debian's libcgal-demo and re-run CMake)";                      \
    }                                                                                              \
  } while (false)
#endif
} // namespace phongvtk_test

#endif
