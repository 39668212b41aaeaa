#!/usr/bin/env bash
# Inputs that parse but are physically or statistically nonsense, for the
# newer commands (loop, model-loop, calibrate, export, plan): negative, zero
# or swapped forces, speeds and pins; a constant outlet force; only rotating
# pins; every force in kN, every pin in metres, every speed in m/s; NaN
# columns and duplicate column names; r-values, stress ratios and angles
# out of range; friction models with mu < 0 or > 1 and reversed domains;
# decks with no elements.  Each case states the exit code and a pattern the
# output must match: exit 2 with file:line: column (or file: column) for
# what no draw-bend test can be, a dropped row named as a data problem, or a
# warning with exit 0 for what is legal but suspicious.  Every file is made
# from the repository's sample inputs, one value or column changed.
# Prints one table row per case:  | command | case | exit | first line |
# With --check, exits 1 unless every case matched.
# Usage: nonsense_matrix.sh DRAWBEND WORKDIR [--check]
set -u
drawbend=$1 work=$2 check=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
limit=${NONSENSE_MATRIX_SECONDS:-120}
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
failed=0
. "$here/matrix_lib.sh"  # expect LABEL CASE RC PATTERN CMD... (a 2 GB cap on each run)

# drawbend loop on the thesis data (5 comment lines, the header on line 6;
# columns 2 pin_diameter_mm 3 pin 4 direction_deg 5 speed_mm_s 7 back_tension_N
# 8 outlet_force_N 9 source), one change per file.
thesis=$root/data/measured/thesis_drawbend.csv
lp() {  # NAME AWK-PROGRAM RC PATTERN CASE
  awk -F, -v OFS=, "$2" "$thesis" >"$1.csv"
  expect loop "$5" "$3" "$4" "$drawbend" loop "$1.csv" --out "o_$1" --permutations 19 --figures= --export none
}
lp neg_force 'NR==10{$8=-$8}1' 0 "neg_force.csv:10: column 'outlet_force_N': negative force" "a negative outlet force (one row)"
lp neg_speed 'NR==10{$5=-25.4}1' 0 "neg_speed.csv:10: column 'speed_mm_s': expected a sliding speed > 0 mm/s" "a negative speed (one row)"
lp zero_pin 'NR==10{$2=0}1' 0 "zero_pin.csv:10: column 'pin_diameter_mm': pin diameter must be positive" "a zero pin diameter (one row)"
lp neg_bt 'NR==10{$7=-100}1' 0 "neg_bt.csv:10: column 'back_tension_N': negative force" "a negative back tension (one row)"
lp bt_above 'NR==10{t=$7;$7=$8;$8=t}1' 0 "bt_above.csv:10: column 'outlet_force_N': outlet force .* below back tension" "back tension above the outlet force (one row)"
lp all_bt_above 'NR>6{t=$7;$7=$8;$8=t}1' 2 "input error: all_bt_above.csv: no usable rows" "back tension above the outlet force (every row)"
lp const_out 'NR>6{$8=5000}1' 2 "input error: .*const_out.csv: column 'outlet_force_N': every usable row has the same outlet force 5000 N while the back tension goes from" "a constant outlet force (5000 N in every row)"
lp const_bt 'NR>6{$7=1000}1' 0 "const_bt.csv:[0-9]+: column 'outlet_force_N': outlet force .* below back tension 1000 N" "a constant back tension (1000 N in every row)"
lp one_pin 'NR<=6||$2==12.7' 0 "one_pin.csv: 52 rows read, 52 used, 0 dropped, 0 problems" "every row of one pin (valid: the loop fits it)"
lp nan_out 'NR>6{$8="nan"}1' 2 "input error: nan_out.csv: no usable rows" "outlet force NaN in every row"
lp inf_bt 'NR>6{$7="inf"}1' 2 "inf_bt.csv:7: column 'back_tension_N': 'inf' is not a finite number" "back tension inf in every row"
lp dup_col 'NR==6{$9="speed_mm_s"}1' 2 "dup_col.csv:6: column 'speed_mm_s': duplicate column name" "a duplicate column name"
lp kN 'NR>6{$7=$7/1000;$8=$8/1000}1' 2 "input error: .*kN.csv: columns 'back_tension_N', 'outlet_force_N': every force is below 10 N" "every force in kN"
lp pin_m 'NR>6{$2=$2/1000}1' 2 "input error: .*pin_m.csv: column 'pin_diameter_mm': every pin diameter is below 1 mm" "every pin diameter in m"
lp speed_m 'NR>6{$5=$5/1000}1' 0 "warning: .*speed_m.csv: column 'speed_mm_s': every speed is below 1 mm/s" "every speed in m/s (warning)"
lp dir_200 'NR==10{$4=200}1' 0 "dir_200.csv:10: column 'direction_deg': direction must lie in 0..90 deg" "a direction of 200 deg (one row)"
lp all_rot 'NR>6{$3="rotating"}1' 2 "input error: .*all_rot.csv: column 'pin': every usable row is 'rotating'" "every row on a rotating pin (no friction to measure)"
lp all_fixed 'NR>6&&$3=="rotating"{next}1' 2 "input error: .*all_fixed.csv: no rotating-pin rows for the 12.7 mm, 25.4 mm, 42 mm pin" "no rotating-pin rows (bending unknown)"
lp one_test 'NR>6{$1="T1"}1' 2 "one_test.csv:[0-9]+: column 'pin_diameter_mm': test 'T1' has 25.4 mm here and 12.7 mm on line 7; a test is one strip drawn over one pin" "one test_id in every row (exit 0 before 2026-12-04: the replicate noise from rows on three pins)"
lp dir_rad 'NR>6{$4=$4*3.14159265/180}1' 0 "warning: .*dir_rad.csv: column 'direction_deg': every direction is below 2 deg \\(largest 1.5708\\)" "every direction in radians (warning)"
lp thick_neg 'NR==6{$0=$0",thickness_mm"} NR>6{$0=$0",-1.04"}1' 0 "thick_neg.csv: 156 rows read, 156 used" "an extra column thickness_mm = -1.04 (valid: an extra column is a candidate variable, constant here, so never chosen)"

