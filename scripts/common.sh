# Sourced by the scripts: which tools they mean, and (phongvtk_debian_clang) which Clang this
# Debian release has.
#
# The first `python3` and `cmake` on PATH may be a pyenv Python and a pip-installed CMake; the
# scripts build against Debian's VTK or ParaView, whose Python modules only Debian's Python loads,
# so they name Debian's tools by path (installed by scripts/setup-debian.sh).
PHONGVTK_PYTHON=/usr/bin/python3
PHONGVTK_CMAKE=/usr/bin/cmake
PHONGVTK_CTEST=/usr/bin/ctest

# Sets PHONGVTK_CLANG_VERSION: Debian 12 ships Clang 14, Debian 13 Clang 19, each release only its
# own. Another system stops the script with one line.
phongvtk_debian_clang() {
  local release
  release="$( (. /etc/os-release && echo "${ID:-}-${VERSION_ID:-}") 2>/dev/null || true)"
  case "$release" in
    debian-12) PHONGVTK_CLANG_VERSION=14 ;;
    debian-13) PHONGVTK_CLANG_VERSION=19 ;;
    *)
      echo "phongvtk: the set-up knows Debian 12 and 13; this is '${release:-unknown}'" >&2
      exit 2
      ;;
  esac
}

# phongvtk_pypi_venv DIR "VENV OPTIONS" "PIP ARGUMENTS" ["PIP ARGUMENTS" ...]
# Makes the virtual environment DIR of Debian's Python with each pip install in turn (each string
# word-split), once for these arguments: DIR/installed records them, and other arguments make it
# anew (a venv cannot be moved, so it is made in place). Returns 1, having removed DIR, when
# PyPI cannot serve the packages.
phongvtk_pypi_venv() {
  local dir=$1 options=$2 step wanted
  shift 2
  wanted="$(printf '%s\n' "$options" "$@")"
  [ -f "$dir/installed" ] && [ "$(cat "$dir/installed")" = "$wanted" ] && return 0
  rm -rf "$dir"
  # shellcheck disable=SC2086 # options and each step are word lists
  if "$PHONGVTK_PYTHON" -m venv $options "$dir" >/dev/null; then
    for step in "$@"; do
      if ! "$dir/bin/pip" install -q --disable-pip-version-check $step; then
        rm -rf "$dir"
        return 1
      fi
    done
    printf '%s\n' "$wanted" >"$dir/installed"
    return 0
  fi
  rm -rf "$dir"
  return 1
}
