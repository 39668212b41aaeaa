#!/usr/bin/env bash
# `--threads N` on every drawbend command (issue 22, item 5; cli/threads.hpp).
# Answers:
#  - N = -1 is an input error on each of the nine commands: exit 2 and the
#    message "--threads: expected a whole number from 0", before any work (no
#    run folder is made); so is N = 1025, one above io::kMaxThreads (run,
#    block-deck), and a deck with [numerics] threads = 1025 names its
#    file:line: key (100,000 threads crashed libgomp on a model that forks);
#  - block-deck, strip-deck, cup-deck and drawbend-deck (without --run) with
#    --threads 2 write "threads = 2" as a key of the deck's [numerics] table,
#    and without --threads write no threads key (the decks as before);
#  - cup-deck --threads 2 on a --base deck whose [numerics] already has
#    threads = 3 replaces that key (one threads key, = 2), and `drawbend run`
#    reads the deck and says "threads: 2 (the deck's [numerics] threads)";
#  - `drawbend run` of the block deck written with --threads 1 runs, and its
#    log says "threads: 1 (the deck's [numerics] threads)"; with --threads 2
#    on the command line it says "threads: 2 (--threads)".
# Usage: threads_option.sh DRAWBEND SCRATCH_DIR
set -u
db=$1 tmp=$2
rm -rf "$tmp"
mkdir -p "$tmp"
fail=0
bad() { echo "FAILED: $*"; fail=1; }

printf 'pin_diameter_mm,back_tension_N,bending_force_N\n12.7,1500,300\n25.4,1500,120\n' > "$tmp/fb.csv"
"$db" block-deck --out "$tmp/block.toml" > /dev/null || bad "block-deck"
neg() {  # neg NAME ARGS...: exit 2 with the --threads message
  local name=$1
  shift
  out=$("$db" "$@" 2>&1)
  rc=$?
  if [ "$rc" != 2 ] || ! grep -q -- "--threads: expected a whole number from 0" <<< "$out"; then
    bad "$name --threads -1: exit $rc, output: $(head -3 <<< "$out")"
  else
    echo "ok   $name --threads -1: exit 2, $(grep -m1 -- '--threads' <<< "$out")"
  fi
}
neg run run "$tmp/block.toml" --out "$tmp/run_neg" --threads -1
out=$("$db" run "$tmp/block.toml" --out "$tmp/run_big" --threads 1025 2>&1); rc=$?
[ $rc = 2 ] && grep -q -- "to 1024, found 1025" <<< "$out" && echo "ok   run --threads 1025: exit 2" || bad "run --threads 1025: exit $rc: $out"
out=$("$db" block-deck --threads 1025 2>&1); rc=$?
[ $rc = 2 ] && grep -q -- "to 1024, found 1025" <<< "$out" && echo "ok   block-deck --threads 1025: exit 2" || bad "block-deck --threads 1025: exit $rc"
sed 's/^\[numerics\]$/[numerics]\nthreads = 1025/' "$tmp/block.toml" > "$tmp/block_big.toml"
out=$("$db" run "$tmp/block_big.toml" --out "$tmp/run_big2" 2>&1); rc=$?
[ $rc = 2 ] && grep -q "block_big.toml:[0-9]*.*numerics.threads.*at most 1024" <<< "$out" &&
  echo "ok   a deck's threads = 1025: exit 2, $(grep -m1 'numerics.threads' <<< "$out")" || bad "deck threads = 1025: exit $rc: $out"
