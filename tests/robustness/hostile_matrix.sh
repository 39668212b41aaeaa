#!/usr/bin/env bash
# Issue 53: every command as a careless user and a hostile script would call
# it, one row per class of input (the classes that the option and entry-point
# matrices do not cover): an option given twice, an option where a value
# belongs, units written into a value, Windows line endings, duplicated TOML
# keys and tables, wrong types and unknown keys in a friction model, absurd
# values in the CSV tables (a flow stress of 1e308 MPa, a stress ratio of
# 1e300, a wall time of 1e-300 s), unwritable output folders, and a builder's
# --friction error that must name the option or the user's file.  Each case
# states the exit code and a pattern the first message line must match.
# Prints one table row per case:  | command | class | exit | first line |
# With --check, exits 1 unless every case matched.
# Usage: hostile_matrix.sh DRAWBEND WORKDIR [--check]
set -u
drawbend=$1 work=$2 check=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
limit=${HOSTILE_MATRIX_SECONDS:-60}
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
deck=$here/decks/restart_block.toml
failed=0
. "$here/matrix_lib.sh"  # expect LABEL CLASS RC PATTERN CMD...

# The inputs.
sed 's/$/\r/' "$deck" >deck_crlf.toml
{ cat "$deck"; printf '\n[case]\nname = "again"\n'; } >dup_table.toml
awk '/^duration = / && !d { print; print "duration = 1.0"; d = 1; next } { print }' "$deck" >dup_key.toml
sed '0,/^E = .*/s//E = "70000 MPa"/' "$deck" >units.toml
printf 'plastic_strain,true_stress_MPa\n0,1e300\n0.1,1e308\n' >curve_huge.csv
printf 'plastic_strain,true_stress_MPa\r\n0,100\r\n0.1,150\r\n' >curve_crlf.csv
printf 'node,mu_RD,mu_TD\n1,0.1,0.1\n' >nodes_short.csv
mkdir -p model
grep -v '^#' "$root/data/thesis/table_6_1.csv" >model/nodes.csv
fm() { printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\n%b' "$2" >"model/$1.toml"; }
fm units 'p_min = "0 MPa"\n'
fm unknown 'colour = 1\n'
fm reversed 'p_min = 80.0\np_max = 0.0\n'
fm huge 'v_max = 1e300\n'
fm good 'p_min = 0.0\np_max = 80.0\nv_min = 6.35\nv_max = 101.6\n'
sed 's/$/\r/' model/good.toml >model/crlf.toml
printf 'test,angle_deg,stress_ratio,r_value\r\nuniaxial,0,1.0,0.7\r\nuniaxial,45,0.98,0.6\r\nuniaxial,90,1.01,0.8\r\nbalanced_biaxial,,1.0,\r\n' >cal_crlf.csv
printf 'test,angle_deg,stress_ratio,r_value\nuniaxial,0,1.0,0.7\nuniaxial,45,1e300,0.6\nuniaxial,90,1.01,0.8\n' >cal_huge.csv
printf 'test,angle_deg,stress_ratio,r_value\nuniaxial,0,1.0,0.7\n' >cal_rd_only.csv
mkdir -p runs/a
cp "$deck" runs/a/deck.toml
printf 'quantity,value\nwall_time,1e-300\n' >runs/a/summary.csv
printf 'pin_diameter_mm,back_tension_N,bending_force_N\r\n12.7,1000,200\r\n25.4,1000,150\r\n' >ml_crlf.csv

echo "| command | class | exit | first line of the message |"
echo "|---|---|---|---|"
# Command-line classes, on every command that takes options.
# COMMAND, an option given twice (two values), and a string option left without its value.
while read -r cmd twice v1 v2 bare; do
  extra=
  [ "$cmd" = plan ] && extra=$deck
  expect "$cmd" "option twice" 2 "option '--$twice' given twice" "$drawbend" $cmd $extra --$twice $v1 --$twice $v2
  expect "$cmd" "option as a value" 2 "option '--$bare' needs a value, found the option '--$twice'" "$drawbend" $cmd $extra --$bare --$twice $v1
done <<'LIST'
drawbend-deck threads 1 2 name
block-deck threads 1 2 name
strip-deck threads 1 2 hardening
cup-deck refine 1 2 base
synth seed 1 2 out
plan nodes 1 2 nodes
LIST
expect run "option twice" 2 "--out' given twice" "$drawbend" run "$deck" --out o1 --out o2 --quiet
expect run "option as a value" 2 "--out' needs a value, found the option '--quiet'" "$drawbend" run "$deck" --out --quiet
expect run "option before the deck" 2 "expected CASE.toml first, found the option '--out'" "$drawbend" run --out o3 "$deck"
expect loop "option twice" 2 "--permutations' given twice" "$drawbend" loop "$root/data/measured/thesis_drawbend.csv" --out l1 --permutations 19 --permutations 99
expect export "option twice" 2 "--to' given twice" "$drawbend" export model/good.toml --to lsdyna --to abaqus --out e.k
expect calibrate "option twice" 2 "--a' given twice" "$drawbend" calibrate cal_crlf.csv --out c1 --a 8 --a 6
expect model-loop "option twice" 2 "--out' given twice" "$drawbend" model-loop ml_crlf.csv --out m1 --out m2
# Vanishing dimensions (1e-300: a unit error; a pin or a die radius of 1e-300 mm was written with exit 0).
while read -r cmd opt; do
  pre= out=
  case $cmd in block-deck | strip-deck) out="--out tiny.toml" ;; model-loop) pre=ml_crlf.csv out="--out m4" ;; esac
  expect "$cmd" "$opt 1e-300" 2 "--$opt: expected (0 or )?a value in \\[0.0*1, " "$drawbend" $cmd $pre --$opt 1e-300 $out
