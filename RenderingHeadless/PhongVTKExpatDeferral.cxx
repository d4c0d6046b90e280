#include "PhongVTKExpatDeferral.h"
#include "PhongVTKImportSlots.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkVersionMacros.h"
#include "vtkXMLDataParser.h"

#include <expat.h>

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <sstream>

namespace
{
using ParserCreateFunction = XML_Parser (*)(const XML_Char*);
using SetDeferralFunction = XML_Bool (*)(XML_Parser, XML_Bool);
ParserCreateFunction ParserCreate = nullptr;      // expat's own XML_ParserCreate
SetDeferralFunction SetReparseDeferral = nullptr; // expat >= 2.6.0 (or a backport) only

/// What vtkXMLParser::CreateParser() now calls instead of XML_ParserCreate.
XML_Parser ParserCreateWithoutDeferral(const XML_Char* encoding)
{
  XML_Parser parser = ParserCreate(encoding);
  if (parser)
  {
    SetReparseDeferral(parser, XML_FALSE);
  }
  return parser;
}

struct Outcome
{
  phongvtk::ExpatDeferral State = phongvtk::ExpatDeferral::Absent;
  std::string Problem;
};

Outcome Apply()
{
  Outcome outcome;
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 1)
  outcome.State = phongvtk::ExpatDeferral::NotNeeded;
#else
  // The expat VTK's XML library was linked with, already loaded as its dependency (Debian's VTK
  // uses the system's; a VTK with its own copy imports mangled names and is not affected).
  void* expat = dlopen("libexpat.so.1", RTLD_NOW | RTLD_NOLOAD);
  if (expat)
  {
    ParserCreate = reinterpret_cast<ParserCreateFunction>(dlsym(expat, "XML_ParserCreate"));
    SetReparseDeferral =
      reinterpret_cast<SetDeferralFunction>(dlsym(expat, "XML_SetReparseDeferralEnabled"));
    dlclose(expat); // only drops the reference dlopen took: VTK's library keeps expat loaded
  }
  const char* keep = std::getenv("PHONGVTK_KEEP_EXPAT_DEFERRAL");
  if (!ParserCreate || !SetReparseDeferral)
  {
    outcome.State = phongvtk::ExpatDeferral::Absent;
  }
  else if (phongvtk::VTKReadsAppendedXML())
  {
    // This VTK stops at AppendedData by itself (Debian's 9.1 carries the upstream fix).
    outcome.State = phongvtk::ExpatDeferral::NotNeeded;
  }
  else if (keep && *keep && std::strcmp(keep, "0") != 0)
  {
    outcome.State = phongvtk::ExpatDeferral::Kept;
  }
  else if (phongvtk::RouteImport("libvtkIOXMLParser", "XML_ParserCreate",
             reinterpret_cast<void*>(&ParserCreateWithoutDeferral), &outcome.Problem) == 0)
  {
    outcome.State = phongvtk::ExpatDeferral::Failed;
  }
  else if (!phongvtk::VTKReadsAppendedXML())
  {
    outcome.State = phongvtk::ExpatDeferral::Failed;
    outcome.Problem = "VTK's XML parser still stops short of appended data with deferral off";
  }
  else
  {
    outcome.State = phongvtk::ExpatDeferral::Disabled;
  }
#endif
  return outcome;
}

const Outcome& Applied()
{
  static const Outcome outcome = Apply();
  return outcome;
}

/// Applied when the library is loaded: before any reader of the program runs (VTK's XML parser
/// library is a dependency of this one, so it is loaded and relocated first).
const bool AppliedAtLoad = (Applied(), true);
}

namespace phongvtk
{

//------------------------------------------------------------------------------
ExpatDeferral GetExpatDeferral(std::string* problem)
{
  (void)AppliedAtLoad;
  const Outcome& outcome = Applied();
  if (problem)
  {
    *problem = outcome.Problem;
  }
  return outcome.State;
}

//------------------------------------------------------------------------------
bool VTKReadsAppendedXML()
{
  // An empty piece, then raw appended data that is no XML at all (bytes 0..255 over and over),
  // longer than the parser's 4 KiB reads: VTK reads it only if it stops at <AppendedData.
  std::string document = "<?xml version=\"1.0\"?>\n"
                         "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                         "header_type=\"UInt64\">\n<PolyData>\n<Piece NumberOfPoints=\"0\" "
                         "NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                         "NumberOfPolys=\"0\">\n</Piece>\n</PolyData>\n"
                         "<AppendedData encoding=\"raw\">\n_";
  for (int i = 0; i < 3 * 4096; ++i)
  {
    document += static_cast<char>(i & 255);
  }
  document += "\n</AppendedData>\n</VTKFile>\n";
  std::istringstream stream(document);
  vtkNew<vtkXMLDataParser> parser;
  vtkNew<vtkCallbackCommand> quiet; // a parse error here is an answer, not a message
  parser->AddObserver(vtkCommand::ErrorEvent, quiet);
  parser->AddObserver(vtkCommand::WarningEvent, quiet);
  parser->SetStream(&stream);
  return parser->Parse() && parser->GetRootElement() && parser->GetAppendedDataPosition() > 0;
}

}
