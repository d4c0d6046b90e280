/**
 * @class   vtkPhongCompositePolyDataMapper
 * @brief   composite-data mapper whose shaders evaluate the Phong reflectance model term by term
 *
 * vtkCompositePolyDataMapper2 (multiblock and partitioned data, per-block colour, opacity and
 * visibility through vtkCompositeDataDisplayAttributes, hardware selection of blocks) with the
 * lighting of vtkPhongPolyDataMapper: the same model, the same flat/Gouraud/Phong shading and
 * the same generated GLSL (one place for it). See vtkPhongPolyDataMapper for the model.
 *
 * Blocks are drawn by one helper mapper per kind of block (with or without scalars, normals,
 * texture coordinates), and each helper generates the shaders its blocks need. A block's colour
 * (vtkCompositeDataDisplayAttributes) replaces the material colour, also where it overrides
 * mapped scalars; the terms present therefore do not depend on the property's colours, only on
 * its coefficients, the specular colour and the lights.
 *
 * Material presets: vtkPhongPolyDataMapper::ApplyPreset.
 *
 * @sa vtkPhongPolyDataMapper vtkCompositePolyDataMapper2 vtkCompositeDataDisplayAttributes
 */
#ifndef vtkPhongCompositePolyDataMapper_h
#define vtkPhongCompositePolyDataMapper_h

#include "vtkCompositePolyDataMapper2.h"
#include "vtkPhongVTKRenderingModule.h" // for export macro

#include <string> // for std::string

class VTKPHONGVTKRENDERING_EXPORT vtkPhongCompositePolyDataMapper
  : public vtkCompositePolyDataMapper2
{
public:
  static vtkPhongCompositePolyDataMapper* New();
  vtkTypeMacro(vtkPhongCompositePolyDataMapper, vtkCompositePolyDataMapper2);
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

  void Render(vtkRenderer* ren, vtkActor* act) override;

protected:
  vtkPhongCompositePolyDataMapper();
  ~vtkPhongCompositePolyDataMapper() override;

  vtkCompositeMapperHelper2* CreateHelper() override;
  void CopyMapperValuesToHelper(vtkCompositeMapperHelper2* helper) override;

  bool SceneAmbient = false;
  bool SpecializeShaders = true;
  int ShaderRebuilds = 0;

private:
  vtkPhongCompositePolyDataMapper(const vtkPhongCompositePolyDataMapper&) = delete;
  void operator=(const vtkPhongCompositePolyDataMapper&) = delete;

  // The last render's first Phong triangles (helpers die with the window's resources).
  std::string VertexSource;
  std::string FragmentSource;
  std::string Configuration;
};

#endif
