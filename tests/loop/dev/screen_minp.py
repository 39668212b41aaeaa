#!/usr/bin/env python3
"""The screen's first round on scored sets of blind_dev.sh (issue 50 diagnosis;
DEVELOPMENT seeds only, it reads truth.json): its family-wise false alarm rate
on null sets and how far the true column is from the threshold elsewhere.

Null sets (class i % 6 == 5): per set the smallest round-1 permutation p over
the undeclared candidates (kind `column` in loop/tables/candidates.csv), against
the screen's threshold alpha / m (m: every round-1 candidate, base-model terms
included) and against what m_u independent uniform p-values would give
(P(min p <= x) = 1 - (1 - x)^m_u, m_u the set's undeclared candidates).  A
p-value the sequential test stopped early on is (1 + #exceedances) / (1 +
permutations) after 100 or 300 permutations: valid but coarse (only the small
ones are sharp).  Interaction sets (i % 6 == 2): the first step, the true
column's round-1 p, permutations, held-out reduction and rank.
usage: screen_minp.py RUNDIR...   (RUNDIR: blind_dev.sh's OUTDIR with set0..)"""
import csv, glob, json, sys

ALPHA = 0.05


def round1(d):
    with open(d + "/loop/tables/candidates.csv") as f:
        return [r for r in csv.DictReader(l for l in f if not l.startswith("#")) if r["round"] == "1"]


def sets(run, cls):
    for d in sorted(glob.glob(run + "/set*"), key=lambda s: int(s.rsplit("set", 1)[1])):
        i = int(d.rsplit("set", 1)[1])
        if i % 6 == cls: yield i, d


def main():
    mins, mus, below = [], [], 0
    print("# null sets: round-1 min p over the undeclared candidates")
    for run in sys.argv[1:]:
        for i, d in sets(run, 5):
            rows = round1(d)
            col = [r for r in rows if r["kind"] == "column"]
            b = min(col, key=lambda r: float(r["p_value"]))
            thr = ALPHA / len(rows)
            mins.append(float(b["p_value"])); mus.append(len(col)); below += float(b["p_value"]) <= thr
            print("%s set%d m=%d m_u=%d thr=%.5f min_p=%s (%s, %s permutations, %s)"
                  % (run, i, len(rows), len(col), thr, b["p_value"], b["candidate"], b["permutations"], b["decision"]))
    n = len(mins)
    if n:
        print("# %d null sets, %d with min p <= alpha/m; m_u mean %.1f" % (n, below, sum(mus) / n))
        for x in (0.002, 0.005, 0.01, 0.02, 0.05):
            obs = sum(v <= x for v in mins)
            exp = sum(1 - (1 - x) ** k for k in mus) / n
            print("# P(min p <= %.3f): observed %d/%d = %.3f, independent uniform %.3f" % (x, obs, n, obs / n, exp))
    print("# interaction sets: the true column in round 1")
    for run in sys.argv[1:]:
        for i, d in sets(run, 2):
            t = json.load(open(d + "/truth.json"))
            rows = round1(d)
            st = json.load(open(d + "/loop/loop_summary.json"))["steps"]
            first = st[0]["variable"] if st else "-"
            tr = [r for r in rows if r["candidate"] in t["aliases"]]
            print("%s set%d thr=%.5f first=%s%s %s" % (run, i, ALPHA / len(rows), first, " (true)" if first in t["aliases"] else "",
                  " ".join("%s p=%s n=%s cv=%s rank=%s" % (r["candidate"], r["p_value"], r["permutations"], r["cv_reduction"], r["rank"])
                           for r in tr)))


if __name__ == "__main__":
    main()
