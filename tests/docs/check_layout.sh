#!/usr/bin/env bash
# Keeps the pictures of the house true (CTest docs.layout, label unit):
#  - every top-level folder and every src/ folder has a row in the README's
#    Layout table (| `name/` |), and every row names a folder that exists;
#  - every library of src/ (add_library(drawbend_...)) is named in
#    docs/architecture.md, and every library named there exists;
#  - its Links column names the drawbend libraries of the library's
#    target_link_libraries line, each of them is included by one of its
#    sources, and every folder its sources include belongs to a library it
#    reaches through its links;
#  - the README, the users' front door, stays under 8 kB (8,000 bytes): the
#    developers' guide's limit; diaries belong in docs/performance-log.md.
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
size=$(wc -c < README.md)
[ "$size" -lt 8000 ] || { echo "README.md: $size bytes, the front door's limit is 8,000"; bad=1; }
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
# The Libraries table's Links column, the CMake link lines and the includes
# agree: for each library, the drawbend libraries named in its Links column
# are those its target_link_libraries line names; each of them is included by
# one of its sources (no stale link); and every folder its sources include
# belongs to a library it reaches through its links (no missing link).
table=$(sed -n '/^## Libraries/,/^## /p' docs/architecture.md | grep '^| `drawbend_')
declare -A lib_of  # source folder -> library (short name), from the Sources column
declare -A links_of  # library -> its CMake drawbend links (short names)
for lib in $libs; do
  short=${lib#drawbend_}
  row=$(printf '%s\n' "$table" | grep "^| \`$lib\` ")
  for f in $(printf '%s\n' "$row" | cut -d'|' -f3 | grep -oE '`[a-z_]+/`' | tr -d '`/'); do lib_of[$f]=$short; done
  links_of[$short]=$(grep -rhzoE "target_link_libraries\($lib [^)]*\)" --include=CMakeLists.txt src | tr '\0' '\n' |
                     grep -oE 'drawbend_[a-z_]+' | grep -vx "$lib" | sed 's/drawbend_//' | sort -u | tr '\n' ' ')
done
reach() {  # the libraries reachable from $1 through links (itself included)
  local seen=" $1 " todo="$1" l n
  while [ -n "$todo" ]; do
    set -- $todo; l=$1; shift; todo="$*"
    for n in ${links_of[$l]}; do case "$seen" in *" $n "*) ;; *) seen="$seen$n "; todo="$todo $n";; esac; done
  done
  echo "$seen"
}
for lib in $libs; do
  short=${lib#drawbend_}
  row=$(printf '%s\n' "$table" | grep "^| \`$lib\` ")
  doc=$(printf '%s\n' "$row" | cut -d'|' -f4 | tr ',' '\n' | tr -d ' ' | while read -r w; do
          printf '%s\n' $libs | grep -qx "drawbend_$w" && echo "$w"; done | sort -u | tr '\n' ' ')
  [ "$doc" = "${links_of[$short]}" ] ||
    { echo "docs/architecture.md: $lib links '${doc% }' in the table, '${links_of[$short]% }' in CMake"; bad=1; }
  dirs=""
  for f in "${!lib_of[@]}"; do [ "${lib_of[$f]}" = "$short" ] && dirs="$dirs src/$f"; done
  used=$(grep -rhoE '^#include "[a-z_]+/' $dirs | sed 's/#include "//; s|/$||' | sort -u | while read -r f; do
           [ -n "${lib_of[$f]}" ] && echo "${lib_of[$f]}"; done | sort -u | grep -vx "$short" | tr '\n' ' ')
  for l in ${links_of[$short]}; do
    case " $used " in *" $l "*) ;; *) echo "$lib links drawbend_$l but includes none of its headers"; bad=1;; esac
  done
  r=$(reach "$short")
  for l in $used; do
    case "$r" in *" $l "*) ;; *) echo "$lib includes headers of drawbend_$l but does not link it"; bad=1;; esac
  done
done
[ $bad = 0 ] && echo "layout: $(printf '%s\n' $folders | wc -l) folders and $(printf '%s\n' $libs | wc -l) libraries as documented"
exit $bad
