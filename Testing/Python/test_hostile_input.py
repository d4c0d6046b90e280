"""Hostile input to the command line (issue 17): files that VTK's readers would read outside
their bytes or their points, outputs that cannot be written whole, and the command's own input
given as its output. Every one must end in one line ``phongvtk: error: ...`` and exit 2, never
a signal, and leave an existing output as it was. The files are made here byte by byte (PLY
with struct-packed records, legacy VTK as text), so what is wrong with each is known."""

import os
import resource
import signal
import struct
import subprocess
import sys
import time

import numpy as np
import pytest
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkVersion
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import phongvtk

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


@pytest.fixture
def cli(tmp_path):
    """Runs ``python3 -m phongvtk ARGS`` in tmp_path (headless); returns the CompletedProcess."""
    env = dict(os.environ)
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(phongvtk.__file__)))
    env["PYTHONPATH"] = os.pathsep.join([package_parent, env.get("PYTHONPATH", "")])
    env.pop("DISPLAY", None)

    def run(*args, limit=None):
        return subprocess.run([sys.executable, "-m", "phongvtk", *map(str, args)], cwd=tmp_path,
                              env=env, capture_output=True, text=True, timeout=300,
                              preexec_fn=limit)

    return run


def expect_clean_error(result, *words):
    """Exit status 2 and exactly one line on stderr, ``phongvtk: error: ...`` with `words`."""
    assert result.returncode == 2, (result.returncode, result.stderr[-2000:])
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("phongvtk: error: "), lines
    for word in words:
        assert word in lines[0], (word, lines[0])


#: The VTK in use (major, minor).
VTK_VERSION = (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion())
#: Whether the VTK in use is 9.3 or later, whose readers differ from 9.1/9.2's on some files.
VTK_AT_LEAST_9_3 = VTK_VERSION >= (9, 3)


def polygons_of(path):
    """The polygons of the VTP file at `path`, as lists of point ids."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    polys = reader.GetOutput().GetPolys()
    offsets = numpy_support.vtk_to_numpy(polys.GetOffsetsArray())
    ids = numpy_support.vtk_to_numpy(polys.GetConnectivityArray())
    return [ids[a:b].tolist() for a, b in zip(offsets[:-1], offsets[1:])]


# --- PLY, binary: every list's count and every index --------------------------------------------

# A grid of (n + 1) x 2 points, faces alternating between a quad and two triangles: runs of one
# record for the walk (the quads and triangles differ in size), then long runs of triangles.
def strip_mesh(n=40):
    points = [(float(i), float(j), 0.0) for i in range(n + 1) for j in range(2)]
    faces = []
    for i in range(n):
        a, b, c, d = 2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1
        faces += [[a, b, c, d]] if i % 2 else [[a, b, c], [a, c, d]]
    return points, faces + [[0, 2, 3]] * 3000


def binary_ply(points, faces, endian="<", count="uchar", index="int", extra=""):
    """A binary PLY file: float x y z vertices, faces with `count`/`index` typed lists, and
    `extra` header lines (with no records) after the faces."""
    formats = {"uchar": "B", "char": "b", "ushort": "H", "int": "i", "uint": "I"}
    name = "binary_little_endian" if endian == "<" else "binary_big_endian"
    header = (f"ply\nformat {name} 1.0\nelement vertex {len(points)}\nproperty float x\n"
              f"property float y\nproperty float z\nelement face {len(faces)}\n"
              f"property list {count} {index} vertex_indices\n{extra}end_header\n").encode()
    body = b"".join(struct.pack(endian + "3f", *p) for p in points)
    body += b"".join(struct.pack(f"{endian}{formats[count]}{len(f)}{formats[index]}", len(f), *f)
                     for f in faces)
    return header + body


def face_offset(data, points, faces, k):
    """The byte of face k's count in binary_ply(points, faces) (uchar counts, int indices)."""
    return data.index(b"end_header\n") + 11 + 12 * len(points) + sum(1 + 4 * len(f)
                                                                      for f in faces[:k])


@pytest.mark.parametrize("endian", ["<", ">"])
def test_binary_ply_of_mixed_faces_is_read_face_for_face(cli, tmp_path, endian):
    points, faces = strip_mesh()
    (tmp_path / "mixed.ply").write_bytes(binary_ply(points, faces, endian))
    result = cli("normals", "mixed.ply", "-o", "out.vtp", "--no-splitting", "-q")
    assert result.returncode == 0, result.stderr
    assert polygons_of(tmp_path / "out.vtp") == faces


