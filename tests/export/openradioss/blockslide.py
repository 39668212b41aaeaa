#!/usr/bin/env python3
"""Load drawbend's OpenRadioss friction export in a real OpenRadioss and compare F_T/F_N with the law.

Not run by CI (CI has no OpenRadioss); see README.md in this folder.  Standard library only.

  blockslide.py MODEL.toml --out DIR [--direction rd|td|mean|ortho] [--points 4,10 8,50 13,95]
                [--densities real=2.7e-9 scaled=2.7e-6] [--drawbend PATH] [--rad FILE]
                [--parts SHEET,TOOL] [--rd-vector X,Y,Z] [--iform 0|1|2]

--parts and --rd-vector go to `drawbend export` (default 1,2 and 1,0,0; part 1 is the block, part 2
the plate).  --direction ortho writes the orthotropic pair (Idir = 1); the block slides along +X, so
the law compared is RD's when the rolling direction is along +-X and TD's when it is along +-Y (any
other --rd-vector is refused).  The starter puts the directions on the shells of the interface's main
surface (the plate, part 2): use --parts 2,1 so /FRIC_ORIENT names the plate.  --iform rewrites
columns 41-50 of every /FRICTION's Ifric card of the exported file (an experiment on the export, said
in the report; Iform 0 and 1: viscous total formulation, VIS_F as written, 1).  --engine runs another
engine build (a patched one, for instance).  A vector starting with '-' is given as --rd-vector=-1,0,0.

Environment: OPENRADIOSS_PATH (the build's root, with exec/starter_linux64_gf, exec/engine_linux64_gf
and hm_cfg_files; `openradioss_env.sh` of build_openradioss.sh sets it), TH_TO_CSV (OpenRadioss/Tools
th_to_csv; default: th_to_csv on PATH).

For each density case and (p [MPa], v [mm/s]) point it fills blockslide_0000.rad.in / _0001.rad.in,
runs the starter and the engine (1 thread), reads the /TH/INTER impulses from the T01 file and reports
  engine  = (I_T(t_end) - I_T(t_a)) / (I_N(t_end) - I_N(t_a)), the mean F_T/F_N over the steady window,
  poly    = the exported polynomial at (p, v) (read here from the file's fixed columns, Ifric = 1 law of
            engine/source/interfaces/int07/i7for3.F: Fric + (C1 + C4 p) p + (C2 + C3 p) v + C5 v^2),
  law     = drawbend's law at (p, v) from MODEL.toml and its nodes CSV (nine-node quadratic surface of
            src/analysis/friction_surface.hpp, p and v clamped to the domain, mu >= 0; evaluated here
            independently of drawbend's code),
and checks |engine - law| / law against the maximum relative error the file states (the pass
criterion of issue 52), plus the starter's error and warning counts (must be 0).
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


# ------------------------------------------------------------------ the law (friction_model.toml)
def read_law(toml_path, direction):
    text = open(toml_path).read()
    sec = re.search(r"^\[friction\](.*?)(^\[|\Z)", text, re.S | re.M)
    if not sec:
        sys.exit(f"{toml_path}: no [friction] table")
    body = sec.group(1)

    def val(key, default=None):
        m = re.search(rf"^{key}\s*=\s*(\S+)", body, re.M)
        if not m:
            if default is None:
                sys.exit(f"{toml_path}: [friction] {key} missing")
            return default
        return m.group(1).strip('"')

    dom = dict(p_min=float(val("p_min", 0.0)), p_max=float(val("p_max", 80.0)),
               v_min=float(val("v_min", 6.35)), v_max=float(val("v_max", 101.6)))
    nodes_csv = os.path.join(os.path.dirname(toml_path), val("nodes"))
    rd, td = [0.0] * 9, [0.0] * 9
    with open(nodes_csv) as f:
        rows = [r for r in csv.reader(l for l in f if not l.startswith("#"))]
    head = rows[0]
    for r in rows[1:]:
        k = int(r[head.index("node")]) - 1
        rd[k] = float(r[head.index("mu_RD")])
        td[k] = float(r[head.index("mu_TD")])
    mu = {"rd": rd, "td": td, "mean": [0.5 * (a + b) for a, b in zip(rd, td)]}[direction]

    def law(p, v):
        p = min(max(p, dom["p_min"]), dom["p_max"])
        v = min(max(v, dom["v_min"]), dom["v_max"])
        xi = 2 * (p - dom["p_min"]) / (dom["p_max"] - dom["p_min"]) - 1
        eta = 2 * (v - dom["v_min"]) / (dom["v_max"] - dom["v_min"]) - 1
        # 1-D quadratic Lagrange functions at -1, 0, +1; node k = 3 i + j + 1 (i: pressure, j: speed)
        lag = lambda t: (0.5 * t * (t - 1), 1 - t * t, 0.5 * t * (t + 1))
        li, lj = lag(xi), lag(eta)
        return max(0.0, sum(li[i] * lj[j] * mu[3 * i + j] for i in range(3) for j in range(3)))

    return law, dom


# ------------------------------------------------------------------ the export (fixed columns)
def col(line, a, b):
    f = line[a - 1:b].strip() if len(line) >= a else ""
    return float(f) if f else 0.0


def read_rad(path):
    """/FRICTION blocks as friction.cfg (radioss2020) lays them out; the pair law of each."""
    lines = [l.rstrip("\n") for l in open(path)]
    comments = [l for l in lines if l.startswith("#")]
    cards = [l for l in lines if l and not l.startswith("#")]
    fr, i = {}, 0
    while i < len(cards):
        if cards[i].startswith("/FRICTION/"):
            fid = int(cards[i].split("/")[2])
            ifric, iform = int(col(cards[i + 2], 1, 10)), int(col(cards[i + 2], 41, 50))
            j, pairs = i + 5, []
            while j < len(cards) and not cards[j].startswith("/"):
                pc, a, b = cards[j], cards[j + 1], cards[j + 2]
                c = [col(a, 1 + 20 * k, 20 + 20 * k) for k in range(5)]
                pr = dict(parts=(int(col(pc, 21, 30)), int(col(pc, 31, 40))), idir=int(col(pc, 51, 60)),
                          c=c, fric=col(b, 21, 40))
                if pr["idir"] == 1:  # direction 2's two cards follow
                    a2, b2 = cards[j + 3], cards[j + 4]
                    pr["dir2"] = dict(c=[col(a2, 1 + 20 * k, 20 + 20 * k) for k in range(5)], fric=col(b2, 21, 40))
                pairs.append(pr)
                j += 5 if int(col(pc, 51, 60)) == 1 else 3
            fr[fid] = dict(ifric=ifric, iform=iform, pairs=pairs)
            i = j
        else:
            i += 1
    bands = []  # (fric_ID, v_lo, v_hi) from the header
    for l in comments:
        m = re.match(r"# band \d+: /FRICTION/(\d+) for v (\S+) to (\S+) mm/s", l)
        if m:
            bands.append((int(m.group(1)), float(m.group(2)), float(m.group(3))))
    stated = None
    for l in comments:
        m = re.search(r"max relative error inside the fitted range: (\S+) %", l)
        if m:
            stated = float(m.group(1)) / 100
    if stated is None:
        sys.exit(f"{path}: no stated maximum relative error in the header")
    return fr, bands, stated


def set_iform(path, iform):
    """Columns 41-50 of the Ifric card (the second card after each /FRICTION/ID) set to iform."""
    lines = open(path).read().split("\n")
    out, after = [], -1
    for l in lines:
        if l.startswith("/FRICTION/"):
            after = 0
        elif after >= 0 and l and not l.startswith("#"):
            after += 1
            if after == 2:
                l = l.ljust(50)[:40] + f"{iform:10d}" + l[50:]
                after = -1
        out.append(l)
    open(path, "w").write("\n".join(out))


def poly_mu(pair, p, v):
    c1, c2, c3, c4, c5 = pair["c"]
    return max(1e-30, pair["fric"] + (c1 + c4 * p) * p + (c2 + c3 * p) * v + c5 * v * v)


# ------------------------------------------------------------------ the deck
def plate_cards():
    """6 x 6 nodes at x, y = -5 .. 20 step 5, z = 0; 25 shells (IDs 1..36, 1..25)."""
    xs = [-5 + 5 * k for k in range(6)]
    nodes, shells = [], []
    nid = lambda i, j: 1 + i + 6 * j
    for j in range(6):
        for i in range(6):
            nodes.append(f"{nid(i, j):10d}{xs[i]:20g}{xs[j]:20g}{0:20g}")
    for j in range(5):
        for i in range(5):
            shells.append(f"{1 + i + 5 * j:10d}{nid(i, j):10d}{nid(i + 1, j):10d}{nid(i + 1, j + 1):10d}{nid(i, j + 1):10d}")
    return "\n".join(nodes), "\n".join(shells)


def fill(template, **kw):
    return open(os.path.join(HERE, template)).read().format(**kw)


def run(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, env=dict(os.environ, OMP_NUM_THREADS="1"))
    return r.returncode, open(os.path.join(cwd, log), errors="replace").read()


def counts(text):
    """Errors and warnings as the starter's summary states them."""
    e = re.findall(r"(\d+)\s+ERROR\(S\)", text)
    w = re.findall(r"(\d+)\s+WARNING\(S\)", text)
    return (int(e[-1]) if e else None), (int(w[-1]) if w else None)


