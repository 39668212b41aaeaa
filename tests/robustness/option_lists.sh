#!/usr/bin/env bash
# Every list-valued option of every command (drawbend COMMAND --help: export's
# --parts, --rd-vector and --speed-band, loop's --export and --parts,
# model-loop's --candidates and the '/' lists inside a candidate): an empty
# item (a leading, doubled or trailing separator), white space, an item given
# twice where the list is a set, NaN, infinity and hexadecimal, each refused
# with exit 2 naming the option and the item (core/list_option.hpp); and the
# valid lists still accepted.  Before 2026-12-04 `--parts 1,2,` and
# `--parts '1, 2'` were taken, `--export lsdyna,lsdyna` wrote the file twice
# and `--candidates voce,voce` or `split:0.3/0.3` ran a candidate twice.
# Prints one table row per case:  | command | case | exit | first line |
# With --check, exits 1 unless every case matched.
# Usage: option_lists.sh DRAWBEND WORKDIR [--check]
set -u
drawbend=$1 work=$2 check=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
limit=${OPTION_LISTS_SECONDS:-30}
rm -rf "$work"
mkdir -p "$work/model"
cd "$work" || exit 1
failed=0
. "$here/matrix_lib.sh"

grep -v '^#' "$root/data/thesis/table_6_1.csv" >model/nodes.csv
printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\np_min = 0.0\np_max = 80.0\nv_min = 6.35\nv_max = 101.6\n' >model/good.toml
points=$root/data/measured/model_loop_points.csv
"$drawbend" synth --effect none --seed 1 --tests-per-pin 2 --rows-per-test 5 --out synth >/dev/null 2>&1

echo "| command | case | exit | first line of the message |"
echo "|---|---|---|---|"
# export's three lists: OPTION VALUE RC PATTERN
while IFS='|' read -r opt value rc pattern; do
  extra=
  [ "$opt" != parts ] && extra="--parts 1,2"
  expect export "--$opt '$value'" "$rc" "$pattern" "$drawbend" export model/good.toml --to openradioss $extra --$opt "$value" --out e.rad
done <<'LIST'
parts|1,2,|2|--parts: item 3 of '1,2,' is empty \(a trailing ','\)
parts|,1,2|2|--parts: item 1 of ',1,2' is empty \(a leading ','\)
parts|1,,2|2|--parts: item 2 of '1,,2' is empty \(a doubled ','\)
parts|1, 2|2|--parts: item 2 ' 2' of '1, 2' holds white space
parts|1,nan|2|--parts: item 2 'nan' of '1,nan' is not a finite number
parts|0x1,2|2|--parts: item 1 '0x1' of '0x1,2' is not a finite number
parts|1,1|2|--parts: the sheet and the tool need different part IDs
parts|3,4|0|wrote e.rad
rd-vector|1,0,0,|2|--rd-vector: item 4 of '1,0,0,' is empty \(a trailing ','\)
rd-vector|1,0,inf|2|--rd-vector: item 3 'inf' of '1,0,inf' is not a finite number
rd-vector|1,1,0|0|wrote e.rad
speed-band|10,20,|2|--speed-band: item 3 of '10,20,' is empty
speed-band|10 ,20|2|--speed-band: item 1 '10 ' of '10 ,20' holds white space
speed-band|10,10|2|--speed-band: expected 0 < MIN < MAX
LIST
# loop's --export and --parts (checked before the analysis).
for v in "lsdyna,lsdyna|'lsdyna' is given twice in 'lsdyna,lsdyna' \\(items 1 and 2\\)" \
         "lsdyna,|item 2 of 'lsdyna,' is empty \\(a trailing ','\\)" \
         "lsdyna, abaqus|item 2 ' abaqus' of 'lsdyna, abaqus' holds white space" \
         "|expected a list separated by ',', found an empty value"; do
  expect loop "--export '${v%%|*}'" 2 "input error: --export: ${v#*|}" "$drawbend" loop synth/data.csv --out l1 --figures= --export "${v%%|*}"
done
expect loop "--parts '1,2,'" 2 "input error: --parts: item 3 of '1,2,' is empty" "$drawbend" loop synth/data.csv --out l2 --figures= --parts 1,2,
# model-loop's candidates (checked before any FE run; a bad executor stops a valid list there).
while IFS='|' read -r value pattern; do
  expect model-loop "--candidates '$value'" 2 "$pattern" "$drawbend" model-loop "$points" --out m1 --candidates "$value" --executor command:none
done <<'LIST'
split:0.3/0.6,|--candidates: item 2 of 'split:0.3/0.6,' is empty \(a trailing ','\)
voce,,hill48|--candidates: item 2 of 'voce,,hill48' is empty \(a doubled ','\)
voce, hill48|--candidates: item 2 ' hill48' of 'voce, hill48' holds white space
offset,offset|--candidates: 'offset' is given twice in 'offset,offset'
split:0.3/0.3|--candidates: candidate 'split:0.3/0.3': the value 0.3 is given twice in '0.3/0.3'
split:0.3//0.6|--candidates: candidate 'split:0.3//0.6': item 2 of '0.3//0.6' is empty \(a doubled '/'\)
chaboche:30/60@|--candidates: candidate 'chaboche:30/60@': expected a list separated by '/', found an empty value
split:0x1|--candidates: candidate 'split:0x1': item 1 '0x1' of '0x1' is not a finite number
split:0.3/0.6,voce|--executor: a command executor needs a template
LIST
exit $failed
