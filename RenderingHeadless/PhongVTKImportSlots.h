/**
 * Private to PhongVTK::RenderingHeadless: redirecting one library's calls to one imported function.
 *
 * Two defects of Debian's VTK 9.1/9.2 on current system libraries are fixed at the one call that
 * goes wrong (GLEW's glewInit on a non-GLX context; expat's XML_ParserCreate, see
 * PhongVTKExpatDeferral.cxx) by rewriting the import slot through which VTK's own library calls
 * that function. The slot is the library's PLT/GOT entry: the dynamic linker wrote the target's
 * address there, and every call from that library (and from no other) goes through it. Linux with
 * glibc on x86-64 and AArch64 only; elsewhere nothing is rewritten and the caller is told why.
 */
#ifndef PhongVTKImportSlots_h
#define PhongVTKImportSlots_h

#include <string>

namespace phongvtk
{

/**
 * Points the import slots of `symbol` in every loaded object whose file name contains `library`
 * at `replacement`. Returns how many slots were rewritten; when none, `*problem` (if given) says
 * why (no such library loaded, no import of the symbol in it, a read-only slot that could not be
 * made writable, an unsupported platform). Not thread-safe: callers run it once, before the
 * library's first call of the symbol that matters.
 */
int RouteImport(const char* library, const char* symbol, void* replacement, std::string* problem);

}

#endif
// VTK-HeaderTest-Exclude: PhongVTKImportSlots.h