done <<'LIST'
drawbend-deck pin-diameter
drawbend-deck thickness
drawbend-deck speed
block-deck size
block-deck speed
block-deck pressure
strip-deck thickness
strip-deck speed
cup-deck die-radius
cup-deck stroke
model-loop thickness
LIST
# An empty file wherever a file is read: exit 2 naming it.
: >empty.toml
: >empty.csv
mkdir -p emodel
printf '[friction]\nlaw = "surface"\nnodes = "empty.csv"\n' >emodel/friction_model.toml
: >emodel/empty.csv
expect run "empty deck" 2 "empty.toml" "$drawbend" run empty.toml --out o11 --quiet
expect run "empty --restart" 2 "empty.csv" "$drawbend" run "$deck" --restart empty.csv --out o12 --quiet
expect drawbend-deck "empty --material" 2 "empty.toml" "$drawbend" drawbend-deck --material empty.toml
expect drawbend-deck "empty --hardening" 2 "empty.csv" "$drawbend" drawbend-deck --hardening empty.csv
expect block-deck "empty --surface-nodes" 2 "empty.csv" "$drawbend" block-deck --surface-nodes empty.csv --out e.toml
expect strip-deck "empty --stribeck-table" 2 "empty.csv" "$drawbend" strip-deck --stribeck-table empty.csv --out e.toml
expect cup-deck "empty --base" 2 "empty.toml" "$drawbend" cup-deck --base empty.toml
expect loop "empty data" 2 "empty.csv" "$drawbend" loop empty.csv --out l2 --figures=
expect model-loop "empty data" 2 "empty.csv" "$drawbend" model-loop empty.csv --out m5
expect export "empty model" 2 "empty.toml" "$drawbend" export empty.toml --to lsdyna --out e6.k
expect export "empty nodes file" 2 "empty.csv" "$drawbend" export emodel/friction_model.toml --to lsdyna --out e7.k
expect calibrate "empty tests" 2 "empty.csv" "$drawbend" calibrate empty.csv --out c4
expect calibrate "empty --compare" 2 "empty.toml" "$drawbend" calibrate cal_crlf.csv --out c5 --compare empty.toml
expect plan "empty deck" 2 "empty.toml" "$drawbend" plan empty.toml
# Units written into a value (an option, a deck key, a table cell).
expect drawbend-deck "units in an option" 2 "--pin-diameter: expected a number, found '12.7 mm'" "$drawbend" drawbend-deck --pin-diameter "12.7 mm"
expect run "units in a deck value" 2 "units.toml:[0-9]+: material.E: expected a finite number, found the string \"70000 MPa\"" "$drawbend" run units.toml --out o4 --quiet
expect export "units in a model value" 2 "units.toml:4: friction.p_min: expected a finite number, found the string \"0 MPa\"" "$drawbend" export model/units.toml --to lsdyna --out e1.k
# Duplicated keys and tables.
expect run "duplicated key" 2 "dup_key.toml:[0-9]+:[0-9]+: TOML syntax error: .*cannot redefine existing .*'duration'" "$drawbend" run dup_key.toml --out o5 --quiet
expect run "duplicated table" 2 "dup_table.toml:[0-9]+:[0-9]+: TOML syntax error: .*cannot redefine existing table 'case'" "$drawbend" run dup_table.toml --out o6 --quiet
expect plan "duplicated key" 2 "dup_key.toml:[0-9]+:[0-9]+: TOML syntax error" "$drawbend" plan dup_key.toml
# Names given twice in a deck (steps name messages, history names are CSV columns).
sed 's/^name = "slide"/name = "press"/' "$deck" >dup_step.toml
expect run "step name twice" 2 "dup_step.toml:[0-9]+: step 'press'.name: expected a unique step name, found it twice" "$drawbend" run dup_step.toml --out o9 --quiet
sed 's/kind = "tool_force", target = "floor", component = 2/kind = "tool_force", target = "floor", component = 2 }, { name = "friction_N", kind = "tool_force", target = "floor", component = 1/' "$deck" >dup_history.toml
expect run "history column twice" 2 "dup_history.toml:[0-9]+: output.history.name: expected a unique column name, found 'friction_N' twice" "$drawbend" run dup_history.toml --out o10 --quiet
# Unknown keys and impossible domains in export's friction model (a silent default before).
expect export "unknown key" 2 "unknown.toml:4: friction.colour: unknown key" "$drawbend" export model/unknown.toml --to lsdyna --out e2.k
expect export "reversed domain" 2 "reversed.toml:1: friction: expected 0 <= p_min < p_max <= 10000 \\[MPa\\], found 80 and 0" "$drawbend" export model/reversed.toml --to lsdyna --out e3.k
expect export "huge domain" 2 "huge.toml:1: friction: expected 0 < v_min < v_max <= 10000 \\[mm/s\\], found 6.35 and 1e\\+300" "$drawbend" export model/huge.toml --to openradioss --parts 1,2 --out e4.rad
# Windows line endings: valid, accepted.
expect run "CRLF deck" 0 "summary: [0-9]+ cycles" "$drawbend" run deck_crlf.toml --out o7 --quiet
expect export "CRLF model" 0 "wrote e5.k" "$drawbend" export model/crlf.toml --to lsdyna --out e5.k
expect calibrate "CRLF tests" 0 "wrote c2/material.toml" "$drawbend" calibrate cal_crlf.csv --out c2
expect drawbend-deck "CRLF hardening" 0 "back_tension in this deck" "$drawbend" drawbend-deck --hardening curve_crlf.csv
expect plan "CRLF deck" 0 "1 cases" "$drawbend" plan deck_crlf.toml
# Absurd numbers in tables: exit 2 naming file:line (exit 0 before).
expect drawbend-deck "flow stress 1e308 MPa" 2 "curve_huge.csv:2: true stress 1e\\+300 MPa is above 100000 MPa" "$drawbend" drawbend-deck --hardening curve_huge.csv
expect calibrate "stress ratio 1e300" 2 "cal_huge.csv:3: column 'stress_ratio': expected a yield-stress ratio to RD in \\[0.1, 10\\]" "$drawbend" calibrate cal_huge.csv --out c3
# Too few tests for the fit: a zero residual over arbitrary anisotropy, exit 0, before.
expect calibrate "RD test only" 2 "missing: sigma\\(45\\) r\\(45\\)" "$drawbend" calibrate cal_rd_only.csv --out c7
expect calibrate "r-values weighted 0" 2 "weights of the uniaxial stress ratios and r-values must be > 0" "$drawbend" calibrate cal_crlf.csv --out c8 --w-r 0
printf 'pin_diameter_mm,back_tension_N,bending_force_N\n1e300,1000,200\n25.4,1000,150\n' >ml_pin.csv
printf 'pin_diameter_mm,back_tension_N,bending_force_N\n25.4,1000,150\n12.7,1000,300\n25.4,1000,150\n' >ml_dup.csv
expect model-loop "a duplicated point" 2 "ml_dup.csv:4: duplicate of .*ml_dup.csv:2 \\(the same pin, back tension and bending force\\)" "$drawbend" model-loop ml_dup.csv --out m7
expect model-loop "pin diameter 1e300 mm" 2 "ml_pin.csv:2: column 'pin_diameter_mm': expected a pin diameter up to 1000 mm" "$drawbend" model-loop ml_pin.csv --out m3
expect plan "wall time 1e-300 s" 0 "warning: .*summary.csv: wall_time 1e-300 s is not a run's wall time" "$drawbend" plan runs
# Unwritable output folders: exit 2 before any work (calibrate: exit 3, a file-system error, before).
expect drawbend-deck "unwritable --run" 2 "--run '/proc/x': cannot create the folder" "$drawbend" drawbend-deck --run /proc/x
touch a_file
expect drawbend-deck "a file as --run" 2 "--run 'a_file': cannot be a folder, because 'a_file' is a file" "$drawbend" drawbend-deck --run a_file
expect calibrate "unwritable --out" 2 "--out '/proc/x': cannot create the folder" "$drawbend" calibrate cal_crlf.csv --out /proc/x
expect export "unwritable --out" 2 "--out.*/proc" "$drawbend" export model/good.toml --to lsdyna --out /proc/e.k
# A builder's --friction: the option or the user's file named, not the generated deck's line.
expect block-deck "--friction missing nodes file" 2 "--friction:1: friction.nodes: cannot open 'nope.csv'" "$drawbend" block-deck --friction '{ law = "surface", nodes = "nope.csv" }' --out b1.toml
expect block-deck "--friction short nodes file" 2 "--friction:1: friction.nodes: .*nodes_short.csv: nodal friction values: expected 9 rows" "$drawbend" block-deck --friction '{ law = "surface", nodes = "nodes_short.csv" }' --out b2.toml
expect block-deck "--surface-nodes short file" 2 "--surface-nodes: .*nodes_short.csv: nodal friction values: expected 9 rows" "$drawbend" block-deck --surface-nodes nodes_short.csv --out b3.toml
expect block-deck "--friction negative mu" 2 "--friction:1: friction.mu: expected a friction coefficient >= 0, found -1" "$drawbend" block-deck --friction '{ law = "coulomb", mu = -1 }' --out b4.toml
expect block-deck "--friction a model file" 2 "reversed.toml:1: friction: expected 0 <= p_min < p_max" "$drawbend" block-deck --friction model/reversed.toml --out b5.toml
expect cup-deck "--friction missing nodes file" 2 "--friction 'nope.csv': cannot open file for reading" "$drawbend" cup-deck --friction nope.csv
expect cup-deck "--friction short nodes file" 2 "--friction: nodes_short.csv: nodal friction values: expected 9 rows" "$drawbend" cup-deck --friction nodes_short.csv
expect strip-deck "--friction wrong type" 2 "--friction:1: friction.mu: expected a finite number, found the string \"0.1\"" "$drawbend" strip-deck --friction '{ law = "coulomb", mu = "0.1" }' --out s1.toml
expect drawbend-deck "--friction wrong type" 2 "--friction:1: friction.mu: expected a finite number" "$drawbend" drawbend-deck --friction '{ law = "coulomb", mu = "0.1" }'
# A builder's deck refused as a whole (its cost, its tool masses, the base deck's radii): the
# options named, not a line of a deck the user never saw (before 2026-12-04:
# "drawbend-deck.toml:26: numerics.mass_scaling", "block-deck.toml:18: mesh", a cup deck's
# "cup_draw.toml:23: numerics.target_dt" for --material, and strip-deck --time-step 1e-12
# wrote a deck whose die `run` then refused without a line).
expect drawbend-deck "cost of --speed 0.001" 2 "input error: --speed or --mass-scaling \\(numerics.mass_scaling of the deck drawbend-deck writes\\): mass scaling multiplies" "$drawbend" drawbend-deck --speed 0.001
expect drawbend-deck "cost of --speed 0.001 with --run" 2 "input error: --speed or --mass-scaling \\(numerics.mass_scaling of the deck" "$drawbend" drawbend-deck --speed 0.001 --run r_slow
expect block-deck "memory of --size and --elements" 2 "input error: --size or --elements \\(mesh of the deck block-deck writes\\): the mesh of" "$drawbend" block-deck --size 1000 --elements 200 --out b10.toml
expect cup-deck "mass scaling of a stiff --material" 2 "  --cycles, --stroke, --speed or --material \\(numerics.target_dt of the deck cup-deck writes\\)" "$drawbend" cup-deck --material '{ type = "j2", E = 1e9 }'
expect cup-deck "--punch-radius beyond the punch wall" 2 "input error: --punch-radius: punch radius 50 mm must lie in \\(0, 24\\)" "$drawbend" cup-deck --punch-radius 50
expect strip-deck "a die too light for --time-step" 2 "input error: --die-mass or --time-step \\(tool 'die'.mass of the deck strip-deck writes\\): 8.446e-19 t is too small" "$drawbend" strip-deck --time-step 1e-12 --out s6.toml
"$drawbend" strip-deck --out s7.toml >/dev/null 2>&1
sed -i 's/^mass = .*/mass = 1e-20/' s7.toml
expect run "a force-driven tool too light" 2 "input error: .*s7.toml:[0-9]+: tool 'die'.mass: 1e-20 t is too small for the stable time step" "$drawbend" run s7.toml --out o17 --quiet
# One element through the thickness of a bending case: a warning of the deck
# (every builder and `run`), not only of drawbend-deck's option.
expect drawbend-deck "one element through the thickness" 0 "warning: --element-length, --across, --through, --width or --draw-length \\(mesh of the deck drawbend-deck writes\\): one element through the thickness under the face set 'zmin', and the sheet bends over the curved surface of tool 'pin'" \
  "$drawbend" drawbend-deck --through 1
