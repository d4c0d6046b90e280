"""PLY files checked before VTK's reader sees them.

vtkPLYReader trusts the file: it allocates what the header declares, reads every list's count
as it comes and every face's vertex indices as they are, and reads on past the end of a file
too short for them (a segmentation fault, heap corruption, or an assertion; see docs/cli.md).
:func:`check_ply` refuses, with one line naming the element and its number, every file that
would take it outside the file or outside the vertices:

- the header: 'ply', a 'format' line, elements 'element NAME COUNT' with properties of the
  types VTK knows (both names of each: `uchar`/`uint8`, ...), none without properties;
- ASCII: at least one line per declared element (vtkPLYReader reads one a line);
- binary: the whole body walked as vtkPLYReader would read it, every list's count read and
  checked against the bytes left, and every face's `vertex_indices` (or `vertex_index`) in
  [0, vertices). Records whose lists have the counts of the record before them are read as one
  numpy view (a mesh of triangles: one view for all its faces), others one by one.
"""

import os
from collections import namedtuple

import numpy as np

from .errors import CommandError

#: numpy's type code of each PLY scalar type, under both of its names.
PLY_TYPES = {"char": "i1", "uchar": "u1", "short": "i2", "ushort": "u2", "int": "i4",
             "uint": "u4", "float": "f4", "double": "f8", "int8": "i1", "uint8": "u1",
             "int16": "i2", "uint16": "u2", "int32": "i4", "uint32": "u4", "float32": "f4",
             "float64": "f8"}
#: Bytes of each PLY scalar type.
PLY_TYPE_SIZES = {name: int(code[1]) for name, code in PLY_TYPES.items()}
#: The face properties vtkPLYReader takes for a face's vertex indices.
INDEX_PROPERTIES = ("vertex_indices", "vertex_index")

#: One property: `count` is the type of a list's count (None for a scalar), `item` the type of
#: the scalar or of a list's items.
Property = namedtuple("Property", "name count item")
#: One element of the header, with the header line that declared it.
Element = namedtuple("Element", "name count properties line")


def quoted(words, limit=40):
    """Header words as text for a message, cut to `limit` characters."""
    text = " ".join(word.decode(errors="replace") for word in words)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def numpy_type(ply_type, endian):
    """The numpy dtype of the PLY scalar type `ply_type` in byte order `endian` ('<', '>')."""
    return np.dtype(endian + PLY_TYPES[ply_type])


def parse_elements(lines, path):
    """The elements declared by the header `lines` (up to 'end_header'). Raises CommandError on
    an element or property line vtkPLYReader cannot take, and on elements without properties
    (vtkPLYReader allocates them all: taking no bytes, they fit any file)."""
    elements = []
    for number, line in enumerate(lines, 1):
        words = line.split()
        if not words:
            continue
        if words[0] in (b"element", b"end_header") and elements:
            last = elements[-1]
            if last.count and not last.properties:
                raise CommandError(f"'{path}' is not a valid PLY file: header line {last.line[0]}"
                                   f" declares elements without properties: '{last.line[1]}'")
        if words[0] == b"end_header":
            break
        if words[0] == b"element":
            if len(words) != 3 or not words[2].isdigit() or len(words[2]) > 18:
                raise CommandError(f"'{path}' is not a valid PLY file: header line {number} "
                                   f"should be 'element NAME COUNT', is '{quoted(words)}'")
            elements.append(Element(words[1].decode(errors="replace"), int(words[2]), [],
                                    (number, quoted(words))))
        elif words[0] == b"property" and elements:
            is_list = len(words) == 5 and words[1] == b"list"
            types = [word.decode(errors="replace") for word in
                     (words[2:4] if is_list else words[1:2])]
            if (len(words) != 3 and not is_list) or any(t not in PLY_TYPE_SIZES for t in types):
                raise CommandError(f"'{path}' is not a valid PLY file: header line {number} "
                                   f"is not a property VTK reads: '{quoted(words)}'")
            name = words[-1].decode(errors="replace")
            elements[-1].properties.append(
                Property(name, types[0], types[1]) if is_list else Property(name, None, types[0]))
    return elements


