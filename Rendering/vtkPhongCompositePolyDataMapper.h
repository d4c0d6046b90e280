/**
 * @class   vtkPhongCompositePolyDataMapper
 * @brief   composite-data mapper whose shaders evaluate the Phong reflectance model term by term
 *
 * VTK's composite-data mapper (multiblock and partitioned data, per-block colour, opacity and
 * visibility through vtkCompositeDataDisplayAttributes, hardware selection of blocks) with the
 * lighting of vtkPhongPolyDataMapper: the same model, the same flat/Gouraud/Phong shading and
 * the same generated GLSL (one place for it). See vtkPhongPolyDataMapper for the model.
 *
 * Blocks are drawn by one helper mapper per kind of block (with or without scalars, normals,
 * texture coordinates), and each helper generates the shaders its blocks need. The composite
 * mapper is the one of the VTK in use (vtkPhongCompositeBase): vtkCompositePolyDataMapper2 with
 * its vtkCompositeMapperHelper2 helpers up to VTK 9.2, vtkCompositePolyDataMapper with its
 * delegators (vtkOpenGLBatchedPolyDataMapper) from 9.3. A block's colour
 * (vtkCompositeDataDisplayAttributes) replaces the material colour, also where it overrides
 * mapped scalars; the terms present therefore do not depend on the property's colours, only on
 * its coefficients, the specular colour and the lights.
 *
 * Material presets: vtkPhongPolyDataMapper::ApplyPreset.
 *
 * @sa vtkPhongPolyDataMapper vtkCompositePolyDataMapper vtkCompositeDataDisplayAttributes
 */
#ifndef vtkPhongCompositePolyDataMapper_h
#define vtkPhongCompositePolyDataMapper_h

#include "vtkPhongVTKRenderingModule.h" // for export macro
#include "vtkVersionMacros.h"           // for VTK_VERSION_NUMBER

// The composite-data mapper of the VTK in use: the one compatibility switch of this header.
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h" // for the superclass
#define PHONGVTK_COMPOSITE_DELEGATORS 1
using vtkPhongCompositeBase = vtkCompositePolyDataMapper;
#else
#include "vtkCompositePolyDataMapper2.h" // for the superclass
#define PHONGVTK_COMPOSITE_DELEGATORS 0
using vtkPhongCompositeBase = vtkCompositePolyDataMapper2;
#endif

#include <string> // for std::string
#include <vector> // for the block mappers' states

namespace phongvtk
{
struct MapperState;
}

class VTKPHONGVTKRENDERING_EXPORT vtkPhongCompositePolyDataMapper : public vtkPhongCompositeBase
{
public:
  static vtkPhongCompositePolyDataMapper* New();
  vtkTypeMacro(vtkPhongCompositePolyDataMapper, vtkPhongCompositeBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Derive the ambient light from the scene (see vtkPhongPolyDataMapper::SetSceneAmbient).
   * Default: off.
   */
  vtkSetMacro(SceneAmbient, bool);
  vtkGetMacro(SceneAmbient, bool);
  vtkBooleanMacro(SceneAmbient, bool);
  ///@}

  ///@{
  /**
   * Generate shaders holding only the terms, lights and light kinds the scene uses; off: a
   * general shader (the same image). Default: on.
   */
  vtkSetMacro(SpecializeShaders, bool);
  vtkGetMacro(SpecializeShaders, bool);
  vtkBooleanMacro(SpecializeShaders, bool);
  ///@}

  /**
   * The GLSL of the program that last drew polygons with the Phong model (vertex, fragment),
   * and the one-line description of its configuration: of the first helper (kind of block)
   * that drew any in the last render. Empty before the first render or when VTK's own lighting
   * drew them.
   */
  std::string GetVertexShaderSource();
  std::string GetFragmentShaderSource();
  std::string GetShaderConfiguration();

  /**
   * How many times shader sources changed, summed over the helpers (one per kind of block).
   */
  vtkGetMacro(ShaderRebuilds, int);

protected:
  vtkPhongCompositePolyDataMapper();
  ~vtkPhongCompositePolyDataMapper() override;

  // The per-kind-of-block mappers (vtkPhongCompositePolyDataMapperHelpers.cxx up to VTK 9.2,
  // vtkPhongCompositePolyDataMapperDelegators.cxx from 9.3).
#if PHONGVTK_COMPOSITE_DELEGATORS
  vtkCompositePolyDataMapperDelegator* CreateADelegator() override;
  void PostRender(
    const std::vector<vtkSmartPointer<vtkCompositePolyDataMapperDelegator>>& delegators,
    vtkRenderer* ren, vtkActor* act) override;
#else
  vtkCompositeMapperHelper2* CreateHelper() override;
  void CopyMapperValuesToHelper(vtkCompositeMapperHelper2* helper) override;
  void Render(vtkRenderer* ren, vtkActor* act) override;
#endif

  /// A new block mapper's state: its options and the shared rebuild count.
  void Configure(phongvtk::MapperState& state);
  /// After a render, remembers the shaders of the first block mapper that drew triangles with
  /// the Phong model (`states`: every block mapper's state, in drawing order).
  void RememberShaders(const std::vector<phongvtk::MapperState*>& states);

  bool SceneAmbient = false;
  bool SpecializeShaders = true;
  int ShaderRebuilds = 0;

private:
  vtkPhongCompositePolyDataMapper(const vtkPhongCompositePolyDataMapper&) = delete;
  void operator=(const vtkPhongCompositePolyDataMapper&) = delete;

  friend class vtkPhongCompositeDelegator; // Configure

  // The last render's first Phong triangles (helpers die with the window's resources).
  std::string VertexSource;
  std::string FragmentSource;
  std::string Configuration;
};

#endif