@pytest.mark.parametrize("face", [3, 17, 60, 1500])  # among short runs, and in the long run
def test_binary_ply_face_with_an_index_past_the_vertices_is_named(cli, tmp_path, face):
    points, faces = strip_mesh()
    faces[face] = faces[face][:-1] + [len(points) + 5]
    (tmp_path / "bad.ply").write_bytes(binary_ply(points, faces))
    expect_clean_error(cli("normals", "bad.ply", "-o", "out.vtp"),
                       f"face {face} refers to vertex {len(points) + 5}", f"has {len(points)}")


def test_binary_ply_face_count_that_runs_past_the_file_is_named(cli, tmp_path):
    points, faces = strip_mesh()
    data = bytearray(binary_ply(points, faces))
    data[face_offset(data, points, faces, len(faces) - 1)] = 255  # the last face: 255 indices
    (tmp_path / "bad.ply").write_bytes(bytes(data))
    expect_clean_error(cli("normals", "bad.ply", "-o", "out.vtp"),
                       f"face {len(faces) - 1} runs past the end of the file")


@pytest.mark.parametrize("face", [0, 5, 3040])
def test_binary_ply_count_changed_earlier_is_an_error(cli, tmp_path, face):
    # The walk is then out of step with the records: an error, whatever it meets first.
    points, faces = strip_mesh()
    data = bytearray(binary_ply(points, faces))
    data[face_offset(data, points, faces, face)] = 200
    (tmp_path / "bad.ply").write_bytes(bytes(data))
    expect_clean_error(cli("normals", "bad.ply", "-o", "out.vtp"), "bad.ply",
                       "not a valid PLY file")


def test_binary_ply_negative_count_and_index_are_errors(cli, tmp_path):
    points, faces = strip_mesh(4)
    data = bytearray(binary_ply(points, faces, count="char"))
    data[face_offset(data, points, faces, 2)] = 0xFF  # -1 as a char
    (tmp_path / "count.ply").write_bytes(bytes(data))
    expect_clean_error(cli("normals", "count.ply", "-o", "out.vtp"), "face 2", "-1 items")
    faces[1] = [0, -3, 2]
    (tmp_path / "index.ply").write_bytes(binary_ply(points, faces))
    expect_clean_error(cli("normals", "index.ply", "-o", "out.vtp"), "face 1 refers to vertex -3")


def test_binary_ply_with_more_elements_and_lists_is_read(cli, tmp_path):
    # Faces with a second list (texture coordinates) after the indices, and an element of
    # scalars after the faces: the walk follows both, and the indices are still checked.
    points, faces = strip_mesh(6)
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(points)}\n"
              "property float x\nproperty float y\nproperty float z\n"
              f"element face {len(faces)}\nproperty list uchar int vertex_indices\n"
              "property list uchar float texcoord\nelement edge 2\nproperty int vertex1\n"
              "property int vertex2\nend_header\n").encode()

    def body(faces):
        data = b"".join(struct.pack("<3f", *p) for p in points)
        for f in faces:
            data += struct.pack(f"<B{len(f)}i", len(f), *f)
            data += struct.pack(f"<B{2 * len(f)}f", 2 * len(f), *([0.5] * 2 * len(f)))
        return data + struct.pack("<4i", 0, 1, 1, 2)

    (tmp_path / "uv.ply").write_bytes(header + body(faces))
    result = cli("normals", "uv.ply", "-o", "out.vtp", "--no-splitting", "-q")
    assert result.returncode == 0, result.stderr
    assert polygons_of(tmp_path / "out.vtp") == faces
    (tmp_path / "short.ply").write_bytes(header + body(faces)[:-5])
    expect_clean_error(cli("normals", "short.ply", "-o", "out.vtp"), "edge 1",
                       "runs past the end")
    faces[9] = [0, 1, 99]
    (tmp_path / "bad.ply").write_bytes(header + body(faces))
    expect_clean_error(cli("normals", "bad.ply", "-o", "out.vtp"), "face 9 refers to vertex 99")


# --- PLY, ASCII: the words each line's properties take ------------------------------------------

