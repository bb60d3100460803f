#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One entry point for a fresh Debian 12 machine (run as root): installs the Debian
# packages disktune needs (only the missing ones), configures and builds in Release
# with -j2, then runs what was asked:
#   bash cmake/setup.sh run     the built-in default job (writes disktune-demo/)
#   bash cmake/setup.sh test    the test suite (ctest)
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

packages=(g++ cmake make libcgal-dev libcli11-dev libgtest-dev nlohmann-json3-dev libpng-dev pkgconf libmuparser-dev libopenmesh-dev libeigen3-dev)
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

case "$mode" in
  run) "$build/bin/disktune" ;;
  test) ctest --test-dir "$build" --output-on-failure -j2 ;;
  bench) "$build/bin/disktune-bench" ;;
esac
