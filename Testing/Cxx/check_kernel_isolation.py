"""Fails when a function of the Filters library, or of one of its object files, outside the
AVX + FMA kernel set holds an AVX instruction (a VEX- or EVEX-encoded one, or a ymm/zmm register).

    check_kernel_isolation.py OBJDUMP LIBRARY [OBJECT...]

The AVX + FMA set lives in the namespace phongvtk::avx_fma (Filters/PhongVTKKernelNamespace.h):
its functions, and the template instances and lambdas that name it, may use AVX. Anything else is
code a baseline caller may reach, on a processor without AVX. The library shows the copies the
linker kept; the object files (OBJECT arguments, also as one ';'-separated list) show every copy
the compiler made, so that a different link order or linker cannot bring one back.
"""
import re
import subprocess
import sys

objdump, library = sys.argv[1], sys.argv[2]
objects = [o for arg in sys.argv[3:] for o in arg.split(";") if o]
function_line = re.compile(r"^[0-9a-f]+ <(.*)>:$")
# AVX instructions are the VEX/EVEX forms: their mnemonics start with "v" (vmovsd, vfmadd...;
# no SSE or x87 one does), and any use of a ymm or zmm register.
avx = re.compile(r"^\s+[0-9a-f]+:\s+v[a-z0-9]+\b|%[yz]mm")


def check(binary):
    """The kernel set's functions in `binary` and the other functions holding AVX code."""
    listing = subprocess.run([objdump, "-d", "-C", "--no-show-raw-insn", binary],
                             capture_output=True, text=True, check=True).stdout
    function, offenders, kernel_functions = None, {}, 0
    for line in listing.splitlines():
        m = function_line.match(line)
        if m:
            function = m.group(1)
            kernel_functions += "avx_fma" in function
            continue
        if function and "avx_fma" not in function and function not in offenders \
                and avx.search(line):
            offenders[function] = line.strip()
    return kernel_functions, offenders


failures = 0
kernel_functions, offenders = check(library)
if kernel_functions == 0:
    sys.exit("no function of the AVX + FMA kernel set in %s: is it built?" % library)
for binary, found in [(library, offenders)] + [(o, check(o)[1]) for o in objects]:
    for function, line in found.items():
        print("AVX outside the AVX + FMA set in %s: %s\n    %s" % (binary, function, line))
    failures += len(found)
if objects and not any("AVXFMA" in o for o in objects):
    sys.exit("none of the %d object files is an AVX + FMA kernel file" % len(objects))
if failures:
    sys.exit("%d function(s) with AVX instructions outside phongvtk::avx_fma" % failures)
print("%s: %d functions of the AVX + FMA set; no AVX instruction elsewhere (library and %d "
      "object files)" % (library, kernel_functions, len(objects)))
