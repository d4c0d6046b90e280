"""Reading and writing meshes for the command-line interface.

Meshes are read with VTK's readers (PLY, STL, OBJ, VTP, legacy VTK) and, for OFF (the format of
CGAL's sample data), with :func:`read_off`. Every failure is a
:class:`~phongvtk.errors.CommandError` with a one-line message naming the file: missing,
empty, unreadable or corrupt, of an unknown kind, or not a surface (no polygons or triangle
strips). CGAL's bunny comes from Debian's libcgal-demo archive (:func:`cgal_mesh`); a parametric
torus stands in when the archive is absent (:func:`default_mesh`).
"""

import contextlib
import os
import tarfile
import tempfile

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints, vtkVersion
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader, vtkSTLWriter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOLegacy import vtkPolyDataReader, vtkPolyDataWriter
from vtkmodules.vtkIOPLY import vtkPLYReader, vtkPLYWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

from .counts import check_legacy_counts, check_vtp_counts
from .errors import CommandError
from .obj import check_obj
from .ply import check_ply
from .progress import Progress, native_lines_dropped, vtk_output_captured

#: Extensions read by VTK's readers (lower case), and the reader of each.
VTK_READERS = {
    ".ply": vtkPLYReader,
    ".stl": vtkSTLReader,
    ".obj": vtkOBJReader,
    ".vtp": vtkXMLPolyDataReader,
    ".vtk": vtkPolyDataReader,
}
#: Every extension :func:`read_mesh` understands.
MESH_EXTENSIONS = (".off",) + tuple(VTK_READERS)
#: Extensions :func:`write_mesh` understands, and the writer of each.
MESH_WRITERS = {
    ".vtp": vtkXMLPolyDataWriter,
    ".vtk": vtkPolyDataWriter,
    ".ply": vtkPLYWriter,
    ".stl": vtkSTLWriter,
}

#: Debian's libcgal-demo ships CGAL's sample data in this archive (meshes under data/meshes/).
CGAL_DATA_ARCHIVE = "/usr/share/doc/libcgal-dev/data.tar.gz"


def extension(path):
    """The lower-case extension of `path`, with its dot ("" when it has none)."""
    return os.path.splitext(path)[1].lower()


def check_readable(path):
    """Raises CommandError unless `path` is an existing, non-empty file that can be opened."""
    if not os.path.exists(path):
        raise CommandError(f"'{path}': no such file")
    if os.path.isdir(path):
        raise CommandError(f"'{path}' is a directory, not a mesh file")
    try:
        with open(path, "rb") as file:
            empty = not file.read(1)
    except OSError as error:
        raise CommandError(f"cannot open '{path}': {error.strerror}") from None
    if empty:
        raise CommandError(f"'{path}' is empty")


def read_mesh(path, progress=None):
    """The surface mesh in the file `path` (kind by extension, see MESH_EXTENSIONS).

    Raises CommandError when the file is missing, empty, unreadable, of an unknown kind, or has
    no polygons or triangle strips.
    """
    progress = progress or Progress(quiet=True)
    kind = extension(path)
    if kind not in MESH_EXTENSIONS:
        known = " ".join(MESH_EXTENSIONS)
        raise CommandError(f"'{path}': unknown mesh format '{kind or '(none)'}' (known: {known})")
    check_readable(path)
    name = os.path.basename(path)
    if kind == ".off":
        mesh = read_off(path, progress)
    else:
        if kind in SNIFFERS:
            SNIFFERS[kind](path)
        reader = VTK_READERS[kind]()
        reader.SetFileName(path)
        what = f"cannot read '{path}' as {kind[1:].upper()}"
        try:
            progress.run(reader, f"read {name}", what)
        except CommandError as error:
            if kind == ".vtp":
                explain_appended_data(path, error)
            raise
        mesh = reader.GetOutput()
    check_surface(mesh, path)
    check_cells(mesh, path)
    drop_mismatched_arrays(mesh, path, progress)
    return mesh