ASCII_HEADER = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
                "end_header\n")
ASCII_VERTICES = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"


@pytest.mark.parametrize("body, words", [
    # The malformed corpus's crash: a newline inside a vertex line leaves it short.
    ("0 0 0\n1 0\n0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n", ["vertex 1 has 2 values", "take 3"]),
    (ASCII_VERTICES + "3 0 1 2\n4 0 2 3\n", ["face 1 has 4 values", "take 5"]),
    (ASCII_VERTICES + "3 0 1 2\n\n3 0 2 3\n", ["face 1 has 0 values"]),
    (ASCII_VERTICES + "3 0 1 2\n3 0 2 4\n", ["face 1 refers to vertex 4", "has 4"]),
    (ASCII_VERTICES + "3 0 1 2\n3 0 -2 3\n", ["face 1 refers to vertex -2"]),
    (ASCII_VERTICES + "-3 0 1 2\n3 0 2 3\n", ["face 0 has a list of -3 items"]),
    (ASCII_VERTICES + "99999999999 0 1 2\n3 0 2 3\n", ["face 0 has 4 values"]),
    (ASCII_VERTICES + "3 0 1 2" + " " * 5000 + "\n3 0 2 3\n", ["face 0", "longer than"]),
    # vtkPLYReader asserted at the end of a last line without its newline.
    (ASCII_VERTICES + "3 0 1 2\n3 0 2 3", ["declares 6 elements", "5 whole lines"]),
    # Found by FuzzReaders: a NUL byte ends the line for VTK, whose last word was then missing.
    ("0 0 0\n1 0 0\0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n", ["line 2", "NUL byte"]),
])
def test_ascii_ply_line_vtk_would_read_past_is_named(cli, tmp_path, body, words):
    (tmp_path / "bad.ply").write_text(ASCII_HEADER + body)
    expect_clean_error(cli("normals", "bad.ply", "-o", "out.vtp"), *words)


@pytest.mark.parametrize("newline", ["\n", "\r\n"])
def test_ascii_ply_with_either_newline_and_blanks_is_read(cli, tmp_path, newline):
    body = ASCII_VERTICES.replace("\n", " \t\n") + "  3 0 1 2\n3\t0 2 3 \n"
    (tmp_path / "ok.ply").write_bytes((ASCII_HEADER + body).replace("\n", newline).encode())
    result = cli("normals", "ok.ply", "-o", "out.vtp", "--no-splitting", "-q")
    assert result.returncode == 0, result.stderr
    assert polygons_of(tmp_path / "out.vtp") == [[0, 1, 2], [0, 2, 3]]


@pytest.mark.parametrize("body, words", [
    # VTK 9.2 reads a line an element and leaves extra words; VTK 9.6 reads a stream of words
    # and would take them for the next face: refused.
    (ASCII_VERTICES + "3 0 1 2 1 100000000\n3 0 2 3\n", ["face 0 has 6 values", "take 4"]),
    (ASCII_VERTICES.replace("1 1 0", "1 1 0 7") + "3 0 1 2\n3 0 2 3\n", ["vertex 2 has 4"]),
    # A carriage return is a blank to vtkPLYReader: the face has three words, not four.
    (ASCII_VERTICES + "3 0 1 \r\n3 0 2 3\n", ["face 0 has 3 values", "take 4"]),
])
def test_ascii_ply_line_with_other_than_its_words_is_named(cli, tmp_path, body, words):
    (tmp_path / "bad.ply").write_bytes((ASCII_HEADER + body).encode())
    expect_clean_error(cli("normals", "bad.ply", "-o", "out.vtp"), *words)


TWO_LISTS = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
             "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
             "property list uchar float texcoord\nend_header\n" + ASCII_VERTICES)


@pytest.mark.parametrize("faces, words", [
    ("3 0 1 2 6 0 0 1 0 1 1\n3 0 2 3 6 0 0 1 1 0 1\n", None),
    ("3 0 1 2 6 0 0 1 0 1 1\n3 0 2 100000000 0\n", ["face 1 refers to vertex 100000000"]),
    ("3 0 1 2 6 0 0 1 0 1 1\n3 0 2 3 6 0 0 1\n", ["face 1 has 8 values", "take 11"]),
])
def test_ascii_ply_faces_with_two_lists_are_checked_word_by_word(cli, tmp_path, faces, words):
    (tmp_path / "uv.ply").write_text(TWO_LISTS + faces)
    result = cli("normals", "uv.ply", "-o", "out.vtp", "--no-splitting", "-q")
    if words is None:
        assert result.returncode == 0, result.stderr
        assert polygons_of(tmp_path / "out.vtp") == [[0, 1, 2], [0, 2, 3]]
    else:
        expect_clean_error(result, *words)


