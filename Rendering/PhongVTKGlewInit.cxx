// VTK's vtkOpenGLRenderWindow::OpenGLInitContext() calls glewInit(), which with Debian's GLEW (a
// GLX build) loads every OpenGL entry point and then fails with GLEW_ERROR_NO_GLX_DISPLAY when the
// current context is not a GLX one. PhongVTK's own windows accept that answer (vtkHeadlessRender-
// Window::OpenGLInitContext), but windows of other classes that share a headless context cannot:
// ParaView's pvbatch renders every view in such a window, which then never counts as initialised
// and logs "GLEW could not be initialized" at every frame. The fix belongs in VTK (glewContextInit
// for non-GLX contexts); until then PhongVTK routes VTK's call to glewInit() through a function
// that gives that answer the meaning VTK needs when a PhongVTK headless context is current, by
// rewriting the one import slot of glewInit in VTK's OpenGL library. Nothing else is touched: any
// other result, any other context, any other caller sees GLEW's own answer.
#include "PhongVTKHeadless.h"

#include "vtk_glew.h"

#include <EGL/egl.h>

#include <dlfcn.h>
#include <elf.h>
#include <link.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <mutex>

namespace
{
using GlewInitFunction = GLenum (*)();
GlewInitFunction GlewInit = nullptr; // GLEW's own glewInit

GLenum GlewInitAcceptingHeadlessContexts()
{
  const GLenum result = GlewInit();
#ifdef GLEW_ERROR_NO_GLX_DISPLAY
  if (result == GLEW_ERROR_NO_GLX_DISPLAY && phongvtk::headless::HeadlessContextIsCurrent())
  {
    return GLEW_OK; // every entry point is loaded; only the GLX extension query was skipped
  }
#endif
  return result;
}

struct Patch
{
  int Slots = 0;
  std::string Problem;
};

/// The address a dynamic entry points to: glibc relocates them in place, other loaders may not.
inline ElfW(Addr) Absolute(ElfW(Addr) base, ElfW(Addr) value)
{
  return value < base ? base + value : value;
}

/// Rewrites the glewInit import slots (PLT and GOT relocations) of one loaded object.
void PatchObject(const dl_phdr_info* info, Patch& patch)
{
  const ElfW(Dyn)* dynamic = nullptr;
  ElfW(Addr) relroStart = 0, relroEnd = 0;
  for (int i = 0; i < info->dlpi_phnum; ++i)
  {
    const ElfW(Phdr)& ph = info->dlpi_phdr[i];
    if (ph.p_type == PT_DYNAMIC)
    {
      dynamic = reinterpret_cast<const ElfW(Dyn)*>(info->dlpi_addr + ph.p_vaddr);
    }
    else if (ph.p_type == PT_GNU_RELRO)
    {
      relroStart = info->dlpi_addr + ph.p_vaddr;
      relroEnd = relroStart + ph.p_memsz;
    }
  }
  if (!dynamic)
  {
    return;
  }
  const ElfW(Sym)* symbols = nullptr;
  const char* strings = nullptr;
  const ElfW(Rela) * tables[2] = { nullptr, nullptr };
  std::size_t sizes[2] = { 0, 0 };
  for (const ElfW(Dyn)* d = dynamic; d->d_tag != DT_NULL; ++d)
  {
    switch (d->d_tag)
    {
      case DT_SYMTAB:
        symbols = reinterpret_cast<const ElfW(Sym)*>(Absolute(info->dlpi_addr, d->d_un.d_ptr));
        break;
      case DT_STRTAB:
        strings = reinterpret_cast<const char*>(Absolute(info->dlpi_addr, d->d_un.d_ptr));
        break;
      case DT_JMPREL:
        tables[0] = reinterpret_cast<const ElfW(Rela)*>(Absolute(info->dlpi_addr, d->d_un.d_ptr));
        break;
      case DT_PLTRELSZ:
        sizes[0] = d->d_un.d_val;
        break;
      case DT_RELA:
        tables[1] = reinterpret_cast<const ElfW(Rela)*>(Absolute(info->dlpi_addr, d->d_un.d_ptr));
        break;
      case DT_RELASZ:
        sizes[1] = d->d_un.d_val;
        break;
      default:
        break;
    }
  }
  if (!symbols || !strings)
  {
    return;
  }
  const long pageSize = sysconf(_SC_PAGESIZE);
  for (int t = 0; t < 2; ++t)
  {
    for (std::size_t k = 0; tables[t] && k < sizes[t] / sizeof(ElfW(Rela)); ++k)
    {
      const ElfW(Rela)& r = tables[t][k];
      const auto type = ELF64_R_TYPE(r.r_info);
      if ((type != R_X86_64_JUMP_SLOT && type != R_X86_64_GLOB_DAT) ||
        std::strcmp(strings + symbols[ELF64_R_SYM(r.r_info)].st_name, "glewInit") != 0)
      {
        continue;
      }
      const ElfW(Addr) slot = info->dlpi_addr + r.r_offset;
      const bool readOnly = slot >= relroStart && slot < relroEnd;
      void* page = reinterpret_cast<void*>(slot & ~static_cast<ElfW(Addr)>(pageSize - 1));
      if (readOnly && mprotect(page, static_cast<std::size_t>(pageSize), PROT_READ | PROT_WRITE))
      {
        patch.Problem = "cannot make the import slot of glewInit writable";
        continue;
      }
      *reinterpret_cast<GlewInitFunction*>(slot) = &GlewInitAcceptingHeadlessContexts;
      if (readOnly)
      {
        mprotect(page, static_cast<std::size_t>(pageSize), PROT_READ);
      }
      ++patch.Slots;
    }
  }
}
}

namespace phongvtk
{
namespace headless
{

//------------------------------------------------------------------------------
bool HeadlessContextIsCurrent()
{
  const OSMesaLibrary* osmesa = OSMesaLibrary::IfLoaded();
  return (osmesa && osmesa->OwnsThreadDispatch()) || eglGetCurrentContext() != EGL_NO_CONTEXT;
}

//------------------------------------------------------------------------------
bool RouteVTKGlewInit(std::string* problem)
{
  static std::once_flag once;
  static Patch patch;
  std::call_once(once,
    []
    {
      GlewInit = reinterpret_cast<GlewInitFunction>(dlsym(RTLD_DEFAULT, "glewInit"));
      if (!GlewInit)
      {
        patch.Problem = "glewInit is not loaded";
        return;
      }
      dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* data)
        {
          if (info->dlpi_name && std::strstr(info->dlpi_name, "libvtkRenderingOpenGL2"))
          {
            PatchObject(info, *static_cast<Patch*>(data));
          }
          return 0;
        },
        &patch);
      if (patch.Slots == 0 && patch.Problem.empty())
      {
        patch.Problem = "no import of glewInit in VTK's OpenGL library";
      }
    });
  if (problem)
  {
    *problem = patch.Problem;
  }
  return patch.Slots > 0;
}

}
}
