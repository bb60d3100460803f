#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One entry point for a fresh Debian 12 machine (run as root): installs the Debian
# packages disktune needs (only the missing ones), configures and builds in Release
# with -j2, then runs what was asked:
#   bash cmake/setup.sh run     the built-in default job (writes disktune-demo/)
#   bash cmake/setup.sh test    the test suite (ctest); then the checking build (clang,
#                               AddressSanitizer and UndefinedBehaviorSanitizer, in
#                               build-asan/): the fast unit tests under the sanitizers
#                               and every reader's fuzz target for a short while
#   bash cmake/setup.sh bench   the benchmark against CGAL's Delaunay time
# Re-running is quick: installed packages are skipped and the build is incremental.
set -euo pipefail
mode=${1:-run}
case "$mode" in run | test | bench) ;; *)
  echo "usage: bash cmake/setup.sh run|test|bench" >&2
  exit 2
  ;;
esac
cd "$(dirname "$0")/.."

packages=(g++ cmake make libcgal-dev libcli11-dev libgtest-dev nlohmann-json3-dev libpng-dev libcairo2-dev pkgconf libmuparser-dev libopenmesh-dev libeigen3-dev libgmsh-dev pybind11-dev python3-dev python3-numpy)
# The checking build: clang with libFuzzer and its sanitizer runtimes (not a dependency
# of the clang package).
[ "$mode" = test ] && packages+=(clang libclang-rt-14-dev python3-meshio python3-pytest)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  if [ "$(id -u)" -ne 0 ]; then
    echo "disktune needs these Debian packages: ${missing[*]}; run this as root, or install them first." >&2
    exit 1
  fi
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

build=${DISKTUNE_BUILD_DIR:-build}
[ -f "$build/CMakeCache.txt" ] || cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j2

# The checking build (README, "Sanitizers and fuzzing"): one clang build serves both the
# sanitized tests and the fuzz targets, so the library is compiled once more, not twice.
# -O1 keeps compiling and running fast; -g1 gives file:line in the reports.
checks() {
  local check=${DISKTUNE_CHECK_BUILD_DIR:-build-asan} launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  [ -f "$check/CMakeCache.txt" ] || cmake -S . -B "$check" -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
    -DDISKTUNE_SANITIZE=ON -DDISKTUNE_FUZZ=ON -DDISKTUNE_BUILD_CLI=OFF -DDISKTUNE_BUILD_BENCH=OFF -DDISKTUNE_BUILD_PYTHON=OFF \
    -DDISKTUNE_INSTALL=OFF "${launcher[@]}"
  cmake --build "$check" -j2 --target disktune_tests disktune_gmsh_tests disktune_fuzz
  # The unit tests but the slowest sweeps (each >= 4 s in Release, about ten times that
  # under the sanitizers), which the Release run above covers, and the layering checks
  # (Python).
  # Not the command's test: ASan reserves terabytes of address space, so its memory-limit
  # case (ulimit -v) cannot run; nor the package test, which rebuilds the library.
  local skip=(
    'layering' 'Surfaces/SurfaceProperty\.'
    'SurfaceTune\.(EjectionAndInjection|WideAttractor|SeedEleven|TunedPackings)'
    'MeshReader\.NoFlippedBit' 'VaryingRadius/' 'VaryingRadiusSteep\.'
    'VaryingRadiusSteps\.' 'VaryingRadiusPeriodic\.(Angle|MpsAndTuning)'
    'Ejection\.(Sifting|WideAttractor|Attractor)EjectionKeeps'
    'Injection\.(Repeller|Void)InjectionKeeps' 'SurfaceMps\.LongBoundaryEdges'
    'PlanarProperty\.(OracleAfterEveryOperation|TargetsOnBothSides)'
    'PeriodicProperty\.(OracleAfterEveryOperation|TargetsOnBothSides)'
    'ConstrainedDelaunay\.ManyPointsAndARoundHole' 'BoundaryTuning\.PlanarSteps'
    'Remesh\.(GivesExactly|WhereTheSurface)' 'PlanarTuning/InDomain\.TuneDownTo04'
    'FeatureMeshing\.' 'FeatureSampling\.(Fandisk|Tuning|EveryPatch)' 'SurfaceSizing\.ThicknessSearch' 'BoundarySpacing\.TuningKeeps')
  local slow="^($(IFS='|'; echo "${skip[*]}"))"
  # Leaks of third-party libraries only (Gmsh's OpenCASCADE data): tests/lsan.supp.
  ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:print_stacktrace=1 \
    LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0" \
    UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    ctest --test-dir "$check" -L unit -E "$slow" --output-on-failure -j2
  bash tests/fuzz/run.sh "$check" "${DISKTUNE_FUZZ_SECONDS:-25}"
}

case "$mode" in
  run) "$build/bin/disktune" ;;
  test) ctest --test-dir "$build" --output-on-failure -j2 && checks ;;
  bench) "$build/bin/disktune-bench" ;;
esac