@pytest.mark.parametrize("header, words", [
    # vtkPLYReader reads the vertex and face elements only and does not skip others.
    (ASCII_HEADER.replace("element vertex 4", "element pad 1\nproperty uchar p\nelement vertex 4"),
     ["element 'pad' comes before"]),
    (ASCII_HEADER.replace("property list uchar int vertex_indices", "property int vertex_indices"),
     ["no list 'vertex_indices'"]),
    (ASCII_HEADER.replace("vertex_indices", "vertex_list"), ["no list 'vertex_indices'"]),
    (ASCII_HEADER.replace("element face 2", "element face 99999999999999999999999"),
     ["should be 'element NAME COUNT'"]),
])
def test_ply_header_vtk_would_misread_is_refused(cli, tmp_path, header, words):
    (tmp_path / "bad.ply").write_text(header + ASCII_VERTICES + "3 0 1 2\n3 0 2 3\n")
    expect_clean_error(cli("normals", "bad.ply", "-o", "out.vtp"), *words)


@pytest.mark.parametrize("elements, words", [
    # Found by FuzzReaders: vertices without y were a SIGSEGV inside vtkPLYReader.
    ("element vertex 3\nproperty float x\nproperty float z\n", "no scalar property 'y'"),
    ("element vertex 3\nproperty list uchar float x\nproperty float y\nproperty float z\n",
     "no scalar property 'x'"),
    ("", "no 'vertex' element"),  # faces without vertices: a SIGSEGV too
    # Found by FuzzReaders: VTK's C strings end at a NUL, leaving an element without a name
    # that ply_close freed as garbage (SIGSEGV).
    ("element vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement\0 x 1\n",
     "header line 7 holds a NUL byte"),
    ("element vertex 3\nproperty float x\nproperty float y\nproperty float z\ncomment " +
     "c" * 5000 + "\n", "header line 7 holds more than 4,094 characters"),
])
def test_ply_vertices_vtk_cannot_read_are_refused(cli, tmp_path, elements, words):
    (tmp_path / "in.ply").write_text("ply\nformat ascii 1.0\n" + elements +
                                     "element face 0\nproperty list uchar int vertex_indices\n"
                                     "end_header\n")
    expect_clean_error(cli("normals", "in.ply", "-o", "out.vtp", "-q"), "in.ply", words)


def test_ply_elements_after_the_faces_are_left_alone(cli, tmp_path):
    header = ASCII_HEADER.replace("end_header", "element edge 1\nproperty int a\nend_header")
    (tmp_path / "ok.ply").write_text(header + ASCII_VERTICES + "3 0 1 2\n3 0 2 3\n5\n")
    result = cli("normals", "ok.ply", "-o", "out.vtp", "--no-splitting", "-q")
    assert result.returncode == 0, result.stderr


# --- legacy VTK and VTP: cell arrays VTK's readers take as they are ------------------------------

LEGACY = """# vtk DataFile Version 5.1
corrupt
ASCII
DATASET POLYDATA
POINTS 4 float
0 0 0 1 0 0 1 1 0 0 1 0
POLYGONS 3 6
OFFSETS vtktypeint64
{offsets}
CONNECTIVITY vtktypeint64
{ids}
"""


