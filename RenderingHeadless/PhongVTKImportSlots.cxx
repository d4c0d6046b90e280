#include "PhongVTKImportSlots.h"

#if defined(__linux__) && defined(__GLIBC__) && (defined(__x86_64__) || defined(__aarch64__))
#define PHONGVTK_IMPORT_SLOTS 1
#include <elf.h>
#include <link.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstring>
#endif

namespace
{
#ifdef PHONGVTK_IMPORT_SLOTS
#if defined(__x86_64__)
constexpr unsigned long CallSlot = R_X86_64_JUMP_SLOT; // PLT: calls
constexpr unsigned long DataSlot = R_X86_64_GLOB_DAT;  // GOT: address taken, or -fno-plt
#else
constexpr unsigned long CallSlot = R_AARCH64_JUMP_SLOT;
constexpr unsigned long DataSlot = R_AARCH64_GLOB_DAT;
#endif

struct Request
{
  const char* Library;
  const char* Symbol;
  void* Replacement;
  int Objects = 0; // loaded objects whose name matched
  int Slots = 0;
  std::string Problem;
};

/// The address a dynamic entry points to: glibc relocates them in place, other loaders may not.
inline ElfW(Addr) Absolute(ElfW(Addr) base, ElfW(Addr) value)
{
  return value < base ? base + value : value;
}

/// Rewrites the request's import slots (PLT and GOT relocations) of one loaded object.
void RouteInObject(const dl_phdr_info* info, Request& request)
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
      // The dynamic linker makes read-only only the whole pages of this range: a partial last
      // page stays writable (it may hold the lazily bound GOT) and must not be touched here.
      const ElfW(Addr) page = static_cast<ElfW(Addr)>(sysconf(_SC_PAGESIZE));
      relroStart = (info->dlpi_addr + ph.p_vaddr) & ~(page - 1);
      relroEnd = (info->dlpi_addr + ph.p_vaddr + ph.p_memsz) & ~(page - 1);
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
      if ((type != CallSlot && type != DataSlot) ||
        std::strcmp(strings + symbols[ELF64_R_SYM(r.r_info)].st_name, request.Symbol) != 0)
      {
        continue;
      }
      const ElfW(Addr) slot = info->dlpi_addr + r.r_offset;
      const bool readOnly = slot >= relroStart && slot < relroEnd;
      void* page = reinterpret_cast<void*>(slot & ~static_cast<ElfW(Addr)>(pageSize - 1));
      if (readOnly && mprotect(page, static_cast<std::size_t>(pageSize), PROT_READ | PROT_WRITE))
      {
        request.Problem = std::string("cannot make the import slot of ") + request.Symbol + " in " +
          info->dlpi_name + " writable";
        continue;
      }
      // What the replacement reads (the original function) is stored before the slot is.
      std::atomic_thread_fence(std::memory_order_release);
      *reinterpret_cast<void**>(slot) = request.Replacement;
      if (readOnly)
      {
        mprotect(page, static_cast<std::size_t>(pageSize), PROT_READ);
      }
      ++request.Slots;
    }
  }
}
#endif
}

namespace phongvtk
{

//------------------------------------------------------------------------------
int RouteImport(const char* library, const char* symbol, void* replacement, std::string* problem)
{
#ifdef PHONGVTK_IMPORT_SLOTS
  Request request{ library, symbol, replacement };
  dl_iterate_phdr(
    [](dl_phdr_info* info, std::size_t, void* data)
    {
      auto& r = *static_cast<Request*>(data);
      if (info->dlpi_name && std::strstr(info->dlpi_name, r.Library))
      {
        ++r.Objects;
        RouteInObject(info, r);
      }
      return 0;
    },
    &request);
  if (request.Slots == 0 && request.Problem.empty())
  {
    request.Problem = request.Objects == 0
      ? std::string("no library named like ") + library + " is loaded"
      : std::string("no import of ") + symbol + " in " + library;
  }
  if (problem)
  {
    *problem = request.Problem;
  }
  return request.Slots;
#else
  (void)library;
  (void)replacement;
  if (problem)
  {
    *problem = std::string("rerouting ") + symbol + " needs Linux/glibc on x86-64 or AArch64";
  }
  return 0;
#endif
}

}
