#include "vtkPVVisibleArea.h"

#include "vtkCamera.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"

vtkStandardNewMacro(vtkPVVisibleArea);

//------------------------------------------------------------------------------
vtkPVVisibleArea::vtkPVVisibleArea() = default;

//------------------------------------------------------------------------------
vtkPVVisibleArea::~vtkPVVisibleArea() = default;

//------------------------------------------------------------------------------
void vtkPVVisibleArea::SetView(vtkObject* view)
{
  vtkPVRenderView* renderView = vtkPVRenderView::SafeDownCast(view);
  if (view && !renderView)
  {
    vtkWarningMacro(
      "A " << view->GetClassName() << " is not a render view: the view direction is used instead.");
  }
  this->SetCamera(renderView ? renderView->GetActiveCamera() : nullptr);
}

//------------------------------------------------------------------------------
void vtkPVVisibleArea::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
