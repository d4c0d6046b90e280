/**
 * libFuzzer target: the command line's front door, `python3 -m phongvtk normals FILE -o OUT`, run
 * in an embedded Python (Debian's libpython) on each input as a file of one of the formats the
 * command line reads (fuzz_cli.py). A signal inside a reader (VTK's or PhongVTK's), a sanitizer
 * report, an escaped Python exception, a status other than 0 or 2, an error that is not one line
 * or a failed run that leaves files behind is a finding.
 *
 * VTK's readers are not instrumented, so libFuzzer sees no coverage of them; PhongVTK's checks in
 * front of them are Python, whose line coverage is fed to libFuzzer here: every line event of a
 * function of the `phongvtk` package (and of the pair previous line -> line, i.e. the branch
 * taken) increments one of 2^16 inline 8-bit counters registered as an extra module, as Google's
 * Atheris does for pure-Python targets.
 */
#define PY_SSIZE_T_CLEAN // "y#" takes a Py_ssize_t length
#include <Python.h>
#include <frameobject.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>
#include <unordered_map>

#if !defined(PHONGVTK_PYTHONPATH) || !defined(PHONGVTK_FUZZ_DIRECTORY)
#error "PHONGVTK_PYTHONPATH (the phongvtk package) and PHONGVTK_FUZZ_DIRECTORY (fuzz_cli.py)"
#endif

namespace
{
constexpr std::size_t CounterCount = 1 << 16;
alignas(64) std::uint8_t Counters[CounterCount];

#ifdef PHONGVTK_LIBFUZZER
alignas(64) std::uintptr_t ProgramCounters[2 * CounterCount];
#endif

PyObject* RunOne = nullptr;
int ReportFd = 2;

/// Per code object: whether it belongs to phongvtk, and a hash of where it is (not its address:
/// the same function must give the same counters in every process).
struct CodeInfo
{
  bool Mine;
  std::uint64_t Where;
};
std::unordered_map<PyCodeObject*, CodeInfo> Codes;
std::uint64_t PreviousLine = 0;

std::uint64_t Mix(std::uint64_t x)
{
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  x *= 0xc4ceb9fe1a85ec53ULL;
  return x ^ (x >> 33);
}

CodeInfo Describe(PyCodeObject* code)
{
  const char* file = PyUnicode_AsUTF8(code->co_filename);
  const char* name = PyUnicode_AsUTF8(code->co_name);
  if (!file || !name)
  {
    PyErr_Clear();
    return { false, 0 };
  }
  const bool mine = std::strstr(file, "/phongvtk/") != nullptr;
  const std::uint64_t where = std::hash<std::string>()(std::string(file) + ":" + name) ^
    Mix(static_cast<std::uint64_t>(code->co_firstlineno));
  return { mine, where };
}

int Trace(PyObject*, PyFrameObject* frame, int what, PyObject*)
{
  if (what != PyTrace_LINE && what != PyTrace_EXCEPTION)
  {
    return 0;
  }
  PyCodeObject* code = PyFrame_GetCode(frame);
  auto found = Codes.find(code);
  if (found == Codes.end())
  {
    Py_INCREF(code); // kept alive: its address stays its key
    found = Codes.emplace(code, Describe(code)).first;
  }
  Py_DECREF(code);
  if (!found->second.Mine)
  {
    return 0;
  }
  const std::uint64_t line =
    Mix(found->second.Where + static_cast<std::uint64_t>(PyFrame_GetLineNumber(frame)) * 2 +
      (what == PyTrace_EXCEPTION ? 1 : 0));
  ++Counters[(line ^ (PreviousLine >> 1)) % CounterCount];
  PreviousLine = line;
  return 0;
}

[[noreturn]] void Fail(const char* what)
{
  dprintf(ReportFd, "FuzzReaders: %s\n", what);
  if (PyErr_Occurred())
  {
    PyErr_Print();
  }
  // fuzz_cli's temporary directory, which an abort leaves behind.
  PyRun_SimpleString("import fuzz_cli, shutil; shutil.rmtree(fuzz_cli._directory, True)");
  std::abort();
}
} // namespace

#ifdef PHONGVTK_LIBFUZZER
extern "C" void __sanitizer_cov_8bit_counters_init(std::uint8_t* start, std::uint8_t* stop);
extern "C" void __sanitizer_cov_pcs_init(const std::uintptr_t* start, const std::uintptr_t* stop);

/// Registers the Python counters as one more instrumented module (with a table of made-up
/// program counters of the same length, as libFuzzer requires of every module).
__attribute__((constructor)) static void RegisterPythonCoverage()
{
  for (std::size_t i = 0; i < CounterCount; ++i)
  {
    ProgramCounters[2 * i] = 0x7e0000000000ULL + i;
    ProgramCounters[2 * i + 1] = 0;
  }
  __sanitizer_cov_8bit_counters_init(Counters, Counters + CounterCount);
  __sanitizer_cov_pcs_init(ProgramCounters, ProgramCounters + 2 * CounterCount);
}
#endif

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  ReportFd = dup(2); // libFuzzer's -close_fd_mask closes stderr later
  Py_InitializeEx(0);
  PyObject* sysPath = PySys_GetObject("path");
  // VTK's own package first when it is not the system's (a VTK built from source), then the
  // package and the fuzzing script in front of it.
  for (const char* path : { PHONGVTK_VTK_PYTHONPATH, PHONGVTK_FUZZ_DIRECTORY, PHONGVTK_PYTHONPATH })
  {
    if (!*path)
    {
      continue;
    }
    PyObject* directory = PyUnicode_FromString(path);
    PyList_Insert(sysPath, 0, directory);
    Py_DECREF(directory);
  }
  PyObject* module = PyImport_ImportModule("fuzz_cli");
  if (!module)
  {
    Fail("cannot import fuzz_cli (the phongvtk package of this build)");
  }
  RunOne = PyObject_GetAttrString(module, "run_one");
  PyObject* started = PyObject_CallMethod(module, "start", "i", ReportFd);
  if (!RunOne || !started)
  {
    Fail("fuzz_cli has no run_one or start");
  }
  Py_DECREF(started);
  Py_DECREF(module);
  PyEval_SetTrace(Trace, nullptr);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  PreviousLine = 0;
  PyObject* result = PyObject_CallFunction(
    RunOne, "y#", reinterpret_cast<const char*>(data), static_cast<Py_ssize_t>(size));
  if (!result)
  {
    Fail("run_one raised");
  }
  Py_DECREF(result);
  return 0;
}