@pytest.mark.parametrize("offsets, ids, words", [
    ("0 3 6", "0 1 2 0 2 3", None),
    ("0 3 2", "0 1 2 0 2 3", "polygons' offsets do not describe them (from polygon 1 on)"),
    ("0 4 6", "0 1 2 0 2 3", None),
    ("0 3 6", "0 1 2 0 2 9", "polygon 1 refers to point 9"),
    ("0 3 6", "0 1 -1 0 2 3", "polygon 0 refers to point -1"),
])
def test_legacy_vtk_cells_that_are_not_cells_are_an_error(cli, tmp_path, offsets, ids, words):
    (tmp_path / "in.vtk").write_text(LEGACY.format(offsets=offsets, ids=ids))
    result = cli("normals", "in.vtk", "-o", "out.vtp", "-q")
    if offsets == "0 4 6" and VTK_VERSION < (9, 2):
        # VTK 9.1 cannot type a polygon of 2 points (its writers then died with SIGSEGV).
        expect_clean_error(result, "in.vtk", "polygon 1 has 2 point(s)", "9.1")
    elif words is None:
        assert result.returncode == 0, result.stderr
    else:
        expect_clean_error(result, "in.vtk", "corrupt", words)


@pytest.mark.parametrize("name, text, words", [
    ("points.vtk", LEGACY.format(offsets="0 3 6", ids="0 1 2 0 2 3").replace(
        "POINTS 4", "POINTS 99999999999"), "'POINTS 99999999999'"),
    ("cells.vtk", LEGACY.format(offsets="0 3 6", ids="0 1 2 0 2 3").replace(
        "POLYGONS 3 6", "POLYGONS 3 99999999999"), "'POLYGONS 3 99999999999'"),
    ("field.vtk", LEGACY.format(offsets="0 3 6", ids="0 1 2 0 2 3") +
     "FIELD FieldData 1\nsize 1 99999999999 double\n1.0\n", "a field array 'size 1 99999999999"),
    ("digits.vtk", LEGACY.format(offsets="0 3 6", ids="0 1 2 0 2 3").replace(
        "POINTS 4", "POINTS " + "9" * 5000), "'POINTS 999"),
    ("piece.vtp", '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1">\n<PolyData>'
     '<Piece NumberOfPoints="99999999999" NumberOfPolys="1"></Piece></PolyData></VTKFile>\n',
     "NumberOfPoints=99999999999"),
])
def test_counts_larger_than_the_file_are_an_error_before_any_allocation(cli, tmp_path, name,
                                                                        text, words):
    # Each ended in SIGABRT (VTK's allocation failure) under a 4 GiB address-space limit.
    (tmp_path / name).write_text(text)
    limit = lambda: resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))  # noqa: E731
    expect_clean_error(cli("normals", name, "-o", "out.vtp", limit=limit), name, words,
                       "declares")


def test_packed_bit_arrays_count_eight_values_a_byte(cli, tmp_path):
    text = LEGACY.format(offsets="0 3 6", ids="0 1 2 0 2 3") + "FIELD FieldData 1\n"
    text += f"mask 1 {8 * (len(text) + 100)} bit\n" + "0 " * 300 + "\n"
    (tmp_path / "bits.vtk").write_text(text)
    result = cli("normals", "bits.vtk", "-o", "out.vtp", "-q")
    assert "declares" not in result.stderr, result.stderr


# --- outputs ----------------------------------------------------------------------------------

# --- OBJ: every index vtkOBJReader uses --------------------------------------------------------

OBJ_TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"


