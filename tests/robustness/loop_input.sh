#!/usr/bin/env bash
# Issue 17: `drawbend loop` on a spreadsheet-like or absurd data file.  Writes a
# small synthetic data set (drawbend synth, 75 rows), turns it into VARIANT, and
# runs `drawbend loop` on it through expect.sh (exit code + message).
# Usage: loop_input.sh DRAWBEND WORKDIR VARIANT WANT_RC
#   speed0      one row with speed_mm_s = 0         -> that row dropped, named
#   force1e308  two rows with outlet_force_N = 1e308 -> those rows dropped, named
#   bom         a UTF-8 byte-order mark first        -> read as usual
#   semicolon   ';' between cells, decimal commas    -> read, and said so
#   nan_inf     'nan' and 'inf' in a numeric column  -> those cells named, column stays numeric
#   out_file    --out names an existing file         -> exit 2 before the analysis
#   out_unwritable  --out /proc (exists, not writable even for root) -> exit 2
set -euo pipefail
drawbend=$1 work=$2 variant=$3 want=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
"$drawbend" synth --effect none --seed 1 --tests-per-pin 2 --rows-per-test 5 --out "$work/synth" >/dev/null
base=$work/synth/data.csv data=$work/data.csv out=$work/out
# Data rows start at line 5 (3 comment lines and the header).
case $variant in
  speed0) awk -F, 'BEGIN{OFS=","} NR==5 {$5="0"} {print}' "$base" >"$data" ;;
  force1e308) awk -F, 'BEGIN{OFS=","} NR==5 || NR==6 {$8="1e308"} {print}' "$base" >"$data" ;;
  bom) { printf '\xef\xbb\xbf'; cat "$base"; } >"$data" ;;
  semicolon) grep -v '^#' "$base" | sed 's/,/;/g; s/\([0-9]\)\.\([0-9]\)/\1,\2/g' >"$data" ;;
  nan_inf) awk -F, 'BEGIN{OFS=","} NR==6 {$13="nan"} NR==9 {$13="inf"} {print}' "$base" >"$data" ;;
  out_file) cp "$base" "$data"; out=$data ;;
  out_unwritable) cp "$base" "$data"; out=/proc ;;
  *) echo "loop_input.sh: unknown variant $variant"; exit 1 ;;
esac
set +e
bash "$here/expect.sh" "$want" "$drawbend" loop "$data" --out "$out" --permutations 19 --figures=
rc=$?
set -e
if [ "$variant" = out_file ] || [ "$variant" = out_unwritable ]; then
  # Refused before the analysis: nothing was read, so nothing was reported on the data.
  if [ -d "$work/out" ]; then echo "FAILED: the analysis ran"; exit 1; fi
fi
exit $rc