# drawbend model-loop on its sample points (header then rows; columns
# pin_diameter_mm, back_tension_N, bending_force_N); each is refused before
# any FE run.
points=$root/data/measured/model_loop_points.csv
h=$(grep -n -m1 -v '^#' "$points" | cut -d: -f1)
ml() {  # NAME AWK-PROGRAM PATTERN CASE
  awk -F, -v OFS=, -v h="$h" "$2" "$points" >"ml_$1.csv"
  expect model-loop "$4" 2 "$3" "$drawbend" model-loop "ml_$1.csv" --out "o_ml_$1"
}
ml neg_bend 'NR==h+1{$3=-$3}1' "ml_neg_bend.csv:[0-9]+: column 'bending_force_N': must be > 0 N" "a negative bending force"
ml zero_pin 'NR==h+1{$1=0}1' "ml_zero_pin.csv:[0-9]+: column 'pin_diameter_mm': must be > 0 mm" "a zero pin diameter"
ml neg_bt 'NR==h+1{$2=-500}1' "ml_neg_bt.csv:[0-9]+: column 'back_tension_N': must be > 0 N" "a negative back tension"
ml nan 'NR==h+1{$3="nan"}1' "ml_nan.csv:[0-9]+: column 'bending_force_N': expected a finite number, found 'nan'" "a NaN bending force"
ml dup_col 'NR==h{$3="back_tension_N"}1' "ml_dup_col.csv:[0-9]+: header cell 3: expected unique column names" "a duplicate column name"
ml kN 'NR>h{$2=$2/1000;$3=$3/1000}1' "input error: .*ml_kN.csv: columns 'back_tension_N', 'bending_force_N': every force is below 10 N" "every force in kN"
ml fb_x1000 'NR>h{$3=$3*1000}1' "ml_fb_x1000.csv:[0-9]+: column 'bending_force_N': back tension \\+ bending force = 3.046e\\+05 N, above what the strip can carry" "every bending force x 1000 (before 2026-12-04 the FE runs started on them)"
ml pin_m 'NR>h{$1=$1/1000}1' "input error: .*ml_pin_m.csv: column 'pin_diameter_mm': every pin diameter is below 1 mm" "every pin diameter in m"

