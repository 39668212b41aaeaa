#!/usr/bin/env bash
# Fourth pass of hostile inputs (2026-12-05, branch robust4): decks that a builder
# wrote and a user then edited by hand (one key changed; the message must name the
# edited line), and the commands the earlier sweeps touched least (calibrate, plan,
# export's every --to, synth, model-loop, cup-deck --base), plus --help and an
# unknown option first on every command.  Each case states the exit code and a
# pattern a message line must match; each failed before the pass (said in its comment).
# Prints one table row per case:  | command | class | exit | first line |
# With --check, exits 1 unless every case matched.
# Usage: edited_decks.sh DRAWBEND WORKDIR [--check]
set -u
drawbend=$1 work=$2 check=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
limit=${EDITED_DECKS_SECONDS:-60}
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
failed=0
. "$here/matrix_lib.sh"  # expect LABEL CLASS RC PATTERN CMD...

echo "| command | class | exit | first line of the message |"
echo "|---|---|---|---|"
# --help exits 0 on every command (version --help: exit 2 before).
for cmd in run drawbend-deck block-deck strip-deck cup-deck loop model-loop synth export calibrate plan help version; do
  expect "$cmd" "--help" 0 "[Uu]sage" "$drawbend" $cmd --help
done
expect help "help version" 0 "^Usage: drawbend version" "$drawbend" help version  # printed the version before
# An unknown option first names the option (loop said "missing DATA.csv", export and calibrate
# printed their usage line).
for cmd in run drawbend-deck block-deck strip-deck cup-deck loop model-loop synth export calibrate plan; do
  expect "$cmd" "unknown option first" 2 "input error: .*'--no-such-option'" "$drawbend" $cmd --no-such-option 1
done
# A flag given a value: --from-thesis=false set the flag (exit 0, the thesis rows written).
expect synth "a flag given =false" 2 "input error: --from-thesis: a flag takes no value .*found 'false'" "$drawbend" synth --from-thesis=false --out y1
expect run "a flag given =1" 2 "input error: --quiet: a flag takes no value" "$drawbend" run "$here/decks/restart_block.toml" --out o1 --quiet=1
# synth --effect none has no hidden law: its --amplitude went into truth.json (exit 0).
expect synth "--amplitude with --effect none" 2 "input error: --amplitude: applies only with an --effect other than none" "$drawbend" synth --effect none --amplitude 5 --out y2

# export: Abaqus's *FRICTION has no part or contact IDs, and Abaqus/Standard writes both
# directions: --parts, --id and --direction were ignored with exit 0.
mkdir -p model
grep -v '^#' "$root/data/thesis/table_6_1.csv" >model/nodes.csv
printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\n' >model/fm.toml
expect export "--parts with --to abaqus" 2 "input error: --parts: applies only with --to lsdyna or openradioss" "$drawbend" export model/fm.toml --to abaqus --parts 1,2 --out e1.inp
expect export "--id with --to abaqus" 2 "input error: --id: applies only with --to lsdyna or openradioss" "$drawbend" export model/fm.toml --to abaqus --id 7 --out e2.inp
# A ragged nodes file: its rows named without the model's friction.nodes line; each direction said to be a
# copy of the other: exported with exit 0 as "TD copied from RD".
printf 'node,mu_RD,mu_TD\n1,0.1,0.1\n2,0.1\n' >model/ragged.csv
printf '[friction]\nlaw = "surface"\nnodes = "ragged.csv"\n' >model/ragged.toml
expect export "ragged nodes file" 2 "input error: model/ragged.toml:3: friction.nodes: .*model/ragged.csv:3: expected 3 cells" "$drawbend" export model/ragged.toml --to lsdyna --out e6.k
printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\n[model]\ntd_copied_from_rd = true\nrd_copied_from_td = true\n' >model/copies.toml
expect export "each direction a copy of the other" 2 "input error: model/copies.toml:6: model.rd_copied_from_td: td_copied_from_rd and rd_copied_from_td are both true" "$drawbend" export model/copies.toml --to abaqus --out e7.inp
expect export "--direction with Abaqus/Standard" 2 "input error: --direction: applies only with --to lsdyna, openradioss or --abaqus explicit" "$drawbend" export model/fm.toml --to abaqus --direction td --out e3.inp
expect export "--direction with Abaqus/Explicit (valid)" 0 "wrote e4.inp" "$drawbend" export model/fm.toml --to abaqus --abaqus explicit --direction td --out e4.inp
expect export "--parts, --id, --direction with LS-DYNA (valid)" 0 "wrote e5.k" "$drawbend" export model/fm.toml --to lsdyna --parts 1,2 --id 3 --direction td --out e5.k

