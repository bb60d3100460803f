#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The wide invariant sweep (issue #21): the property tests with the environment
# variable DISKTUNE_SWEEP=full, ten times the seeds CI runs, every result judged by the
# independent oracles. Prints one "[figures]" line per surface or domain (combinations,
# targets reached, oracle calls, seconds), one "[ features ]" line per surface of the
# sample and tuned meshes' topology check (#15; the tuned one alone takes about 80
# minutes at 50 seeds), and any failure.
# Usage: bash tests/invariant_sweep.sh [BUILD_DIR [FIRST_SEED COUNT]]   (default: build)
# With FIRST_SEED and COUNT, seeds FIRST_SEED .. FIRST_SEED + COUNT - 1 of the property
# tests and the sample meshes' topology (not the tuned meshes': about 7 minutes a seed),
# so that a long sweep runs as shards, e.g. 1 500 and 501 500 on two cores.
set -euo pipefail
build=${1:-build}
tests="$build/bin/disktune_tests"
[ -x "$tests" ] || { echo "no $tests: build first (bash cmake/setup.sh test)" >&2; exit 2; }
filter='*SurfaceProperty*:*PlanarProperty*:*PeriodicProperty*:FeatureMeshing.*MeshesHaveTheInputsTopology*'
if [ $# -ge 3 ]; then
  export DISKTUNE_SWEEP_FIRST_SEED=$2 DISKTUNE_SWEEP_SEEDS=$3
  filter='*SurfaceProperty*:*PlanarProperty*:*PeriodicProperty*:FeatureMeshing.SampleMeshesHaveTheInputsTopology*'
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
DISKTUNE_SWEEP=full "$tests" --gtest_filter="$filter" >"$log" 2>&1 || status=$?
grep -E '^\[figures\]|^\[ features \]|^\[  (PASSED|FAILED) |Failure' "$log" || true
exit "$status"