# drawbend calibrate on the AA6016-T4 tests (test, angle_deg, stress_ratio, r_value).
tests=$root/data/materials/aa6016_t4_esaform2021.csv
cal() {  # NAME AWK-PROGRAM RC PATTERN CASE
  awk -F, -v OFS=, "$2" "$tests" >"cal_$1.csv"
  expect calibrate "$5" "$3" "$4" "$drawbend" calibrate "cal_$1.csv" --out "o_cal_$1"
}
u45='$1=="uniaxial"&&$2==45'
cal r_neg "$u45"'{$4=-0.2}1' 2 "cal_r_neg.csv:[0-9]+: column 'r_value': must be > 0, found -0.2" "r-value < 0"
cal r_zero "$u45"'{$4=0}1' 2 "cal_r_zero.csv:[0-9]+: column 'r_value': must be > 0, found 0" "r-value = 0"
cal s_neg "$u45"'{$3=-0.8}1' 2 "cal_s_neg.csv:[0-9]+: column 'stress_ratio': must be > 0" "stress ratio < 0"
cal s_zero "$u45"'{$3=0}1' 2 "cal_s_zero.csv:[0-9]+: column 'stress_ratio': must be > 0" "stress ratio = 0"
cal s_mpa "$u45"'{$3=250}1' 2 "cal_s_mpa.csv:[0-9]+: column 'stress_ratio': expected a yield-stress ratio to RD in \\[0.1, 10\\]" "a stress in MPa, not a ratio (one row)"
cal all_mpa '$1=="uniaxial"{$3=$3*160}1' 2 "cal_all_mpa.csv:[0-9]+: column 'stress_ratio': expected a yield-stress ratio" "every uniaxial stress in MPa"
cal angle_120 "$u45"'{$2=120}1' 2 "cal_angle_120.csv:[0-9]+: column 'angle_deg': expected an angle in \\[0, 90\\] deg" "angle 120 deg"
cal angle_neg "$u45"'{$2=-45}1' 2 "cal_angle_neg.csv:[0-9]+: column 'angle_deg': expected an angle in \\[0, 90\\] deg" "angle -45 deg"
cal angle_rep '$1=="uniaxial"&&$2==60{$2=45}1' 2 "cal_angle_rep.csv:[0-9]+: column 'stress_ratio': the same test is given twice" "an angle repeated"
cal nan "$u45"'{$4="nan"}1' 2 "cal_nan.csv:[0-9]+: column 'r_value': expected a finite number, found 'nan'" "r-value NaN"

