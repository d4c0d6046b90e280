"""``python3 -m phongvtk``: the command-line interface (see :mod:`phongvtk.cli`)."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
