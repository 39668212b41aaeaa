#!/usr/bin/env python3
"""DEVELOPMENT study (issue 50, branch h50-newkinds): kinds of data neither
synthetic generator writes.  Takes a set written by `drawbend synth --generator
blind|wild`, adds ONE undeclared perturbation of a named kind, runs the loop
on it and scores it with blind_dev.sh's rule (heldout_protocol.md): an effect
set is detected when the first step names a truth column (or a column whose
row partition equals it) AND the final held-out RMS <= 2 x the set's noise; on
a set without a planted effect, a step on an undeclared variable is a false
alarm.  Dev data only: fresh seeds 54500100+ (generator 1) and 54700100+
(wild); the guard refuses 58000000-60999999.

Kinds (checked against blind_synth.hpp and wild_synth.hpp: neither writes
any of them):
  nuisance (should NOT alarm, should not hide a planted effect):
    outliers      1.5 % of rows (at least 3) shifted by +-5..10 noise sd
    spikes        3 rows (logger glitches) shifted by +-30..60 noise sd
    slipped_grip  every row of one fixed-pin test shifted by +-5..10 noise sd
    heavy_tail    extra noise sd * t(3 dof) / sqrt(3) on every row
    hetero        extra noise N(0, (sd * F_out / mean F_out)^2): grows with force
    duplicates    5 % of rows written twice (the copy right after the row)
    row_ids       two columns unique per row: sample_uid (random hex) and
                  entry_no (1..N in file order), and a per-row free-text note
    lab_mu        the lab's own mu column, ln(F_out / F_back) / (pi / 2) from
                  the MEASURED forces (a function of the response)
  effects (SHOULD be found, with a column to name; planted on null sets):
    loadcell_gain a new column load_cell (2-3 ids drawn per test); one id
                  reads the outlet force (1 + g), |g| 1-3 %
    product       delta ~ z1 z2 (two standardized numeric decoys, centred) x
                  (F_out - F_back) / mean: an effect of the product of two columns
                  (a pure crossover: no main effect of either column alone)
    product_pos   the same with u1 u2, u = (x - min) / (max - min) in [0, 1]
                  (a product of two positive quantities: main effects too)
    running_in    a new column sample_no (1..n within the test, file order);
                  delta ~ exp(-(j - 1) / tau), tau 1-3 samples, centred, on
                  (F_out - F_back) / mean
Effect sizes of 'product' and 'running_in': RMS on the outlet force k x noise
sd, k uniform 2.5-6 (as both generators).  The score's noise for a nuisance
kind that adds noise is the expected total: sqrt(sd^2 + mean(added^2)).

usage: newkinds.py BIN OUTDIR KIND GEN BASE SEED0 N [LOOP ARGS...]
  KIND one of the above or 'none' (the unperturbed base); GEN blind|wild;
  BASE null (class null) or effect (the generator's effect classes in turn);
  set j: seed SEED0 + j, noise 3 N when j even else 8 N.
One line per set: kind gen j class noise outcome final/noise cpu_s | truth | steps
"""
import csv, io, json, math, os, random, resource, subprocess, sys, zlib

EFFECT_CLASSES = {"blind": ["level", "smooth", "interaction", "bending", "test-level"],
                  "wild": ["level", "smooth", "interaction", "channel", "test-level"]}
# numeric decoy columns of each generator (per row or per test), for 'product'
DECOYS = {"blind": ["humidity_pct", "tool_temp_C", "thickness_mm", "lube_film_g_m2"],
          "wild": ["load_cell_temp_C", "pin_temp_F", "ra_strip_um", "blank_thickness_um"]}
NUISANCE = ["outliers", "spikes", "slipped_grip", "heavy_tail", "hetero", "duplicates", "row_ids", "lab_mu"]
EFFECTS = ["loadcell_gain", "product", "product_pos", "running_in"]


def read_set(path):
    lines = open(path).read().splitlines(keepends=True)
    head = [l for l in lines if l.startswith("#")]
    body = [l for l in lines if not l.startswith("#")]
    rd = csv.reader(io.StringIO("".join(body)))
    cols = next(rd)
    return head, cols, [r for r in rd if r]


def write_set(path, head, cols, rows):
    with open(path, "w", newline="") as f:
        f.writelines(head)
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        w.writerows(rows)