"$drawbend" drawbend-deck --through 1 --element-length 2 --draw-length 2 >one_layer.toml 2>/dev/null
expect run "one element through the thickness" 0 "warning: .*one_layer.toml:[0-9]+: mesh: one element through the thickness" \
  "$drawbend" run one_layer.toml --out o8 --quiet --checkpoint-every 1 --halt-after-cycles 1
# An option the chosen mode does not read: refused, naming it (synth's --class
# with the library generator, --data without --from-thesis, loop's --parts with
# --export none were accepted and ignored with exit 0 before).
expect synth "option of another generator" 2 "--class: applies only with --generator blind or wild" "$drawbend" synth --class word --out y1
expect synth "option of another generator" 2 "--effect: applies only with --generator library" "$drawbend" synth --generator blind --effect speed --out y2
expect synth "--noise alone too large" 2 "input error: --noise 1e\\+06 \\(with --effect none's default amplitude\\): an outlet force of" "$drawbend" synth --noise 1e6 --out y5
expect synth "option without --from-thesis" 2 "--data: applies only with --from-thesis" "$drawbend" synth --data word --out y3
expect synth "option with --from-thesis" 2 "--seed: applies only without --from-thesis" "$drawbend" synth --from-thesis --seed 3 --out y4
expect loop "option without exports" 2 "--parts: applies only with exports" "$drawbend" loop "$root/data/measured/thesis_drawbend.csv" --out l3 --export none --parts 3,4
expect export "option of another format" 2 "--rd-vector: applies only with --to openradioss" "$drawbend" export model/good.toml --to lsdyna --rd-vector 0,1,0 --out e8.k
expect export "option of another format" 2 "--abaqus: applies only with --to abaqus" "$drawbend" export model/good.toml --to lsdyna --abaqus explicit --out e9.k
expect loop "--cv test where a pin has one rotating-pin test" 2 "input error: --cv test: the rotating-pin rows of the 12.7 mm pin are one test only" "$drawbend" loop "$root/data/measured/thesis_drawbend.csv" --out l11 --cv test --figures= --export none
expect loop "unknown name" 2 "input error: --cv: expected auto, test or bt-block, found 'word'" "$drawbend" loop "$root/data/measured/thesis_drawbend.csv" --out l4 --cv word
# A binary file where CSV text belongs (a program's first 4 kB; an .xlsx is a zip): named as binary, not
# as UTF-16 (NUL bytes between the characters of UTF-16 text sit on every other byte).
head -c 4096 "$drawbend" >binary.csv
expect loop "binary file as data" 2 "binary.csv: the file holds NUL bytes \\(a binary file" "$drawbend" loop binary.csv --out l5
expect calibrate "binary file as tests" 2 "binary.csv: the file holds NUL bytes \\(a binary file" "$drawbend" calibrate binary.csv --out c6
# A value too large for its type (1e300 cycles was cast to a long).
expect run "--checkpoint-every 1e300" 2 "--checkpoint-every: expected a whole number of cycles .*found '1e300'" "$drawbend" run "$deck" --out o13 --quiet --checkpoint-every 1e300
# help, version and --help take nothing more (version extra was exit 0).
expect drawbend "version with an argument" 2 "drawbend version: unexpected argument 'extra'" "$drawbend" version extra
expect drawbend "--help with an argument" 2 "drawbend --help: unexpected argument 'extra'" "$drawbend" --help extra
expect drawbend "help help" 0 "^usage: drawbend COMMAND" "$drawbend" help help
expect drawbend "help CMD with an argument" 2 "drawbend help run: unexpected argument 'extra'" "$drawbend" help run extra
expect drawbend "help of an unknown command" 2 "unknown command 'nosuch'" "$drawbend" help nosuch
# No warning where the sheet is thicker: one element across the strip is not one through it,
# and a flat floor bends nothing.
for case in "drawbend-deck --across 1 --through 4" "block-deck --elements 1 --out b6.toml"; do
  out=$("$drawbend" $case 2>&1 >/dev/null)
  printf '| %s | no warning | %s | %s |\n' "${case%% *}" "$?" "$(printf '%s' "$out" | grep -m1 warning)"
  if [ -n "$check" ] && printf '%s' "$out" | grep -q "one element through"; then
    echo "FAILED: $case: a one-element warning where the sheet is not one element thick or bends over nothing"
    failed=1
  fi
