"""Checks of an OBJ file against what VTK's vtkOBJReader (VTK 9.1/9.2) reads without bounds.

vtkOBJReader reads a face's texture-coordinate index straight out of its list of ``vt`` lines,
writes it into an array of that length, and later reads vertex and normal indices the same way:
an index past the ``v``, ``vt`` or ``vn`` lines (``f 1/2 ...`` in a file without ``vt``) is a
SIGSEGV or a write past the end of an array; a ``usemtl`` name of 100 characters or more
overflows its buffer on the stack. :func:`check_obj` walks the file as that reader does — lines
as ``fgets`` with its 262,144-byte buffer gives them, commands and ``\\`` continuations, each
index as C's ``sscanf`` parses ``%d/%d/%d``, ``%d//%d``, ``%d/%d``, ``%d`` — and refuses every
index the reader would use outside its list. Files VTK reads keep working unchanged.
"""

import re

import numpy as np

from .errors import CommandError

#: vtkOBJReader's line buffer (MAX_LINE): longer lines are an error of its own.
MAX_LINE = 262144
#: Its buffer for a material name (``char tcoordsName[100]``).
MAX_NAME = 100
#: C's isspace() in the C locale.
SPACE = b" \t\n\v\f\r"
INT_RANGE = 1 << 32


def fgets_lines(data):
    """The strings fgets(buffer, MAX_LINE) returns one after the other, each cut at its first
    NUL byte as strlen() sees it."""
    start = 0
    while start < len(data):
        end = data.find(b"\n", start, start + MAX_LINE - 1)
        end = start + MAX_LINE - 1 if end < 0 else end + 1
        end = min(end, len(data))
        yield data[start:end].split(b"\0", 1)[0]
        start = end


def scan_int(text, at):
    """sscanf's %d at `at`: (value, position after it), or None when no integer starts there.
    glibc reads a long (saturated) and stores its low 32 bits in the int."""
    while at < len(text) and text[at] in SPACE:
        at += 1
    start = at
    if at < len(text) and text[at] in b"+-":
        at += 1
    digits = at
    while at < len(text) and 48 <= text[at] <= 57:
        at += 1
    if at == digits:
        return None
    value = max(-(1 << 63), min(int(text[start:at]), (1 << 63) - 1))
    value %= INT_RANGE
    return (value - INT_RANGE if value >= INT_RANGE // 2 else value), at


def scan(text, at, pattern):
    """The integers sscanf(text + at, pattern) assigns, for patterns of %d and '/' only."""
    values = []
    for item in pattern.split(b"%d"):
        if values or item:
            if text[at:at + len(item)] != item:
                return values
            at += len(item)
        if len(values) == pattern.count(b"%d"):
            break
        result = scan_int(text, at)
        if result is None:
            return values
        value, at = result
        values.append(value)
    return values


#: Element lines (f, l, p) and their arguments; element arguments that are not plain positive
#: indices; lines fgets would cut; material names.
ELEMENTS = re.compile(rb"^[ \t\v\f\r]*[flp][ \t\v\f\r]+([^\n]*)", re.M)
UNUSUAL = re.compile(rb"[^0-9 \t\v\f\r]")
LONG_LINE = re.compile(rb"[^\n]{%d}" % (MAX_LINE - 1))
MATERIAL = re.compile(rb"^[ \t\v\f\r]*usemtl[ \t\v\f\r]+([^ \t\n\v\f\r]*)", re.M)
COMMANDS = {kind: re.compile(rb"^[ \t\v\f\r]*%s(?:[ \t\n\v\f\r]|\Z)" % kind, re.M)
            for kind in (b"v", b"vt", b"vn")}


def only_plain_vertex_indices(data):
    """Whether every element line of `data` holds plain positive indices (what exporters write
    for meshes without texture coordinates or normals), all of them naming a vertex the file
    has: then nothing else needs a look, and numpy checks them at once."""
    if b"\0" in data or LONG_LINE.search(data):
        return False
    arguments = ELEMENTS.findall(data)
    if any(UNUSUAL.search(part) for part in arguments):
        return False
    indices = b" ".join(arguments).split()
    if not indices or max(map(len, indices)) > 9:
        return not indices
    values = np.array(indices, dtype=np.int64)
    vertices = len(COMMANDS[b"v"].findall(data))
    return bool(values.min() >= 1 and values.max() <= vertices)


def check_obj(path):
    """Raises CommandError when vtkOBJReader would use an index of `path` outside the vertices,
    texture coordinates or normals the file has, or overflow its material-name buffer."""
    with open(path, "rb") as file:
        data = file.read()
    if all(len(name) < MAX_NAME for name in MATERIAL.findall(data)) and \
            only_plain_vertex_indices(data):
        return
    lines = list(fgets_lines(data))

    def refuse(number, what):
        raise CommandError(f"'{path}' is a corrupt OBJ file: line {number} {what}")

    # vtkOBJReader's first pass: every line, continuation lines too, is a command to it.
    totals = {b"v": 0, b"vt": 0, b"vn": 0}
    for number, line in enumerate(lines, 1):
        words = line.split(None, 2)
        if words and words[0] in totals:
            totals[words[0]] += 1
        elif words[:1] == [b"usemtl"] and len(words) > 1 and len(words[1]) >= MAX_NAME:
            refuse(number, f"names a material of {len(words[1])} characters (VTK reads at most "
                   f"{MAX_NAME - 1})")

    def index(number, kind, value, seen):
        """The 0-based index vtkOBJReader makes of `value` (relative to the `seen` lines of
        `kind` so far when negative); refused outside the file's lines of that kind."""
        resolved = seen + value if value < 0 else value - 1
        if not 0 <= resolved < totals[kind]:
            noun = {b"v": "vertex", b"vt": "texture coordinate", b"vn": "normal"}[kind]
            refuse(number, f"refers to {noun} {value}; the file has {totals[kind]}")

    seen = {b"v": 0, b"vt": 0, b"vn": 0}
    number = 0
    position = 0
    while position < len(lines):
        line = lines[position]
        position += 1
        number += 1
        words = line.split(None, 1)
        if not words:
            continue
        command = words[0]
        if command in seen:
            seen[command] += 1
            continue
        if command not in (b"f", b"l", b"p"):
            continue
        at = line.index(command) + len(command)
        while at < len(line):
            while at < len(line) and line[at] in SPACE:
                at += 1
            if at >= len(line):
                break
            if line[at:] == b"\\\n":  # continuation: the next line replaces this one
                if position >= len(lines):
                    break
                line, at = lines[position], 0
                position += 1
                number += 1
                continue
            if command == b"f":
                values = scan(line, at, b"%d/%d/%d")
                if len(values) == 3:
                    kinds = (b"v", b"vt", b"vn")
                else:
                    values = scan(line, at, b"%d//%d")
                    if len(values) == 2:
                        kinds = (b"v", b"vn")
                    else:
                        values = scan(line, at, b"%d/%d")
                        kinds = (b"v", b"vt") if len(values) == 2 else (b"v",)
                        values = values if len(values) == 2 else scan(line, at, b"%d")
            else:
                values = scan(line, at, b"%d/%d") if command == b"l" else []
                values = values[:1] if len(values) == 2 else scan(line, at, b"%d")
                kinds = (b"v",)
            if not values:
                break  # vtkOBJReader stops with an error of its own
            for kind, value in zip(kinds, values):
                index(number, kind, value, seen[kind])
            while at < len(line) and line[at] not in SPACE:
                at += 1
