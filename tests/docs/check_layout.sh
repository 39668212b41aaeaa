#!/usr/bin/env bash
# Keeps the pictures of the house true (CTest docs.layout, label unit):
#  - every top-level folder and every src/ folder has a row in the README's
#    Layout table (| `name/` |), and every row names a folder that exists;
#  - every library of src/ (add_library(drawbend_...)) is named in
#    docs/architecture.md, and every library named there exists.
# Usage: check_layout.sh SOURCE_DIR.  Exit 1 with one line per mismatch.
src=${1:?usage: check_layout.sh SOURCE_DIR}
cd "$src" || exit 2
bad=0
# The folders git tracks (so a build tree or a run's --out folder in the
# source tree is no folder of the project); without git, those on disk.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  folders=$(git ls-files | awk -F/ 'NF > 1 { print $1 } NF > 2 && $1 == "src" { print $1 "/" $2 }' | sort -u)
else
  folders=$( (ls -d */ | grep -v '^build'; ls -d src/*/) | sed 's|/$||')
fi
rows=$(sed -n '/^## Layout/,/^## /p' README.md | grep -o '^| `[^`]*/`' | sed 's/^| `//; s|/`$||')
for f in $folders; do
  printf '%s\n' "$rows" | grep -qx "$f" || { echo "README.md: Layout: no row for folder '$f/'"; bad=1; }
done
for r in $rows; do
  [ -d "$r" ] || { echo "README.md: Layout: row '$r/' names no folder"; bad=1; }
done
libs=$(grep -rhoE 'add_library\(drawbend_[a-z_]+' --include=CMakeLists.txt src | sed 's/add_library(//' | sort -u)
named=$(grep -oE '`drawbend_[a-z_]+`' docs/architecture.md | tr -d '`' | sort -u)
for l in $libs; do
  printf '%s\n' "$named" | grep -qx "$l" || { echo "docs/architecture.md: library '$l' is not named"; bad=1; }
done
for n in $named; do
  printf '%s\n' "$libs" | grep -qx "$n" || { echo "docs/architecture.md: names '$n', which src/ does not build"; bad=1; }
done
[ $bad = 0 ] && echo "layout: $(printf '%s\n' $folders | wc -l) folders and $(printf '%s\n' $libs | wc -l) libraries as documented"
exit $bad