done
# Fuzz pass (2026-12-04): hexadecimal numbers (std::stod reads 0x10 as 16; every real-valued
# option and every table cell took it before), option relations named by their options
# (the builders' spec fields were named), a choice option named, a checkpoint interval
# far below the time step (a hang that SIGTERM could not stop), a Stribeck table's
# parameter given twice or missing.
expect drawbend-deck "hexadecimal option" 2 "--back-tension: expected a number, found '0x10'" "$drawbend" drawbend-deck --back-tension 0x10
awk -F, -v OFS=, '$1=="uniaxial" && $2==45 {$4="0x10"} 1' "$root/data/materials/aa6016_t4_esaform2021.csv" >cal_hex.csv
expect calibrate "hexadecimal cell" 2 "cal_hex.csv:[0-9]+: column 'r_value': expected a number, found '0x10'" "$drawbend" calibrate cal_hex.csv --out c9
awk -F, -v OFS=, 'NR==8 {$2="0x10"} 1' "$root/data/measured/thesis_drawbend.csv" >loop_hex.csv
expect loop "hexadecimal cell" 0 "data problem: .*loop_hex.csv:8: column 'pin_diameter_mm': '0x10' is not a number" "$drawbend" loop loop_hex.csv --out l6 --permutations 19 --figures= --export none
expect drawbend-deck "back tension 0" 2 "--back-tension: expected a value in \\(0, " "$drawbend" drawbend-deck --back-tension 0
expect drawbend-deck "unknown strip direction" 2 "--strip-direction: expected rd or td, found 'xx'" "$drawbend" drawbend-deck --strip-direction xx
expect block-deck "ramp longer than its step" 2 "--press-ramp: expected a ramp shorter than --press-time \\(0.002 s\\), found 0.005 s" "$drawbend" block-deck --press-ramp 0.005 --out b7.toml
expect block-deck "ramp as long as its step" 2 "--speed-ramp: expected a ramp shorter than --slide-time \\(0.003 s\\), found 0.003 s" "$drawbend" block-deck --speed-ramp 0.003 --out b8.toml
expect strip-deck "ramp longer than its step" 2 "--force-ramp: expected a ramp no longer than --press-time \\(0.05 s\\), found 1 s" "$drawbend" strip-deck --force-ramp 1 --out s2.toml
expect run "--checkpoint-every 1e-300s" 0 "halted after cycle 3 " "$drawbend" run "$deck" --out o14 --quiet --checkpoint-every 1e-300s --halt-after-cycles 3
grep -v '^#' "$root/data/thesis/table_3_1.csv" >strib_twice.csv
printf 'mu_BL,0.2,-\n' >>strib_twice.csv
expect strip-deck "Stribeck parameter twice" 2 "--stribeck-table: strib_twice.csv:8: column 'parameter': Stribeck parameter 'mu_BL' given twice \\(first on line 2\\)" "$drawbend" strip-deck --stribeck-table strib_twice.csv --out s3.toml
grep -v '^#' "$root/data/thesis/table_3_1.csv" | grep -v '^eta' >strib_short.csv
expect strip-deck "Stribeck parameter missing" 2 "--stribeck-table: strib_short.csv: missing Stribeck parameter 'eta'" "$drawbend" strip-deck --stribeck-table strib_short.csv --out s4.toml
# A history signal of a tool or node set the deck does not have: before, an unknown
# tool ended the run with "no tool named 'nope'" (no file, no line) and `plan` took
# the deck; an unknown node set wrote a column of zeros with exit 0.
sed 's/kind = "tool_force", target = "floor", component = 2/kind = "tool_force", target = "nope", component = 2/' "$deck" >hist_tool.toml
expect run "history of an unknown tool" 2 "hist_tool.toml:[0-9]+: output.history.target: expected the name of a \\[\\[tool\\]\\], found 'nope'" "$drawbend" run hist_tool.toml --out o15 --quiet
expect plan "history of an unknown tool" 2 "hist_tool.toml:[0-9]+: output.history.target: expected the name of a \\[\\[tool\\]\\]" "$drawbend" plan hist_tool.toml
sed 's/kind = "tool_force", target = "floor", component = 2/kind = "reaction", target = "nope", component = 2/' "$deck" >hist_set.toml
expect run "history of an unknown node set" 2 "hist_set.toml:[0-9]+: output.history.target: expected a node set \\(.*\\), found 'nope'" "$drawbend" run hist_set.toml --out o16 --quiet
# loop --maps: an FE map's numbers (before: "input error: stod" for a word, "error: stod"
# and exit 3 for 1e999, and a pressure of 1e300 MPa ran with exit 0 and an "inf %" export).
"$drawbend" synth --effect none --seed 1 --tests-per-pin 2 --rows-per-test 5 --out maps_data >/dev/null 2>&1
map_dir() {  # DIR COMMENT PRESSURE: one five-node map per pin of the synthetic data
  mkdir -p "$1"
  for d in 12.7 25.4 42; do
    { printf '%s\n' "$2" "node,x_mm,y_mm,z_mm,x0_mm,y0_mm,z0_mm,surface,u_tool,v_tool_mm,pressure_MPa,area_mm2,normal_force_N,tangential_force_N,slip_speed_mm_s,penetration_mm"
      for i in 1 2 3 4 5; do echo "$i,0,0,0,0,0,0,0,0,0,$3,0.5,0,0,0,0"; done; } >"$1/pin_${d}mm.csv"
  done
}
map_dir maps_word '# reference_back_tension_N: abc' 20
expect loop "--maps: a word as the reference tension" 2 "maps_word/pin_12.7mm.csv: reference_back_tension_N: expected a number, found 'abc'" "$drawbend" loop maps_data/data.csv --maps maps_word --out l7 --figures= --permutations 19
# Our own maps write a note in brackets after the number (Chapter 4's maps; the
# strict parse first refused them and stopped Chapter 7): read as the number.
map_dir maps_note '# reference_back_tension_N: 1512.4 (full strip; the map is the half model'"'"'s)' 20
expect loop "--maps: a number with a bracketed note" 0 "rows read" "$drawbend" loop maps_data/data.csv --maps maps_note --out l10 --figures= --permutations 19 --export none
map_dir maps_big '# reference_back_tension_N: 1e999' 20
expect loop "--maps: 1e999 as the reference tension" 2 "maps_big/pin_12.7mm.csv: reference_back_tension_N: expected a number, found '1e999'" "$drawbend" loop maps_data/data.csv --maps maps_big --out l8 --figures= --permutations 19
map_dir maps_huge '# reference_back_tension_N: 1000' 1e300
expect loop "--maps: a pressure of 1e300 MPa" 2 "maps_huge/pin_12.7mm.csv:3: expected a contact pressure up to 100000 MPa" "$drawbend" loop maps_data/data.csv --maps maps_huge --out l9 --figures= --permutations 19
# A 100,000-character cell: named, clipped (the message echoed it whole before 2026-12-04).
{ printf 'test,angle_deg,stress_ratio,r_value\nuniaxial,0,1,'; head -c 100000 /dev/zero | tr '\0' 9; printf '\n'; } >cal_long.csv
expect calibrate "a 100,000-character cell" 2 "cal_long.csv:2: column 'r_value': expected a number, found '9{80}\\.\\.\\. \\(100000 bytes\\)'" "$drawbend" calibrate cal_long.csv --out c10
# A file option given as '' (before: "draw-bend spec: no hardening curve", or
# ": expected a file name, found an empty one" naming no option).
while read -r cmd opt extra; do
  expect "$cmd" "empty --$opt" 2 "input error: --$opt: expected a file name, found an empty one" "$drawbend" $cmd $extra --$opt ""
