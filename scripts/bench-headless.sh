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
  # The server picks a free display and writes its number once it accepts connections.
  number_file=$(mktemp)
  Xvfb -displayfd 3 -screen 0 1280x1280x24 -nolisten tcp -noreset 3>"$number_file" >/dev/null 2>&1 &
  xvfb_pid=$!
  for _ in $(seq 100); do
    if [ -n "$(tr -d '\n' <"$number_file")" ] || ! kill -0 "$xvfb_pid" 2>/dev/null; then
      break
    fi
    sleep 0.1
  done
  number=$(tr -d '\n' <"$number_file")
  rm -f "$number_file"
  if [ -n "$number" ]; then
    export DISPLAY=":$number"
  fi
fi
"$bench" "$@"
