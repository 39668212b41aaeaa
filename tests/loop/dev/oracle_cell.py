#!/usr/bin/env python3
"""Oracle permutation p of a one-cell (interaction) effect on a scored set of
blind_dev.sh (issue 50 diagnosis; DEVELOPMENT seeds only, it reads truth.json).

Is the set detectable at all with its data?  The true column's true shape g
(truth.json's `shape`, x scaled to [0, 1] over the data) is tested on the base
model's held-out residual (loop/tables/residuals.csv, resid_before_N) with ONE
degree of freedom, by test means (a test-level effect: a test is the unit),
centred per block (the `pin` column: rotating / fixed) inside the cell:
  fixed    the true cell only; g permuted between the tests of the cell and
           block; no multiplicity at all (the best any screen could do);
  searched every cell (each value of pin_diameter_mm, speed_mm_s,
           direction_deg, lubricant with 4+ tests) by its 1-dof F-like ratio,
           the maximum over cells inside each permutation, g permuted between
           the tests of a block (the screen's scheme for a test-level column):
           the shape known, the cell searched.
Both are exact permutation p-values (1 + #{T* >= T}) / (1 + P) of a valid test;
compare them with the screen's threshold alpha / m (about 0.0018).  Row-level
columns are reduced to test means too (weaker than the screen's within-test
permutation for them).  Shapes it cannot parse are reported, not guessed.
usage: oracle_cell.py PERMUTATIONS SETDIR...   (SETDIR: blind_dev.sh's setN)"""
import csv, json, math, random, re, sys

INPUTS = ["pin_diameter_mm", "speed_mm_s", "direction_deg", "lubricant"]
ALIASES = {"pin": "pin_diameter_mm", "speed": "speed_mm_s", "direction": "direction_deg"}  # generator 1's cell names


def table(path):
    with open(path) as f:
        return list(csv.DictReader(l for l in f if not l.startswith("#")))


def shape_values(shape, xs):
    """g per row from truth.json's shape text; raises on a shape it does not know."""
    lo, hi = min(xs), max(xs)
    m = re.match(r"(?:one level apart|random levels|monotone then flat|levels) \[(.*)\]", shape)
    if m:  # weights per distinct value, ascending
        w = [float(v) for v in m.group(1).split(",")]
        dv = sorted(set(xs))
        return [w[dv.index(v)] if dv.index(v) < len(w) else 0.0 for v in xs]
    e = shape.split(", x =")[0].split(" (x =")[0]
    m = re.match(r"step at x = ([0-9.]+)", shape)
    if m: e = "(x > %s) * 1.0" % m.group(1)
    m = re.match(r"bump at ([0-9.]+)", shape)
    if m: e = "exp(-((x - %s) / 0.15)**2)" % m.group(1)  # width not in the text: 0.15 assumed
    for word in ("threshold ", "saturating ", "sigmoid ", "power ", "U ", "periodic "):
        if e.startswith(word): e = e[len(word):]
    if e.strip() == "linear": e = "x"
    e = e.replace("2pi ", "2*pi*").replace("^", "**")
    e = re.sub(r"(\d)\s+x", r"\1*x", e)
    e = re.sub(r"(\d)\s*\(", r"\1*(", e)
    env = {"log": math.log, "exp": math.exp, "max": max, "min": min, "tanh": math.tanh, "sin": math.sin,
           "cos": math.cos, "abs": abs, "pi": math.pi}
    return [eval(e, dict(env, x=(v - lo) / (hi - lo) if hi > lo else 0.0)) for v in xs]


def tests_of(d, truth):
    """Per test: block, weight (rows), mean residual, mean g, the inputs' raw values."""
    rows = table(d + "/loop/tables/residuals.csv")
    raw = table(d + "/data.csv")  # residuals.csv's `line` is the file line: 2 comment lines, the header
    g = shape_values(truth["shape"], [float(r[truth["variable"]]) for r in rows])
    T = {}
    for i, r in enumerate(rows):
        x = raw[int(r["line"]) - 4]
        e = T.setdefault(r["test_id"], [r["pin"], 0, 0.0, 0.0, {c: x[c] for c in INPUTS}])
        e[1] += 1; e[2] += float(r["resid_before_N"]); e[3] += g[i]
    return [(e[0], e[1], e[2] / e[1], e[3] / e[1], e[4]) for _, e in sorted(T.items())]


