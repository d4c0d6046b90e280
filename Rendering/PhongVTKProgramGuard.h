// A primitive whose shader program does not compile or link draws nothing and says so once,
// instead of crashing: VTK 9.2's vtkOpenGLPolyDataMapper::UpdateShaders reads the old program
// of a primitive whose first build failed (a null pointer), and VTK 9.6's keeps drawing with the
// last program that did build and tries the failing one again every frame. Private to
// PhongVTK::Rendering; used by MapperCore.
#ifndef PhongVTKProgramGuard_h
#define PhongVTKProgramGuard_h

#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

namespace phongvtk
{

/// A program that draws nothing: every vertex outside the clip volume, every fragment discarded.
/// Made (once per context) and bound by the window's shader cache, which owns it.
inline vtkShaderProgram* BlankProgram(vtkRenderer* ren)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window)
  {
    return nullptr;
  }
  static const char* vertex = "//VTK::System::Dec\n"
                              "void main() { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); }\n";
  static const char* fragment = "//VTK::System::Dec\n"
                                "//VTK::Output::Dec\n"
                                "void main() { discard; }\n";
  return window->GetShaderCache()->ReadyShaderProgram(vertex, fragment, "");
}

/// What the guard remembers of one primitive.
struct ProgramGuard
{
  bool Placeholder = false; ///< the program is the blank one, put in before a build
  bool Failed = false;      ///< the last build failed: the blank program draws it

  /// Before VTK's UpdateShaders: a primitive never goes into it without a program (VTK 9.2
  /// compares the old one's time when the new one fails). The blank program then forces the
  /// build that a missing program would have asked for.
  void Before(vtkOpenGLHelper& cellBO, vtkRenderer* ren)
  {
    if (!cellBO.Program)
    {
      cellBO.Program = BlankProgram(ren);
      this->Placeholder = cellBO.Program != nullptr;
    }
  }

  /// Whether GetNeedToRebuildShaders must say yes whatever VTK says.
  bool MustBuild() const { return this->Placeholder; }

  /// After VTK's UpdateShaders. `built` says whether it built (BuildShaders ran) and
  /// `sourceTime` is the primitive's ShaderSourceTime before the call. Returns true when this
  /// build failed and the primitive had drawn until now (say so, once).
  bool After(vtkOpenGLHelper& cellBO, vtkRenderer* ren, bool built, vtkMTimeType sourceTime)
  {
    this->Placeholder = false;
    if (!built)
    {
      return false;
    }
    // VTK 9.2 leaves no program; VTK 9.6 leaves the old one and does not mark the sources built.
    const bool failed = !cellBO.Program || cellBO.ShaderSourceTime.GetMTime() == sourceTime;
    const bool newly = failed && !this->Failed;
    this->Failed = failed;
    if (failed)
    {
      cellBO.Program = BlankProgram(ren);
      cellBO.VAO->ReleaseGraphicsResources();
      cellBO.VAO->Bind();
      // Built as far as it goes: no new attempt until something changes.
      cellBO.ShaderSourceTime.Modified();
    }
    return newly;
  }
};

}

#endif