def partition_aliases(cols, rows, carrier):
    """Columns whose row partition equals the carrier's (value <-> value one to one)."""
    c = cols.index(carrier)
    out = []
    for k, name in enumerate(cols):
        a, b = {}, {}
        ok = True
        for r in rows:
            if a.setdefault(r[c], r[k]) != r[k] or b.setdefault(r[k], r[c]) != r[c]:
                ok = False
                break
        if ok:
            out.append(name)
    return out


def tests_of(cols, rows):
    t = {}
    ti = cols.index("test_id")
    for i, r in enumerate(rows):
        t.setdefault(r[ti], []).append(i)
    return t


def perturb(kind, gen, cols, rows, sd, rng):
    """Apply the kind in place; returns (cols, rows, truth_columns, added noise variance per row)."""
    fo, fb = cols.index("outlet_force_N"), cols.index("back_tension_N")
    F = [float(r[fo]) for r in rows]
    B = [float(r[fb]) for r in rows]
    rise = [f - b for f, b in zip(F, B)]
    mrise = sum(rise) / len(rise)
    n = len(rows)
    added = 0.0

    def set_f(i, v):
        rows[i][fo] = "%.4f" % v

    def plant(g):  # centred shape g (per row) on the force rise, RMS k sd
        m = sum(g) / n
        d = [(x - m) * r / mrise for x, r in zip(g, rise)]
        rms = math.sqrt(sum(x * x for x in d) / n)
        k = rng.uniform(2.5, 6)
        for i in range(n):
            set_f(i, F[i] + d[i] * k * sd / rms)
        return k

    truth, k = [], 0
    if kind == "outliers":
        m = max(3, round(0.015 * n))
        for i in rng.sample(range(n), m):
            s = rng.choice([-1, 1]) * rng.uniform(5, 10) * sd
            set_f(i, F[i] + s)
            added += s * s
    elif kind == "spikes":
        for i in rng.sample(range(n), 3):
            s = rng.choice([-1, 1]) * rng.uniform(30, 60) * sd
            set_f(i, F[i] + s)
            added += s * s
    elif kind == "slipped_grip":
        pin = cols.index("pin")
        t = tests_of(cols, rows)
        fixed = sorted(k_ for k_, ix in t.items() if rows[ix[0]][pin] == "fixed")
        s = rng.choice([-1, 1]) * rng.uniform(5, 10) * sd
        for i in t[rng.choice(fixed)]:
            set_f(i, F[i] + s)
            added += s * s
    elif kind == "heavy_tail":
        for i in range(n):
            z = rng.gauss(0, 1)
            chi = sum(rng.gauss(0, 1) ** 2 for _ in range(3))
            e = sd * z / math.sqrt(chi / 3) / math.sqrt(3)
            set_f(i, F[i] + e)
            added += e * e
    elif kind == "hetero":
        mf = sum(F) / n
        for i in range(n):
            e = rng.gauss(0, sd * F[i] / mf)
            set_f(i, F[i] + e)
            added += e * e
    elif kind == "duplicates":
        dup = set(rng.sample(range(n), max(3, round(0.05 * n))))
        new = []
        for i, r in enumerate(rows):
            new.append(r)
            if i in dup:
                new.append(list(r))
        rows[:] = new
    elif kind == "row_ids":
        cols += ["sample_uid", "entry_no", "note"]
        words = ["visual ok", "slight pick-up", "edge burr", "ok", "re-clamped", "oil wiped"]
        for i, r in enumerate(rows):
            r += ["%08x" % rng.getrandbits(32), str(i + 1),
                  "piece %d of %s, %s" % (i + 1, r[0], rng.choice(words))]
    elif kind == "lab_mu":
        cols.append("mu_lab")
        for i, r in enumerate(rows):
            r.append("%.4f" % (math.log(F[i] / B[i]) / (math.pi / 2)))
    elif kind == "loadcell_gain":
        cols.append("load_cell")
        ids = ["LC-%d" % (100 + rng.randrange(900)) for _ in range(rng.choice([2, 3]))]
        t = tests_of(cols, rows)
        keys = list(t)
        rng.shuffle(keys)  # every id on at least two tests, the rest drawn
        per = {tid: ids[q % len(ids)] if q < 2 * len(ids) else rng.choice(ids) for q, tid in enumerate(keys)}
        bad, g = rng.choice(ids), rng.choice([-1, 1]) * rng.uniform(0.01, 0.03)
        for tid, ix in t.items():
            for i in ix:
                rows[i].append(per[tid])
                if per[tid] == bad:
                    set_f(i, F[i] * (1 + g))
        truth, k = ["load_cell"], g
    elif kind in ("product", "product_pos"):
        z1, z2 = rng.sample(DECOYS[gen], 2)
        zs = []
        for c in (z1, z2):
            x = [float(r[cols.index(c)]) for r in rows]
            m = sum(x) / n
            s = math.sqrt(sum((v - m) ** 2 for v in x) / n)
            if kind == "product_pos":
                zs.append([(v - min(x)) / (max(x) - min(x)) for v in x])
            else:
                zs.append([(v - m) / s for v in x])
        k = plant([a * b for a, b in zip(*zs)])
        truth = [z1, z2]
    elif kind == "running_in":
        cols.append("sample_no")
        tau = rng.uniform(1, 3)
        t = tests_of(cols, rows)
        j = [0] * n
        for ix in t.values():
            for q, i in enumerate(ix):
                j[i] = q + 1
        for i, r in enumerate(rows):
            r.append(str(j[i]))
        k = plant([math.exp(-(x - 1) / tau) for x in j])
        truth = ["sample_no"]
    elif kind != "none":
        raise SystemExit("unknown kind " + kind)
    return truth, k, added / n