def vtk_reads_appended_xml():
    """Whether VTK's XML reader, as this process has it now, reads appended data longer than one
    of its reads: VTK before 9.3.1 does not when the system's expat defers reparsing (expat >=
    2.6.0, or Debian 12's backport in 2.5.0-1+deb12u2 and later) unless PhongVTK's module turned
    deferral off (see PhongVTKExpatDeferral.h), which importing phongvtk does when needed."""
    points = vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(np.random.default_rng(1).random((4000, 3)), deep=1))
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetCompressorTypeToNone()
    writer.WriteToOutputStringOn()
    writer.Write()
    reader = vtkXMLPolyDataReader()
    reader.ReadFromInputStringOn()
    reader.SetInputString(writer.GetOutputString())
    with vtk_output_captured():  # a failure here is an answer, not a message
        reader.Update()
    return reader.GetOutput().GetNumberOfPoints() == 4000


def explain_appended_data(path, error):
    """Raises a CommandError that says why when `path` (which VTK's reader failed on) holds XML
    appended data that this VTK cannot parse with the system's expat; returns otherwise."""
    with open(path, "rb") as file:
        head = file.read(1 << 20)
    if b"<AppendedData" not in head or vtk_reads_appended_xml():
        return  # this VTK reads appended data: the file itself is the problem
    keep = os.environ.get("PHONGVTK_KEEP_EXPAT_DEFERRAL", "")
    cause = ("PHONGVTK_KEEP_EXPAT_DEFERRAL is set, which leaves the system's expat as it is"
             if keep and keep != "0" else "PhongVTK could not turn it off here")
    raise CommandError(
        f"{error}. '{path}' stores its data in VTK's appended mode, which VTK "
        f"{vtkVersion.GetVTKVersion()} cannot read with the system's expat (it defers reparsing, "
        f"VTK issue 19258) and {cause}; unset that variable, or write the file in VTK's inline "
        "binary mode (vtkXMLWriter.SetDataModeToBinary(), ParaView: Data Mode 'Binary')"
    ) from None


#: Bytes KWSys's DetectFileType counts as text (vtkSTLReader's choice between ASCII and binary).
STL_TEXT_BYTES = bytes(range(0x20, 0x80)) + b"\n\r\t"


def check_stl_size(path):
    """Raises CommandError when `path` would be read as binary STL but is not 80 + 4 + 50 n bytes
    long for its n triangles: vtkSTLReader trusts the count and aborts the process on a corrupt
    one. It reads binary what vtksys::SystemTools::DetectFileType calls binary: 5 % or more of
    the first 256 bytes outside printable ASCII, newline, carriage return and tab."""
    with open(path, "rb") as file:
        head = file.read(256)
    others = len(head.translate(None, STL_TEXT_BYTES))
    if head and others / len(head) < 0.05:
        return  # ASCII: vtkSTLReader's parser reports errors itself
    size = os.path.getsize(path)
    triangles = int.from_bytes(head[80:84], "little") if len(head) >= 84 else None
    if triangles is None or size < 84 + 50 * triangles:
        raise CommandError(f"'{path}' is not a valid STL file: not ASCII, and too short for a "
                           "binary STL of the triangle count in its header")


#: Checks of a file before VTK's reader sees it, by extension.
SNIFFERS = {".ply": check_ply, ".stl": check_stl_size, ".vtk": check_legacy_counts,
            ".vtp": check_vtp_counts, ".obj": check_obj}


def check_output(path, extensions, source=None):
    """Raises CommandError unless `path` ends with one of `extensions` and names a file that can
    be made (checked before any work, so that a typo does not cost a long computation), and is
    not the file `source` the command reads (under any name: a symbolic or hard link too)."""
    if extension(path) not in extensions:
        raise CommandError(f"'{path}': cannot write '{extension(path) or '(none)'}' files "
                           f"(known: {' '.join(extensions)})")
    target = os.path.realpath(path)
    if os.path.isdir(target):
        raise CommandError(f"cannot write '{path}': it is a directory")
    if not os.path.isdir(os.path.dirname(target)):
        raise CommandError(f"cannot write '{path}': no such directory")
    with contextlib.suppress(OSError):  # either missing: they cannot be one file
        if source is not None and os.path.samefile(source, path):
            raise CommandError(f"will not write '{path}': it is the input file '{source}' "
                               "(write to another file)")


