#!/bin/bash
# Issue 55, item 1: every run writes its answer (src/io/run_result.hpp).
#  1. `drawbend-deck --run` leaves result.toml with F_X, F_Y, F_B, the friction
#     force and mu by Eq. (2.3) on the full strip and on the half model; the
#     full-strip values are twice the half model's (relative 1e-9: both are
#     printed with 10 significant digits from the same double times 2).
#  2. `drawbend run` of that run's deck prints the same answer lines and writes
#     the same [drawbend] tables: the solver is deterministic for one deck and
#     thread count, so the two runs agree exactly.
#  3. history.csv states its basis and signs in '# basis:' / '# signs:' comment
#     lines and has F_Y_full_strip_N, whose mean over the last third of the
#     draw step is result.toml's full-strip F_Y_N (relative 1e-6: history cells
#     are printed with 8 significant digits).
#  4. A tabulated mu(p, v) law whose pressure domain (3.3-13.7 MPa) misses the
#     run's pressures (mean about 17 MPa) reports clamped_pressure > 0 and a
#     share of contact area outside its domain > 0, in result.toml and on the console.
#  5. A frictionless run takes F_B from itself (F_B = F_Y - F_X, friction force 0).
# Usage: run_result.sh DRAWBEND DATA_DIR WORK_DIR
set -u
bin=$1 data=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
small=(--pin-diameter 12.7 --back-tension 1500 --element-length 1.5 --through 2 --across 1 --draw-length 12 --threads 1 --frames 2)

"$bin" drawbend-deck "${small[@]}" --friction '{ law = "coulomb", mu = 0.15 }' --run coul > coul.out 2>&1 || fail "drawbend-deck --run (exit $?)"
test -s coul/result.toml || fail "no coul/result.toml"
"$bin" run coul/deck.toml --out coul-rerun --threads 1 --quiet > rerun.out 2>&1 || fail "drawbend run (exit $?)"
answer() { sed -n '/^forces on the/,/^  mu by/p' "$1"; }
test -n "$(answer coul.out)" || fail "drawbend-deck --run printed no answer"
diff <(answer coul.out) <(answer rerun.out) || fail "drawbend run printed another answer than drawbend-deck --run"
diff <(sed -n '/^\[drawbend/,$p' coul/result.toml) <(sed -n '/^\[drawbend/,$p' coul-rerun/result.toml) ||
  fail "the two result.toml differ"
grep -q '^# basis: the model is the half strip' coul/history.csv || fail "history.csv: no '# basis:' line"
grep -q '^# signs:' coul/history.csv || fail "history.csv: no '# signs:' line"

python3 - coul/result.toml coul/history.csv <<'PY' || exit 1
import csv, sys, tomllib
r = tomllib.load(open(sys.argv[1], "rb"))
d = r["drawbend"]
full, half = d["full_strip"], d["half_model"]
for k in ("F_X_N", "F_Y_N", "F_B_N", "friction_force_N", "F_Y_minus_F_X_N"):
    if abs(full[k] - 2 * half[k]) > 1e-9 * abs(full[k]):
        sys.exit(f"FAIL: full-strip {k} {full[k]} is not twice the half model's {half[k]}")
if not (0 < d["mu_eq_2_3"] < 1): sys.exit(f"FAIL: mu {d['mu_eq_2_3']}")
if "Swift" not in d["F_B_source"]: sys.exit(f"FAIL: F_B source {d['F_B_source']}")
rows = [row for row in csv.DictReader(l for l in open(sys.argv[2]) if not l.startswith("#")) if row["step"] == "draw"]
n = len(rows); last = rows[n - n // 3:]
fy = sum(float(x["F_Y_full_strip_N"]) for x in last) / len(last)
fx = float(rows[-1]["F_X_full_strip_N"])
if abs(fy - full["F_Y_N"]) > 1e-6 * full["F_Y_N"]: sys.exit(f"FAIL: history F_Y_full_strip_N mean {fy} != {full['F_Y_N']}")
if abs(fx - full["F_X_N"]) > 1e-6 * full["F_X_N"]: sys.exit(f"FAIL: history F_X_full_strip_N {fx} != {full['F_X_N']}")
print(f"coulomb: F_Y {full['F_Y_N']:.2f} N full strip, mu {d['mu_eq_2_3']:.4f}; history's full-strip columns agree")
PY

"$bin" drawbend-deck "${small[@]}" --run surf \
  --friction "{ law = \"surface\", nodes = \"$data/thesis/table_6_1.csv\", p_min = 3.3, p_max = 13.7 }" > surf.out 2>&1 ||
  fail "surface-law run (exit $?)"
grep -q '% of the contact area at the end has a pressure outside' surf.out || fail "no console warning of the domain"
python3 - surf/result.toml <<'PY' || exit 1
import sys, tomllib
c = tomllib.load(open(sys.argv[1], "rb"))["contact"][0]
if not c["clamped_pressure"] > 0: sys.exit(f"FAIL: clamped_pressure {c['clamped_pressure']}")
if not 0 < c["area_share_pressure_outside_domain"] <= 1: sys.exit(f"FAIL: area share {c['area_share_pressure_outside_domain']}")
if not 0 < c["clamped_share_of_evaluations"] <= 1: sys.exit("FAIL: clamped share")
print(f"surface law: {c['clamped_pressure']:.0f} clamped pressures, {100*c['area_share_pressure_outside_domain']:.1f} % of the area outside 3.3-13.7 MPa")
PY

"$bin" drawbend-deck "${small[@]}" --run free > free.out 2>&1 || fail "frictionless run (exit $?)"
grep -q 'F_B_source = "frictionless run' free/result.toml || fail "frictionless: F_B source"
grep -q '^friction_force_N = 0.0' free/result.toml || fail "frictionless: friction force not 0"
echo "run_result: result.toml on both bases, drawbend run = drawbend-deck --run, history basis and full-strip columns, clamps reported"