@pytest.mark.parametrize("body, polygons, words", [
    # Found by FuzzReaders: a texture index in a file without `vt` lines was a SIGSEGV.
    ("f 1/2 2/1 3/1\n", None, "line 4 refers to texture coordinate 2; the file has 0"),
    ("vt 0 0\nf 1/1 2/1 3/1\n", 1, None),
    ("f 1/1 2/1 3/1\nvt 0 0\n", 1, None),  # indices are global: a later `vt` counts
    ("vn 0 0 1\nf 1//1 2//1 3//2\n", None, "line 5 refers to normal 2; the file has 1"),
    ("vt 0 0\nvn 0 0 1\nf 1/1/1 2//1 3/1\n", None, ""),  # VTK's own error: mixed forms
    ("vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/0 3/1/1\n", None, "line 6 refers to normal 0"),
    ("f 1 2 4\n", None, "line 4 refers to vertex 4; the file has 3"),
    ("f -3 -2 -1\n", 1, None),
    ("f -1 -2 -4\n", None, "line 4 refers to vertex -4"),
    # C's int: vtkOBJReader up to 9.2 reads vertex 3; later ones refuse the token themselves.
    ("f 1 2 4294967299\n", 1, None),
    ("f 1 2 \\\n 3\n", 1, None),  # a continuation line
    ("f 1 2 \\\n 9\n", None, "line 5 refers to vertex 9"),
    ("l 1/7 2\nf 1 2 3\n", 1, None),  # a line's texture index is ignored; GroupIds is left out
    ("p 4\nf 1 2 3\n", None, "line 4 refers to vertex 4"),
    ("usemtl " + "m" * 99 + "\nf 1 2 3\n", 1, None),
    ("usemtl " + "m" * 100 + "\nf 1 2 3\n", None, "material of 100 characters"),
    # A continuation line is a command of its own to vtkOBJReader's first pass.
    ("f 1 2 3 \\\nusemtl " + "m" * 120 + "\n", None, "line 5 names a material of 120"),
])
def test_obj_indices_vtk_would_use_outside_the_file_are_named(cli, tmp_path, body, polygons,
                                                               words):
    (tmp_path / "in.obj").write_text(OBJ_TRIANGLE + body)
    result = cli("normals", "in.obj", "-o", "out.vtp", "-q")
    if "4294967299" in body and VTK_AT_LEAST_9_3:
        expect_clean_error(result, "in.obj")  # "Unexpected token in OBJ file at L.4"
    elif words is None:
        assert result.returncode == 0, result.stderr
        assert len(polygons_of(tmp_path / "out.vtp")) == polygons
    elif words:
        expect_clean_error(result, "in.obj", "corrupt OBJ", words)
    else:
        expect_clean_error(result, "in.obj")


def test_obj_arrays_that_do_not_match_the_points_are_left_out_with_a_warning(cli, tmp_path):
    # Texture coordinates indexed like the vertices become a point array of one value per `vt`
    # line: four of them for three points would be read past by every filter downstream.
    (tmp_path / "in.obj").write_text(OBJ_TRIANGLE + "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
                                     "f 1/1 2/2 3/3\n")
    result = cli("normals", "in.obj", "-o", "out.vtp")
    assert result.returncode == 0, result.stderr
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(tmp_path / "out.vtp"))
    reader.Update()
    coordinates = reader.GetOutput().GetPointData().GetArray("TCoords")
    if VTK_AT_LEAST_9_3 and coordinates is not None:
        # Later vtkOBJReaders give one texture coordinate per point themselves.
        assert coordinates.GetNumberOfTuples() == reader.GetOutput().GetNumberOfPoints()
        return
    assert "phongvtk: warning: 'in.obj': point array 'TCoords' left out: it has 4 values for 3 " \
        "points" in result.stderr
    assert coordinates is None


STL_TRIANGLE = ("facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
                " endloop\nendfacet\n")


def test_stl_kind_is_decided_as_vtk_decides_it(cli, tmp_path):
    # vtkSTLReader reads binary when 5 % of the first 256 bytes are not text (KWSys's
    # DetectFileType). Found by FuzzReaders: 20 NUL bytes in 201 were taken for ASCII here and
    # read as binary by VTK, whose triangle count then asked for 13 GB (an abort).
    (tmp_path / "nul.stl").write_bytes(b"solid x\n" + b"\0" * 20 + b"x" * 173)
    expect_clean_error(cli("normals", "nul.stl", "-o", "out.vtp", "-q"), "nul.stl",
                       "not a valid STL file")
    # Two bytes above 127 (a UTF-8 name) in an ASCII file: text for VTK, and read.
    (tmp_path / "utf8.stl").write_bytes(("solid caf\u00e9\n" + STL_TRIANGLE + "endsolid\n").encode())
    result = cli("normals", "utf8.stl", "-o", "out.vtp", "-q")
    assert result.returncode == 0, result.stderr
    assert len(polygons_of(tmp_path / "out.vtp")) == 1


def sphere_vtp(directory, resolution=200):
    """A sphere of about 2 resolution^2 triangles as directory/sphere.vtp."""
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    source = vtkSphereSource()
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(source.GetOutputPort())
    writer.SetFileName(str(directory / "sphere.vtp"))
    assert writer.Write() == 1
    return directory / "sphere.vtp"