def check_surface(mesh, path):
    """Raises CommandError unless `mesh` (read from `path`) has polygons or triangle strips."""
    if mesh.GetNumberOfPolys() + mesh.GetNumberOfStrips() > 0:
        return
    parts = [
        f"{count} {noun}{'' if count == 1 else 's'}"
        for count, noun in (
            (mesh.GetNumberOfPoints(), "point"),
            (mesh.GetNumberOfVerts(), "vertex cell"),
            (mesh.GetNumberOfLines(), "line"),
        )
        if count
    ]
    holds = ", ".join(parts) if parts else "nothing"
    raise CommandError(f"'{path}' is not a surface: it holds {holds}, no polygons or strips")


#: vtkPolyData's cell arrays in its cell order, with the noun of one of their cells and the
#: fewest points such a cell has.
CELL_ARRAYS = (("GetVerts", "vertex cell", 1), ("GetLines", "line", 2), ("GetPolys", "polygon", 3),
               ("GetStrips", "triangle strip", 3))


def check_cells(mesh, path):
    """Raises CommandError when a cell array of `mesh` (read from `path`) does not describe its
    cells (offsets that do not start at 0, decrease, or do not end at the connectivity's
    length) or a cell refers to a point the mesh does not have: what VTK's legacy and XML
    readers build from a corrupt file without a word. Cells of too few points pass where this
    VTK can hold them (check_cell_types)."""
    points = mesh.GetNumberOfPoints()
    short = None
    for getter, noun, fewest in CELL_ARRAYS:
        cells = getattr(mesh, getter)()
        if cells is None or cells.GetNumberOfCells() == 0:
            continue
        offsets = numpy_support.vtk_to_numpy(cells.GetOffsetsArray())
        ids = numpy_support.vtk_to_numpy(cells.GetConnectivityArray())
        backwards = np.flatnonzero(offsets[1:] < offsets[:-1])
        if offsets[0] != 0 or backwards.size or offsets[-1] != len(ids):
            cell = 0 if offsets[0] != 0 else int(backwards[0]) if backwards.size else len(
                offsets) - 2
            raise CommandError(f"'{path}' is corrupt: its {noun}s' offsets do not describe "
                               f"them (from {noun} {cell} on)")
        outside = np.flatnonzero((ids < 0) | (ids >= points))
        if outside.size:
            cell = int(np.searchsorted(offsets, outside[0], side="right")) - 1
            raise CommandError(f"'{path}' is corrupt: {noun} {cell} refers to point "
                               f"{ids[outside[0]]}; the mesh has {points} points")
        small = np.flatnonzero(np.diff(offsets) < fewest)
        if small.size and short is None:
            cell = int(small[0])
            short = f"{noun} {cell} has {offsets[cell + 1] - offsets[cell]} point(s)"
    if short is not None:
        check_cell_types(mesh, path, short)


def check_cell_types(mesh, path, described):
    """Raises CommandError when this VTK cannot give the cells of `mesh` (read from `path`)
    their types. VTK 9.1 refuses a polygon of fewer than 3 points (the first such cell is
    `described`) when it builds its cell map, and its writers then die with SIGSEGV; later
    VTKs take such cells as they are, and the filters flag them."""
    errors = []
    tag = mesh.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
    try:
        mesh.BuildCells()
    finally:
        mesh.RemoveObserver(tag)
    if errors:
        raise CommandError(f"'{path}': {described}, which this VTK "
                           f"({vtkVersion.GetVTKVersion()}) cannot hold")


def drop_mismatched_arrays(mesh, path, progress):
    """Removes, with a warning each, the point and cell arrays of `mesh` (read from `path`) that
    do not hold one value per point or cell: every filter downstream would read past their end.
    VTK's OBJ reader makes them from valid files (``GroupIds`` numbers only the faces of a file
    with lines or points too; texture coordinates indexed like the vertices have one value per
    ``vt`` line)."""
    for data, count, noun in ((mesh.GetPointData(), mesh.GetNumberOfPoints(), "point"),
                              (mesh.GetCellData(), mesh.GetNumberOfCells(), "cell")):
        for i in reversed(range(data.GetNumberOfArrays())):
            array = data.GetAbstractArray(i)
            if array is not None and array.GetNumberOfTuples() != count:
                progress.warn(f"'{path}': {noun} array '{array.GetName()}' left out: it has "
                              f"{array.GetNumberOfTuples()} values for {count} {noun}s")
                data.RemoveArray(i)


# --- OFF ------------------------------------------------------------------------------------


