"""Progress bars on stderr fed by VTK's ProgressEvent, and VTK errors turned into exceptions.

A bar reads ``name [#########                     ]  30%``. On a terminal it is redrawn in place
(``\\r``) as the work advances; on a pipe or a file only the final line is written, so logs stay
short. A quiet :class:`Progress` draws nothing.

VTK reports errors through events and its output window rather than exceptions:
:meth:`Progress.run` catches the ErrorEvent and WarningEvent of an algorithm and of its executive,
keeps VTK's own printing off meanwhile, and raises :class:`~phongvtk.errors.CommandError` with the
algorithm's message when the execution failed.
"""

import contextlib
import os
import re
import sys
import tempfile

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkLogger, vtkOutputWindow, vtkStringOutputWindow

from .errors import CommandError


class Bar:
    """One bar: :meth:`update` with the fraction done, then :meth:`finish` or :meth:`abandon`."""

    WIDTH = 30

    def __init__(self, name, stream, live):
        self.name = name
        self.stream = stream
        self.live = live  # redraw in place (a terminal) rather than write the final line only
        self.shown = -1  # the percentage on screen, -1 before the first draw
        self.done = False

    def line(self, fraction):
        """The text of the bar at `fraction` (clamped to [0, 1])."""
        fraction = min(max(fraction, 0.0), 1.0)
        filled = int(round(fraction * self.WIDTH))
        bar = "#" * filled + " " * (self.WIDTH - filled)
        return f"{self.name} [{bar}] {int(fraction * 100):3d}%"

    def update(self, fraction):
        """Shows `fraction` done (on a terminal, when the percentage changes)."""
        percent = int(min(max(fraction, 0.0), 1.0) * 100)
        if self.live and not self.done and percent != self.shown:
            self.shown = percent
            self.stream.write("\r" + self.line(fraction))
            self.stream.flush()

    def finish(self):
        """Writes the complete bar and ends its line; later calls do nothing."""
        if not self.done:
            self.done = True
            self.stream.write(("\r" if self.live else "") + self.line(1.0) + "\n")
            self.stream.flush()

    def abandon(self):
        """Stops without claiming completion: ends a partly drawn terminal line, if any."""
        if self.live and not self.done and self.shown >= 0:
            self.stream.write("\n")
            self.stream.flush()
        self.done = True


class SilentBar:
    """What a quiet :class:`Progress` hands out: takes the calls of :class:`Bar`, draws nothing."""

    def update(self, fraction):
        pass

    def finish(self):
        pass

    def abandon(self):
        pass


#: One report in a VTK output window's text: the location line and the message line.
VTK_REPORT = re.compile(r"(?:ERROR|Warning): In [^\n]*\n[^\n]*")


def vtk_message(text):
    """The message of a VTK error or warning text, without its source location and object
    address ("ERROR: In file.cxx, line 7\\nvtkX (0x1): Could not open" -> "Could not open")."""
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    if len(lines) > 1 and lines[0].startswith(("ERROR: In ", "Warning: In ")):
        lines = lines[1:]
    body = re.sub(r"^\w+ \(0x[0-9a-fA-F]+\): ", "", lines[0] if lines else "")
    return " ".join(body.split())


@contextlib.contextmanager
def vtk_output_captured():
    """Within the block VTK's output window and logger write nothing to the terminal; yields the
    vtkStringOutputWindow that collects what objects without an observer reported."""
    window = vtkStringOutputWindow()
    previous = vtkOutputWindow.GetInstance()
    cutoff = vtkLogger.GetCurrentVerbosityCutoff()
    vtkOutputWindow.SetInstance(window)
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    try:
        yield window
    finally:
        vtkLogger.SetStderrVerbosity(cutoff)
        vtkOutputWindow.SetInstance(previous)


@contextlib.contextmanager
def native_lines_dropped(prefixes):
    """Within the block, lines that native libraries write straight to the process's standard
    error (file descriptor 2) and that start with one of `prefixes` are dropped (libpng's
    "libpng error: Write Error", which the writer reports again); other lines written there go
    on to it when the block ends."""
    sys.stderr.flush()
    saved = os.dup(2)
    with tempfile.TemporaryFile() as sink:
        os.dup2(sink.fileno(), 2)
        try:
            yield
        finally:
            sys.stderr.flush()
            os.dup2(saved, 2)
            os.close(saved)
            sink.seek(0)
            for line in sink.read().decode(errors="replace").splitlines(keepends=True):
                if not line.startswith(prefixes):
                    sys.stderr.write(line)
            sys.stderr.flush()


