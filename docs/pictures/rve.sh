#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes docs/rve.md's pictures from the built command (bash cmake/setup.sh run first):
#   bash docs/pictures/rve.sh [BUILD_DIR]
set -euo pipefail
bin=${1:-build}/bin/disktune
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/vf70" "$work/vf67" "$work/unequal"
# vf 0.70 with g = 0.05 D in a 20 D cell, its statistics plots; the paper's 0.67 touching;
# unequal fibers (CV 0.1) at vf 0.70; a small cell's periodic mesh.
"$bin" rve -d 1 -g 0.05 --vf 0.70 --width 20 --height 20 --seed 1 -o "$work/vf70.csv" --png-dir "$work/vf70"
"$bin" rve -d 1 -g 0 --vf 0.67 --width 20 --height 20 --seed 1 -o "$work/vf67.csv" --png-dir "$work/vf67"
"$bin" rve -d 1 -g 0.05 --diameter-cv 0.1 --vf 0.70 --width 20 --height 20 --seed 1 -o "$work/unequal.csv" \
  --png-dir "$work/unequal"
"$bin" rve -d 1 -g 0.05 --vf 0.65 --width 6 --height 6 --seed 2 -o "$work/mesh.csv" --msh "$work/mesh.msh" \
  --fiber-segments 16
mkdir -p "$here/rve"
for f in cell pair_correlation ripley_l nearest psi6_local; do cp "$work/vf70/$f.png" "$here/rve/vf70-$f.png"; done
cp "$work/vf67/cell.png" "$here/rve/vf67-cell.png"
cp "$work/unequal/cell.png" "$here/rve/unequal-cell.png"
/usr/bin/python3 "$here/mesh_svg.py" "$work/mesh.msh" "$here/rve/mesh.svg"