def same(a, b):
    try: return abs(float(a) - float(b)) < 1e-6
    except ValueError: return a.strip() == b.strip()


def cell_stat(idx_blocks, w, r, gv, s2):
    """1-dof statistic of g on r over the cell's tests, centred per block: (sum w g r)^2 / (sum w g^2) / s2."""
    num = den = 0.0
    for s in idx_blocks:
        sw = sum(w[i] for i in s)
        mg = sum(w[i] * gv[i] for i in s) / sw
        mr = sum(w[i] * r[i] for i in s) / sw
        for i in s:
            gc = gv[i] - mg
            num += w[i] * gc * (r[i] - mr); den += w[i] * gc * gc
    return num * num / den / s2 if den > 0 else 0.0


def cells_of(tests, only=None):
    """(name, value, tests per block, residual variance) for every cell (or the one named)."""
    w = [t[1] for t in tests]; r = [t[2] for t in tests]
    out = []
    for c in INPUTS:
        for v in sorted(set(t[4][c] for t in tests)):
            if only and not (c == only[0] and same(v, only[1])): continue
            by = {}
            for i, t in enumerate(tests):
                if same(t[4][c], v): by.setdefault(t[0], []).append(i)
            blocks = [s for s in by.values() if len(s) >= 2]
            n = sum(len(s) for s in blocks)
            if n < 4: continue
            ss = 0.0
            for s in blocks:
                m = sum(w[i] * r[i] for i in s) / sum(w[i] for i in s)
                ss += sum(w[i] * (r[i] - m) ** 2 for i in s)
            out.append((c, v, blocks, ss / max(1, n - len(blocks))))
    return out


def perm_p(tests, cells, groups, P, seed):
    """Max over the cells of the 1-dof statistic, g permuted within each group of tests."""
    w = [t[1] for t in tests]; r = [t[2] for t in tests]; g = [t[3] for t in tests]
    def stat(gv): return max(cell_stat(b, w, r, gv, s2) for _, _, b, s2 in cells)
    T0 = stat(g)
    best = max(cells, key=lambda cl: cell_stat(cl[2], w, r, g, cl[3]))
    rng, ge = random.Random(seed), 0
    for _ in range(P):
        gp = list(g)
        for s in groups:
            v = [g[i] for i in s]; rng.shuffle(v)
            for i, x in zip(s, v): gp[i] = x
        ge += stat(gp) >= T0 * (1 - 1e-12)
    return (1 + ge) / (1 + P), best


def main():
    P = int(sys.argv[1])
    for d in sys.argv[2:]:
        t = json.load(open(d + "/truth.json"))
        c, v = [s.strip() for s in t["cell"].split("=")]
        if c in ALIASES: c, v = ALIASES[c], v.split()[0]
        head = "%s %s %s | cell %s = %s |" % (d, t["variable"], t["shape"][:36], c, v)
        try: tests = tests_of(d, t)
        except Exception as e:
            print(head, "not computed:", e); continue
        fixed = cells_of(tests, (c, v))
        if not fixed:
            print(head, "cell not found"); continue
        fb = fixed[0][2]
        pf, _ = perm_p(tests, fixed, fb, P, 1)
        allc = cells_of(tests)
        blocks = {}
        for i, x in enumerate(tests): blocks.setdefault(x[0], []).append(i)
        ps, best = perm_p(tests, allc, list(blocks.values()), P, 2)
        print(head, "tests in cell %d | fixed p %.5f | searched over %d cells p %.5f (best cell %s = %s) | %d perms"
              % (sum(len(s) for s in fb), pf, len(allc), ps, best[0], best[1], P), flush=True)


if __name__ == "__main__":
    main()
