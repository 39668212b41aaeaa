#!/bin/bash
# Development scorer of the loop on generator 1 (blind) sets, scored as in
# chapters/ch7-closing-the-loop/heldout_protocol.md (set i: class i % 6, noise
# 3 N when (i / 6) even, else 8 N; detected = first step names an alias AND
# final held-out RMS <= 2 x the true noise sd; null: a step on an undeclared
# variable (class "undeclared variable") is a false alarm, steps only on the
# model's own inputs (class "base model") are base_mismatch, issue 50 item 4).
# ONLY for development seeds (heldout_protocol_v3.md: 50500000..50500143,
# 52000000..52999999, 53100000..53100143; wild 54200000..54200143 and
# 55000000+; heldout_protocol_v4.md adds 57100000..57100143 and
# 57200000..57200143); never on held-out seeds in 58000000..60999999 that no recorded run has
# spent (the guard below; heldout_protocol_v7.md), nor in 62900000..62999999
# (heldout_protocol_v11.md), nor in 64900000..64999999 (heldout_protocol_v12.md),
# nor in 72000000..72099999 (heldout_protocol_v13.md), nor in 72200000..72299999
# (heldout_protocol_v14.md), nor in 75500000..75599999 (heldout_protocol_v15.md),
# nor in 76600000..76699999 (heldout_protocol_v16.md), nor in 79800000..79899999
# (heldout_protocol_v17.md), nor in 80600000..80699999 (heldout_protocol_v18.md),
# nor in 82800000..82899999 (heldout_protocol_v19.md), nor in 84000000..84099999
# (heldout_protocol_v20.md), nor in 85200000..85299999 (heldout_protocol_v21.md), nor in 88600000..88699999
# (heldout_protocol_v22.md).
# usage: blind_dev.sh BIN SEED0 N OUTDIR [PERM] [FIRST] [GEN]
#   LOOP_ARGS (environment): extra loop options, e.g. "--cell-probes true"
#   PERM: permutation cap, default 20000 as the loop (with 2000 no candidate
#   can be decided significant at alpha/25 candidates: every step undecided)
#   GEN blind (default) or wild (generator 2: class 'channel' in place of
#   'bending'); one line per set: i class noise outcome final/noise time | truth | steps
BIN=$1; S0=$2; N=$3; OUT=$4; PERM=${5:-20000}; FIRST=${6:-0}; GEN=${7:-blind}
# Seeds in 58000000-60999999 are held out unless a held-out run has spent
# them (heldout_record.md): runs 7-8 (58100000, 58200000 + 0..143), 9-10
# (59100000, 59200000 + 0..47), 11-12 (60100000, 60200000 + 0..47) and 13-14
# (60300000, 60400000 + 0..47) and 15-16 (60500000, 60600000 + 0..47)
# and 17-18 (60700000, 60800000 + 0..47) and 19-20 (60900000, 60950000 +
# 0..47, 2026-12-05) and 21-22 (62900000, 62950000 + 0..47, 2026-12-05)
# and 23-24 (64900000, 64950000 + 0..47, 2026-12-06) and 25-26 (72000000,
# 72050000 + 0..47, 2026-12-06) and 27-28 (72200000, 72250000 + 0..47,
# 2026-12-06) and 29-30 (75500000, 75550000 + 0..47, 2026-12-07) and 31-32
# (76600000, 76650000 + 0..47, 2026-12-07) and 33-34 (79800000, 79850000 +
# 0..47, 2026-12-07) and 35-36 (80600000, 80650000 + 0..47, 2026-12-07) and
# 37-38 (82800000, 82850000 + 0..47, 2026-12-07) and 39-40 (84000000, 84050000 +
# 0..47, 2026-12-07) and 41-42 (85200000, 85250000 + 0..47, 2026-12-08) are
# development data now.
released() {  # is seed $1 spent by a recorded held-out run?
  local s=$1
  for r in 58100000:144 58200000:144 59100000:48 59200000:48 60100000:48 60200000:48 60300000:48 60400000:48 60500000:48 60600000:48 60700000:48 60800000:48 60900000:48 60950000:48 62900000:48 62950000:48 64900000:48 64950000:48 72000000:48 72050000:48 72200000:48 72250000:48 75500000:48 75550000:48 76600000:48 76650000:48 79800000:48 79850000:48 80600000:48 80650000:48 82800000:48 82850000:48 84000000:48 84050000:48 85200000:48 85250000:48; do
    local b=${r%%:*} n=${r##*:}
    if (( s >= b && s < b + n )); then return 0; fi
  done
  return 1
}
for ((i=FIRST;i<N;i++)); do
  s=$((S0+i))
  if (( (s >= 58000000 && s < 61000000) || (s >= 62900000 && s < 63000000) || (s >= 64900000 && s < 65000000) || (s >= 72000000 && s < 72100000) || (s >= 72200000 && s < 72300000) || (s >= 75500000 && s < 75600000) || (s >= 76600000 && s < 76700000) || (s >= 79800000 && s < 79900000) || (s >= 80600000 && s < 80700000) || (s >= 82800000 && s < 82900000) || (s >= 84000000 && s < 84100000) || (s >= 85200000 && s < 85300000) || (s >= 88600000 && s < 88700000) )) && ! released $s; then
    if (( s >= 88600000 )); then why=heldout_protocol_v22.md; elif (( s >= 85200000 )); then why=heldout_protocol_v21.md; elif (( s >= 84000000 )); then why=heldout_protocol_v20.md; elif (( s >= 82800000 )); then why=heldout_protocol_v19.md; elif (( s >= 80600000 )); then why=heldout_protocol_v18.md; elif (( s >= 79800000 )); then why=heldout_protocol_v17.md; elif (( s >= 76600000 )); then why=heldout_protocol_v16.md; elif (( s >= 75500000 )); then why=heldout_protocol_v15.md; elif (( s >= 72200000 )); then why=heldout_protocol_v14.md; elif (( s >= 72000000 )); then why=heldout_protocol_v13.md; elif (( s >= 64900000 )); then why=heldout_protocol_v12.md; elif (( s >= 62900000 )); then why=heldout_protocol_v11.md; else why="heldout_protocol_v7.md: 58000000-60999999, unless a recorded run spent it"; fi
    echo "seed $s is held out ($why): not for development" >&2; exit 2; fi
done
classes=(level smooth interaction bending test-level null)
if [ "$GEN" = wild ]; then classes=(level smooth interaction channel test-level null); fi
mkdir -p $OUT
for ((i=FIRST;i<N;i++)); do
  cls=${classes[$((i%6))]}; if (( (i/6)%2 )); then noise=8; else noise=3; fi
  s=$((S0+i)); d=$OUT/set$i
  $BIN synth --generator $GEN --class $cls --seed $s --noise $noise --out $d >/dev/null 2>&1
  /usr/bin/time -f "%U %e" -o $d/time $BIN loop $d/data.csv --out $d/loop --permutations $PERM --threads 1 $LOOP_ARGS >$d/log 2>&1
  python3 - $d $cls $noise $i <<'PY'
import json,sys
d,cls,noise,i=sys.argv[1],sys.argv[2],float(sys.argv[3]),sys.argv[4]
t=json.load(open(d+'/truth.json')); 
try: r=json.load(open(d+'/loop/loop_summary.json'))
except Exception as e: print(i,cls,'ERROR',e); sys.exit()
st=r['steps']; fin=r['heldout_rms_N']/noise
tm=open(d+'/time').read().split()[-1]
if cls=='null':  # issue 50 item 4: a step on the model's own inputs is base-model mismatch, not an alarm
  und=[s for s in st if s.get('class')=='undeclared variable']
  out='FALSE_ALARM' if und else 'base_mismatch' if st else 'quiet'
else:
  named = bool(st) and st[0]['variable'] in t['aliases']
  out = 'detected' if named and fin<=2 else 'named_high' if named else 'no_step' if not st else 'wrong_first'
steps='; '.join(s['variable']+'->'+s['effect'] for s in st)
print(i,cls,noise,out,'%.2f'%fin,tm+'s','|',t.get('variable'),t.get('shape'),t.get('channel'),t.get('cell'),'k=%.1f'%t.get('k',0),'sup=%s'%t.get('support_tests','-'),'|',steps)
PY
done
