#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# find_package(disktune) from another project (ctest label `package`):
#  1. installs this build tree into a temporary prefix, builds the project in
#     tests/consumer/ against it and runs it: the remeshing program, and the same code
#     in a shared library (with a static libdisktune.a, that needs -fPIC);
#  2. builds disktune again as the other kind of library (shared when this build is
#     static, static when it is shared; the library alone, Release, -j2), installs it
#     into a second prefix and does the same.
# The output of each run must be an OFF file with exactly N vertices and some faces
# (read here, not by disktune), and both programs of a build must write the same file.
# Usage: bash tests/consumer_test.sh BUILD_DIR SOURCE_DIR [CMAKE [LIBRARY_TYPE]]
#   LIBRARY_TYPE is STATIC_LIBRARY or SHARED_LIBRARY, the kind BUILD_DIR holds.
set -euo pipefail
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
cmake=${3:-cmake}
kind=${4:-STATIC_LIBRARY}
input=$src/data/surfaces/elephant.off
n=3000

work=$(mktemp -d "${TMPDIR:-/tmp}/disktune-package.XXXXXX")
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# run WHAT COMMAND...: quiet on success; on failure the end of its output.
run() {
  local what=$1 log=$work/log start=$SECONDS
  shift
  if ! "$@" >"$log" 2>&1; then
    echo "FAIL: $what; the command was: $*" >&2
    tail -n 40 "$log" | sed 's/^/    /' >&2
    exit 1
  fi
  echo "ok: $what ($((SECONDS - start)) s)"
}

cache() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
# The same generator, compiler and compiler launcher (ccache) as this build.
common=(-G "$(cache CMAKE_GENERATOR)" -DCMAKE_BUILD_TYPE=Release
        -DCMAKE_CXX_COMPILER="$(cache CMAKE_CXX_COMPILER)")
launcher=$(cache CMAKE_CXX_COMPILER_LAUNCHER)
if [ -n "$launcher" ]; then common+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"); fi

# check_off FILE: an OFF file with exactly $n vertices and at least one face.
check_off() {
  local counts v f
  [ -s "$1" ] || fail "$1 was not written"
  counts=$(awk '{ sub(/#.*/, ""); for (i = 1; i <= NF && k < 3; i++) tok[++k] = $i }
                k >= 3 { exit }
                END { if (k >= 3 && tok[1] == "OFF") print tok[2], tok[3] }' "$1")
  read -r v f <<<"$counts" || true
  [[ ${v:-} =~ ^[0-9]+$ && ${f:-} =~ ^[0-9]+$ ]] || fail "$1 has no OFF header with counts"
  [ "$v" -eq "$n" ] || fail "$1 has $v vertices, not $n"
  [ "$f" -ge 1 ] || fail "$1 has no faces"
  echo "ok: $(basename "$1"): $v vertices, $f faces"
}

# consume static|shared PREFIX: build and run tests/consumer against the disktune in
# PREFIX, a static or a shared library.
consume() {
  local lib=$1 prefix=$2 name="the installed $1 library" dir=$work/consumer-$1 start libs
  run "configure the consumer against $name" \
    "$cmake" -S "$src/tests/consumer" -B "$dir" "${common[@]}" -DCMAKE_PREFIX_PATH="$prefix"
  grep -qx "disktune_DIR:PATH=$prefix/.*" "$dir/CMakeCache.txt" ||
    fail "the consumer found another disktune: $(sed -n 's/^disktune_DIR:PATH=//p' "$dir/CMakeCache.txt")"
  run "build the consumer against $name" "$cmake" --build "$dir" -j2
  libs=$(ldd "$dir/consumer")
  if [ "$lib" = shared ]; then
    grep -q "libdisktune\.so.* => $prefix/" <<<"$libs" ||
      fail "the consumer does not load libdisktune.so from $prefix"
  elif grep -q libdisktune <<<"$libs"; then
    fail "the consumer loads a shared libdisktune"
  fi
  start=$SECONDS
  run "consumer $n vertices ($name)" "$dir/consumer" "$input" "$n" "$dir/direct.off"
  check_off "$dir/direct.off"
  run "consumer through the plugin ($name)" "$dir/consumer_plugin" "$input" "$n" "$dir/plugin.off"
  check_off "$dir/plugin.off"
  cmp -s "$dir/direct.off" "$dir/plugin.off" || fail "the program and the plugin wrote different meshes"
  echo "ok: runs against $name ($((SECONDS - start)) s)"
}

[ -f "$input" ] || fail "no $input"
[ -f "$build/CMakeCache.txt" ] || fail "no build tree at $build"

# 1. This build tree.
if [ "$kind" = SHARED_LIBRARY ]; then this=shared other=static other_flag=OFF; else
  this=static other=shared other_flag=ON; fi
run "install $build" "$cmake" --install "$build" --prefix "$work/prefix-$this"
if [ -x "$work/prefix-$this/bin/disktune" ]; then  # finds a shared libdisktune (RPATH)
  run "the installed command runs" "$work/prefix-$this/bin/disktune" --help
fi
consume "$this" "$work/prefix-$this"

# 2. The other kind, built from the same sources.
run "configure disktune as a $other library" \
  "$cmake" -S "$src" -B "$work/build-$other" "${common[@]}" -DBUILD_SHARED_LIBS=$other_flag \
  -DDISKTUNE_BUILD_TESTS=OFF -DDISKTUNE_BUILD_BENCH=OFF -DDISKTUNE_BUILD_CLI=OFF -DDISKTUNE_BUILD_PYTHON=OFF
run "build disktune as a $other library" "$cmake" --build "$work/build-$other" -j2
run "install the $other library" "$cmake" --install "$work/build-$other" --prefix "$work/prefix-$other"
consume "$other" "$work/prefix-$other"
echo "package test passed"