def main():
    if len(sys.argv) < 8:
        raise SystemExit(__doc__)
    bin_, out, kind, gen, base, s0, N = sys.argv[1:8]
    extra = sys.argv[8:]
    s0, N = int(s0), int(N)
    for j in range(N):
        if 58000000 <= s0 + j < 61000000:
            raise SystemExit("seed %d is in the held-out block 58000000-60999999: not here" % (s0 + j))
    for j in range(N):
        seed = s0 + j
        sd = 3.0 if j % 2 == 0 else 8.0
        cls = "null" if base == "null" else EFFECT_CLASSES[gen][j % 5]
        d = os.path.join(out, "%s_%s_%s_%d" % (kind, gen, base, j))
        os.makedirs(d, exist_ok=True)
        subprocess.run([bin_, "synth", "--generator", gen, "--class", cls, "--seed", str(seed),
                        "--noise", "%g" % sd, "--out", d], check=True, capture_output=True)
        truth = json.load(open(d + "/truth.json"))
        head, cols, rows = read_set(d + "/data.csv")
        rng = random.Random(seed * 1000 + zlib.crc32(kind.encode()))
        new_truth, k, added = perturb(kind, gen, cols, rows, sd, rng)
        write_set(d + "/data.csv", head, cols, rows)
        aliases = list(truth.get("aliases", []))
        if new_truth:  # a planted new-kind effect is the set's truth
            aliases = sorted(set(a for c in new_truth for a in partition_aliases(cols, rows, c)))
        noise = math.sqrt(sd * sd + added)
        json.dump({"kind": kind, "truth_columns": new_truth, "aliases": aliases, "k_or_gain": k,
                   "noise_eff_N": noise}, open(d + "/newkind.json", "w"), indent=1)
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        with open(d + "/log", "w") as lg:
            subprocess.run([bin_, "loop", d + "/data.csv", "--out", d + "/loop", "--threads", "1",
                            "--figures", "", "--export", "none"] + extra, stdout=lg, stderr=lg)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = r1.ru_utime + r1.ru_stime - r0.ru_utime - r0.ru_stime
        try:
            r = json.load(open(d + "/loop/loop_summary.json"))
        except Exception as e:
            print(kind, gen, j, cls, sd, "ERROR", e, flush=True)
            continue
        st = r["steps"]
        fin = r["heldout_rms_N"] / noise
        effect = bool(new_truth) or cls != "null"
        if not effect:
            und = [s for s in st if s.get("class") == "undeclared variable"]
            res = "FALSE_ALARM" if und else "base_mismatch" if st else "quiet"
        else:
            # a pair step (h50-pairs) names a truth column when either of its two columns is one
            named = bool(st) and (st[0]["variable"] in aliases or any(c in aliases for c in st[0].get("columns", [])))
            res = "detected" if named and fin <= 2 else "named_high" if named else "no_step" if not st else "wrong_first"
        steps = "; ".join(s["variable"] + "->" + s["effect"] for s in st)
        tr = ",".join(new_truth) if new_truth else "%s %s %s" % (truth.get("variable"), truth.get("shape"), truth.get("channel"))
        print(kind, gen, j, cls, sd, res, "%.2f" % fin, "%.1fs" % cpu, "|", tr, "|", steps, flush=True)


if __name__ == "__main__":
    main()
