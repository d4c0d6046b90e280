/**
 * @class   vtkPVVisibleArea
 * @brief   vtkVisibleArea seen through a ParaView render view's camera
 *
 * The Visible Area filter of the PhongVTK plugin: vtkVisibleArea plus SetView(), which takes a
 * render view (vtkPVRenderView) and looks through its active camera, or, given null, goes back
 * to ViewDirection. The camera is shared, not copied: the filter re-executes when the camera
 * has changed and the pipeline is updated.
 *
 * @sa vtkVisibleArea vtkPVRenderView
 */
#ifndef vtkPVVisibleArea_h
#define vtkPVVisibleArea_h

#include "vtkPhongVTKParaViewModule.h" // for export macro
#include "vtkVisibleArea.h"

class VTKPHONGVTKPARAVIEW_EXPORT vtkPVVisibleArea : public vtkVisibleArea
{
public:
  static vtkPVVisibleArea* New();
  vtkTypeMacro(vtkPVVisibleArea, vtkVisibleArea);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Look through the active camera of `view` (a vtkPVRenderView); null, or an object that is not
   * a render view, uses ViewDirection. Default: none.
   */
  void SetView(vtkObject* view);

protected:
  vtkPVVisibleArea();
  ~vtkPVVisibleArea() override;

private:
  vtkPVVisibleArea(const vtkPVVisibleArea&) = delete;
  void operator=(const vtkPVVisibleArea&) = delete;
};

#endif
