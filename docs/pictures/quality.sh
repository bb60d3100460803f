#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes docs/quality.md's pictures from the built command (bash cmake/setup.sh run first):
#   bash docs/pictures/quality.sh [BUILD_DIR]
set -euo pipefail
bin=${1:-build}/bin/disktune
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/mps" "$work/dense" "$work/fandisk"
# An MPS of the unit box (r = 0.01), the same tuned to eta 0.80 (automatic schedule), and fandisk
# remeshed at 10^4 vertices with its sharp edges kept.
"$bin" sample --radius 0.01 --seed 1 -o "$work/mps.csv"
"$bin" report "$work/mps.csv" --radius 0.01 --png-dir "$work/mps"
"$bin" tune --radius 0.01 --seed 1 --target-fraction 0.8 -o "$work/dense.csv"
"$bin" report "$work/dense.csv" --radius 0.01 --png-dir "$work/dense"
"$bin" remesh "$here/../../data/surfaces/fandisk.off" -n 10000 -o "$work/fandisk.off" --png-dir "$work/fandisk"
mkdir -p "$here/quality"
for f in spectrum radial_mean angles; do cp "$work/mps/$f.png" "$here/quality/mps-$f.png"; done
for f in spectrum orientation angles; do cp "$work/dense/$f.png" "$here/quality/dense80-$f.png"; done
for f in surface angles; do cp "$work/fandisk/$f.png" "$here/quality/fandisk-remesh-$f.png"; done
