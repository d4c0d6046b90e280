"""The counts a legacy VTK or VTP file declares, against what the file can hold.

VTK's readers allocate what a file's header declares before they read a value: a legacy
`POINTS 99999999999 float` or a VTP piece with `NumberOfPoints="99999999999"` in a file of a few
kilobytes ends the process in an allocation abort (SIGABRT from vtkXMLDataReader::SetupOutputData
and vtkPolyDataReader, measured with the malformed corpus under a 4 GiB address-space limit).
Every value takes at least one byte in these formats (binary: a char at least; ASCII: a digit
and a separator), so a declared count of values larger than the file is an error before any
allocation; a compressed VTP may hold more values than bytes, up to COMPRESSION times (zlib's
limit is about 1032:1, LZ4's 255:1; LZMA's grows with the input, so this bound is generous).
"""

import contextlib
import mmap
import os
import re

from .errors import CommandError

#: How many values a byte of compressed VTP data may stand for, at most.
COMPRESSION = 10000

#: Legacy VTK lines that declare counts: (keyword, first count, second count or None).
LEGACY_COUNT = re.compile(
    rb"(?m)^[ \t]*(POINTS|VERTICES|LINES|POLYGONS|TRIANGLE_STRIPS|POINT_DATA|CELL_DATA)"
    rb"[ \t]+(\d+)(?:[ \t]+(\d+))?")
#: A field data array's line: name, components, tuples, type.
LEGACY_FIELD_ARRAY = re.compile(
    rb"(?m)^[ \t]*\S+[ \t]+(\d+)[ \t]+(\d+)[ \t]+(bit|unsigned_char|char|unsigned_short|short|"
    rb"unsigned_int|int|unsigned_long|long|float|double|vtkIdType|vtktypeint64|vtktypeuint64|"
    rb"vtktypeint32|vtktypeuint32|string)\b")
#: The values each keyword's first count stands for (POINTS: three coordinates each).
VALUES_PER_ITEM = {b"POINTS": 3}

#: A VTP piece, and the counts it declares.
VTP_PIECE = re.compile(rb"<Piece\b[^>]*>")
VTP_COUNT = re.compile(rb'\b(NumberOf(?:Points|Verts|Lines|Strips|Polys))\s*=\s*"\s*(\d+)\s*"')


@contextlib.contextmanager
def mapped(path):
    """The bytes of the (non-empty) file `path`, mapped rather than read."""
    with open(path, "rb") as file, mmap.mmap(file.fileno(), 0, access=mmap.ACCESS_READ) as data:
        yield data


def number(digits):
    """The count written as `digits` (bytes); more than 18 digits: a count beyond any file."""
    return int(digits) if len(digits) <= 18 else 10 ** 19


def refuse(path, what, values, size):
    raise CommandError(f"'{path}' is not a valid file: it declares {what}, {values} values "
                       f"or more, and holds {size} bytes")


def check_legacy_counts(path):
    """Raises CommandError when a count in the legacy VTK file `path` asks for more values than
    the file has bytes."""
    size = os.path.getsize(path)
    with mapped(path) as data:
        for match in LEGACY_COUNT.finditer(data):
            keyword, first, second = match.groups()
            values = max(number(first) * VALUES_PER_ITEM.get(keyword, 1), number(second or b"0"))
            if values > size:
                refuse(path, f"'{match.group(0).decode(errors='replace').strip()}'", values,
                       size)
        for match in LEGACY_FIELD_ARRAY.finditer(data):
            values = number(match.group(1)) * number(match.group(2))
            if match.group(3) == b"bit":  # packed eight to a byte
                values = (values + 7) // 8
            if values > size:
                refuse(path, "a field array "
                       f"'{match.group(0).decode(errors='replace').strip()}'", values, size)


def check_vtp_counts(path):
    """Raises CommandError when a piece of the VTP file `path` declares more points and cells
    than the file could hold (COMPRESSION values a byte when it is compressed)."""
    size = os.path.getsize(path)
    with mapped(path) as data:
        end = data.find(b"<AppendedData")
        pieces = [piece.group(0) for piece in VTP_PIECE.finditer(data, 0, size if end < 0 else end)]
        factor = COMPRESSION if b"compressor=" in data[:4096] else 1
    for piece in pieces:
        counts = {name.decode(): number(value) for name, value in VTP_COUNT.findall(piece)}
        values = 3 * counts.get("NumberOfPoints", 0) + sum(
            count for name, count in counts.items() if name != "NumberOfPoints")
        if values > factor * size:
            declared = ", ".join(f"{name}={count}" for name, count in counts.items())
            refuse(path, f"a piece of {declared}", values, size)