# drawbend export on a friction model (Table 6.1's nodes, the thesis domain).
mkdir -p model
grep -v '^#' "$root/data/thesis/table_6_1.csv" >model/nodes.csv
good='p_min = 0.0\np_max = 80.0\nv_min = 6.35\nv_max = 101.6\n'
ex() {  # NAME DOMAIN NODES-SED RC PATTERN CASE
  mkdir -p "ex_$1"
  printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\n%b' "$2" >"ex_$1/friction_model.toml"
  sed "$3" model/nodes.csv >"ex_$1/nodes.csv"
  expect export "$6" "$4" "$5" "$drawbend" export "ex_$1/friction_model.toml" --to lsdyna --out "ex_$1/out.k"
}
ex mu_neg "$good" 's/^1,0.0142,/1,-0.3,/' 2 "ex_mu_neg/nodes.csv:2: column 'mu_RD': friction coefficient must be >= 0" "mu < 0 at a node"
ex mu_big "$good" 's/^1,0.0142,/1,1.7,/' 0 "warning: .*ex_mu_big/nodes.csv: column 'mu_RD': node 1 has mu = 1.7, above 1" "mu = 1.7 at a node (warning)"
ex mu_nan "$good" 's/^1,0.0142,/1,nan,/' 2 "ex_mu_nan/nodes.csv:2: column 'mu_RD': expected a finite number, found 'nan'" "mu NaN at a node"
ex p_rev 'p_min = 80.0\np_max = 0.0\nv_min = 6.35\nv_max = 101.6\n' '' 2 "friction: expected 0 <= p_min < p_max <= 10000 \\[MPa\\], found 80 and 0" "p grid reversed"
ex p_eq 'p_min = 40.0\np_max = 40.0\nv_min = 6.35\nv_max = 101.6\n' '' 2 "friction: expected 0 <= p_min < p_max <= 10000 \\[MPa\\], found 40 and 40" "p grid of zero width"
ex v_rev 'p_min = 0.0\np_max = 80.0\nv_min = 101.6\nv_max = 6.35\n' '' 2 "friction: expected 0 < v_min < v_max <= 10000 \\[mm/s\\], found 101.6 and 6.35" "v grid reversed"
ex p_neg 'p_min = -3.0\np_max = 80.0\nv_min = 6.35\nv_max = 101.6\n' '' 2 "friction: expected 0 <= p_min < p_max" "p_min < 0"
ex v_zero 'p_min = 0.0\np_max = 80.0\nv_min = 0.0\nv_max = 101.6\n' '' 2 "friction: expected 0 < v_min < v_max" "v_min = 0"
ex v_tiny 'p_min = 0.0\np_max = 80.0\nv_min = 1e-300\nv_max = 1e-299\n' '' 2 "friction.v_min: expected a sliding speed of at least 0.001 mm/s" "v grid of 1e-300 mm/s (exit 0 to LS-DYNA before 2026-12-04)"
ex p_tiny 'p_min = 0.0\np_max = 1e-9\nv_min = 6.35\nv_max = 101.6\n' '' 2 "friction: expected p_max - p_min of at least 0.001 MPa" "p grid 1e-9 MPa wide"
ex p_nan 'p_min = nan\np_max = 80.0\nv_min = 6.35\nv_max = 101.6\n' '' 2 "friction.p_min: expected a finite number, found nan" "p_min = nan"
# A frictionless model (mu = 0 at every node) is a valid law: written with Fric = C1..C5 = 0
# (before 2026-12-04 the OpenRadioss fit aimed at mu = 1e-4, missed 0 by "100 %" and refused it).
mkdir -p ex_mu0
printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\n%b' "$good" >ex_mu0/friction_model.toml
awk -F, -v OFS=, 'NR > 1 { $2 = 0; $3 = 0 } 1' model/nodes.csv >ex_mu0/nodes.csv
expect export "mu = 0 at every node (frictionless) to OpenRadioss" 0 "wrote ex_mu0/out.rad \\(openradioss; max relative error 0 % in 1 speed band" \
  "$drawbend" export ex_mu0/friction_model.toml --to openradioss --parts 1,2 --out ex_mu0/out.rad
# An OpenRadioss speed band outside the model's measured speeds fits the
# surface's clamped edge: a valid polynomial, written with a warning.
mkdir -p ex_band
printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\n%b' "$good" >ex_band/friction_model.toml
cp model/nodes.csv ex_band/nodes.csv
expect export "a speed band beyond the measured speeds (warning)" 0 \
  "warning: --speed-band 1000,2000 mm/s reaches outside the model's measured speeds \\(6.35 to 101.6 mm/s\\)" \
  "$drawbend" export ex_band/friction_model.toml --to openradioss --parts 1,2 --speed-band 1000,2000 --out ex_band/out.rad