def check_structure(elements, path):
    """Raises CommandError unless vtkPLYReader reads the elements where they are: it reads the
    'vertex' and 'face' elements only, without skipping others, so no other element may come
    before them; the vertices need scalar x, y and z (without one it crashes); and a face's
    vertex indices (and texture coordinates) must be lists (it reads them into lists,
    uninitialised otherwise)."""
    names = [element.name for element in elements]
    if "vertex" not in names:
        raise CommandError(f"'{path}' is not a PLY file VTK reads: it has no 'vertex' element")
    last = max((k for k, name in enumerate(names) if name in ("vertex", "face")), default=-1)
    for element in elements[:last]:
        if element.name not in ("vertex", "face") and element.count:
            raise CommandError(f"'{path}' is not a PLY file VTK reads: element "
                               f"'{element.name}' comes before the vertices or faces, and "
                               "vtkPLYReader does not skip it")
    for element in elements:
        props = {prop.name: prop for prop in element.properties}
        if element.name == "vertex":
            missing = [name for name in "xyz" if name not in props or props[name].count]
            if missing:
                raise CommandError(f"'{path}' is not a PLY file VTK reads: its vertices have no "
                                   f"scalar property '{missing[0]}' (vtkPLYReader needs x, y "
                                   "and z)")
        if element.name != "face" or not element.count:
            continue
        index = [props[name] for name in INDEX_PROPERTIES if name in props]
        if not index or index[0].count is None:
            raise CommandError(f"'{path}' is not a PLY file VTK reads: its faces have no list "
                               "'vertex_indices'")
        if "texcoord" in props and props["texcoord"].count is None:
            raise CommandError(f"'{path}' is not a PLY file VTK reads: its faces' 'texcoord' "
                               "is not a list")


def least_body(elements, binary):
    """The fewest bytes the body of a PLY file with `elements` can take: binary, every scalar's
    size and every list's count; ASCII, one character a value."""
    return sum(element.count * sum(PLY_TYPE_SIZES[prop.count or prop.item] if binary else 1
                                   for prop in element.properties)
               for element in elements)


def body_bytes(path, start):
    """The bytes of `path` from `start` on, as uint8, mapped rather than read (empty: an empty
    array, which a map cannot be)."""
    if os.path.getsize(path) <= start:
        return np.zeros(0, dtype=np.uint8)
    return np.memmap(path, dtype=np.uint8, mode="r", offset=start)


def check_ply(path):
    """Raises CommandError unless `path` is a PLY file that vtkPLYReader reads within its
    bytes and its vertices (see the module's description)."""
    with open(path, "rb") as file:
        head = file.read(1 << 16)
    raw = head.split(b"\n")
    lines = [line.strip() for line in raw]
    if not lines or lines[0] != b"ply" or b"end_header" not in lines:
        raise CommandError(f"'{path}' is not a PLY file: no header 'ply' ... 'end_header'")
    header = lines[: lines.index(b"end_header") + 1]
    for number, line in enumerate(raw[: len(header)], 1):
        # vtkPLY reads header lines as C strings with fgets(4096): a NUL byte ends the line for it
        # (and left an element without a name, freed as garbage), a longer line is two lines.
        if b"\0" in line or len(line) >= 4095:
            what = "a NUL byte" if b"\0" in line else "more than 4,094 characters"
            raise CommandError(f"'{path}' is not a valid PLY file: header line {number} holds "
                               f"{what}")
    formats = [line.split() for line in header if line.startswith(b"format ")]
    if not formats:
        raise CommandError(f"'{path}' is not a PLY file: no 'format' line in its header")
    binary = formats[0][1:2] != [b"ascii"]
    body_start = sum(len(line) + 1 for line in raw[: len(header)])
    elements = parse_elements(header, path)
    check_structure(elements, path)
    least = least_body(elements, binary)
    body = os.path.getsize(path) - body_start
    if body < least:
        raise CommandError(f"'{path}' is not a valid PLY file: its header declares elements "
                           f"that take at least {least} bytes, the file has {max(body, 0)} "
                           "after its header")
    if binary:
        endian = ">" if formats[0][1:2] == [b"binary_big_endian"] else "<"
        BinaryBody(body_bytes(path, body_start), endian, path).walk(elements)
    else:
        AsciiBody(body_bytes(path, body_start), path).walk(elements)


