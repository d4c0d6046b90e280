// Shared by the rendering tests: a small lit scene whose key pixels are known analytically, a
// catcher for VTK's warnings and errors, and render-count observers.
#ifndef PhongVTKRenderingTestSupport_h
#define PhongVTKRenderingTestSupport_h

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkConeSource.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <string>
#include <vector>

namespace phongvtk
{
namespace testing
{

/// The scene's colours (linear, 0..1). The sphere is lit only diffusely by VTK's headlight, so
/// the pixel at the centre of the sphere, whose normal faces the camera and the light, is the
/// diffuse colour itself (n.l = 1); the corners show the background.
constexpr double SceneBackground[3] = { 0.1, 0.2, 0.3 };
constexpr double SphereColour[3] = { 1.0, 0.3, 0.2 };

/// A sphere (radius 0.5 at the origin, facing the camera) and a cone beside it, camera on +z.
/// The sphere is the renderer's first actor.
inline vtkSmartPointer<vtkRenderer> AddScene(vtkRenderWindow* window, int width = 240,
  int height = 180, vtkPolyDataMapper* sphereMapper = nullptr)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(48);
  vtkSmartPointer<vtkPolyDataMapper> mapper = sphereMapper;
  if (!mapper)
  {
    mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  }
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(mapper);
  sphereActor->GetProperty()->SetColor(SphereColour[0], SphereColour[1], SphereColour[2]);
  sphereActor->GetProperty()->SetAmbient(0.0);
  sphereActor->GetProperty()->SetDiffuse(1.0);
  sphereActor->GetProperty()->SetSpecular(0.0);

  vtkNew<vtkConeSource> cone;
  cone->SetCenter(0.95, 0.1, 0.0);
  cone->SetHeight(0.6);
  cone->SetRadius(0.25);
  cone->SetResolution(24);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->GetProperty()->SetColor(0.3, 0.9, 0.4);
  coneActor->GetProperty()->SetSpecular(0.6);
  coneActor->GetProperty()->SetSpecularPower(20);

  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(sphereActor);
  renderer->AddActor(coneActor);
  renderer->SetBackground(SceneBackground[0], SceneBackground[1], SceneBackground[2]);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 4);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(1, 10);
  window->AddRenderer(renderer);
  window->SetSize(width, height);
  return renderer;
}

/// Collects VTK's warnings and errors while it is installed (RAII): nothing reaches stderr.
class MessageCatcher
{
public:
  MessageCatcher()
  {
    this->Previous = vtkOutputWindow::GetInstance();
    this->Previous->Register(nullptr);
    vtkOutputWindow::SetInstance(this->Window);
  }
  ~MessageCatcher()
  {
    vtkOutputWindow::SetInstance(this->Previous);
    this->Previous->UnRegister(nullptr);
  }
  MessageCatcher(const MessageCatcher&) = delete;
  void operator=(const MessageCatcher&) = delete;

  const std::vector<std::string>& Warnings() const { return this->Window->Warnings; }
  const std::vector<std::string>& Errors() const { return this->Window->Errors; }

private:
  class Catcher : public vtkOutputWindow
  {
  public:
    static Catcher* New()
    {
      auto* catcher = new Catcher;
      catcher->InitializeObjectBase();
      return catcher;
    }
    vtkTypeMacro(Catcher, vtkOutputWindow);
    void DisplayText(const char* text) override { this->Others.emplace_back(text); }
    void DisplayErrorText(const char* text) override { this->Errors.emplace_back(text); }
    void DisplayWarningText(const char* text) override { this->Warnings.emplace_back(text); }
    void DisplayGenericWarningText(const char* text) override { this->Warnings.emplace_back(text); }
    std::vector<std::string> Warnings, Errors, Others;
  };
  vtkNew<Catcher> Window;
  vtkOutputWindow* Previous = nullptr;
};

/// Counts the renders of a window (vtkRenderWindow::Render fires StartEvent once per frame).
class RenderCounter
{
public:
  explicit RenderCounter(vtkRenderWindow* window)
    : Window(window)
  {
    this->Callback->SetClientData(&this->Count);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
    this->Tag = window->AddObserver(vtkCommand::StartEvent, this->Callback);
  }
  ~RenderCounter() { this->Window->RemoveObserver(this->Tag); }
  RenderCounter(const RenderCounter&) = delete;
  void operator=(const RenderCounter&) = delete;
  int Renders() const { return this->Count; }

private:
  vtkRenderWindow* Window;
  vtkNew<vtkCallbackCommand> Callback;
  unsigned long Tag = 0;
  int Count = 0;
};

}
}

#endif
