# Sourced by the scripts: which Debian release this is and which tools they mean.
#
# The first `python3` and `cmake` on PATH may be a pyenv Python and a pip-installed CMake; the
# scripts build against Debian's VTK or ParaView, whose Python modules only Debian's Python loads,
# so they name Debian's tools by path (installed by scripts/setup-debian.sh).
PHONGVTK_PYTHON=/usr/bin/python3
PHONGVTK_CMAKE=/usr/bin/cmake
PHONGVTK_CTEST=/usr/bin/ctest

# Debian 12 ships Clang 14, Debian 13 Clang 19 (each release has only its own).
phongvtk_debian_release="$(. /etc/os-release 2>/dev/null && echo "${VERSION_ID:-}")"
case "$phongvtk_debian_release" in
  12) PHONGVTK_CLANG_VERSION=14 ;;
  13) PHONGVTK_CLANG_VERSION=19 ;;
  *)
    echo "phongvtk: the set-up knows Debian 12 and 13; this is '${phongvtk_debian_release:-unknown}'" >&2
    exit 2
    ;;
esac
