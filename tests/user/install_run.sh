#!/bin/bash
# Issue 55, item 8: `make install` (CMake's install rules) into a temporary
# prefix, then the installed binary on its own data:
#  - bin/drawbend, share/drawbend/data (materials, thesis tables, example
#    decks), share/drawbend/figures (gnuplot scripts) and share/doc/drawbend
#    (README.md, LICENSE, CITATION.cff, docs/) are there;
#  - `drawbend version` prints CMakeLists.txt's project VERSION;
#  - the installed binary finds its data under the prefix, not in this source
#    tree: `drawbend strip-deck` names the prefix's hardening curve and
#    friction table (core/install_paths.hpp);
#  - the installed example deck data/cases/block_slide.toml runs from there
#    (exit 0) and leaves history.csv, result.toml and the ParaView frames.
# Usage: install_run.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -u
build=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 || fail "cmake --install: $(tail -3 "$work/install.log")"
for f in bin/drawbend share/drawbend/data/materials/aa5754_o_rd.csv share/drawbend/data/thesis/table_3_1.csv \
         share/drawbend/data/cases/block_slide.toml share/drawbend/figures/common.gp share/doc/drawbend/README.md \
         share/doc/drawbend/LICENSE share/doc/drawbend/CITATION.cff share/doc/drawbend/docs/architecture.md; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
v=$(sed -n 's/^project(drawbend VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
out=$(env -u DRAWBEND_DATA_DIR "$prefix/bin/drawbend" version) || fail "drawbend version: exit $?"
echo "$out" | grep -q "$v" || fail "drawbend version printed '$out', expected version $v"
deck=$(cd "$work" && env -u DRAWBEND_DATA_DIR "$prefix/bin/drawbend" strip-deck) || fail "strip-deck: exit $?"
echo "$deck" | grep -Eq "hardening = [\"']$prefix/share/drawbend/data/materials/aa5754_o_rd.csv[\"']" ||
  fail "the installed strip-deck does not name the installed hardening curve: $(echo "$deck" | grep hardening)"
echo "$deck" | grep -q "$src/data" && fail "the installed binary names the source tree's data"
env -u DRAWBEND_DATA_DIR OMP_NUM_THREADS=1 "$prefix/bin/drawbend" run "$prefix/share/drawbend/data/cases/block_slide.toml" \
  --out "$work/run" --quiet > "$work/run.log" 2>&1 || fail "installed run: exit $? ($(tail -3 "$work/run.log"))"
for f in history.csv result.toml summary.csv fields.pvd fields_0.vtu; do
  [ -s "$work/run/$f" ] || fail "the installed run left no $f"
done
echo "installed under $prefix: drawbend version $v; block_slide.toml ran from the installed data"