def off_lines(text):
    """The lines of OFF `text` that hold something, as (line number, tokens); '#' starts a
    comment that runs to the end of its line."""
    for number, line in enumerate(text.splitlines(), start=1):
        tokens = line.split("#", 1)[0].split()
        if tokens:
            yield number, tokens


def is_off_keyword(token):
    """True for OFF with any of Geomview's optional prefixes ST, C, N (COFF, NOFF, STCNOFF...)."""
    if not token.endswith("OFF"):
        return False
    rest = token[:-3]
    for prefix in ("ST", "C", "N"):
        if rest.startswith(prefix):
            rest = rest[len(prefix):]
    return rest == ""


def parse_count(token):
    """A non-negative integer token, or None."""
    return int(token) if token.isascii() and token.isdigit() else None


def shown(tokens, limit=40):
    """The tokens of a line as quoted in a message, shortened to about `limit` characters."""
    text = " ".join(tokens)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def parse_off(text, name="OFF"):
    """Parses ASCII OFF `text` into (points, offsets, connectivity) numpy arrays.

    Understood: an optional header keyword (OFF, COFF, NOFF, STOFF...) with the counts
    ``vertices faces [edges]`` on the same line or the next, ``#`` comments, blank lines, one
    vertex per line (x y z, then anything: colours, normals are ignored), one face per line
    (``n i0 ... i(n-1)``, then optionally a colour, ignored). Coordinates are Python floats, i.e.
    the decimal values correctly rounded to double. Raises CommandError ("name:line: why").
    """
    lines = off_lines(text)

    def next_line(expected):
        try:
            return next(lines)
        except StopIteration:
            raise CommandError(f"{name}: unexpected end of file, expected {expected}") from None

    number, tokens = next_line("the OFF header")
    if is_off_keyword(tokens[0]):
        tokens = tokens[1:]
        if tokens and tokens[0] == "BINARY":
            raise CommandError(f"{name}:{number}: binary OFF is not supported")
        if not tokens:
            number, tokens = next_line("the counts 'vertices faces edges'")
    elif tokens[0].endswith("OFF"):
        raise CommandError(f"{name}:{number}: the header '{tokens[0]}' is not supported")
    counts = [parse_count(token) for token in tokens]
    if not 2 <= len(counts) <= 3 or None in counts:
        raise CommandError(
            f"{name}:{number}: expected the OFF header or the counts 'vertices faces edges', "
            f"found '{shown(tokens)}'"
        )
    num_points, num_faces = counts[0], counts[1]
    if num_points + num_faces > text.count("\n") + 1:  # before allocating for them
        raise CommandError(f"{name}:{number}: the counts say {num_points} vertices and "
                           f"{num_faces} faces, more than the file has lines")

    points = np.empty((num_points, 3))
    for i in range(num_points):
        number, tokens = next_line(f"vertex {i} of {num_points}")
        try:
            if len(tokens) < 3:
                raise ValueError("too few coordinates")
            points[i] = [float(token) for token in tokens[:3]]
        except ValueError:
            raise CommandError(
                f"{name}:{number}: expected the coordinates 'x y z' of vertex {i}, "
                f"found '{shown(tokens)}'"
            ) from None

    offsets = np.zeros(num_faces + 1, dtype=np.int64)
    connectivity = []
    for f in range(num_faces):
        number, tokens = next_line(f"face {f} of {num_faces}")
        size = parse_count(tokens[0])
        ids = [parse_count(token) for token in tokens[1:1 + size]] if size is not None else []
        if size is None or size < 3 or len(ids) < size or None in ids:
            raise CommandError(
                f"{name}:{number}: expected face {f} as 'n i0 ... i(n-1)' with n >= 3, "
                f"found '{shown(tokens)}'"
            )
        bad = [i for i in ids if i >= num_points]
        if bad:
            raise CommandError(
                f"{name}:{number}: face {f} has the vertex index {bad[0]}, "
                f"not in [0, {num_points})"
            )
        connectivity.extend(ids)
        offsets[f + 1] = len(connectivity)
    return points, offsets, np.array(connectivity, dtype=np.int64)


def polydata_from_arrays(points, offsets, connectivity):
    """A vtkPolyData with double `points` (n x 3) and one polygon per face given as VTK's
    offsets and connectivity arrays."""
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(points), deep=True))
    polys = vtkCellArray()
    polys.SetData(
        numpy_support.numpy_to_vtkIdTypeArray(offsets, deep=True),
        numpy_support.numpy_to_vtkIdTypeArray(connectivity, deep=True),
    )
    mesh = vtkPolyData()
    mesh.SetPoints(vtk_points)
    mesh.SetPolys(polys)
    return mesh