class Progress:
    """Bars on `stream` (default stderr) unless `quiet`, and checked execution of VTK algorithms.

    Warnings that VTK algorithms raise during :meth:`run` are written as one line each,
    ``phongvtk: warning: ...``, unless quiet.
    """

    def __init__(self, quiet=False, stream=None):
        self.quiet = quiet
        self.stream = stream if stream is not None else sys.stderr
        self.live = bool(getattr(self.stream, "isatty", lambda: False)())
        self.bars = []

    def bar(self, name):
        """A new bar for work done in Python, or a silent stand-in when quiet."""
        if self.quiet:
            return SilentBar()
        bar = Bar(name, self.stream, self.live)
        self.bars.append(bar)
        return bar

    def abandon(self):
        """Ends every unfinished bar, so that an error message starts on its own line."""
        for bar in self.bars:
            bar.abandon()
        self.bars = []

    def warn(self, message):
        """Writes ``phongvtk: warning: message`` unless quiet."""
        if not self.quiet:
            self.stream.write(f"phongvtk: warning: {message}\n")
            self.stream.flush()

    def run(self, algorithm, name, what, action="Update"):
        """Executes `algorithm` (``algorithm.<action>()``; any vtkObject that reports progress,
        e.g. a render window's Render) under a bar called `name`.

        Raises CommandError("`what`: <VTK's message>") when the algorithm or its executive
        reports an error (VTK's own printing is off meanwhile); when it succeeds, its warnings
        and what other objects reported meanwhile are passed on with :meth:`warn`. Returns what
        the action returned.
        """
        errors, warnings = [], []

        @calldata_type(VTK_STRING)
        def on_error(caller, event, text):
            errors.append((caller is algorithm, vtk_message(text or "")))

        @calldata_type(VTK_STRING)
        def on_warning(caller, event, text):
            warnings.append(vtk_message(text or ""))

        bars = []  # made at the first StartEvent or ProgressEvent (some writers send no start)

        def on_progress(caller, event):
            if not bars:
                bars.append(self.bar(name))
            bars[0].update(0.0 if event == "StartEvent" else caller.GetProgress())

        observed = [
            (algorithm, vtkCommand.StartEvent, on_progress),
            (algorithm, vtkCommand.ProgressEvent, on_progress),
            (algorithm, vtkCommand.ErrorEvent, on_error),
            (algorithm, vtkCommand.WarningEvent, on_warning),
        ]
        executive = algorithm.GetExecutive() if hasattr(algorithm, "GetExecutive") else None
        if executive is not None:
            observed.append((executive, vtkCommand.ErrorEvent, on_error))
        tags = [(obj, obj.AddObserver(event, callback)) for obj, event, callback in observed]
        result, completed = None, False
        try:
            with vtk_output_captured() as others:
                result = getattr(algorithm, action)()
            completed = True
        finally:
            for obj, tag in tags:
                obj.RemoveObserver(tag)
            # Writers' Write() returns 0 on failure; Update() returns nothing.
            failed = not completed or bool(errors) or result == 0
            for bar in bars:
                if failed:
                    bar.abandon()
                else:
                    bar.finish()
        if failed:
            # The algorithm's own words first (a reader's warning often says why it failed), then
            # what its helpers said (e.g. an XML parser); the executive's "returned failure for
            # request" says nothing useful.
            own = [message for from_algorithm, message in errors if from_algorithm]
            helpers = [vtk_message(text) for text in VTK_REPORT.findall(others.GetOutput())]
            reason = (own + warnings + helpers + [f"{algorithm.GetClassName()} failed"])[0]
            raise CommandError(f"{what}: {reason}")
        for message in dict.fromkeys(warnings):
            self.warn(f"{algorithm.GetClassName()}: {message}")
        for report in dict.fromkeys(VTK_REPORT.findall(others.GetOutput())):
            self.warn(vtk_message(report))
        return result