class BinaryBody:
    """The body of a binary PLY file (`data`, bytes as uint8) walked element by element."""

    #: Records a uniform run is first looked for in, and the fewest that make a run worth a
    #: numpy view: shorter runs are walked one record at a time, this many at once.
    WINDOW = 4096
    SHORT_RUN = 16

    def __init__(self, data, endian, path):
        self.data = data
        self.raw = memoryview(data)
        self.endian = endian
        self.path = path
        self.vertices = 0

    def fail(self, element, index, why):
        raise CommandError(f"'{self.path}' is not a valid PLY file: {element.name} {index} "
                           f"{why}")

    def walk(self, elements):
        """Walks every element from the body's start; raises CommandError on the first record
        that does not fit."""
        at = 0
        for element in elements:
            if element.name == "vertex":
                self.vertices = element.count
            if all(prop.count is None for prop in element.properties):
                record = sum(PLY_TYPE_SIZES[p.item] for p in element.properties)
                if at + element.count * record > len(self.data):
                    self.fail(element, (len(self.data) - at) // record,
                              "runs past the end of the file")
                at += element.count * record
            else:
                at = self.walk_lists(element, at)

    def counts_at(self, element, at, index):
        """(the list counts of the record of `element` (number `index`) at byte `at`, its
        size); raises CommandError when it runs past the file's end or a count is negative."""
        counts = []
        size = 0
        order = "little" if self.endian == "<" else "big"
        for prop in element.properties:
            if prop.count is None:
                size += PLY_TYPE_SIZES[prop.item]
                continue
            width = PLY_TYPE_SIZES[prop.count]
            if at + size + width > len(self.data):
                self.fail(element, index, "runs past the end of the file")
            count = int.from_bytes(self.raw[at + size: at + size + width], order,
                                   signed=PLY_TYPES[prop.count][0] == "i")
            if count < 0:
                self.fail(element, index, f"has a list '{prop.name}' of {count} items")
            counts.append(count)
            size += width + count * PLY_TYPE_SIZES[prop.item]
        if at + size > len(self.data):
            self.fail(element, index, "runs past the end of the file")
        return tuple(counts), size

    def layout(self, element, counts):
        """The numpy record type of a record of `element` whose lists have `counts` items:
        fields count0, count1, ... for the lists' counts and `indices` for a face's vertex
        indices."""
        names, formats, offsets = [], [], []
        size = 0
        lists = iter(counts)
        for prop in element.properties:
            if prop.count is None:
                size += PLY_TYPE_SIZES[prop.item]
                continue
            names.append(f"count{len(names)}")
            formats.append(numpy_type(prop.count, self.endian))
            offsets.append(size)
            size += PLY_TYPE_SIZES[prop.count]
            items = next(lists)
            if element.name == "face" and prop.name in INDEX_PROPERTIES and "indices" not in names:
                names.append("indices")
                formats.append((numpy_type(prop.item, self.endian), (items,)))
                offsets.append(size)
            size += items * PLY_TYPE_SIZES[prop.item]
        return np.dtype({"names": names, "formats": formats, "offsets": offsets,
                         "itemsize": size})

    def bad_index(self, records):
        """(the first of `records` with a vertex index outside [0, vertices), that index), or
        None."""
        if "indices" not in records.dtype.names or records.size == 0:
            return None
        indices = records["indices"].reshape(len(records), -1)
        if indices.shape[1] == 0:
            return None
        outside = (indices < 0) | (indices >= self.vertices)
        rows = np.flatnonzero(outside.any(axis=1))
        if not rows.size:
            return None
        row = int(rows[0])
        return row, indices[row][outside[row]][0]

    def walk_lists(self, element, at):
        """Walks the records of an element with list properties from byte `at`; returns the
        byte after its last record."""
        index = 0
        window = self.WINDOW
        while index < element.count:
            counts, size = self.counts_at(element, at, index)
            most = min(element.count - index, window, (len(self.data) - at) // size)
            layout = self.layout(element, counts)
            records = np.frombuffer(self.data, dtype=layout, count=most, offset=at)
            run = most
            for name, count in zip((n for n in layout.names if n.startswith("count")), counts):
                differs = np.flatnonzero(records[name][:run] != count)
                if differs.size:
                    run = int(differs[0])
            if run >= self.SHORT_RUN or run == element.count - index:
                self.refuse_bad_index(element, index, records[:run])
                index += run
                at += run * size
                window = 2 * window if run == most else self.WINDOW
            else:
                index, at = self.walk_short(element, index, at)
        return at

    def walk_short(self, element, index, at):
        """Walks up to WINDOW records one at a time from record `index` at byte `at`; returns
        where the next record starts (index, byte)."""
        starts = {}  # list counts -> ([record numbers], [bytes])
        for _ in range(min(self.WINDOW, element.count - index)):
            counts, size = self.counts_at(element, at, index)
            numbers, places = starts.setdefault(counts, ([], []))
            numbers.append(index)
            places.append(at)
            index += 1
            at += size
        bad = []
        for counts, (numbers, places) in starts.items():
            layout = self.layout(element, counts)
            rows = np.asarray(places)[:, None] + np.arange(layout.itemsize)
            records = self.data[rows].reshape(-1).view(layout)
            found = self.bad_index(records)
            if found:
                bad.append((numbers[found[0]], found[1]))
        if bad:
            number, value = min(bad)
            self.fail(element, number, f"refers to vertex {value}; the file has {self.vertices}")
        return index, at


    def refuse_bad_index(self, element, first, records):
        """Raises CommandError when one of `records` (record `first` of `element` and those
        after it) has a vertex index outside [0, vertices)."""
        found = self.bad_index(records)
        if found:
            self.fail(element, first + found[0],
                      f"refers to vertex {found[1]}; the file has {self.vertices}")


class AsciiBody:
    """The body of an ASCII PLY file (`data`, bytes as uint8) read as vtkPLYReader reads it:
    a line an element, words split at spaces and tabs, a list's count by atoi. It takes the
    words a line's properties need without looking how many there are (a short line: a read
    past its words, a segmentation fault), and reads a line in pieces of 4,095 characters."""

    #: The longest line vtkPLYReader reads whole (its buffer, BIG_STRING, less the NUL).
    LONGEST_LINE = 4095
    #: Lines looked at in one numpy pass.
    CHUNK = 1 << 16

    def __init__(self, data, path):
        self.data = data
        self.path = path
        ends = np.flatnonzero(data == 10)
        self.starts = np.concatenate(([0], ends + 1))
        self.ends = np.concatenate((ends, [len(data)]))

    def fail(self, element, index, why):
        raise CommandError(f"'{self.path}' is not a valid PLY file: {element.name} {index} "
                           f"{why}")

    def walk(self, elements):
        """Checks every element's lines; raises CommandError on the first one vtkPLYReader
        would read past or in pieces."""
        # Whole lines only: vtkPLYReader asserts at the end of a file whose last element's
        # line has no newline.
        count = sum(element.count for element in elements)
        lines = len(self.starts) - 1
        # A NUL byte ends a line for vtkPLYReader's C strings: the words after it are missing
        # (a read of a null word: SIGSEGV, found by FuzzReaders).
        nul = np.flatnonzero(self.data[: self.ends[min(count, lines) - 1]] == 0) if count else []
        if len(nul):
            line = int(np.searchsorted(self.starts, nul[0], side="right"))
            raise CommandError(f"'{self.path}' is not a valid PLY file: line {line} after its "
                               "header holds a NUL byte")
        if lines < count:
            raise CommandError(f"'{self.path}' is not a valid PLY file: its header declares "
                               f"{count} elements, a line each in ASCII; the file has {lines} "
                               "whole lines after its header")
        line = 0
        vertices = 0
        for element in elements:
            if element.name == "vertex":
                vertices = element.count
            lists = [k for k, prop in enumerate(element.properties) if prop.count is not None]
            indices = element.name == "face" and any(
                element.properties[k].name in INDEX_PROPERTIES for k in lists)
            for first in range(0, element.count, self.CHUNK):
                count = min(self.CHUNK, element.count - first)
                self.check_lines(element, first, line + first, count, lists,
                                 vertices if indices else None)
            line += element.count

    def check_lines(self, element, first, line, count, lists, vertices):
        """Checks lines `line` ... `line + count` (records `first` ... of `element`)."""
        starts = self.starts[line: line + count]
        ends = self.ends[line: line + count]
        long = np.flatnonzero(ends - starts > self.LONGEST_LINE)
        if long.size:
            self.fail(element, first + int(long[0]), f"is on a line longer than the "
                      f"{self.LONGEST_LINE} characters vtkPLYReader reads at once")
        lo, hi = int(starts[0]), int(ends[-1])
        text = np.concatenate((self.data[lo:hi], np.full(12, 32, np.uint8)))
        gap = (text == 32) | (text == 9) | (text == 10) | (text == 13)
        begins = np.flatnonzero(~gap & np.concatenate(([True], gap[:-1])))
        words_from = np.searchsorted(begins, starts - lo)
        words = np.searchsorted(begins, ends - lo) - words_from
        scalars = len(element.properties) - len(lists)
        if len(lists) > 1:
            # Several lists: each one's count sits after the lists before it, line by line.
            for k in range(count):
                self.check_words(element, first + k, text[starts[k] - lo: ends[k] - lo],
                                 vertices)
            return
        needed = np.full(count, scalars, dtype=np.int64)
        if lists:
            at = lists[0]  # the count is word `at`: only scalars come before it
            has_count = words > at
            items = np.zeros(count, dtype=np.int64)
            items[has_count] = atoi(text, begins[words_from[has_count] + at])
            negative = np.flatnonzero(items < 0)
            if negative.size:
                k = int(negative[0])
                self.fail(element, first + k, f"has a list of {items[k]} items")
            needed += 1 + items
            if vertices is not None:
                self.check_indices(element, first, text, begins, words_from + at + 1, items,
                                   words == needed, vertices)
        # VTK 9.2 reads a line an element, VTK 9.6 a stream of words: a line with more words
        # than its properties take puts 9.6 out of step, one with fewer puts 9.2 past them.
        wrong = np.flatnonzero(words != needed)
        if wrong.size:
            k = int(wrong[0])
            self.fail(element, first + k, f"has {words[k]} values on its line; its properties "
                      f"take {needed[k]}")

    def check_indices(self, element, first, text, begins, firsts, items, complete, vertices):
        """Raises CommandError when a face (complete: its line holds its values) has a vertex
        index outside [0, vertices); `firsts` the number of each line's first index word."""
        rows = np.flatnonzero(complete & (items > 0))
        if not rows.size:
            return
        lengths = items[rows]
        words = np.repeat(firsts[rows] - np.cumsum(lengths) + lengths, lengths) + np.arange(
            int(lengths.sum()))
        values = atoi(text, begins[words])
        outside = np.flatnonzero((values < 0) | (values >= vertices))
        if outside.size:
            row = int(np.searchsorted(np.cumsum(lengths), outside[0], side="right"))
            self.fail(element, first + int(rows[row]),
                      f"refers to vertex {values[outside[0]]}; the file has {vertices}")

    def check_words(self, element, index, line, vertices):
        """Checks one line of an element with several lists, word by word (`vertices`: the
        bound of a face's vertex indices, None when not a face)."""
        words = bytes(line).replace(b"\t", b" ").replace(b"\r", b" ").split(b" ")
        words = [word for word in words if word]
        at = 0
        for prop in element.properties:
            if at >= len(words):
                self.fail(element, index, f"has {len(words)} values on its line; its "
                          "properties take more")
            if prop.count is None:
                at += 1
                continue
            items = word_value(words[at])
            if items < 0:
                self.fail(element, index, f"has a list of {items} items")
            if vertices is not None and prop.name in INDEX_PROPERTIES:
                for word in words[at + 1: at + 1 + items]:
                    value = word_value(word)
                    if not 0 <= value < vertices:
                        self.fail(element, index, f"refers to vertex {value}; the file has "
                                  f"{vertices}")
            at += 1 + items
        if at != len(words):
            self.fail(element, index, f"has {len(words)} values on its line; its properties "
                      f"take {at}")


def word_value(word):
    """atoi of one word (bytes)."""
    return int(atoi(np.frombuffer(word + b" " * 12, np.uint8), np.zeros(1, np.int64))[0])


def atoi(text, begins):
    """C's atoi of the words of `text` (uint8, with 12 spaces after its end) starting at
    `begins`: an optional sign and the digits that follow, 0 for none; more than nine digits
    give a value beyond any count or index a file can hold (1e10)."""
    negative = text[begins] == 45
    at = begins + (negative | (text[begins] == 43))
    value = np.zeros(len(begins), dtype=np.int64)
    going = np.ones(len(begins), dtype=bool)
    for k in range(10):
        digit = text[at + k].astype(np.int64) - 48
        going &= (digit >= 0) & (digit <= 9)
        value = np.where(going, value * 10 + digit, value)
    value = np.where(going, 10 ** 10, value)  # a tenth digit: too many
    return np.where(negative, -value, value)
