// The Phong model's overrides of vtkOpenGLPolyDataMapper, written once for every mapper that
// uses them: vtkPhongPolyDataMapper (a vtkOpenGLPolyDataMapper) and the block mapper of
// vtkPhongCompositePolyDataMapper (a vtkCompositeMapperHelper2 up to VTK 9.2, a
// vtkOpenGLBatchedPolyDataMapper from 9.3). Each mapper keeps a MapperState, declares
// `friend struct phongvtk::MapperCore<ItsClass>` and forwards its overrides here;
// MapperCore<M> calls M::Superclass where VTK's own code runs. Private to PhongVTK::Rendering.
#ifndef PhongVTKMapperCore_h
#define PhongVTKMapperCore_h

#include "PhongVTKProgramGuard.h"
#include "PhongVTKShading.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkLightingMapPass.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkShaderProperty.h"

#include <map>
#include <string>

namespace phongvtk
{

/// What a mapper remembers of its primitives' shaders.
struct MapperState
{
  struct Primitive
  {
    bool Active = false; ///< the Phong model (not VTK's lighting) draws this primitive
    shading::Configuration Configuration;
    std::string VertexSource;
    std::string FragmentSource;
    ProgramGuard Guard; ///< a program that fails to build draws nothing, reported once
    bool Built = false; ///< BuildShaders ran in the current UpdateShaders
  };
  std::map<const vtkOpenGLHelper*, Primitive> Primitives;
  const vtkOpenGLHelper* Triangles = nullptr; ///< the mapper's primitive of polygons
  shading::Scene Scene;
  bool WarnedNoPointNormals = false;
  int ShaderRebuilds = 0;
  int* SharedRebuilds = nullptr; ///< counts the rebuilds instead (a composite mapper's helpers)

  // The user's options (a composite mapper copies its own to its helpers).
  bool SceneAmbient = false;
  bool SpecializeShaders = true;
  bool BlockColours = false;

  /// The primitive `cellBO` of the mapper as last built.
  const Primitive& Get(const vtkOpenGLHelper* cellBO) { return this->Primitives[cellBO]; }
};

template <class M>
struct MapperCore
{
  using ShaderMap = std::map<vtkShader::Type, vtkShader*>;
  using Base = typename M::Superclass;

