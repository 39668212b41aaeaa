#!/bin/bash
# Issue 55, item 7: loop.md speaks to an engineer first.
#  - it opens with "## What the data say": a table of mu by lubricant, speed and
#    direction, each "value ± standard error", what else matters and how good
#    the model is; the statistics follow under "# Evidence";
#  - the replicate noise is explained where it is printed, and no bullet of the
#    evidence is printed twice;
#  - each fitted surface is a coloured map (gnuplot `set view map`, pm3d, a
#    colour box) with the fixed-pin rows drawn on it (a points file of "p v
#    rows" lines, each distinct point at the figure's resolution once with its
#    count of fixed-pin rows of that lubricant and direction; a surface
#    without rows in its direction says so in its title).
# On the thesis data set (data/measured/thesis_drawbend.csv), with figures.
# Usage: loop_md.sh DRAWBEND DATA_DIR WORK_DIR
set -u
bin=$1 data=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
"$bin" loop "$data/measured/thesis_drawbend.csv" --out "$work/lp" > "$work/out" 2>&1 || fail "loop: exit $?"
md="$work/lp/loop.md"
[ "$(sed -n 3p "$md")" = "## What the data say" ] || fail "loop.md does not open with 'What the data say': $(head -4 "$md")"
s=$(grep -n '^## What the data say' "$md" | cut -d: -f1); e=$(grep -n '^# Evidence' "$md" | cut -d: -f1)
[ -n "$e" ] && [ "$s" -lt "$e" ] || fail "no '# Evidence' after the summary"
sed -n "${s},${e}p" "$md" | grep -Eq '^\| MP404 [a-z]+ \| [0-9.]+ mm/s \| (RD|TD) \| [0-9.]+ ± [0-9.e-]+ \|' || fail "no mu ± se table in the summary"
sed -n "${s},${e}p" "$md" | grep -q '^\*\*How good the model is:\*\* it predicts a held-out' || fail "no model quality line"
grep -q 'Replicate noise (the scatter of repeated samples within one test' "$md" || fail "replicate noise not explained"
dups=$(grep '^- ' "$md" | sort | uniq -d)
[ -z "$dups" ] || fail "bullets printed twice: $dups"
for gp in "$work"/lp/figures/surface*_RD.gp "$work"/lp/figures/surface*_TD.gp; do
  grep -q '^set view map' "$gp" && grep -q 'with pm3d' "$gp" && grep -q '^set colorbox' "$gp" || fail "$gp is not a coloured map"
  if grep -q 'no fixed-pin rows in this direction' "$gp"; then continue; fi  # e.g. no TD rows of a lubricant
  pts=$(sed -n "s/.*, '\([^']*surface_points[^']*\.dat\)'.*/\1/p" "$gp")
  [ -n "$pts" ] && [ "$(grep -vc '^#' "$pts")" -gt 0 ] || fail "$gp draws no data points ($pts)"
  drawn=$((${drawn:-0} + 1))
done
[ "${drawn:-0}" -ge 2 ] || fail "fewer than two surfaces drawn with their rows"
ls "$work"/lp/figures/surface*.svg > /dev/null 2>&1 || fail "no surface figure"
echo "loop.md: summary first (mu ± se by cell, effects, model quality), evidence after; surfaces as coloured maps with the rows"
