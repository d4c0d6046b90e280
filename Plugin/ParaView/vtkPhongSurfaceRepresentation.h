/**
 * @class   vtkPhongSurfaceRepresentation
 * @brief   ParaView's Surface representation lit by PhongVTK's Phong reflectance model
 *
 * A vtkGeometryRepresentationWithFaces whose mappers are vtkPhongCompositePolyDataMapper: the
 * surface, colouring by arrays, opacity, per-block attributes and selection are those of
 * ParaView's Surface representation; the lighting is the Phong model evaluated term by term
 * (see vtkPhongPolyDataMapper) with flat, Gouraud or Phong shading. The material is the
 * representation's Ambient, Diffuse, Specular, SpecularPower and colours, or a preset of
 * vtkPhongPolyDataMapper applied to the diffuse colour.
 *
 * Values that mean nothing (a negative or NaN coefficient or specular power, an unknown
 * shading or preset) are errors naming the value; the previous value stays.
 *
 * @sa vtkPhongCompositePolyDataMapper vtkPhongPolyDataMapper vtkGeometryRepresentation
 */
#ifndef vtkPhongSurfaceRepresentation_h
#define vtkPhongSurfaceRepresentation_h

#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkPhongVTKParaViewModule.h" // for export macro

class VTKPHONGVTKPARAVIEW_EXPORT vtkPhongSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkPhongSurfaceRepresentation* New();
  vtkTypeMacro(vtkPhongSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ShadingModes
  {
    FLAT = 0,
    GOURAUD = 1,
    PHONG = 2
  };

  ///@{
  /**
   * Shading: FLAT (one normal per cell), GOURAUD (the model at the vertices, colours
   * interpolated) or PHONG (normals interpolated, the model per fragment). Default is PHONG.
   */
  void SetShading(int shading);
  vtkGetMacro(Shading, int);
  ///@}

  ///@{
  /**
   * Material preset, a vtkPhongPolyDataMapper::MaterialPreset value (ApplyPreset on the diffuse
   * colour): CUSTOM (0) for the representation's own coefficients, PLASTIC (1), METAL (2) or
   * MATTE (3). A preset overrides Ambient, Diffuse, Specular, SpecularPower, AmbientColor and
   * SpecularColor. Default is CUSTOM.
   */
  void SetMaterialPreset(int preset);
  vtkGetMacro(MaterialPreset, int);
  ///@}

  ///@{
  /**
   * Derive the ambient light from the scene's lights (vtkPhongPolyDataMapper::SetSceneAmbient).
   * Default is off.
   */
  void SetSceneAmbient(bool sceneAmbient);
  vtkGetMacro(SceneAmbient, bool);
  ///@}

  ///@{
  /**
   * The model's coefficients, checked: negative or NaN values are errors and change nothing.
   */
  void SetAmbient(double ka) override;
  void SetDiffuse(double kd) override;
  void SetSpecular(double ks) override;
  void SetSpecularPower(double alpha) override;
  ///@}

  /**
   * Ignored: Shading sets the interpolation of this representation (ParaView pushes the Surface
   * representation's Interpolation, which has no Phong, to every representation).
   */
  void SetInterpolation(int) override {}

protected:
  vtkPhongSurfaceRepresentation();
  ~vtkPhongSurfaceRepresentation() override;

  void UpdateColoringParameters() override;

  int Shading = PHONG;
  int MaterialPreset = 0; // vtkPhongPolyDataMapper::CUSTOM
  bool SceneAmbient = false;

private:
  vtkPhongSurfaceRepresentation(const vtkPhongSurfaceRepresentation&) = delete;
  void operator=(const vtkPhongSurfaceRepresentation&) = delete;

  bool CheckCoefficient(const char* name, double value);
};

#endif
