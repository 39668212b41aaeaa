#!/bin/bash
# Issue 55, item 2: portable inputs (src/io/portable_paths.hpp).
#  1. The round trip loop -> friction model -> run: `drawbend loop` writes
#     friction_model.toml, whose `nodes` is relative to it; `drawbend-deck
#     --friction lp/friction_model.toml --run case` reads it from the current
#     folder (exit 0, and the surface law is in the run).
#  2. The run folder holds its tables (the hardening curve, the friction nodes)
#     beside deck.toml, which names them by file name (no absolute path);
#     moved to another folder, `drawbend run moved/deck.toml` reruns it and
#     gives the same answer (deterministic: same deck, one thread).
#  3. A relative path in an inline --friction table is taken from the current
#     folder, where it was typed.
#  4. A table missing from a moved folder stops with exit 2 and names the deck
#     line that asked for it (deck.toml:LINE: material.hardening / contact.friction.nodes).
#  5. block-deck --out sub/deck.toml copies its Table 6.1 beside the deck, which
#     then runs from any folder.
# Usage: portable_run.sh DRAWBEND DATA_DIR WORK_DIR
set -u
bin=$1 data=$2 work=$3
rm -rf "$work" && mkdir -p "$work/a" "$work/b" && cd "$work/a" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
small=(--pin-diameter 12.7 --back-tension 1500 --element-length 1.5 --through 2 --across 1 --draw-length 12 --threads 1 --frames 1)
answer() { sed -n '/^forces on the/,/^  mu by/p' "$1"; }

"$bin" loop "$data/measured/thesis_drawbend.csv" --out lp --figures '' > loop.out 2>&1 || fail "loop (exit $?)"
"$bin" drawbend-deck "${small[@]}" --friction lp/friction_model.toml --run case > case.out 2>&1 ||
  fail "drawbend-deck --friction lp/friction_model.toml (exit $?): $(tail -3 case.out)"
# (the deck is written by io::to_toml: keys sorted, strings in single or double quotes)
grep -Eq "friction = \{.*law = [\"']surface[\"'], nodes = [\"']friction_surface_nodes.csv[\"']" case/deck.toml ||
  fail "the deck does not name its nodes file by name"
test -s case/friction_surface_nodes.csv || fail "the nodes table was not copied beside the deck"
test -s case/aa5754_o_rd.csv || fail "the hardening curve was not copied beside the deck"
grep -nE "= [\"']/" case/deck.toml && fail "the run folder's deck names an absolute path"
mv case "$work/b/moved"
cd "$work/b" || exit 1
"$bin" run moved/deck.toml --out moved/rerun --threads 1 --quiet > rerun.out 2>&1 || fail "rerun of the moved folder (exit $?)"
diff <(answer "$work/a/case.out") <(answer rerun.out) || fail "the moved folder gives another answer"

cd "$work/a" || exit 1
mkdir -p tables && cp "$data/thesis/table_6_1.csv" tables/t61.csv
"$bin" drawbend-deck "${small[@]}" --friction '{ law = "surface", nodes = "tables/t61.csv" }' --run inl > inl.out 2>&1 ||
  fail "relative inline --friction nodes (exit $?): $(tail -3 inl.out)"
test -s inl/t61.csv || fail "inline table not copied"

cp -r "$work/b/moved" "$work/b/broken" && rm "$work/b/broken/aa5754_o_rd.csv" "$work/b/broken/friction_surface_nodes.csv"
"$bin" run "$work/b/broken/deck.toml" --out "$work/b/broken/x" > broken.out 2>&1
rc=$?
[ $rc -eq 2 ] || fail "a missing table: exit $rc, expected 2"
grep -Eq 'deck.toml:[0-9]+: material.hardening: .*aa5754_o_rd.csv' broken.out || fail "missing hardening not named with its deck line: $(cat broken.out)"
grep -Eq 'deck.toml:[0-9]+: contact.friction.nodes: .*friction_surface_nodes.csv' broken.out ||
  fail "missing nodes not named with its deck line: $(cat broken.out)"

"$bin" block-deck --pressure 40 --speed 70 --out blk/deck.toml > blk.out 2>&1 || fail "block-deck (exit $?)"
test -s blk/table_6_1.csv || fail "block-deck did not copy Table 6.1 beside its deck"
mv blk "$work/b/blk" && cd / && "$bin" run "$work/b/blk/deck.toml" --out "$work/b/blk/run" --quiet > /dev/null 2>&1 ||
  fail "the moved block deck does not run"
echo "portable: loop -> friction model -> run -> moved -> rerun, same answer; missing tables named by deck line"
