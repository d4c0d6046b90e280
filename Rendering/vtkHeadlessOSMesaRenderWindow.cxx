#include "vtkHeadlessOSMesaRenderWindow.h"

#include "PhongVTKHeadless.h"

#include "vtkObjectFactory.h"

#include <algorithm>

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
  this->ResizeContextBuffer(this->Size[0], this->Size[1]);
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
  std::vector<unsigned char>().swap(this->Buffer);
  this->BufferSize[0] = this->BufferSize[1] = 0;
}

//------------------------------------------------------------------------------
void vtkHeadlessOSMesaRenderWindow::ResizeContextBuffer(int width, int height)
{
  // VTK's Start() renders at least 300 x 300 when no size is set.
  this->BufferSize[0] = std::max(width > 0 ? width : 300, 1);
  this->BufferSize[1] = std::max(height > 0 ? height : 300, 1);
  this->Buffer.assign(4 * static_cast<size_t>(this->BufferSize[0]) * this->BufferSize[1], 0);
}

//------------------------------------------------------------------------------
bool vtkHeadlessOSMesaRenderWindow::BindContext(std::string& problem)
{
  return OSMesaLibrary::Get(nullptr)->Bind(
    this->Context, this->Buffer.data(), this->BufferSize[0], this->BufferSize[1], &problem);
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
  os << indent << "BufferSize: " << this->BufferSize[0] << " x " << this->BufferSize[1] << "\n";
}
