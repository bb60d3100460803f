#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs every libFuzzer target of BUILD_DIR (built with -DDISKTUNE_FUZZ=ON, in
# BUILD_DIR/fuzz/) for SECONDS each, on a copy of its seed corpus (corpus/<name>/, so new
# inputs never land in the source tree), JOBS targets at a time (default: the cores).
# Fails when any target finds a crash, a timeout (10 s for one input), a leak, a
# sanitizer report or an exception other than InvalidInput and IoError; the input that
# did it is kept in BUILD_DIR/fuzz-findings/<name>/ and its path printed.
#   bash tests/fuzz/run.sh BUILD_DIR SECONDS
# Replay a finding: BUILD_DIR/fuzz/<name>_fuzz FILE
set -uo pipefail
if [ $# -ne 2 ] || ! [[ "$2" =~ ^[0-9]+$ ]]; then
  echo "usage: bash tests/fuzz/run.sh BUILD_DIR SECONDS" >&2
  exit 2
fi
build=$(cd "$1" && pwd) || exit 2
seconds=$2
here=$(cd "$(dirname "$0")" && pwd)
jobs=${JOBS:-$(nproc)}
targets=(off obj ply stl poly points_csv surface_csv sizing_expression sizing_grid)
for name in "${targets[@]}"; do
  if [ ! -x "$build/fuzz/${name}_fuzz" ]; then
    echo "no fuzz target $build/fuzz/${name}_fuzz: configure with -DDISKTUNE_FUZZ=ON (clang) and build the target disktune_fuzz" >&2
    exit 2
  fi
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
findings="$build/fuzz-findings"
# A sanitizer report must stop the run with its stack (UBSan does not stop by itself);
# libFuzzer then saves the input.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}

fuzz_one() {  # fuzz_one NAME: runs the target, 0 when it found nothing
  local name=$1
  mkdir -p "$work/$name" "$findings/$name"
  cp -r "$here/corpus/$name" "$work/$name/corpus"
  (cd "$work/$name" && "$build/fuzz/${name}_fuzz" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=4096 -max_len=4096 -print_final_stats=1 -artifact_prefix="$findings/$name/" corpus \
    >log 2>&1)
}

declare -A pid_of
for name in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n; done
  fuzz_one "$name" &
  pid_of[$name]=$!
done

failed=0
for name in "${targets[@]}"; do
  wait "${pid_of[$name]}"
  rc=$?
  log="$work/$name/log"
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  if [ "$rc" -eq 0 ]; then
    echo "fuzz $name: ${runs:-?} inputs in ${seconds} s, nothing found"
    rmdir "$findings/$name" 2>/dev/null
    continue
  fi
  failed=1
  echo "fuzz $name: FAILED (exit $rc); the input is in $findings/$name/:"
  ls -1 "$findings/$name" | sed "s|^|    $findings/$name/|"
  echo "  its report:"
  # From the sanitizer's or libFuzzer's first error line on, else the log's end.
  if grep -qE 'ERROR|runtime error' "$log"; then
    sed -nE '/ERROR|runtime error/,$p' "$log" | head -n 60 | sed 's/^/    /'
  else
    tail -n 30 "$log" | sed 's/^/    /'
  fi
done
rmdir "$findings" 2>/dev/null
exit "$failed"
