#!/usr/bin/env python3
"""Readings of the centre row's contact pressure at the end of a draw-bend run
(issue 51 item 4, docs/issue51-large-pin.md, 'Stated causes tested, continued').

Usage: scripts/centre-row-readings.py RUN_DIR...   (folders of `drawbend drawbend-deck --run`)

Reads the run's last contact map (contact_<N>_0.csv), takes the angle round the
pin from the inlet tangent point as atan2(x, z) and the rows by reference y,
as sim/drawbend_case.cpp and sim/map_tools.cpp do, and prints for the centre
row (y = 0):
  - the arc at 0.5 MPa (linear interpolation between nodes, as the chapter's
    contact_arc) and at fractions of the row's largest pressure;
  - the thresholds that put the start inside the thesis's 11.5 +- 2.3 deg and
    the end at those thresholds;
  - the last node without pressure and the first with it (the pressure front);
  - the entry and exit peaks (< 45 deg, >= 45 deg), the entry peak's width
    above half its height, and the inlet zone's line load: the integral of
    p ds on the pin radius from the 0.5 MPa start to the first minimum after
    the entry peak [N/mm].
"""
import csv
import glob
import math
import re
import sys

PIN_RADIUS = 12.7 / 2
BAND = (11.5 - 2.3, 11.5 + 2.3)  # the thesis's start and the check's tolerance


def centre_row(run):
    files = glob.glob(run + "/contact_*_0.csv")
    last = max(files, key=lambda p: int(re.search(r"contact_(\d+)_0\.csv$", p).group(1)))
    with open(last) as fh:
        rows = [q for q in csv.DictReader(l for l in fh if not l.startswith("#")) if float(q["y0_mm"]) == 0.0]
    return sorted((math.degrees(math.atan2(float(q["x_mm"]), float(q["z_mm"]))), float(q["pressure_MPa"])) for q in rows)


def arc(n, th):
    idx = [i for i, (_, p) in enumerate(n) if p > th]
    cross = lambda i, j: n[i][0] + (th - n[i][1]) / (n[j][1] - n[i][1]) * (n[j][0] - n[i][0])
    a, b = idx[0], idx[-1]
    return (cross(a - 1, a) if a > 0 else n[a][0]), (cross(b + 1, b) if b + 1 < len(n) else n[b][0])


def main(runs):
    for run in runs:
        n = centre_row(run)
        pmax = max(p for _, p in n)
        s, e = arc(n, 0.5)
        print(f"{run}: arc at 0.5 MPa {s:.2f}-{e:.2f} deg; row max {pmax:.2f} MPa")
        print("  fractions of the row max: " + "; ".join(
            f"{f:.2f}: {arc(n, f * pmax)[0]:.2f}-{arc(n, f * pmax)[1]:.2f}" for f in (0.1, 0.25, 0.5, 0.75, 0.9)))
        ok = [(k / 1000 * pmax, *arc(n, k / 1000 * pmax)) for k in range(1, 1000)]
        ok = [x for x in ok if BAND[0] <= x[1] <= BAND[1]]
        if ok:
            print(f"  start in {BAND[0]:.1f}-{BAND[1]:.1f} deg for thresholds {ok[0][0]:.2f}-{ok[-1][0]:.2f} MPa "
                  f"({100 * ok[0][0] / pmax:.0f}-{100 * ok[-1][0] / pmax:.0f} % of the row max); end there "
                  f"{ok[0][2]:.2f} to {ok[-1][2]:.2f} deg")
        i = next(k for k, (_, p) in enumerate(n) if p > 0.5)
        print(f"  pressure front: last node without pressure {n[i - 1][0]:.2f} deg, first with it {n[i][0]:.2f} deg "
              f"({n[i][1]:.1f} MPa), next {n[i + 1][0]:.2f} deg ({n[i + 1][1]:.1f} MPa)")
        ip = max((k for k in range(len(n)) if n[k][0] < 45), key=lambda k: n[k][1])
        ex = max((q for q in n if q[0] >= 45), key=lambda q: q[1])
        j = ip
        while j + 1 < len(n) and n[j + 1][1] < n[j][1]:
            j += 1
        pts = [(s, 0.5)] + [q for q in n if s < q[0] <= n[j][0]]
        load = sum(0.5 * (pts[k][1] + pts[k + 1][1]) * math.radians(pts[k + 1][0] - pts[k][0]) * PIN_RADIUS
                   for k in range(len(pts) - 1))
        half = n[ip][1] / 2
        a = ip
        while a > 0 and n[a - 1][1] > half:
            a -= 1
        b = ip
        while b + 1 <= j and n[b + 1][1] > half:
            b += 1
        lw = n[a - 1][0] + (half - n[a - 1][1]) / (n[a][1] - n[a - 1][1]) * (n[a][0] - n[a - 1][0])
        rw = n[b][0] + (half - n[b][1]) / (n[b + 1][1] - n[b][1]) * (n[b + 1][0] - n[b][0])
        print(f"  entry peak {n[ip][1]:.2f} MPa at {n[ip][0]:.2f} deg, exit peak {ex[1]:.2f} MPa at {ex[0]:.2f} deg; "
              f"width above half the entry peak {rw - lw:.2f} deg; first minimum {n[j][1]:.2f} MPa at {n[j][0]:.2f} "
              f"deg; inlet line load {load:.2f} N/mm; node spacing {n[ip + 1][0] - n[ip][0]:.2f} deg")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
