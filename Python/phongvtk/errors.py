"""The one exception the command-line interface turns into ``phongvtk: error: ...`` (status 2)."""


class CommandError(Exception):
    """A problem the user can fix (a missing or unreadable file, an unusable mesh): the message
    is one line naming the file and what is wrong, without a traceback."""