[ -e "$tmp/run_neg" ] && bad "run --threads -1 made its output folder"
neg drawbend-deck drawbend-deck --threads -1 --run "$tmp/dd_neg"
[ -e "$tmp/dd_neg" ] && bad "drawbend-deck --threads -1 made its run folder"
neg drawbend-deck-print drawbend-deck --threads -1
neg block-deck block-deck --threads -1
neg strip-deck strip-deck --threads -1
neg cup-deck cup-deck --threads -1
neg loop loop "$tmp/fb.csv" --out "$tmp/loop_neg" --threads -1
neg synth synth --out "$tmp/synth_neg" --threads -1
neg export export "$tmp/none.toml" --to abaqus --threads -1
neg model-loop model-loop "$tmp/fb.csv" --out "$tmp/ml_neg" --threads -1
neg loop-model-fe loop "$tmp/fb.csv" --model fe --out "$tmp/ml_neg2" --threads -1

in_numerics() {  # in_numerics FILE: the [numerics] table has "threads = 2"
  awk '/^\[/{t=$0} t=="[numerics]" && /^threads = 2( |$)/{f=1} END{exit !f}' "$1"
}
for cmd in block-deck strip-deck cup-deck drawbend-deck; do
  "$db" $cmd --threads 2 > "$tmp/$cmd.toml" 2> "$tmp/$cmd.err" || bad "$cmd --threads 2: exit $?"
  if in_numerics "$tmp/$cmd.toml"; then echo "ok   $cmd --threads 2: threads = 2 in [numerics]"
  else bad "$cmd --threads 2: no 'threads = 2' in [numerics]"; fi
  "$db" $cmd > "$tmp/$cmd.plain.toml" 2> /dev/null
  if grep -q '^threads' "$tmp/$cmd.plain.toml"; then bad "$cmd without --threads wrote a threads key"; fi
done

data=$(cd "$(dirname "$0")/../../data" && pwd)
sed -e "s#\"\.\./#\"$data/#g" -e 's/^\[numerics\]$/[numerics]\nthreads = 3/' "$data/cases/cup_draw.toml" > "$tmp/cup_base.toml"
grep -q '^threads = 3' "$tmp/cup_base.toml" || bad "the test's base deck has no threads = 3"
"$db" cup-deck --base "$tmp/cup_base.toml" --threads 2 --stroke 1 --cycles 600 > "$tmp/cup_t.toml" || bad "cup-deck --base --threads 2: exit $?"
if [ "$(grep -c '^threads' "$tmp/cup_t.toml")" = 1 ] && in_numerics "$tmp/cup_t.toml"; then
  echo "ok   cup-deck --base (threads = 3) --threads 2: one threads key, = 2"
else
  bad "cup-deck --base --threads 2: $(grep -n '^threads' "$tmp/cup_t.toml" | tr '\n' ' ')"
fi
"$db" run "$tmp/cup_t.toml" --out "$tmp/cup_run" --quiet > "$tmp/cup_run.log" 2>&1 || bad "run of that cup deck: exit $?"
grep -q "threads: 2 (the deck's \[numerics\] threads)" "$tmp/cup_run.log" && echo "ok   run of that cup deck: threads: 2" ||
  bad "cup run log: $(grep -m3 -E 'threads|error' "$tmp/cup_run.log")"

"$db" block-deck --threads 1 --out "$tmp/block1.toml" > /dev/null || bad "block-deck --threads 1 --out"
"$db" run "$tmp/block1.toml" --out "$tmp/run1" --quiet > "$tmp/run1.log" 2>&1 || bad "run of the --threads 1 deck: exit $?"
grep -q "threads: 1 (the deck's \[numerics\] threads)" "$tmp/run1.log" && echo "ok   run: threads: 1 from the deck" ||
  bad "run log: $(grep threads "$tmp/run1.log")"
"$db" run "$tmp/block1.toml" --out "$tmp/run2" --quiet --threads 2 > "$tmp/run2.log" 2>&1 || bad "run --threads 2: exit $?"
grep -q "threads: 2 (--threads)" "$tmp/run2.log" && echo "ok   run --threads 2: threads: 2 from the command line" ||
  bad "run --threads 2 log: $(grep threads "$tmp/run2.log")"
if [ $fail = 0 ]; then echo "threads option: all ok"; else exit 1; fi
