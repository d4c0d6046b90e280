#!/usr/bin/env bash
# Fails when a C++ file of the project is not clang-format clean (VTK's style, .clang-format).
#
# The format is clang-format 14's (Debian 12's). Other major versions lay out some lines
# differently with the same .clang-format (Debian 13's clang-format 19 rewraps lambdas and long
# for headers), so where Debian's is another version the check runs clang-format 14.0.6 from PyPI,
# installed once into a virtual environment of its own (PHONGVTK_TOOLS_DIR, default
# ~/.cache/phongvtk). Without PyPI there the format is not checked, and the script says so: it is
# a property of the sources, checked wherever clang-format 14 is at hand (Debian 12, CI).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$here/scripts/common.sh"
cd "$here"
clang_format=clang-format
if [[ "$(clang-format --version 2>/dev/null)" != *"version 14."* ]]; then
  tools="${PHONGVTK_TOOLS_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/phongvtk}/clang-format-14.0.6"
  if [ ! -f "$tools/installed" ]; then
    echo "phongvtk: installing clang-format 14.0.6 from PyPI into $tools" >&2
  fi
  if ! phongvtk_pypi_venv "$tools" "" "clang-format==14.0.6"; then
    echo "phongvtk: format NOT checked: clang-format 14 could not be installed from PyPI and" \
      "Debian's is $(clang-format --version 2>/dev/null | sed 's/.*version //')" >&2
    exit 0
  fi
  clang_format="$tools/bin/clang-format"
fi
if command -v git >/dev/null && git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  # Tracked files and new ones not yet added (but not ignored ones, such as a build folder's).
  mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.h' '*.cxx' | sort)
else
  # No git (a fresh minimal root has none; an unpacked archive): every source but the build's.
  mapfile -t files < <(find . \( -path './build*' -o -path './.git' \) -prune -o \
    \( -name '*.h' -o -name '*.cxx' \) -type f -print | sed 's|^\./||' | sort)
fi
if [ "${#files[@]}" -eq 0 ]; then
  echo "phongvtk: no C++ file found to check" >&2
  exit 1
fi
if ! "$clang_format" --dry-run -Werror "${files[@]}"; then
  echo "phongvtk: the files above are not clang-format clean; run: $clang_format -i <file>" >&2
  exit 1
fi
echo "phongvtk: clang-format clean (${#files[@]} files, $("$clang_format" --version | sed 's/.*version //'))"
