#!/usr/bin/env python3
"""Compare two sides of check_sides.sh: counts per generator and class, gains
and losses (effect sets detected on one side only), the one-sided sign test
P(Bin(G + L, 1/2) >= G), null alarms, and elapsed (median of per-set ratios,
ratio of sums). usage: cmp_sides.py OUT [S0 ...]  (default: every block in OUT)
Block generator: read from the line's class ('channel' only in wild, 'bending'
only in blind) and printed per block."""
import glob, math, os, statistics, sys

def read(path):
    rows = {}
    for line in open(path):
        f = line.split()
        if len(f) < 6 or not f[0].isdigit():
            continue
        rows[int(f[0])] = (f[1], f[3], float(f[5].rstrip('s')) if f[5].endswith('s') else float('nan'),
                           f[4], line.strip())
    return rows

out = sys.argv[1]
blocks = sys.argv[2:] or sorted({os.path.basename(p)[5:-4] for p in glob.glob(out + '/main_*.txt')})
G = L = 0; alarms = {'main': 0, 'branch': 0}; ratios = []; tm = tb = 0.0
per = {}  # (generator, class) -> [main detected, branch detected, sets]
changes = []
for s0 in blocks:
    m = read(f'{out}/main_{s0}.txt'); b = read(f'{out}/branch_{s0}.txt')
    gen = 'wild' if any(v[0] == 'channel' for v in m.values()) else 'blind' if any(v[0] == 'bending' for v in m.values()) else '?'
    for i in sorted(set(m) & set(b)):
        cm, om, em, fm, _ = m[i]; cb, ob, eb, fb, _ = b[i]
        seed = int(s0) + i
        tm += em; tb += eb
        if em > 0: ratios.append(eb / em)
        if cm == 'null':
            alarms['main'] += om == 'FALSE_ALARM'; alarms['branch'] += ob == 'FALSE_ALARM'
            if om != ob: changes.append(f'  null {seed}: {om} -> {ob}')
            continue
        c = per.setdefault((gen, cm), [0, 0, 0]); c[0] += om == 'detected'; c[1] += ob == 'detected'; c[2] += 1
        dm, db = om == 'detected', ob == 'detected'
        if db and not dm: G += 1; changes.append(f'  GAIN {seed} {cm}: {om} {fm} -> {ob} {fb}')
        elif dm and not db: L += 1; changes.append(f'  LOSS {seed} {cm}: {om} {fm} -> {ob} {fb}')
        elif om != ob or fm != fb: changes.append(f'  same-outcome {seed} {cm}: {om} {fm} -> {ob} {fb}')
n = G + L
p = sum(math.comb(n, k) for k in range(G, n + 1)) / 2 ** n if n else 1.0
print('generator class: main -> branch detected of n')
for (gen, cm), (a, c, t) in sorted(per.items()):
    print(f'  {gen:5s} {cm:12s} {a:3d} -> {c:3d} of {t}')
for gen in sorted({g for g, _ in per}):
    a = sum(v[0] for k, v in per.items() if k[0] == gen); c = sum(v[1] for k, v in per.items() if k[0] == gen)
    t = sum(v[2] for k, v in per.items() if k[0] == gen)
    print(f'  {gen:5s} all          {a:3d} -> {c:3d} of {t}')
print(f'G {G} / L {L}, p = {p:.4f}; null alarms main {alarms["main"]}, branch {alarms["branch"]}')
if ratios:
    print(f'elapsed: median ratio {statistics.median(ratios):.3f}, summed {tb:.0f} / {tm:.0f} s = {tb / tm:.3f}')
print('\n'.join(changes))
