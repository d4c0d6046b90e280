#!/usr/bin/env bash
# Benchmarks the headless render windows (OSMesa, EGL) against VTK's own GLX window under Xvfb
# in the same run: 1,000,000 triangles at 1024 x 1024, first frame and frame times, medians and
# ratios. Xvfb (Debian package xvfb) is optional: without it only the headless windows run.
#
#   scripts/bench-headless.sh [--benchmark_repetitions=5] [other Google Benchmark flags]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PHONGVTK_BUILD_DIR:-$here/build}"
bench="$build/bin/PhongVTKBenchHeadlessRendering"
if [ ! -x "$bench" ]; then
  "$here/scripts/build.sh"
fi
xvfb_pid=
cleanup() {
  if [ -n "$xvfb_pid" ]; then
    kill "$xvfb_pid" 2>/dev/null || true
  fi
}
trap cleanup EXIT
unset DISPLAY
if command -v Xvfb >/dev/null; then
  for n in $(seq 90 99); do
    if [ ! -e "/tmp/.X$n-lock" ]; then
      Xvfb ":$n" -screen 0 1280x1280x24 -nolisten tcp -noreset >/dev/null 2>&1 &
      xvfb_pid=$!
      export DISPLAY=":$n"
      for _ in $(seq 50); do
        [ -e "/tmp/.X11-unix/X$n" ] && break
        sleep 0.1
      done
      break
    fi
  done
fi
"$bench" "$@"