# calibrate --compare with yld2004 of another type: the file named without the key's line.
printf '[material]\nyld2004 = 5\n' >yld_number.toml
expect calibrate "--compare: yld2004 a number" 2 "yld_number.toml:2: material.yld2004: expected a table \\{ a, c1 = \\[9 numbers\\], c2 = \\[9 numbers\\] \\}, found a number" \
  "$drawbend" calibrate "$root/data/materials/aa6016_t4_esaform2021.csv" --out c1 --compare yld_number.toml
# An --out file name that ends in '/': the folder was made (with block-deck's tables copied into it),
# then "cannot replace the file (Not a directory)" or "it is a folder".
expect export "--out ending in /" 2 "input error: --out 'ex_dir/': expected a file name, found a folder's" "$drawbend" export model/fm.toml --to lsdyna --out ex_dir/
expect block-deck "--out ending in /" 2 "input error: --out 'bd_dir/': expected a file name, found a folder's" "$drawbend" block-deck --out bd_dir/
for d in ex_dir bd_dir; do
  if [ -n "$check" ] && [ -e "$d" ]; then echo "FAILED: --out $d/ left the folder $d behind"; failed=1; fi
done
# plan: a run's summary.csv with wall_time twice (the last was taken without a word), or a
# folder named summary.csv (skipped without a word).
deck=$here/decks/restart_block.toml
mkdir -p runs2/a runs3/a/summary.csv
cp "$deck" runs2/a/deck.toml
cp "$deck" runs3/a/deck.toml
printf 'quantity,value\nwall_time,5\nwall_time,6\n' >runs2/a/summary.csv
expect plan "wall_time twice" 0 "warning: runs2/a/summary.csv:3: column 'quantity': wall_time given twice \\(also on line 2\\)" "$drawbend" plan runs2
expect plan "a folder as summary.csv" 0 "warning: runs3/a/summary.csv: expected a run's summary file, found no regular file" "$drawbend" plan runs3

