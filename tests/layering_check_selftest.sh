#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Shows that layering_check.py can fail: small fabricated trees in a temporary folder,
# with this repository's docs/ARCHITECTURE.md (its table and allowed includes), each
# with one defect. A clean tree must pass; each defect must fail with exit 1 and a
# message naming the place and the reason.
#   layering_check_selftest.sh PYTHON CHECKER REPOSITORY
set -u
python=$1 checker=$2 repo=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
pass=0

# A tree that follows the rules: geometry at the bottom, packing above it, the CLI on
# top; a comment and a literal with "--" in them that name no flag.
clean_tree() {
  rm -rf "$work/t" && mkdir -p "$work/t/docs" "$work/t/include/disktune" "$work/t/src/geometry" \
    "$work/t/src/packing" "$work/t/plugins/cli"
  cp "$repo/docs/ARCHITECTURE.md" "$work/t/docs/"
  printf '#pragma once\nstruct Vec2 { double x, y; };\n' >"$work/t/include/disktune/geometry.h"
  printf '#pragma once\n#include "disktune/geometry.h"\nstruct Packing {};\n' >"$work/t/include/disktune/packing.h"
  cat >"$work/t/src/geometry/circle.cpp" <<'EOF'
#include "disktune/geometry.h"
// The command line's --radius is not the library's business.
const char* separator = "--";
const char* sum = "a - -b";
EOF
  cat >"$work/t/src/packing/packing.cpp" <<'EOF'
#include "disktune/packing.h"
#include "../geometry/arc.h"
const char* what = "give the radius the packing was made with";
EOF
  printf '#pragma once\n#include "disktune/geometry.h"\n' >"$work/t/src/geometry/arc.h"
  cat >"$work/t/plugins/cli/main.cpp" <<'EOF'
#include "commands.h"
#include "disktune/packing.h"
void add(App& app) { app.add_subcommand(
    "sample", "--radius R"); }
EOF
  printf '#pragma once\n' >"$work/t/plugins/cli/commands.h"
}

# run NAME WANTED_EXIT PATTERN...: runs the checker on the tree; every PATTERN (fixed
# text) must be in its output.
run() {
  local name=$1 want=$2
  shift 2
  local out rc ok=1
  out=$("$python" "$checker" "$work/t" 2>&1)
  rc=$?
  [ "$rc" -eq "$want" ] || ok=0
  for pattern in "$@"; do grep -qF -- "$pattern" <<<"$out" || ok=0; done
  if [ "$ok" -eq 1 ]; then
    pass=$((pass + 1))
  else
    echo "FAIL $name: exit $rc (wanted $want), wanted: $*; output:"
    echo "$out" | sed 's/^/    /'
    fails=$((fails + 1))
  fi
}

clean_tree
run clean 0 "all allowed"

clean_tree  # a wrong-way include: geometry reaching up to packing
printf '#include "disktune/packing.h"\n' >>"$work/t/src/geometry/circle.cpp"
run wrong-way 1 'src/geometry/circle.cpp:5: #include "disktune/packing.h"' "geometry -> packing is not allowed"

clean_tree  # the same through a relative path into another layer's folder
printf '#include "../packing/grid.h"\n' >>"$work/t/src/geometry/arc.h"
printf '#pragma once\n' >"$work/t/src/packing/grid.h"
run wrong-way-relative 1 "src/geometry/arc.h:3:" "geometry -> packing is not allowed"

clean_tree  # a public header reaching up
printf '#include "disktune/packing.h"\n' >>"$work/t/include/disktune/geometry.h"
run wrong-way-public 1 "include/disktune/geometry.h:3:" "geometry -> packing"

clean_tree  # the library including the front end
printf '#include "../../plugins/cli/commands.h"\n' >>"$work/t/src/packing/packing.cpp"
run into-plugins 1 "src/packing/packing.cpp:4:" "reaches into plugins/"

clean_tree  # a file in no layer's folder
mkdir -p "$work/t/src/misc" && printf 'int x;\n' >"$work/t/src/misc/x.cpp"
run unmapped-folder 1 "src/misc/x.cpp: cannot tell its layer" "not a layer"

clean_tree  # a public header the table does not list
printf '#pragma once\n' >"$work/t/include/disktune/extra.h"
run unlisted-header 1 "include/disktune/extra.h: cannot tell its layer" "extra.h"

clean_tree  # an include of a file that is not there
printf '#include "nowhere.h"\n' >>"$work/t/src/packing/packing.cpp"
run missing-include 1 'src/packing/packing.cpp:4: #include "nowhere.h": no such file'

clean_tree  # a library message naming a flag, also split over two literals
printf 'const char* m = "give the box with --width and --height";\n' >>"$work/t/src/packing/packing.cpp"
printf 'const char* n = "(-"\n    "-radius 0.1)";\n' >>"$work/t/src/geometry/circle.cpp"
run flag-literal 1 "src/packing/packing.cpp:4: a string literal names a command-line flag (--width)" \
  "src/geometry/circle.cpp:5: a string literal names a command-line flag (--radius)"

clean_tree  # a library message naming a command of the CLI
printf 'const char* m = "start from a sample (disktune sample)";\n' >>"$work/t/src/packing/packing.cpp"
run command-literal 1 "src/packing/packing.cpp:4: a string literal names a command of the CLI ('disktune sample')"

clean_tree  # a doc without the allowed list
sed -i 's/^## Allowed includes$/## Something else/' "$work/t/docs/ARCHITECTURE.md"
run no-allowed-list 1 'no "## Allowed includes" section'

clean_tree  # a doc whose list misses a layer
sed -i '/^## Allowed includes$/,/^## /{/^packing:/d}' "$work/t/docs/ARCHITECTURE.md"
run layer-without-line 1 'layer packing has no line in "Allowed includes"'

echo "$pass passed, $fails failed"
[ "$fails" -eq 0 ]