def read_off(path, progress=None):
    """The ASCII OFF file at `path` as a vtkPolyData (see :func:`parse_off`): double points, one
    polygon per face in file order (cell id = face index)."""
    progress = progress or Progress(quiet=True)
    bar = progress.bar(f"read {os.path.basename(path)}")
    try:
        with open(path, "rb") as file:
            text = file.read().decode("utf-8-sig", errors="replace")
    except OSError as error:
        raise CommandError(f"cannot open '{path}': {error.strerror}") from None
    bar.update(0.3)
    try:
        mesh = polydata_from_arrays(*parse_off(text, path))
    except CommandError:
        bar.abandon()
        raise
    bar.finish()
    return mesh


# --- writing --------------------------------------------------------------------------------


def write_atomically(writer, path, progress):
    """Runs the VTK `writer` into a new temporary file beside `path` (through a symbolic link: its
    target), then renames it to `path`: a reader never sees half a file, and a failed write
    leaves an existing `path` as it was. The file gets the mode an existing one had, else the
    usual one (0666 less the umask)."""
    target = os.path.realpath(path)
    directory = os.path.dirname(target)
    try:
        # Ending in the target's extension: vtkPLYWriter appends '.ply' to a name without it
        # (and the file made here would have been renamed empty into place).
        handle, partial = tempfile.mkstemp(dir=directory, prefix=f".{os.path.basename(target)}.",
                                           suffix=f".part{extension(target)}")
        os.close(handle)
    except OSError as error:
        raise CommandError(f"cannot write '{path}': {error.strerror}") from None
    try:
        what = f"cannot write '{path}'"
        if writes_through_memory(writer):
            writer.WriteToOutputStringOn()
            progress.run(writer, f"write {os.path.basename(path)}", what, "Write")
            with open(partial, "wb") as file:
                file.write(writer.GetOutputString().encode("ascii"))
        else:
            writer.SetFileName(partial)
            progress.run(writer, f"write {os.path.basename(path)}", what, "Write")
        # Some writers (vtkPNGWriter) report a file they cannot write through the error code.
        if hasattr(writer, "GetErrorCode") and writer.GetErrorCode():
            raise CommandError(what)
        if os.path.getsize(partial) == 0:  # no format here is empty: the writer wrote elsewhere
            raise CommandError(f"{what}: {type(writer).__name__} wrote nothing")
        if extension(target) == ".ply":
            # vtkPLYWriter ignores failed writes (a full disk, ulimit -f): what it wrote must
            # hold what its header declares.
            try:
                check_ply(partial)
            except CommandError:
                raise CommandError(f"{what}: vtkPLYWriter could not write all of it (is the "
                                   "disk full, or a file size limit set?)") from None
        with open(partial, "rb") as file:
            os.fsync(file.fileno())
        os.chmod(partial, usual_mode(target))
        os.replace(partial, target)
    except OSError as error:
        raise CommandError(f"cannot write '{path}': {error.strerror}") from None
    finally:
        with contextlib.suppress(OSError):
            os.remove(partial)


def writes_through_memory(writer):
    """Whether `writer` writes into memory first (and Python then to the file): VTK's XML writer
    crashes when a write fails (a full disk, ulimit -f) in VTK 9.1 (SIGSEGV) and 9.6.2 (it frees
    its position arrays twice), so VTP always goes through memory. In inline binary mode the
    document is ASCII."""
    return isinstance(writer, vtkXMLPolyDataWriter)


