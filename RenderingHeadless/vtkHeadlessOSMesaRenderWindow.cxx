#include "vtkHeadlessOSMesaRenderWindow.h"

#include "PhongVTKHeadless.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkHeadlessOSMesaRenderWindow);

using phongvtk::headless::OSMesaLibrary;

//------------------------------------------------------------------------------
vtkHeadlessOSMesaRenderWindow::vtkHeadlessOSMesaRenderWindow() = default;

//------------------------------------------------------------------------------
vtkHeadlessOSMesaRenderWindow::~vtkHeadlessOSMesaRenderWindow()
{
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkHeadlessOSMesaRenderWindow::IsAvailable(std::string* why)
{
  return OSMesaLibrary::Get(why) != nullptr;
}

//------------------------------------------------------------------------------
void* vtkHeadlessOSMesaRenderWindow::GetGenericContext()
{
  return this->Context;
}

//------------------------------------------------------------------------------
bool vtkHeadlessOSMesaRenderWindow::CreateContext(std::string& problem)
{
  const OSMesaLibrary* library = OSMesaLibrary::Get(&problem);
  if (!library)
  {
    return false;
  }
  this->Context = library->CreateContext(&problem);
  if (!this->Context)
  {
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkHeadlessOSMesaRenderWindow::DestroyContext()
{
  if (this->Context)
  {
    OSMesaLibrary::Get(nullptr)->DestroyContext(this->Context);
    this->Context = nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkHeadlessOSMesaRenderWindow::BindContext(std::string& problem)
{
  return OSMesaLibrary::Get(nullptr)->Bind(this->Context, &problem);
}

//------------------------------------------------------------------------------
void vtkHeadlessOSMesaRenderWindow::UnbindContext()
{
  OSMesaLibrary::Get(nullptr)->Unbind();
}

//------------------------------------------------------------------------------
bool vtkHeadlessOSMesaRenderWindow::IsContextBound()
{
  return this->Context && OSMesaLibrary::Get(nullptr)->IsBound(this->Context);
}

//------------------------------------------------------------------------------
void vtkHeadlessOSMesaRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: " << static_cast<void*>(this->Context) << "\n";
}