def read_th(case_dir, run_name, th_to_csv):
    """The /TH/INTER channels FNZ and FTX of the T01 file, via OpenRadioss/Tools th_to_csv.

    th_to_csv names the columns and turns cumulated impulses into forces (central differences)
    only when the T01 file has its _TITLES companion; otherwise the group's channels come as
    "<group> var N" in the order of the /TH/INTER card (FNX FNY FNZ FTX FTY FTZ: the last six
    columns) and stay impulses.  Returns (time, I_N, I_T) as cumulated impulses either way."""
    t01 = os.path.join(case_dir, run_name + "T01")
    if not os.path.exists(t01):
        return None
    subprocess.run([th_to_csv, t01], cwd=case_dir, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if not os.path.exists(t01 + ".csv"):
        return None
    with open(t01 + ".csv") as f:
        rows = list(csv.reader(f))
    head = [h.strip().upper() for h in rows[0]]
    data = [[float(x) for x in r if x.strip()] for r in rows[1:] if r and r[0].strip()]
    t = [r[0] for r in data]
    named = [k for k, h in enumerate(head) if h.split()[-1:] in (["FNZ"], ["FTX"])]
    if len(named) == 2:  # forces: integrate back to impulses (trapezoid)
        kn = next(k for k, h in enumerate(head) if h.split()[-1] == "FNZ")
        kx = next(k for k, h in enumerate(head) if h.split()[-1] == "FTX")
        ky = next(k for k, h in enumerate(head) if h.split()[-1] == "FTY")
        imp = lambda k: [0.0] + [sum(0.5 * (data[j][k] + data[j + 1][k]) * (t[j + 1] - t[j]) for j in range(i))
                                 for i in range(1, len(t))]
        return t, imp(kn), imp(kx), imp(ky)
    n = len(data[0])
    return t, [r[n - 4] for r in data], [r[n - 3] for r in data], [r[n - 2] for r in data]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("model")
    ap.add_argument("--out", required=True)
    ap.add_argument("--direction", default="rd")
    ap.add_argument("--points", nargs="+", default=["4,10", "8,50", "13,95"])
    ap.add_argument("--densities", nargs="+", default=["real=2.7e-9", "scaled=2.7e-6"])
    ap.add_argument("--drawbend", default=os.path.join(HERE, "..", "..", "..", "build", "src", "drawbend"))
    ap.add_argument("--rad", help="use this exported file instead of running drawbend export")
    ap.add_argument("--t-end", type=float, default=0.010)
    ap.add_argument("--dry", action="store_true", help="write the decks only")
    ap.add_argument("--parts", default="1,2")
    ap.add_argument("--rd-vector", default="1,0,0")
    ap.add_argument("--iform", type=int, choices=[0, 1, 2])
    ap.add_argument("--engine", help="engine executable (default: $OPENRADIOSS_PATH/exec/engine_linux64_gf)")
    a = ap.parse_args()
    rdv = [float(x) for x in a.rd_vector.split(",")]
    nrd = math.sqrt(sum(x * x for x in rdv))
    along = abs(rdv[0]) / nrd  # 1: sliding (+X) along RD, 0: along TD
    if a.direction == "ortho" and 1e-9 < along < 1 - 1e-9:
        sys.exit("--direction ortho: --rd-vector must lie along X or Y (the law compared is RD's or TD's)")
    slid = "td" if a.direction == "ortho" and along < 0.5 else "rd" if a.direction == "ortho" else a.direction
    orpath = os.environ.get("OPENRADIOSS_PATH", "")
    if not orpath and not a.dry:
        sys.exit("OPENRADIOSS_PATH is not set (source openradioss_env.sh of build_openradioss.sh)")
    starter = os.path.join(orpath, "exec", "starter_linux64_gf")
    engine = a.engine or os.path.join(orpath, "exec", "engine_linux64_gf")
    th_to_csv = os.environ.get("TH_TO_CSV") or shutil.which("th_to_csv") or ("" if a.dry else sys.exit("TH_TO_CSV not set"))
    os.makedirs(a.out, exist_ok=True)
    rad = os.path.join(a.out, "friction_openradioss.rad")
    if a.rad:
        shutil.copy(a.rad, rad)
    else:
        subprocess.run([a.drawbend, "export", a.model, "--to", "openradioss", "--parts", a.parts, "--direction",
                        a.direction, "--rd-vector", a.rd_vector, "--out", rad], check=True)
    if a.iform is not None:
        set_iform(rad, a.iform)
    friction_text = open(rad).read().rstrip("\n")
    fr, bands, stated = read_rad(rad)
    law, dom = read_law(a.model, slid)
    plate_nodes, plate_shells = plate_cards()
    t_end = a.t_end
    t1, t2 = 0.2 * t_end, 0.4 * t_end  # load ramp, speed ramp
    t_a = 0.5 * t_end                  # steady window [t_a, t_end]
    rows = []
    echo_done = False
    for dens in a.densities:
        name, rho = dens.split("=")
        for pt in a.points:
            p, v = (float(x) for x in pt.split(","))
            fid = next((b[0] for b in bands if b[1] <= v <= b[2]), min(fr))
            run_name = "blockslide"
            case = os.path.join(a.out, f"{name}_p{p:g}_v{v:g}")
            os.makedirs(case, exist_ok=True)
            kw = dict(run=run_name, pressure=f"{p:g}", speed=f"{v:g}", t1=f"{t1:g}", t2=f"{t2:g}", tend=f"{t_end:g}",
                      rho_block=rho, node_force=f"{-p * 25:g}", fric_id=fid, plate_nodes=plate_nodes,
                      plate_shells=plate_shells, friction=friction_text, dt_th=f"{t_end / 1000:g}")
            open(os.path.join(case, run_name + "_0000.rad"), "w").write(fill("blockslide_0000.rad.in", **kw))
            open(os.path.join(case, run_name + "_0001.rad"), "w").write(fill("blockslide_0001.rad.in", **kw))
            if a.dry:
                continue
            rc_s, out_s = run([starter, "-i", run_name + "_0000.rad", "-np", "1"], case, "starter.log")
            listing = os.path.join(case, run_name + "_0000.out")
            lst = open(listing, errors="replace").read() if os.path.exists(listing) else ""
            ne, nw = counts(out_s + "\n" + lst)
            if not echo_done and lst:
                shutil.copy(listing, os.path.join(a.out, "starter_listing_first_case.out"))
                echo_done = True
            eng = eng_y = None
            if rc_s == 0 and ne == 0:
                rc_e, out_e = run([engine, "-i", run_name + "_0001.rad"], case, "engine.log")
                th = read_th(case, run_name, th_to_csv)
                if th:
                    t, i_n, i_t, i_ty = th
                    ia = min(range(len(t)), key=lambda k: abs(t[k] - t_a))
                    dn, dt_ = i_n[-1] - i_n[ia], i_t[-1] - i_t[ia]
                    if dn != 0:
                        eng = abs(dt_ / dn)
                        eng_y = abs((i_ty[-1] - i_ty[ia]) / dn)
            pl = [pr for pr in fr[fid]["pairs"] if set(pr["parts"]) == {1, 2}]
            if pl and a.direction == "ortho" and slid == "td":
                pl = [pl[0]["dir2"]]
            poly = poly_mu(pl[0], p, v) if pl else float("nan")
            mu_law = law(p, v)
            rows.append(dict(case=name, rho=rho, p=p, v=v, fid=fid, errors=ne, warnings=nw, engine=eng, poly=poly,
                             law=mu_law, across=eng_y))
    # report
    lines = [f"stated max relative error of the file: {100 * stated:.3f} %  (model {a.model}, direction {a.direction}, "
             f"parts {a.parts}, rd-vector {a.rd_vector}, sliding along +X = {slid.upper()}"
             + (f", Iform SET TO {a.iform} in the exported file" if a.iform is not None else ", Iform as exported")
             + (f", engine {a.engine}" if a.engine else "") + ")",
             "| case | rho [Mg/mm^3] | p [MPa] | v [mm/s] | fric_ID | starter errors | warnings | engine F_T/F_N"
             " | engine F_across/F_N | exported polynomial | law | engine vs law | engine vs polynomial | within stated |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    ok = True
    for r in rows:
        e = r["engine"]
        rel = (e - r["law"]) / r["law"] if e is not None else float("nan")
        relp = (e - r["poly"]) / r["poly"] if e is not None else float("nan")
        good = e is not None and r["errors"] == 0 and r["warnings"] == 0 and abs(rel) <= stated
        ok &= good
        lines.append(f"| {r['case']} | {r['rho']} | {r['p']:g} | {r['v']:g} | {r['fid']} | {r['errors']} | {r['warnings']} | "
                     + (f"{e:.5f}" if e is not None else "no result") + " | "
                     + (f"{r['across']:.5f}" if r['across'] is not None else "-") + f" | {r['poly']:.5f} | {r['law']:.5f} | "
                     f"{100 * rel:+.2f} % | {100 * relp:+.2f} % | {'yes' if good else 'NO'} |")
    text = "\n".join(lines) + "\n"
    open(os.path.join(a.out, "blockslide_report.md"), "w").write(text)
    print(text)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
