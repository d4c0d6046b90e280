"""Fails when a function of the Filters library outside the AVX + FMA kernel set holds an AVX
instruction (a VEX- or EVEX-encoded one, or a ymm/zmm register).

    check_kernel_isolation.py OBJDUMP LIBRARY

The AVX + FMA set lives in the namespace phongvtk::avx_fma (Filters/PhongVTKKernelNamespace.h):
its functions, and the template instances and lambdas that name it, may use AVX. Anything else is
code a baseline caller may reach, on a processor without AVX.
"""
import re
import subprocess
import sys

objdump, library = sys.argv[1], sys.argv[2]
listing = subprocess.run([objdump, "-d", "-C", "--no-show-raw-insn", library],
                         capture_output=True, text=True, check=True).stdout
function_line = re.compile(r"^[0-9a-f]+ <(.*)>:$")
# AVX instructions are the VEX/EVEX forms: their mnemonics start with "v" (vmovsd, vfmadd...;
# no SSE or x87 one does), and any use of a ymm or zmm register.
avx = re.compile(r"^\s+[0-9a-f]+:\s+v[a-z0-9]+\b|%[yz]mm")
function, offenders, kernel_functions = None, {}, 0
for line in listing.splitlines():
    m = function_line.match(line)
    if m:
        function = m.group(1)
        kernel_functions += "avx_fma" in function
        continue
    if function and "avx_fma" not in function and function not in offenders and avx.search(line):
        offenders[function] = line.strip()
if kernel_functions == 0:
    sys.exit("no function of the AVX + FMA kernel set in %s: is it built?" % library)
for function, line in offenders.items():
    print("AVX outside the AVX + FMA set: %s\n    %s" % (function, line))
if offenders:
    sys.exit("%d function(s) with AVX instructions outside phongvtk::avx_fma" % len(offenders))
print("%s: %d functions of the AVX + FMA set; no AVX instruction elsewhere"
      % (library, kernel_functions))
