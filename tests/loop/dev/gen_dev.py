#!/usr/bin/env python3
"""DEVELOPMENT scenarios for the loop's screen (issue 50).  These are dev data:
they were written by the person changing the loop and used while developing it,
so results on them are NOT a held-out measure.  Written independently of the
loop's code (plain Python, no shared code path): pins 12.7/25.4/42 mm with the
Table 5.3 bending lines, 16 fixed + 3 rotating tests per pin, 40 rows per test
(2280 rows), directions 0/45/90 deg, four speeds, decoy columns (test_order,
coil, lot, thickness_mm, temperature_C, tool_temp_C, lube_g, humidity_pct,
operator).  Usage: gen_dev.py SCENARIO NOISE SEED OUT.csv (prints the truth).
Units: mm, N, mm/s, deg, C, g."""
import math, random, sys, json

PINS = [(12.7, 1450, 1800, -0.0625, 396.84), (25.4, 1650, 2050, -0.0123, 129.39), (42.0, 1500, 2100, -0.0118, 70.133)]
MU_RD, MU_TD, WRAP = 0.09, 0.075, math.pi / 2
SCEN = {
    # name: (class, truth variable aliases)
    "level_peak": ("level", ["lube_g"]),          # mid level of a 3-level numeric column
    "dir_peak": ("level", ["direction_deg"]),     # 45 deg bump, only 0/45/90 tested
    "one_cell_pin": ("interaction", ["temperature_C"]),  # slope on the 12.7 mm pin only
    "one_cell_speed": ("interaction", ["coil"]),  # coil C at the highest speed only
    "coil_pin_nuis": ("test-level", ["coil"]),    # coil + a pin-surface nuisance (base mismatch)
    "lot_small": ("test-level", ["lot"]),         # two lots, small effect
    "thickness_bend": ("bending", ["thickness_mm"]),  # F_B ~ t^2
    "sat_exp": ("smooth", ["tool_temp_C"]),       # 1 - exp(-(T-20)/6)
    "linear": ("smooth", ["temperature_C"]),      # plain linear
    "null": ("null", []),
    "null_mismatch": ("null", []),                # pin factor + pressure-like pin dependence + bending curvature
}

def ellipse(a, b, phi):
    c, s = math.cos(phi), math.sin(phi)
    return a * b / math.sqrt(b * b * c * c + a * a * s * s)

def main():
    scen, noise, seed, out = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    if scen not in SCEN:
        sys.exit("unknown scenario " + scen)
    rng = random.Random(seed * 7919 + sum(map(ord, scen)))
    speeds = [5.0, 20.0, 50.0, 100.0]
    tests = []
    for p in range(3):
        for j in range(16):
            tests.append((p, False, [0.0, 45.0, 90.0][j % 3], speeds[(j + p) % 4]))
        for j in range(3):
            tests.append((p, True, 0.0, 20.0))
    order = list(range(1, len(tests) + 1))
    rng.shuffle(order)
    rows = []
    for ti, (p, rot, d, v) in enumerate(tests):
        dpin, lo, hi, b1, b0 = PINS[p]
        coil = rng.choice("ABC")
        lot = rng.choice(["L1", "L2"])
        th = round(rng.uniform(0.95, 1.10), 3)
        temp = round(rng.uniform(19.0, 24.0), 2)
        tool = round(rng.uniform(20.0, 60.0), 1)
        lube = rng.choice([1, 2, 3])
        oper = rng.choice(["ann", "bob"])
        n = 40
        slots = list(range(n))
        rng.shuffle(slots)
        for k in range(n):
            F = lo + (hi - lo) * slots[k] / (n - 1)
            bend = b0 + b1 * F
            if scen == "thickness_bend":
                bend *= (th / 1.025) ** 2
            if scen == "null_mismatch":
                bend += 0.02 * (F - (lo + hi) / 2) ** 2 / (hi - lo)  # slight curvature of the bending line
            y = F + bend
            if not rot:
                phi = math.radians(d)
                mu = ellipse(MU_RD, MU_TD, phi)
                if scen == "level_peak" and lube == 2: mu *= 1.12
                if scen == "dir_peak" and d == 45.0: mu *= 1.12
                if scen == "one_cell_pin" and p == 0: mu *= 1 + 0.25 * (temp - 21.5) / 2.5
                if scen == "one_cell_speed" and coil == "C" and v == 100.0: mu *= 1.25
                if scen == "coil_pin_nuis":
                    if coil == "B": mu *= 1.12
                    if p == 2: mu *= 1.10
                if scen == "lot_small" and lot == "L2": mu *= 1.06
                if scen == "sat_exp": mu *= 1 + 0.2 * (1 - math.exp(-(tool - 20.0) / 6.0)) - 0.1
                if scen == "linear": mu *= 1 + 0.1 * (temp - 21.5) / 2.5
                if scen == "null_mismatch":
                    mu *= {0: 1.06, 1: 1.0, 2: 0.97}[p] * (1 + 0.00002 * (F - 1750))
                y += F * (math.exp(mu * WRAP) - 1)
            y += rng.gauss(0.0, noise)
            s = 20 + 180.0 * k / (n - 1)
            rows.append([f"{'rot' if rot else 'fix'}-{ti}", dpin, "rotating" if rot else "fixed", d, v, "MP404",
                         round(F, 3), round(y, 4), round(s, 3), round(s / v, 4), order[ti], coil, lot, th, temp, tool,
                         lube, round(rng.uniform(40, 60), 2), oper])
    with open(out, "w") as f:
        f.write(f"# DEV scenario {scen} (issue 50 development data, not held out), noise {noise} N, seed {seed}\n")
        f.write("test_id,pin_diameter_mm,pin,direction_deg,speed_mm_s,lubricant,back_tension_N,outlet_force_N,"
                "sliding_distance_mm,time_s,test_order,coil,lot,thickness_mm,temperature_C,tool_temp_C,lube_g,"
                "humidity_pct,operator\n")
        for r in rows:
            f.write(",".join(str(x) for x in r) + "\n")
    print(json.dumps({"scenario": scen, "class": SCEN[scen][0], "aliases": SCEN[scen][1], "noise": noise, "seed": seed}))

main()
