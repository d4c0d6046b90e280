#!/usr/bin/env bash
# Fails when a C++ file of the project is not clang-format clean (VTK's style, .clang-format).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
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
if ! clang-format --dry-run -Werror "${files[@]}"; then
  echo "phongvtk: the files above are not clang-format clean; run: clang-format -i <file>" >&2
  exit 1
fi
echo "phongvtk: clang-format clean (${#files[@]} files)"