done <<LIST
drawbend-deck hardening
block-deck hardening --out b9.toml
block-deck surface-nodes --out b9.toml
strip-deck hardening --out s5.toml
strip-deck stribeck-table --out s5.toml
cup-deck base
model-loop hardening ml_crlf.csv --out m6
LIST
# A checkpoint with one byte changed (format 2 carries a checksum; before, a
# damaged checkpoint restarted with exit 0 from the damaged state).
"$drawbend" run "$deck" --out ck --quiet --checkpoint-every 200 --halt-after-cycles 200 >/dev/null 2>&1
cp ck/checkpoint.bin ck_damaged.bin
byte=$(od -An -tx1 -j 5000 -N 1 ck_damaged.bin | tr -d ' ')
if [ "$byte" = 5a ]; then printf 'Y' | dd of=ck_damaged.bin bs=1 seek=5000 conv=notrunc 2>/dev/null
else printf 'Z' | dd of=ck_damaged.bin bs=1 seek=5000 conv=notrunc 2>/dev/null; fi
expect run "a damaged checkpoint" 2 "ck_damaged.bin: checkpoint is damaged \\(its checksum does not match its contents\\)" "$drawbend" run "$deck" --out ck --quiet --restart ck_damaged.bin
# Third pass (2026-12-04, branch robust3).  Names in a deck: an empty tool name ran the whole case and
# then failed on "fields_0.vtm: a block with an empty name" (exit 2 naming an output file, no deck line);
# a line break in a step, tool or history name broke history.csv's comment lines and rows (exit 0).
sed '0,/^name = "floor"/s//name = ""/; s/tool = "floor"/tool = ""/; s/target = "floor"/target = ""/' "$deck" >tool_empty.toml
expect run "empty tool name" 2 "tool_empty.toml:[0-9]+: tool.name: expected a name, found an empty one" "$drawbend" run tool_empty.toml --out o18 --quiet
sed 's/^name = "slide"/name = "a\\nb"/' "$deck" >step_nl.toml
expect run "line break in a step name" 2 "step_nl.toml:[0-9]+: step.name: expected a name without control characters .*found \"a\\\\nb\"" "$drawbend" run step_nl.toml --out o19 --quiet
sed 's/name = "friction_N"/name = "a\\tb"/' "$deck" >hist_tab.toml
expect run "tab in a history name" 2 "hist_tab.toml:[0-9]+: output.history.name: expected a name without control characters" "$drawbend" run hist_tab.toml --out o20 --quiet
expect plan "empty tool name" 2 "tool_empty.toml:[0-9]+: tool.name: expected a name, found an empty one" "$drawbend" plan tool_empty.toml
# A mesh axis with both forms ({ from, to, n } was ignored beside { breaks, counts }), and breaks out of
# order (named by the mesher's internal "uniform_lines: need n >= 1 and b > a").
sed 's/^x = { from = 0.0, to = 1.0, n = 4 }/x = { from = 0.0, to = 1.0, n = 4, breaks = [0.0, 1.0], counts = [4] }/' "$deck" >mesh_both.toml
expect run "mesh axis in both forms" 2 "mesh_both.toml:[0-9]+: mesh.x.from: not used with 'breaks' and 'counts'" "$drawbend" run mesh_both.toml --out o21 --quiet
sed 's/^x = { from = 0.0, to = 1.0, n = 4 }/x = { breaks = [0.0, 1.0, 0.5], counts = [2, 2] }/' "$deck" >mesh_breaks.toml
expect run "mesh breaks out of order" 2 "mesh_breaks.toml:[0-9]+: mesh.x.breaks: expected increasing coordinates, found 0.5 after 1" "$drawbend" run mesh_breaks.toml --out o22 --quiet
# An input named as the output: replaced by the output with exit 0 before.
cp "$root/data/materials/aa5754_o_rd.csv" own_curve.csv
expect block-deck "--out is the --hardening file" 2 "--out 'own_curve.csv': is also an input of this command" "$drawbend" block-deck --hardening own_curve.csv --out own_curve.csv
expect strip-deck "--out is the --hardening file" 2 "--out 'own_curve.csv': is also an input of this command" "$drawbend" strip-deck --hardening own_curve.csv --out own_curve.csv
expect export "--out is the model" 2 "--out 'model/good.toml': is also an input of this command" "$drawbend" export model/good.toml --to lsdyna --out model/good.toml
expect export "--out is the nodes file" 2 "--out 'model/nodes.csv': is also an input of this command" "$drawbend" export model/good.toml --to lsdyna --out model/nodes.csv
mkdir -p cal_in
cp cal_crlf.csv cal_in/calibration.csv
expect calibrate "--out holds TESTS.csv as calibration.csv" 2 "--out 'cal_in/calibration.csv': is also an input of this command" "$drawbend" calibrate cal_in/calibration.csv --out cal_in
# A default law's options beside --friction, and --hardening beside a --material with its own flow curve:
# ignored with exit 0 before.
expect block-deck "--surface-nodes with --friction" 2 "--surface-nodes: applies only without --friction" "$drawbend" block-deck --friction '{ law = "coulomb", mu = 0.1 }' --surface-nodes "$root/data/thesis/table_6_1.csv" --out b11.toml
expect block-deck "--interval with --friction" 2 "--interval: applies only without --friction" "$drawbend" block-deck --friction '{ law = "coulomb", mu = 0.1 }' --interval 5 --out b12.toml
expect strip-deck "--stribeck-table with --friction" 2 "--stribeck-table: applies only without --friction" "$drawbend" strip-deck --friction '{ law = "coulomb", mu = 0.1 }' --stribeck-table "$root/data/thesis/table_3_1.csv" --out s8.toml
expect drawbend-deck "--hardening with a --material curve" 2 "--hardening: applies only with a --material that has no flow curve of its own \\(this --material names one" "$drawbend" drawbend-deck --material '{ type = "j2", yield = 100.0 }' --hardening own_curve.csv
expect drawbend-deck "--hardening with an elastic --material" 2 "--hardening: applies only with a --material .*this --material is elastic" "$drawbend" drawbend-deck --material '{ type = "elastic" }' --hardening own_curve.csv
expect drawbend-deck "--hardening with a --material without a curve" 0 "back_tension in this deck" "$drawbend" drawbend-deck --material '{ type = "j2_combined", kinematic = { beta = 0.5 } }' --hardening own_curve.csv
# A back tension the strip cannot carry (above the flow stress at 100 % plastic strain over the section):
# the deck was written with exit 0 and its run ended in exit 3, an element inverted (before 2026-12-04).
expect drawbend-deck "back tension above the strip's capacity" 2 "--back-tension: 1e\\+06 N on the full strip is above what the strip can carry" "$drawbend" drawbend-deck --back-tension 1e6
expect drawbend-deck "back tension above a Swift strip's capacity" 2 "--back-tension: 20000 N on the full strip is above what the strip can carry, .* 401 MPa" "$drawbend" drawbend-deck --back-tension 20000 --material '{ swift = { K = 400, e0 = 0.01, n = 0.25 } }'
expect drawbend-deck "back tension within the capacity, half basis" 0 "back_tension in this deck is on the half model: 5000 N" "$drawbend" drawbend-deck --back-tension 5000 --basis half
expect drawbend-deck "an elastic strip has no bound" 0 "back_tension in this deck" "$drawbend" drawbend-deck --back-tension 9000 --material '{ type = "elastic" }'
# plan: a finished run's wall time that is not a number was left out without a word (a range error warned).
mkdir -p runs_word/a
cp "$deck" runs_word/a/deck.toml
printf 'quantity,value\nwall_time,abc\n' >runs_word/a/summary.csv
expect plan "wall time not a number" 0 "warning: runs_word/a/summary.csv:2: column 'value': expected a number, found 'abc'; that run's measurement is left out" "$drawbend" plan runs_word
# Two choice options said in another style than the house's "--name: expected ..., found '...'".
expect loop "unknown --bending" 2 "input error: --bending: expected linear, constant, swift, fe or none, found 'quadratic'" "$drawbend" loop "$root/data/measured/thesis_drawbend.csv" --out l12 --bending quadratic
expect export "unknown --to" 2 "input error: --to: expected lsdyna, openradioss or abaqus, found 'nastran'" "$drawbend" export model/good.toml --to nastran --out e10.k
# run's draw-bend options on a deck without a draw-bend answer (ignored with exit 0 before).
expect run "--bending-force on a block deck" 2 "input error: --bending-force: applies only with a draw-bend deck" "$drawbend" run "$deck" --out o23 --quiet --bending-force 300
expect run "--basis on a block deck" 2 "input error: --basis: applies only with a draw-bend deck" "$drawbend" run "$deck" --out o24 --quiet --basis half
# synth --from-thesis --data of a missing folder: named by its option (a derived table path before).
expect synth "--data of a missing folder" 2 "input error: --data 'no_such_data': expected the repository's data folder \\(holding thesis/\\), found nothing there" "$drawbend" synth --from-thesis --data no_such_data --out y6
exit $failed
