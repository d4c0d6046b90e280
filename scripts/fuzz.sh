#!/usr/bin/env bash
# Builds the fuzz targets of Testing/Fuzz as libFuzzer programs (Debian's Clang, AddressSanitizer +
# UndefinedBehaviorSanitizer) in build-fuzz/ (PHONGVTK_FUZZ_BUILD_DIR) and runs each for SECONDS
# (default 60) on one core, starting from the committed seeds and the corpus of earlier runs
# (build-fuzz/corpus/<target>). Prints each target's last status line; a finding is kept in
# build-fuzz/findings/<target>/ and fails the script (status 1).
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]    targets: FuzzAreaVector FuzzPolyDataFilters FuzzReaders
#
# A finding replays with `build-fuzz/bin/<target> <file>`; once fixed, copy the file into
# Testing/Fuzz/regressions/<target>/ so that every build's CTest replays it.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$here/scripts/common.sh"
phongvtk_debian_clang
clang="$PHONGVTK_CLANG_VERSION"
seconds=60
if [ $# -gt 0 ]; then
  if ! [[ "$1" =~ ^[0-9]+$ ]]; then
    echo "phongvtk: usage: scripts/fuzz.sh [SECONDS] [TARGET...] ('$1' is not a number)" >&2
    exit 2
  fi
  seconds="$1"
  shift
fi
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(FuzzAreaVector FuzzPolyDataFilters FuzzReaders)
fi

# The main build (scripts/build.sh, also the set-up): FuzzReaders runs its command line.
"$here/scripts/build.sh"
missing=()
for package in "clang-$clang" "libfuzzer-$clang-dev"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=()
  [ "$(id -u)" -ne 0 ] && sudo=(sudo)
  echo "phongvtk: installing ${missing[*]}" >&2
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends \
    "${missing[@]}"
fi

build="${PHONGVTK_FUZZ_BUILD_DIR:-$here/build-fuzz}"
flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=all -fno-omit-frame-pointer -g"
python_version="$("$PHONGVTK_PYTHON" -c 'import sys; print("python%d.%d" % sys.version_info[:2])')"
if [ ! -f "$build/build.ninja" ]; then
  CC="clang-$clang" CXX="clang++-$clang" CFLAGS="$flags" CXXFLAGS="$flags" \
    LDFLAGS="-fsanitize=address,undefined" \
    "$PHONGVTK_CMAKE" -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DPython3_EXECUTABLE="$PHONGVTK_PYTHON" -DPHONGVTK_FUZZING=ON -DPHONGVTK_BUILD_RENDERING=OFF \
    -DPHONGVTK_BUILD_PLUGIN=OFF -DPHONGVTK_BUILD_BENCHMARKS=OFF \
    -DPHONGVTK_FUZZ_PYTHONPATH="${PHONGVTK_BUILD_DIR:-$here/build}/lib/$python_version/site-packages"
fi
"$PHONGVTK_CMAKE" --build "$build" --target "${targets[@]}" -- -j"$(nproc)"

# Leaks: the embedded Python keeps its caches, and libFuzzer checks every input that mallocs more
# than it frees; the other targets are checked.
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
status=0
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target"
  findings="$build/findings/$target"
  mkdir -p "$corpus" "$findings"
  leaks=1
  [ "$target" = FuzzReaders ] && leaks=0
  log="$build/fuzz-$target.log"
  echo "phongvtk: fuzzing $target for ${seconds}s (log $log)" >&2
  if ASAN_OPTIONS="detect_leaks=$leaks:allocator_may_return_null=0" \
    PYTHONDONTWRITEBYTECODE=1 "$build/bin/$target" -max_total_time="$seconds" \
    -detect_leaks="$leaks" -rss_limit_mb=4096 -timeout=60 -close_fd_mask=3 \
    -print_final_stats=1 -artifact_prefix="$findings/" \
    "$corpus" "$here/Testing/Fuzz/corpus/$target" >"$log" 2>&1; then
    echo "$target: $(grep -E '^#[0-9]+' "$log" | tail -1)"
    grep -E 'stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)' "$log" |
      sed "s/^/$target: /" || true
  else
    status=1
    echo "$target: FINDING (see $log and $findings/)"
    grep -E '^(FuzzAreaVector|FuzzPolyDataFilters|FuzzReaders|==[0-9]+==ERROR|SUMMARY)' "$log" |
      head -5 | sed "s/^/$target: /" || true
  fi
done
exit "$status"
