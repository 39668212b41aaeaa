#!/bin/bash
# The loop's figures of a data set of more than 5,000 rows stay small and
# readable (src/loop/figure_data.hpp): the lab-style file (50,040 rows) drew
# 10 MB of SVG per residual figure and took 8 s of gnuplot.
#  - each residual figure draws bins (tables/residual_bins.csv, 40 bins or one
#    per value, one per level of a categorical column; bin rows add up to the
#    rows used) and is under 200 kB (the binned figures are about 60 kB; a
#    scatter of 6,900 rows is about 1.4 MB);
#  - each surface's points file holds distinct points whose "rows" add up to
#    the fixed-pin rows its header counts.
# Data: drawbend synth, 20 fixed-pin tests per pin of 100 rows (6,900 rows).
# Usage: loop_large_figures.sh DRAWBEND WORK_DIR
set -u
bin=$1 work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
"$bin" synth --out "$work/sy" --tests-per-pin 20 --rows-per-test 100 --seed 3 > /dev/null || fail "synth: exit $?"
"$bin" loop "$work/sy/data.csv" --out "$work/lp" --threads 1 > "$work/out" 2>&1 || fail "loop: exit $?"
used=$(grep -o '[0-9]* rows read, [0-9]* used' "$work/out" | awk '{print $4}')
[ "${used:-0}" -gt 5000 ] || fail "expected more than 5,000 rows used, found '${used:-}'"
bins="$work/lp/tables/residual_bins.csv"
[ -f "$bins" ] || fail "no tables/residual_bins.csv"
n=0
for svg in "$work"/lp/figures/resid_*.svg; do
  [ -f "$svg" ] || fail "no residual figure"
  size=$(stat -c %s "$svg")
  [ "$size" -lt 200000 ] || fail "$svg is $size bytes (not binned?)"
  n=$((n + 1))
done
sums=$(awk -F, '!/^#/ && $1 ~ /^[0-9]+$/ {s[$1] += $3} END {for (k in s) print s[k]}' "$bins" | sort -u)
[ "$sums" = "$used" ] || fail "bin rows per candidate add up to '$sums', not the $used rows used"
for pts in "$work"/lp/tables/surface_points*.dat; do
  want=$(sed -n '1s/^# p_MPa v_mm_s rows: \([0-9]*\) fixed-pin rows.*/\1/p' "$pts")
  got=$(awk '!/^#/ {s += $3} END {print s + 0}' "$pts")
  [ -n "$want" ] && [ "$want" = "$got" ] || fail "$pts: rows add up to $got, header says '${want:-nothing}'"
  [ "$(grep -vc '^#' "$pts")" -lt "$want" ] || fail "$pts: no two rows share a point"
done
echo "large data set ($used rows): $n residual figures binned, each under 200 kB; surface points distinct, rows add up"