# Builders' decks edited by hand: the message names the edited line.
"$drawbend" drawbend-deck >db.toml 2>/dev/null
"$drawbend" cup-deck >cup.toml 2>/dev/null
"$drawbend" strip-deck --out strip/strip.toml >/dev/null 2>&1
line_of() { grep -n -m1 -- "$2" "$1" | cut -d: -f1; }  # FILE PATTERN: the line of the edit
# A strain point far outside the sheet: the nearest element's strain written under its name, exit 0.
sed '0,/point = \[ -9.395685383, 3.175, 6.48 \]/s//point = [ 1000.0, 3.175, 6.48 ]/' db.toml >db_point.toml
n=$(line_of db_point.toml 'point = \[ 1000.0')
expect run "strain point outside the sheet" 2 "db_point.toml:$n: output.history.point: expected a point in the sheet, found \\[1000, 3.175, 6.48\\]" "$drawbend" run db_point.toml --out o2 --quiet
expect plan "strain point outside the sheet" 2 "db_point.toml:$n: output.history.point: expected a point in the sheet" "$drawbend" plan db_point.toml
# The reduction's holder, step and tool: no line ("output.reduce.step: no step named"), and an
# unknown holder passed plan and cup-deck --base and stopped run.
sed 's/^    holder = .lower_die./    holder = "nobody"/' cup.toml >cup_holder.toml
n=$(line_of cup_holder.toml 'holder = "nobody"')
expect plan "unknown reduce.holder" 2 "cup_holder.toml:$n: output.reduce.holder: expected the name of a \\[\\[tool\\]\\] \\(punch, lower_die, upper_die\\), found 'nobody'" "$drawbend" plan cup_holder.toml
expect cup-deck "--base with an unknown reduce.holder" 2 "input error: --base: cup_holder.toml:$n: output.reduce.holder" "$drawbend" cup-deck --base cup_holder.toml
sed 's/^    step = .draw./    step = "nostep"/' cup.toml >cup_step.toml
n=$(line_of cup_step.toml 'step = "nostep"')
expect run "unknown reduce.step" 2 "cup_step.toml:$n: output.reduce.step: expected the name of a \\[\\[step\\]\\] \\(clamp, draw\\), found 'nostep'" "$drawbend" run cup_step.toml --out o3 --quiet
# cup-deck --base: a bad value of the base deck named as an option of the deck cup-deck writes.
sed 's/^mass = .*/mass = 0.0/' cup.toml >cup_mass.toml
n=$(line_of cup_mass.toml '^mass = 0.0')
expect cup-deck "--base with a tool mass 0" 2 "input error: --base: cup_mass.toml:$n: tool 'lower_die'.mass: expected a number > 0, found 0" "$drawbend" cup-deck --base cup_mass.toml
# A contact penalty of 1e300: exit 3 (an element inverted) without a line.
sed '0,/^penalty = 0.1/s//penalty = 1e300/' db.toml >db_penalty.toml
n=$(line_of db_penalty.toml '^penalty = 1e300')
expect run "contact penalty 1e300" 2 "db_penalty.toml:$n: contact.penalty: expected a penalty scale in \\(0, 1e\\+06\\]" "$drawbend" run db_penalty.toml --out o4 --quiet
# A deck's hardening file or Stribeck table with the wrong columns: the file named, not the deck's line.
sed "s/^hardening = .*/hardening = 'table_3_1.csv'/" strip/strip.toml >strip/hard.toml
n=$(line_of strip/hard.toml "^hardening = 'table_3_1.csv'")
expect run "deck's hardening file of another table" 2 "hard.toml:$n: material.hardening: .*table_3_1.csv: missing required column 'plastic_strain'" "$drawbend" run strip/hard.toml --out o5 --quiet
sed "s/table = 'table_3_1.csv'/table = 'aa5754_o_rd.csv'/" strip/strip.toml >strip/table.toml
n=$(line_of strip/table.toml "table = 'aa5754_o_rd.csv'")
expect plan "deck's Stribeck table of another table" 2 "table.toml:$n: contact.friction.table: .*aa5754_o_rd.csv: missing required column 'parameter'" "$drawbend" plan strip/table.toml
# A Stribeck parameter beside the table that gives them all: ignored with exit 0.
sed "s/table = 'table_3_1.csv'/table = 'table_3_1.csv', mu_BL = 0.1/" strip/strip.toml >strip/both.toml
n=$(line_of strip/both.toml "mu_BL = 0.1")
expect run "Stribeck table and a parameter" 2 "both.toml:$n: contact.friction.mu_BL: not used with 'table'" "$drawbend" run strip/both.toml --out o6 --quiet
# A tool surface's bounds reversed: "empty bounds" without which, and a history's key said twice
# ("step 'bend'.force.magnitude: step 'bend'.force.magnitude: history times must increase").
sed '0,/angle_max = 1.5707963/s//angle_max = -1.0/' cup.toml >cup_angle.toml
expect plan "tool surface angles reversed" 2 "cup_angle.toml:[0-9]+: tool 'punch' surface: empty bounds: expected angle_min < angle_max, found angle_min = 0 and angle_max = -1" "$drawbend" plan cup_angle.toml
sed 's/magnitude = { t = \[ 0.0, 0.075 \]/magnitude = { t = [ 0.075, 0.0 ]/' db.toml >db_times.toml
n=$(line_of db_times.toml 't = \[ 0.075, 0.0 \]')
expect run "load history times reversed" 2 "db_times.toml:$n: step 'bend'.force.magnitude: history times must increase" "$drawbend" run db_times.toml --out o7 --quiet
# drawbend-deck --hardening with the wrong columns: the file named without its option.
printf 'a,b\n1,2\n' >cols.csv
expect drawbend-deck "--hardening with the wrong columns" 2 "input error: --hardening: .*cols.csv: missing required column 'plastic_strain'" "$drawbend" drawbend-deck --hardening cols.csv
# model-loop --hardening as a relative path: the FE decks in OUT/runs/*/ named it relative to
# their own folder, and every run stopped with exit 2 ("cannot open 'curve.csv'"). The command
# executor reads each deck with `plan` (no FE run), so the case ends at the missing summary.csv.
grep -v '^#' "$root/data/measured/model_loop_points.csv" >points.csv
grep -v '^#' "$root/data/materials/aa5754_o_rd.csv" >curve.csv
expect model-loop "--hardening as a relative path" 3 "the executor command ended with exit 0 but left no summary.csv" \
  "$drawbend" model-loop points.csv --out m1 --hardening curve.csv --executor "command:$drawbend plan {deck} > {dir}/plan.log 2>&1"
# The draw step renamed: the run ended with exit 0 and result.toml without F_X, F_Y and mu, and
# nothing said why (noticed in the fourth pass, fixed 2026-12-05).  A short deck (2 mm of draw).
"$drawbend" drawbend-deck --element-length 1.5 --through 2 --draw-length 2 2>/dev/null |
  sed "s/^name = 'draw'\$/name = 'pull'/" >db_pull.toml
expect run "draw step renamed" 0 "warning: db_pull.toml:[0-9]+: step: .*no step named 'draw' \\(its steps: 'bend', 'tension', 'pull'\\)" \
  "$drawbend" run db_pull.toml --out o8 --quiet --threads 1
exit $failed
