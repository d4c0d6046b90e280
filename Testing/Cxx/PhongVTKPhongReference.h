// An independent CPU evaluation of the Phong reflectance model in world coordinates, in double
// precision, and ray casting through pixel centres: the exact sphere for Phong shading, the
// triangles of a mesh for flat (face normal) and Gouraud (colours at the vertices, interpolated
// with the hit point's barycentric coordinates) shading. The rendering tests compare
// vtkPhongPolyDataMapper's images with it; nothing here uses the mapper's code.
#ifndef PhongVTKPhongReference_h
#define PhongVTKPhongReference_h

#include "PhongVTKImageRegression.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace phongvtk
{
namespace testing
{

using Vec = std::array<double, 3>;
inline Vec operator+(const Vec& a, const Vec& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
inline Vec operator-(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Vec operator*(double s, const Vec& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}
inline Vec Mul(const Vec& a, const Vec& b) // component-wise
{
  return { a[0] * b[0], a[1] * b[1], a[2] * b[2] };
}
inline double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline Vec Unit(const Vec& a)
{
  return (1.0 / std::sqrt(Dot(a, a))) * a;
}

/// A light as the user describes it to vtkLight (world coordinates).
struct LightSpec
{
  bool Positional = false;
  Vec Position = { 0, 0, 1 };
  Vec FocalPoint = { 0, 0, 0 };
  Vec Diffuse = { 1, 1, 1 };
  Vec Specular = { 1, 1, 1 };
  Vec Ambient = { 0, 0, 0 };
  double Intensity = 1;
  Vec Attenuation = { 1, 0, 0 };
  double ConeAngle = 30; ///< vtkLight's default
  double Exponent = 1;
};

/// A material as the user describes it to vtkProperty.
struct MaterialSpec
{
  double Ambient = 0, Diffuse = 1, Specular = 0, SpecularPower = 1;
  Vec AmbientColor = { 1, 1, 1 }, DiffuseColor = { 1, 1, 1 }, SpecularColor = { 1, 1, 1 };
};

struct SceneSpec
{
  std::vector<LightSpec> Lights;
  Vec RendererAmbient = { 0, 0, 0 };
  bool TwoSided = true;
};

struct CameraSpec
{
  Vec Position = { 0, 0, 4 };
  Vec FocalPoint = { 0, 0, 0 };
  Vec ViewUp = { 0, 1, 0 };
  double ViewAngle = 30;
  bool Parallel = false;
  double ParallelScale = 0.6;
};

/// A warm plastic: ka = 0.15 C, kd = 0.7 C with C = (0.9, 0.6, 0.3), a white highlight (0.5,
/// exponent 40). The tests' and benchmarks' material with every term present.
inline MaterialSpec WarmMaterial()
{
  MaterialSpec m;
  m.Ambient = 0.15;
  m.Diffuse = 0.7;
  m.Specular = 0.5;
  m.SpecularPower = 40;
  m.AmbientColor = m.DiffuseColor = { 0.9, 0.6, 0.3 };
  m.SpecularColor = { 1, 1, 1 };
  return m;
}

/// vtkSphereSource's sphere (2 theta (phi - 2) triangles, point normals), by default at the
/// origin.
inline vtkSmartPointer<vtkPolyData> SphereMesh(
  int theta, int phi, double radius = 0.5, const Vec& centre = { 0, 0, 0 })
{
  vtkNew<vtkSphereSource> source;
  source->SetRadius(radius);
  source->SetCenter(centre.data());
  source->SetThetaResolution(theta);
  source->SetPhiResolution(phi);
  source->Update();
  return source->GetOutput();
}

/// The same scene for VTK.
inline void Apply(const SceneSpec& scene, const CameraSpec& camera, vtkRenderer* renderer)
{
  renderer->RemoveAllLights();
  for (const LightSpec& spec : scene.Lights)
  {
    auto light = vtkSmartPointer<vtkLight>::New();
    light->SetLightTypeToSceneLight();
    light->SetPositional(spec.Positional);
    light->SetPosition(spec.Position.data());
    light->SetFocalPoint(spec.FocalPoint.data());
    light->SetDiffuseColor(spec.Diffuse.data());
    light->SetSpecularColor(spec.Specular.data());
    light->SetAmbientColor(spec.Ambient.data());
    light->SetIntensity(spec.Intensity);
    light->SetAttenuationValues(spec.Attenuation.data());
    light->SetConeAngle(spec.ConeAngle);
    light->SetExponent(spec.Exponent);
    renderer->AddLight(light);
  }
  renderer->SetAmbient(scene.RendererAmbient.data());
  renderer->SetTwoSidedLighting(scene.TwoSided);
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetPosition(camera.Position.data());
  cam->SetFocalPoint(camera.FocalPoint.data());
  cam->SetViewUp(camera.ViewUp.data());
  cam->SetViewAngle(camera.ViewAngle);
  cam->SetParallelProjection(camera.Parallel);
  cam->SetParallelScale(camera.ParallelScale);
  cam->SetClippingRange(0.5, 20);
}

inline void Apply(const MaterialSpec& material, vtkProperty* property)
{
  property->SetAmbient(material.Ambient);
  property->SetDiffuse(material.Diffuse);
  property->SetSpecular(material.Specular);
  property->SetSpecularPower(material.SpecularPower);
  property->SetAmbientColor(material.AmbientColor.data());
  property->SetDiffuseColor(material.DiffuseColor.data());
  property->SetSpecularColor(material.SpecularColor.data());
}

/// The model at surface point p with unit normal n (turned toward the viewer's side), unit eye
/// vector v, clamped to [0, 1]; `lit` false: a back face under one-sided lighting (ambient only).
inline Vec PhongColour(const SceneSpec& scene, const MaterialSpec& material, const Vec& p,
  const Vec& n, const Vec& v, bool lit = true)
{
  const Vec ka = material.Ambient * material.AmbientColor;
  const Vec kd = material.Diffuse * material.DiffuseColor;
  const Vec ks = material.Specular * material.SpecularColor;
  Vec ia = scene.RendererAmbient;
  for (const LightSpec& light : scene.Lights)
  {
    ia = ia + light.Intensity * light.Ambient;
  }
  Vec colour = Mul(ka, ia);
  for (const LightSpec& light : scene.Lights)
  {
    if (!lit)
    {
      break;
    }
    const Vec id = light.Intensity * light.Diffuse;
    const Vec is = light.Intensity * light.Specular;
    Vec l;
    double attenuation = 1;
    if (!light.Positional)
    {
      l = Unit(light.Position - light.FocalPoint);
    }
    else
    {
      const Vec toLight = light.Position - p;
      const double d = std::sqrt(Dot(toLight, toLight));
      l = (1 / d) * toLight;
      const Vec& a = light.Attenuation;
      attenuation = 1 / (a[0] + a[1] * d + a[2] * d * d);
      if (light.ConeAngle < 90)
      {
        const double c = -Dot(l, Unit(light.FocalPoint - light.Position));
        attenuation *=
          c >= std::cos(light.ConeAngle * M_PI / 180) ? std::pow(c, light.Exponent) : 0.0;
      }
    }
    const double nl = Dot(n, l);
    if (nl <= 0)
    {
      continue; // the light is behind the surface
    }
    const Vec r = (2 * nl) * n - l;
    const double vr = std::max(Dot(v, r), 0.0);
    colour = colour + (attenuation * nl) * Mul(kd, id) +
      (attenuation * std::pow(vr, material.SpecularPower)) * Mul(ks, is);
  }
  for (double& c : colour)
  {
    c = std::min(std::max(c, 0.0), 1.0);
  }
  return colour;
}

/// The ray through the centre of pixel (px, py) (origin at the bottom left, as
/// vtkWindowToImageFilter stores the image).
struct Ray
{
  Vec Origin, Direction; // Direction is a unit vector
};
inline Ray PixelRay(const CameraSpec& camera, int px, int py, int width, int height)
{
  const Vec f = Unit(camera.FocalPoint - camera.Position);
  const Vec right = Unit(Cross(f, camera.ViewUp));
  const Vec up = Cross(right, f);
  const double x = (px + 0.5) / width * 2 - 1;
  const double y = (py + 0.5) / height * 2 - 1;
  const double aspect = double(width) / height;
  if (camera.Parallel)
  {
    const double s = camera.ParallelScale;
    return { camera.Position + (x * s * aspect) * right + (y * s) * up, f };
  }
  const double t = std::tan(camera.ViewAngle * M_PI / 360);
  return { camera.Position, Unit(f + (x * t * aspect) * right + (y * t) * up) };
}

/// What a reference says a pixel shows: nothing to compare (a miss, near a silhouette or an
/// edge), or a colour.
using Reference = std::function<bool(int px, int py, Vec& colour)>;

/// The exact sphere (centre c, radius r) shaded per pixel; pixels whose ray meets the surface at
/// a cosine below `margin` are not compared (the mesh's silhouette differs from the sphere's).
inline Reference AnalyticSphere(const SceneSpec& scene, const MaterialSpec& material,
  const CameraSpec& camera, const Vec& c, double r, int width, int height, double margin = 0.3)
{
  return [=](int px, int py, Vec& colour)
  {
    const Ray ray = PixelRay(camera, px, py, width, height);
    const Vec oc = ray.Origin - c;
    const double b = Dot(oc, ray.Direction);
    const double disc = b * b - (Dot(oc, oc) - r * r);
    if (disc <= 0)
    {
      return false;
    }
    const double s = -b - std::sqrt(disc);
    const Vec p = ray.Origin + s * ray.Direction;
    const Vec n = (1 / r) * (p - c);
    const Vec v = -1.0 * ray.Direction;
    if (Dot(n, v) < margin)
    {
      return false;
    }
    colour = PhongColour(scene, material, p, n, v);
    return true;
  };
}

/// The triangles of `mesh` (point normals for Gouraud) ray cast per pixel: flat uses each face's
/// normal, Gouraud the model evaluated at the three vertices (each clamped) and interpolated with
/// the hit's barycentric coordinates, which are the perspective-correct ones. Pixels within
/// `edge` (barycentric) of a triangle's edge or whose ray meets the face at a cosine below
/// `margin` are not compared.
inline Reference RayCastMesh(const SceneSpec& scene, const MaterialSpec& material,
  const CameraSpec& camera, vtkPolyData* mesh, bool gouraud, int width, int height,
  double edge = 0.02, double margin = 0.3)
{
  struct Triangle
  {
    Vec P[3], N[3];
  };
  auto triangles = std::make_shared<std::vector<Triangle>>();
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType npts;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    for (vtkIdType k = 1; k + 1 < npts; ++k) // a fan, as VTK triangulates convex polygons
    {
      Triangle t;
      const vtkIdType corner[3] = { ids[0], ids[k], ids[k + 1] };
      for (int i = 0; i < 3; ++i)
      {
        mesh->GetPoint(corner[i], t.P[i].data());
        if (normals)
        {
          normals->GetTuple(corner[i], t.N[i].data());
          t.N[i] = Unit(t.N[i]);
        }
      }
      triangles->push_back(t);
    }
  }
  return [=](int px, int py, Vec& colour)
  {
    const Ray ray = PixelRay(camera, px, py, width, height);
    double best = 1e300, bu = 0, bv = 0;
    const Triangle* hit = nullptr;
    for (const Triangle& t : *triangles) // Moeller-Trumbore
    {
      const Vec e1 = t.P[1] - t.P[0], e2 = t.P[2] - t.P[0];
      const Vec h = Cross(ray.Direction, e2);
      const double a = Dot(e1, h);
      if (std::abs(a) < 1e-14)
      {
        continue;
      }
      const Vec s = ray.Origin - t.P[0];
      const double u = Dot(s, h) / a;
      const Vec q = Cross(s, e1);
      const double v = Dot(ray.Direction, q) / a;
      const double dist = Dot(e2, q) / a;
      if (u < 0 || v < 0 || u + v > 1 || dist <= 0 || dist >= best)
      {
        continue;
      }
      best = dist;
      bu = u;
      bv = v;
      hit = &t;
    }
    if (!hit || std::min({ bu, bv, 1 - bu - bv }) < edge)
    {
      return false;
    }
    Vec face = Unit(Cross(hit->P[1] - hit->P[0], hit->P[2] - hit->P[0]));
    const Vec view = -1.0 * ray.Direction;
    if (Dot(face, view) < 0)
    {
      face = -1.0 * face; // the viewer's side
    }
    if (Dot(face, view) < margin)
    {
      return false;
    }
    const Vec p = ray.Origin + best * ray.Direction;
    if (!gouraud)
    {
      colour = PhongColour(scene, material, p, face, view);
      return true;
    }
    const double w[3] = { 1 - bu - bv, bu, bv };
    colour = { 0, 0, 0 };
    for (int i = 0; i < 3; ++i)
    {
      const Vec eye = camera.Parallel ? Unit(camera.Position - camera.FocalPoint)
                                      : Unit(camera.Position - hit->P[i]);
      colour = colour + w[i] * PhongColour(scene, material, hit->P[i], hit->N[i], eye);
    }
    return true;
  };
}

/// Differences between an image and a reference, in LSB (1/255) over every channel of every
/// compared pixel.
struct Agreement
{
  int Pixels = 0;
  double RMS = 0;
  double Max = 0;
  int MaxX = -1, MaxY = -1;
  std::string Describe() const
  {
    std::ostringstream text;
    text << Pixels << " pixels compared, RMS " << RMS << " LSB, max " << Max << " LSB at (" << MaxX
         << ", " << MaxY << ")";
    return text.str();
  }
};

inline Agreement Compare(const Image& image, const Reference& reference)
{
  Agreement agreement;
  double sum = 0;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      Vec expected;
      if (!reference(x, y, expected))
      {
        continue;
      }
      ++agreement.Pixels;
      for (int c = 0; c < 3; ++c)
      {
        const double d = image.At(x, y, c) - 255 * expected[c];
        sum += d * d;
        if (std::abs(d) > agreement.Max)
        {
          agreement.Max = std::abs(d);
          agreement.MaxX = x;
          agreement.MaxY = y;
        }
      }
    }
  }
  agreement.RMS = agreement.Pixels ? std::sqrt(sum / (3.0 * agreement.Pixels)) : 0;
  return agreement;
}

}
}

#endif