# drawbend plan on nothing to plan.
mkdir -p empty
expect plan "an empty folder" 2 "drawbend plan: no deck.toml under .*empty" "$drawbend" plan empty
# A folder is searched three levels down, never the whole file system (before 2026-12-04
# `plan /` walked every folder of the machine): a deck four levels down is not planned, and
# /proc (tens of thousands of entries three levels down, no deck) ends at once.
mkdir -p deep/a/b/c/d
cp "$here/decks/restart_block.toml" deep/a/b/c/d/deck.toml
expect plan "a deck four levels down" 2 "drawbend plan: no deck.toml under deep \\(a folder is searched 3 levels down\\)" "$drawbend" plan deep
cp "$here/decks/restart_block.toml" deep/a/b/c/deck.toml
expect plan "a deck three levels down" 0 "^deep/a/b/c/deck.toml,64," "$drawbend" plan deep
expect plan "the same deck named twice" 0 "warning: deep/a/b/c/deck.toml is named twice .*planned once" "$drawbend" plan deep deep/a/b/c/deck.toml
expect plan "the whole of /proc" 2 "drawbend plan: no deck.toml under /proc" "$drawbend" plan /proc
"$drawbend" block-deck --out zero/deck.toml >/dev/null 2>&1
sed -i 's/^x = { from = 0.0, n = 4, to = 1.0 }/x = { from = 0.0, n = 0, to = 1.0 }/' zero/deck.toml
expect plan "a deck with n = 0 elements along x" 2 "deck.toml:[0-9]+: mesh.x.n: expected a whole number >= 1" "$drawbend" plan zero/deck.toml
"$drawbend" block-deck --out flat/deck.toml >/dev/null 2>&1
sed -i 's/^x = { from = 0.0, n = 4, to = 1.0 }/x = { from = 0.0, n = 4, to = 0.0 }/' flat/deck.toml
expect plan "a deck of zero length along x" 2 "deck.toml:[0-9]+: mesh.x: expected 'to' > 'from'" "$drawbend" plan flat/deck.toml
# Friction coefficients and speeds no test has (fuzz pass, 2026-12-04: each ran or
# was written with exit 0 before; core/strip_limits.hpp's kMaxFrictionCoefficient
# and kMaxSlidingSpeedMMs).
lp speed_huge 'NR==10{$5=1e300}1' 0 "speed_huge.csv:10: column 'speed_mm_s': expected a sliding speed up to 10000 mm/s" "a speed of 1e300 mm/s (one row)"
ex mu_huge "$good" 's/^1,0.0142,/1,1e300,/' 2 "ex_mu_huge/nodes.csv:2: column 'mu_RD': friction coefficient must be at most 10" "mu = 1e300 at a node"
sed 's/mu = 0.1 }/mu = 1e300 }/' "$here/decks/restart_block.toml" >mu_huge.toml
expect run "a Coulomb mu of 1e300 in a deck" 2 "mu_huge.toml:[0-9]+: contact.friction.mu: expected a friction coefficient up to 10" "$drawbend" run mu_huge.toml --out o_mu_huge --quiet
expect block-deck "a Coulomb mu of 1e300 in --friction" 2 "--friction:1: friction.mu: expected a friction coefficient up to 10" "$drawbend" block-deck --friction '{ law = "coulomb", mu = 1e300 }' --out b_mu.toml
grep -v '^#' "$root/data/thesis/table_6_1.csv" | sed 's/^5,0.0583,/5,1e300,/' >nodes_huge.csv
expect block-deck "a nodal mu of 1e300" 2 "--surface-nodes: nodes_huge.csv:6: column 'mu_RD': friction coefficient must be at most 10" "$drawbend" block-deck --surface-nodes nodes_huge.csv --out b_nodes.toml
grep -v '^#' "$root/data/thesis/table_3_1.csv" | sed 's/^mu_BL,0.1,/mu_BL,1e300,/' >strib_huge.csv
expect strip-deck "a Stribeck mu_BL of 1e300" 2 "--stribeck-table: strib_huge.csv:2: column 'value': mu_BL: expected a friction coefficient in \\[0, 10\\], found 1e\\+300" "$drawbend" strip-deck --stribeck-table strib_huge.csv --out s_huge.toml
exit $failed
