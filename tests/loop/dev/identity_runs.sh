#!/bin/bash
# Byte-identity check of a pure speed change of the loop (issue 50 item 6):
# runs `drawbend loop` with --threads 1 and --threads 2 on 19 sets, then, given
# a second run's folder, `cmp`s every loop.md, loop_summary.json and tables/*.
# Sets: DEVELOPMENT seeds only (blind 52100000..52100007, wild 55100000..55100007;
# never 58000000-59999999, heldout_protocol_v5.md), two synth sets and the
# thesis data.
# usage: identity_runs.sh BIN OUT SETS [REF_OUT]
#   BIN drawbend binary; OUT its outputs; SETS the generated sets (made once,
#   reused); REF_OUT: an earlier OUT (another binary) to compare with
BIN=$1; OUT=$2; SETS=$3; REF=$4
REPO=$(cd "$(dirname "$0")/../../.." && pwd)
mkdir -p "$SETS" "$OUT"
classes=(level smooth interaction bending test-level null)
wclasses=(level smooth interaction channel test-level null)
if [ ! -f "$SETS/.done" ]; then
  for i in 0 1 2 3 4 5 6 7; do n=$(( (i/6)%2 ? 8 : 3 ))
    "$BIN" synth --generator blind --class ${classes[$((i%6))]} --seed $((52100000+i)) --noise $n --out "$SETS/blind$i" >/dev/null 2>&1
    "$BIN" synth --generator wild --class ${wclasses[$((i%6))]} --seed $((55100000+i)) --noise $n --out "$SETS/wild$i" >/dev/null 2>&1
  done
  "$BIN" synth --tests-per-pin 40 --rows-per-test 40 --seed 3 --out "$SETS/synth5k" >/dev/null 2>&1
  "$BIN" synth --effect drift --seed 7 --noise 5 --tests-per-pin 20 --rows-per-test 40 --out "$SETS/drift" >/dev/null 2>&1
  mkdir -p "$SETS/thesis" && cp "$REPO/data/measured/thesis_drawbend.csv" "$SETS/thesis/data.csv"
  touch "$SETS/.done"
fi
for d in "$SETS"/*/; do s=$(basename "$d"); mkdir -p "$OUT/$s"
  for t in 1 2; do
    "$BIN" loop "$d/data.csv" --out "$OUT/$s/t$t" --threads $t --figures '' > "$OUT/$s/t$t.log" 2>&1 || echo "FAIL $s t$t"
  done
done
[ -z "$REF" ] && exit 0
same=0; diff=0
for f in $(cd "$REF" && find . -path '*/t[12]/*' -type f \( -name loop.md -o -name loop_summary.json -o -path '*/tables/*' \) | sort); do
  if cmp -s "$REF/$f" "$OUT/$f"; then same=$((same+1)); else diff=$((diff+1)); echo "DIFF $f"; fi
done
echo "identical $same, different $diff"
[ $diff -eq 0 ]
