"""The Python half of FuzzReaders: one input through `python3 -m phongvtk normals FILE -o OUT`.

The first byte picks the format (the file's extension), the rest is the file. The command must
either succeed and leave a non-empty output file, or fail with status 2 and exactly one line
``phongvtk: error: ...``; anything else (another status, a traceback, a Python exception) is
reported on the fuzzer's own stderr and aborts, so that libFuzzer keeps the input.
"""

import atexit
import contextlib
import io
import os
import shutil
import tempfile
import traceback

from phongvtk import cli

FORMATS = (".off", ".ply", ".stl", ".obj", ".vtk", ".vtp")
_directory = tempfile.mkdtemp(
    prefix="phongvtk-fuzz-", dir="/dev/shm" if os.path.isdir("/dev/shm") else None)
_report = None
atexit.register(shutil.rmtree, _directory, ignore_errors=True)


def start(report_fd):
    """Violations are written to `report_fd` (the process's stderr before libFuzzer closed it)."""
    global _report
    _report = os.fdopen(report_fd, "w", closefd=False)


def violation(data, what):
    _report.write(f"FuzzReaders: {what}\n")
    _report.flush()
    shutil.rmtree(_directory, ignore_errors=True)
    os.abort()


def run_one(data):
    kind = FORMATS[data[0] % len(FORMATS)] if data else ".off"
    source = os.path.join(_directory, "input" + kind)
    target = os.path.join(_directory, "output.vtp")
    for name in os.listdir(_directory):
        os.unlink(os.path.join(_directory, name))
    with open(source, "wb") as file:
        file.write(data[1:])
    stderr = io.StringIO()
    try:
        with contextlib.redirect_stderr(stderr), contextlib.redirect_stdout(io.StringIO()):
            status = cli.main(["normals", source, "-o", target, "--quiet"])
    except BaseException:  # noqa: B902 - every escape is the finding
        violation(data, f"{kind}: an exception escaped the command line:\n{traceback.format_exc()}")
    lines = stderr.getvalue().splitlines()
    if status == 2:
        if len(lines) != 1 or not lines[0].startswith("phongvtk: error: "):
            violation(data, f"{kind}: status 2 with stderr {lines!r}")
        if os.path.exists(target):
            violation(data, f"{kind}: failed but left {target}")
    elif status == 0:
        if not os.path.isfile(target) or os.path.getsize(target) == 0:
            violation(data, f"{kind}: status 0 without an output file")
    else:
        violation(data, f"{kind}: status {status}, stderr {lines!r}")
    leftovers = sorted(set(os.listdir(_directory)) - {os.path.basename(source), "output.vtp"})
    if leftovers:
        violation(data, f"{kind}: temporary files left: {leftovers}")
