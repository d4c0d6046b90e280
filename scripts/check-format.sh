#!/usr/bin/env bash
# Fails when a C++ file of the project is not clang-format clean (VTK's style, .clang-format).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
# Tracked files and new ones not yet added (but not ignored ones, such as a build folder's).
mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.h' '*.cxx' | sort)
if ! clang-format --dry-run -Werror "${files[@]}"; then
  echo "phongvtk: the files above are not clang-format clean; run: clang-format -i <file>" >&2
  exit 1
fi
echo "phongvtk: clang-format clean (${#files[@]} files)"