@pytest.mark.parametrize("kind", [".vtp", ".vtk", ".ply", ".stl"])
def test_every_output_format_is_written_whole(cli, tmp_path, kind):
    # vtkPLYWriter appends '.ply' to a name without it: the CLI's temporary files keep the
    # extension, and an empty result is never renamed into place.
    sphere_vtp(tmp_path, 20)
    result = cli("normals", "sphere.vtp", "-o", "out" + kind, "-q")
    assert result.returncode == 0, result.stderr
    assert (tmp_path / ("out" + kind)).stat().st_size > 10000
    assert sorted(os.listdir(tmp_path)) == sorted(["sphere.vtp", "out" + kind])
    again = cli("normals", "out" + kind, "-o", "again.vtp", "--no-splitting", "-q")
    assert again.returncode == 0, again.stderr


def small_file_limit():
    """In the child: files of at most 64 KiB (RLIMIT_FSIZE), as on a nearly full disk."""
    resource.setrlimit(resource.RLIMIT_FSIZE, (1 << 16, 1 << 16))


@pytest.mark.parametrize("kind", [".vtp", ".vtk", ".ply", ".stl", ".png"])
def test_output_that_does_not_fit_leaves_the_old_file_and_no_temporary(cli, tmp_path, kind):
    sphere_vtp(tmp_path, 100)
    (tmp_path / ("out" + kind)).write_bytes(b"an older result")
    command = "render" if kind == ".png" else "normals"
    args = ["--size", "1200", "1200"] if kind == ".png" else []
    result = cli(command, "sphere.vtp", "-o", "out" + kind, "-q", *args, limit=small_file_limit)
    expect_clean_error(result, "cannot write", "out" + kind)
    assert (tmp_path / ("out" + kind)).read_bytes() == b"an older result"
    assert sorted(os.listdir(tmp_path)) == sorted(["sphere.vtp", "out" + kind])


def test_output_killed_midway_leaves_the_old_file(cli, tmp_path):
    sphere_vtp(tmp_path, 700)  # ~1M triangles: writing ASCII legacy VTK takes a while
    (tmp_path / "out.vtk").write_bytes(b"an older result")
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.dirname(os.path.dirname(os.path.abspath(phongvtk.__file__))),
         env.get("PYTHONPATH", "")])
    child = subprocess.Popen([sys.executable, "-m", "phongvtk", "normals", "sphere.vtp", "-o",
                              "out.vtk", "--point-normals", "-q"], cwd=tmp_path, env=env)
    deadline = time.monotonic() + 120
    while not any(name.endswith(".part.vtk") for name in os.listdir(tmp_path)):
        assert child.poll() is None, "finished before it could be killed"
        assert time.monotonic() < deadline
        time.sleep(0.005)
    child.send_signal(signal.SIGKILL)
    child.wait()
    assert (tmp_path / "out.vtk").read_bytes() == b"an older result"


@pytest.mark.parametrize("how", ["same", "symlink", "hardlink", "relative"])
def test_the_input_is_never_the_output(cli, tmp_path, how):
    sphere_vtp(tmp_path, 10)
    before = (tmp_path / "sphere.vtp").read_bytes()
    output = {"same": "sphere.vtp", "symlink": "link.vtp", "hardlink": "hard.vtp",
              "relative": "./sub/../sphere.vtp"}[how]
    (tmp_path / "sub").mkdir()
    (tmp_path / "link.vtp").symlink_to(tmp_path / "sphere.vtp")
    os.link(tmp_path / "sphere.vtp", tmp_path / "hard.vtp")
    expect_clean_error(cli("normals", "sphere.vtp", "-o", output), "input file")
    expect_clean_error(cli("area", "sphere.vtp", "--view", "0", "0", "1", "-o", output),
                       "input file")
    assert (tmp_path / "sphere.vtp").read_bytes() == before


# --- the corpus -------------------------------------------------------------------------------

def test_malformed_corpus_ends_in_clean_errors_only():
    # 173 files: a small sphere in every format the CLI reads, cut short, mutated, random, with
    # counts far past its size and with types no reader knows, each through the CLI under a
    # 4 GiB address-space limit (scripts/malformed-corpus.py).
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(
        [os.path.dirname(os.path.dirname(os.path.abspath(phongvtk.__file__))),
         env.get("PYTHONPATH", "")])
    result = subprocess.run([sys.executable, os.path.join(SOURCE, "scripts", "malformed-corpus.py"),
                             "--seed", "2"], capture_output=True, text=True, env=env, timeout=1200)
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.strip().splitlines()[-1] == "0 of 173 files not handled cleanly"