def usual_mode(path):
    """The permission bits of the existing file `path`, else 0666 less the process's umask."""
    try:
        return os.stat(path).st_mode & 0o7777
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def write_mesh(mesh, path, progress=None):
    """Writes the vtkPolyData `mesh` to `path` atomically, the kind by extension (see
    MESH_WRITERS).

    VTP and legacy VTK keep every array; PLY keeps the geometry (and what vtkPLYWriter writes of
    point data); STL keeps only triangles (polygons and strips are triangulated), in binary STL.
    VTP is written in inline binary mode, which every VTK and ParaView reads on every expat
    (appended mode, the writer's default, is unreadable for VTK before 9.3.1 on expat >= 2.6
    without PhongVTK).
    """
    progress = progress or Progress(quiet=True)
    check_output(path, MESH_WRITERS)
    kind = extension(path)
    if kind == ".stl":
        triangles = vtkTriangleFilter()
        triangles.SetInputData(mesh)
        triangles.Update()
        mesh = triangles.GetOutput()
    writer = MESH_WRITERS[kind]()
    writer.SetInputData(mesh)
    if kind == ".vtp":
        writer.SetDataModeToBinary()
    if kind == ".stl":
        # Binary: ASCII STL is written through {fmt} from VTK 9.4 on, which aborts the process
        # when a write fails (measured on 9.6.2); the binary writer reports it.
        writer.SetFileTypeToBinary()
    write_atomically(writer, path, progress)


def write_png(image, path, progress=None):
    """Writes the vtkImageData `image` (RGB or RGBA, unsigned char) as a PNG file, atomically."""
    progress = progress or Progress(quiet=True)
    check_output(path, [".png"])
    writer = vtkPNGWriter()
    writer.SetCompressionLevel(9)  # smallest files; images here are small, so it costs little
    writer.SetInputData(image)
    with native_lines_dropped(("libpng warning:", "libpng error:")):
        write_atomically(writer, path, progress)


# --- data nobody here wrote -----------------------------------------------------------------


def cache_dir():
    """Where extracted sample data is kept: $XDG_CACHE_HOME/phongvtk (~/.cache/phongvtk)."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "phongvtk")


def cgal_mesh(name="bunny00.off", archive=CGAL_DATA_ARCHIVE):
    """Path of CGAL's sample mesh `name` (data/meshes/<name> in Debian's libcgal-demo archive),
    extracted once into :func:`cache_dir` (a temporary directory when that is not writable), or
    None when the archive or the mesh is absent."""
    for directory in (cache_dir(), os.path.join(tempfile.gettempdir(), f"phongvtk-{os.getuid()}")):
        path = os.path.join(directory, name)
        if os.path.isfile(path):
            return path
        if not os.path.isfile(archive):
            return None
        try:
            os.makedirs(directory, exist_ok=True)
            with tarfile.open(archive) as tar:
                member = tar.extractfile(f"data/meshes/{name}")
                data = member.read()
            partial = f"{path}.{os.getpid()}.part"  # concurrent runs never see half a file
            with open(partial, "wb") as file:
                file.write(data)
            os.replace(partial, path)
            return path
        except KeyError:
            return None  # not in the archive
        except (OSError, tarfile.TarError):
            continue  # not writable (or a broken archive): try the next directory
    return None


def torus(ring_segments=256, tube_segments=None, ring_radius=1.0, tube_radius=0.5):
    """A torus about the z axis, `ring_segments` x `tube_segments` (default: the same) quads
    each split in two, counter-clockwise seen from outside: 2 u v triangles on u v points, every
    point shared by all its faces (no seam). Double points, no normals."""
    v_count = tube_segments or ring_segments
    u = 2 * np.pi * np.arange(ring_segments) / ring_segments
    v = 2 * np.pi * np.arange(v_count) / v_count
    uu, vv = np.meshgrid(u, v, indexing="ij")
    distance = ring_radius + tube_radius * np.cos(vv)
    points = np.stack([distance * np.cos(uu), distance * np.sin(uu), tube_radius * np.sin(vv)],
                      axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(ring_segments), np.arange(v_count), indexing="ij")
    a = i * v_count + j
    b = ((i + 1) % ring_segments) * v_count + j
    c = ((i + 1) % ring_segments) * v_count + (j + 1) % v_count
    d = i * v_count + (j + 1) % v_count
    triangles = np.stack([np.stack([a, b, c], -1), np.stack([a, c, d], -1)], axis=2)
    offsets = np.arange(0, triangles.size + 1, 3, dtype=np.int64)
    return polydata_from_arrays(points, offsets, triangles.reshape(-1).astype(np.int64))


def default_mesh(progress=None, resolution=256):
    """(mesh, label): CGAL's bunny when Debian's libcgal-demo is installed, else a torus of
    `resolution` squared quads split in two."""
    path = cgal_mesh()
    if path is not None:
        return read_mesh(path, progress), os.path.basename(path)
    return torus(resolution), f"torus {resolution}x{resolution}"
