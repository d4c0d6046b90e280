/**
 * Private to PhongVTK::RenderingHeadless: VTK 9.1/9.2's XML readers on an expat with reparse
 * deferral.
 *
 * Expat 2.6.0 defers reparsing a token that was incomplete at the end of the previous input until
 * enough new input has arrived (the fix of CVE-2023-52425; Debian 12 backports it into
 * 2.5.0-1+deb12u2 and later). VTK 9.1/9.2's vtkXMLDataParser learns that it has reached a file's
 * AppendedData section from the element handler expat calls for it, and feeds the rest of that
 * tag a few bytes at a time: with deferral the handler has not run when VTK reads on, the
 * appended data reaches expat as if it were XML ("not well-formed (invalid token)"), and the
 * reader returns no cells.
 * Appended data is vtkXMLWriter's default mode, so this loses most .vtp/.vtu files; ParaView
 * 5.11's own ranks exchange data that way (RedistributeDataSet under MPI hangs on it).
 *
 * When this library is loaded, and VTK's parser is found to fail that way (it parses such a
 * document from memory), every expat parser that VTK's XML parser library creates from then on
 * has deferral turned off: the behaviour VTK 9.1/9.2 was written for (every expat before 2.6).
 * VTK 9.3.1 and later stop at AppendedData without the handler (so does Debian's VTK 9.1 since
 * 9.1.0+really9.1.0+dfsg2-5+deb12u1, which carries that fix), and nothing is changed there. The
 * cost deferral saves, reparsing one token that spans many of VTK's 4 KiB reads, does not arise
 * with VTK's files: their large contents (ASCII and base64 data) are character data, which expat
 * reports as it goes. Set PHONGVTK_KEEP_EXPAT_DEFERRAL=1 to leave expat as it is.
 */
#ifndef PhongVTKExpatDeferral_h
#define PhongVTKExpatDeferral_h

#include "vtkPhongVTKRenderingHeadlessModule.h" // for the export macro

#include <string>

namespace phongvtk
{

enum class ExpatDeferral
{
  Absent,    ///< the expat VTK uses has no reparse deferral: nothing to do
  Disabled,  ///< VTK's XML parsers are created with deferral off
  Kept,      ///< VTK fails, and PHONGVTK_KEEP_EXPAT_DEFERRAL asked to leave expat as it is
  NotNeeded, ///< this VTK reads appended data with deferral on
  Failed     ///< VTK fails, and turning deferral off did not help (see the problem)
};

/// What was done when the library was loaded; `*problem` (if given) says why for Failed.
VTKPHONGVTKRENDERINGHEADLESS_EXPORT ExpatDeferral GetExpatDeferral(std::string* problem = nullptr);

/**
 * Whether VTK's XML parser, as it is now, reads a document whose appended data spans several of
 * its reads (parsed from memory, errors kept from the output window): the case deferral breaks.
 */
VTKPHONGVTKRENDERINGHEADLESS_EXPORT bool VTKReadsAppendedXML();

}

#endif
// VTK-HeaderTest-Exclude: PhongVTKExpatDeferral.h
