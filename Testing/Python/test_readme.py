"""The README's examples work as written: every command line of its shell blocks that runs the
build's launcher, every Python block (Debian's python3 through build/bin/phongvtk-python; the
ParaView block under pvbatch when ParaView is here), from a fresh directory in which `build` is
this build tree, with an environment that sets nothing of PhongVTK's."""

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[2] / "README.md"
BUILD = Path(os.environ.get("PHONGVTK_BUILD_DIR", Path(__file__).resolve().parents[2] / "build"))
BLOCKS = re.findall(r"```(\w+)\n(.*?)```", README.read_text(), re.S)
CLEAN = {"PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": os.environ.get("HOME", "/root")}


def commands():
    return [line for language, code in BLOCKS if language == "sh" for line in code.splitlines()
            if line.startswith("build/bin/")]


def python_blocks(paraview):
    return [code for language, code in BLOCKS
            if language == "python" and ("paraview" in code) == paraview]


@pytest.fixture
def workdir(tmp_path):
    (tmp_path / "build").symlink_to(BUILD)
    return tmp_path


def run(command, cwd, **kwargs):
    result = subprocess.run(command, cwd=cwd, env=CLEAN, capture_output=True, text=True,
                            timeout=300, **kwargs)
    assert result.returncode == 0, f"{command}:\n{result.stdout}\n{result.stderr}"
    return result


def test_the_readme_has_examples_to_run():
    assert len(commands()) >= 3 and python_blocks(False) and python_blocks(True)


@pytest.mark.parametrize("command", commands())
def test_command_line_example(workdir, command):
    run(command, workdir, shell=True)


@pytest.mark.parametrize("index", range(len(python_blocks(False))))
def test_python_example(workdir, index):
    run([str(BUILD / "bin" / "phongvtk-python"), "-c", python_blocks(False)[index]], workdir)


@pytest.mark.skipif(not shutil.which("pvbatch"), reason="no ParaView in this flavour")
@pytest.mark.skipif(not any((BUILD / "lib").glob("paraview-*/plugins/PhongVTK")),
                    reason="this build has no ParaView plugin (built against a plain VTK)")
@pytest.mark.parametrize("index", range(len(python_blocks(True))))
def test_paraview_example(workdir, index):
    script = workdir / "example.py"
    script.write_text(python_blocks(True)[index])
    run(["pvbatch", str(script)], workdir)
    assert (workdir / "sphere.png").stat().st_size > 1000