  static bool GetNeedToRebuildShaders(
    M& m, MapperState& state, vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
  {
    // The superclass decides whether VTK would light this primitive at all (and remembers it).
    bool rebuild = m.Base::GetNeedToRebuildShaders(cellBO, ren, act);
    MapperState::Primitive& primitive = state.Primitives[&cellBO];
    rebuild = rebuild || primitive.Guard.MustBuild();

    vtkProperty* property = act->GetProperty();
    vtkInformation* keys = act->GetPropertyKeys();
    const auto& info = m.PrimitiveInfo[&cellBO];
    const bool active = info.LastLightComplexity > 0 && info.LastLightCount > 0 &&
      property->GetInterpolation() != VTK_PBR && !m.DrawingTubesOrSpheres(cellBO, act) &&
      !(keys &&
        (keys->Has(vtkLightingMapPass::RENDER_NORMALS()) ||
          keys->Has(vtkLightingMapPass::RENDER_LUMINANCE())));

    shading::Configuration config;
    if (active)
    {
      state.Scene = shading::GatherScene(ren, state.SceneAmbient);

      shading::Request request;
      request.Shading = property->GetInterpolation() == VTK_FLAT ? shading::Mode::Flat
        : property->GetInterpolation() == VTK_GOURAUD            ? shading::Mode::Gouraud
                                                                 : shading::Mode::Phong;
      if (request.Shading != shading::Mode::Flat && m.VBOs->GetNumberOfComponents("normalMC") != 3)
      {
        if (!state.WarnedNoPointNormals)
        {
          vtkWarningWithObjectMacro(&m,
            "Smooth shading needs point normals and the input has none: shading flat (cell "
            "normals or the derivatives of the position). Compute them with vtkPolygonNormals "
            "(ComputePointNormals on) or set the interpolation to flat.");
          state.WarnedNoPointNormals = true;
        }
        request.Shading = shading::Mode::Flat;
      }

      // Where kd and ka come from: the same cases as VTK's colour code.
      if (m.VBOs->GetNumberOfComponents("scalarColor") != 0 && !m.DrawingVertices)
      {
        request.Colours = shading::Material::PointColours;
      }
      else if ((m.InterpolateScalarsBeforeMapping && m.ColorCoordinates && !m.DrawingVertices) ||
        (m.HaveCellScalars && !m.DrawingVertices && !m.PointPicking) || act->GetBackfaceProperty())
      {
        request.Colours = shading::Material::FragmentOnly;
      }

      // Code that is not ours may read the interpolated position: keep it then.
      vtkShaderProperty* sp = act->GetShaderProperty();
      request.KeepPosition = sp->HasVertexShaderCode() || sp->HasFragmentShaderCode() ||
        sp->HasGeometryShaderCode() || sp->GetNumberOfShaderReplacements() > 0 ||
        (keys && keys->Has(vtkOpenGLRenderPass::RenderPasses())) || m.DrawingEdges(ren, act);
      request.DerivativeNormals = request.Shading == shading::Mode::Flat && !m.HaveCellNormals;
      request.BlockColours = state.BlockColours;
      // Vertex-bound when the triangles are few pixels each (on average at most 8 pixels of
      // the viewport per triangle).
      int width = 0;
      int height = 0;
      ren->GetTiledSize(&width, &height);
      const vtkIdType triangles = m.CurrentInput
        ? m.CurrentInput->GetNumberOfPolys() + m.CurrentInput->GetNumberOfStrips()
        : 0;
      request.SmallTriangles =
        triangles > 0 && static_cast<double>(width) * height <= 8.0 * triangles;
      request.Specialize = state.SpecializeShaders;
      config = shading::Configure(state.Scene, property, act->GetBackfaceProperty(), request);
    }

    if (active != primitive.Active || (active && config != primitive.Configuration))
    {
      rebuild = true;
    }
    primitive.Active = active;
    primitive.Configuration = config;
    return rebuild;
  }

  static void BuildShaders(
    M& m, MapperState& state, ShaderMap shaders, vtkRenderer* ren, vtkActor* act)
  {
    m.Base::BuildShaders(shaders, ren, act);
    MapperState::Primitive& primitive = state.Primitives[m.LastBoundBO];
    primitive.Built = true;
    const std::string vertex = shaders[vtkShader::Vertex]->GetSource();
    const std::string fragment = shaders[vtkShader::Fragment]->GetSource();
    if (vertex != primitive.VertexSource || fragment != primitive.FragmentSource)
    {
      ++(state.SharedRebuilds ? *state.SharedRebuilds : state.ShaderRebuilds);
    }
    primitive.VertexSource = primitive.Active ? vertex : std::string();
    primitive.FragmentSource = primitive.Active ? fragment : std::string();
  }

  static void UpdateShaders(
    M& m, MapperState& state, vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
  {
    MapperState::Primitive& primitive = state.Primitives[&cellBO];
    primitive.Guard.Before(cellBO, ren);
    primitive.Built = false;
    const vtkMTimeType sourceTime = cellBO.ShaderSourceTime.GetMTime();
    m.Base::UpdateShaders(cellBO, ren, act);
    if (primitive.Guard.After(cellBO, ren, primitive.Built, sourceTime))
    {
      vtkErrorWithObjectMacro(&m,
        "The shader program of this actor does not compile or link (VTK's shader error above "
        "names the line): nothing of it is drawn until it builds. Check the shader "
        "replacements and custom shader code of the actor's vtkShaderProperty.");
    }
  }

  static void ReplaceShaderColor(
    M& m, MapperState& state, ShaderMap shaders, vtkRenderer* ren, vtkActor* act)
  {
    const MapperState::Primitive& primitive = state.Get(m.LastBoundBO);
    if (!primitive.Active || primitive.Configuration.FragmentUsesSpecular())
    {
      m.Base::ReplaceShaderColor(shaders, ren, act);
      return;
    }
    // VTK's colour code declares the specular material whenever the primitive is lit; it does
    // so only when the light complexity is non-zero, so hide it for that call. (An int up to
    // VTK 9.2, primitiveInfo::LightingTypeEnum from 9.3: 0 is "no lighting" in both.)
    auto& complexity = m.PrimitiveInfo[m.LastBoundBO].LastLightComplexity;
    const auto lit = complexity;
    complexity = decltype(lit){};
    m.Base::ReplaceShaderColor(shaders, ren, act);
    complexity = lit;
  }

  static void ReplaceShaderNormal(
    M& m, MapperState& state, ShaderMap shaders, vtkRenderer* ren, vtkActor* act)
  {
    const MapperState::Primitive& primitive = state.Get(m.LastBoundBO);
    if (!primitive.Active || primitive.Configuration.Shading != shading::Mode::Gouraud ||
      primitive.Configuration.KeepPosition)
    {
      // Flat and Phong read VTK's normal (turned toward the viewer on back faces); so does code
      // that is not ours.
      m.Base::ReplaceShaderNormal(shaders, ren, act);
    }
    // Gouraud: the normal is used in the vertex shader only (declared with the light code).
  }

  static void ReplaceShaderPositionVC(
    M& m, MapperState& state, ShaderMap shaders, vtkRenderer* ren, vtkActor* act)
  {
    const MapperState::Primitive& primitive = state.Get(m.LastBoundBO);
    const shading::Configuration& config = primitive.Configuration;
    if (!primitive.Active || config.FragmentNeedsPosition())
    {
      m.Base::ReplaceShaderPositionVC(shaders, ren, act);
      return;
    }
    // Nothing reads the interpolated position: the vertex shader only projects (and a Gouraud
    // vertex shader computes the position for its own use).
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    const bool vertexPosition = config.Shading == shading::Mode::Gouraud && config.NeedsPosition();
    vtkShaderProgram::Substitute(vs, "//VTK::Camera::Dec",
      vertexPosition ? "uniform mat4 MCDCMatrix;\nuniform mat4 MCVCMatrix;"
                     : "uniform mat4 MCDCMatrix;");
    vtkShaderProgram::Substitute(
      vs, "//VTK::PositionVC::Impl", "  gl_Position = MCDCMatrix * vertexMC;\n");
    vtkShaderProgram::Substitute(fs, "//VTK::Camera::Dec", "uniform int cameraParallel;\n", false);
    shaders[vtkShader::Vertex]->SetSource(vs);
    shaders[vtkShader::Fragment]->SetSource(fs);
  }

  static void ReplaceShaderLight(
    M& m, MapperState& state, ShaderMap shaders, vtkRenderer* ren, vtkActor* act)
  {
    const MapperState::Primitive& primitive = state.Get(m.LastBoundBO);
    if (!primitive.Active)
    {
      m.Base::ReplaceShaderLight(shaders, ren, act);
      return;
    }
    const shading::Configuration& config = primitive.Configuration;
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(fs, "//VTK::Light::Dec", shading::FragmentDeclarations(config));
    vtkShaderProgram::Substitute(
      fs, "//VTK::Light::Impl", shading::FragmentImplementation(config), false);
    shaders[vtkShader::Fragment]->SetSource(fs);

    if (config.Shading == shading::Mode::Gouraud)
    {
      std::string vs = shaders[vtkShader::Vertex]->GetSource();
      // VTK's normal code declared normalMC and normalMatrix when it ran.
      vtkShaderProgram::Substitute(
        vs, "//VTK::Light::Dec", shading::VertexDeclarations(config, !config.KeepPosition));
      vtkShaderProgram::Substitute(vs, "//VTK::Light::Impl", shading::VertexImplementation(config));
      shaders[vtkShader::Vertex]->SetSource(vs);
      std::string gs = shaders[vtkShader::Geometry]->GetSource();
      if (!gs.empty())
      {
        vtkShaderProgram::Substitute(
          gs, "//VTK::Light::Dec", shading::GeometryDeclarations(config));
        vtkShaderProgram::Substitute(
          gs, "//VTK::Light::Impl", shading::GeometryImplementation(config));
        shaders[vtkShader::Geometry]->SetSource(gs);
      }
    }
  }

  static void SetLightingShaderParameters(
    M& m, MapperState& state, vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
  {
    const MapperState::Primitive& primitive = state.Get(&cellBO);
    if (!primitive.Active)
    {
      m.Base::SetLightingShaderParameters(cellBO, ren, act);
      return;
    }
    shading::SetUniforms(cellBO.Program, primitive.Configuration, state.Scene);
  }
};

}

#endif
