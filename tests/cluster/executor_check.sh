#!/usr/bin/env bash
# The executors, for real (sim/executor.hpp; ctest cluster.executors):
#  1. three short draw-bend cases, a block slide, a strip draw and a cup run in
#     process (DRAWBEND_EXECUTOR=local);
#  2. the same through a command template (a shell wrapper that runs the job);
#  3. the same through a single-node Slurm started here (tests/cluster/local_slurm.sh);
#  4. Slurm again, one job cancelled (scancel) while it runs, after its solver
#     wrote summary.csv: the driver must fail naming the case, the job id and
#     CANCELLED, leave that case without a summary.csv, and a rerun must
#     complete with the same results.
# Every run's cases.csv, kinds.csv and cups.csv and every run folder's deck, reduction.csv, history, contact maps and
# ParaView files must equal the local run's byte for byte (summary.csv too,
# less its wall_time row; history.csv and summary.csv less their first line,
# result.toml less its deck = line, which names the
# deck's path, here another folder; run.log holds wall times and is not
# compared).
# Exit 77 (skipped) when Slurm cannot be started here (not root, no packages):
# steps 1-2 have then run and passed, and the output says what was skipped.
set -u
cases=$1 drawbend=$2 tmp=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$tmp"; mkdir -p "$tmp"
export DRAWBEND_BIN=$drawbend DRAWBEND_EXECUTOR_POLL=0.2
fail() { echo "FAIL: $*"; exit 1; }

same_runs() {  # same_runs A B: byte-identical outputs
  local a=$1 b=$2 f
  cmp "$a/cases.csv" "$b/cases.csv" || fail "cases.csv differs: $a vs $b"
  cmp "$a/kinds.csv" "$b/kinds.csv" || fail "kinds.csv (block, strip draw, cup) differs: $a vs $b"
  cmp "$a/cups.csv" "$b/cups.csv" || fail "cups.csv differs: $a vs $b"
  for f in "$a"/runs/*/*; do
    local n=${f#"$a"/}
    case $n in
      */run.log|*/job.log|*/slurm.log) continue ;;
      */summary.csv) diff <(tail -n +2 "$f" | grep -v '^wall_time') <(tail -n +2 "$b/$n" | grep -v '^wall_time') >/dev/null ||
        fail "$n differs" ;;
      */result.toml) # its deck = line names the deck by its path, which differs between the two folders
        diff <(grep -v '^deck = ' "$f") <(grep -v '^deck = ' "$b/$n") >/dev/null || fail "$n differs between $a and $b" ;;
      */history.csv) # its first line names the deck by its path, which differs between the two folders
        diff <(tail -n +2 "$f") <(tail -n +2 "$b/$n") >/dev/null || fail "$n differs between $a and $b" ;;
      *) cmp -s "$f" "$b/$n" || fail "$n differs between $a and $b" ;;
    esac
  done
}

t0=$(date +%s)
DRAWBEND_EXECUTOR=local "$cases" --out "$tmp/local" > "$tmp/local.log" 2>&1 || { cat "$tmp/local.log"; fail "local run"; }
echo "local: $(( $(date +%s) - t0 )) s"

t0=$(date +%s)
DRAWBEND_EXECUTOR='command:{drawbend} run {deck} --out {dir} {args} --quiet --threads {cores} > {dir}/run.log' \
  "$cases" --out "$tmp/command" > "$tmp/command.log" 2>&1 || { cat "$tmp/command.log"; fail "command executor run"; }
same_runs "$tmp/local" "$tmp/command"
echo "command executor: byte-identical to local ($(( $(date +%s) - t0 )) s)"
# A failing command is reported with the case and its exit code, and exits non-zero.
DRAWBEND_EXECUTOR='command:false {deck}' "$cases" --out "$tmp/cmdfail" > "$tmp/cmdfail.log" 2>&1 && fail "a failing command exited 0"
grep -q "executor command ended with exit 1" "$tmp/cmdfail.log" || { cat "$tmp/cmdfail.log"; fail "failing command not named"; }
echo "command executor: a failing launcher is reported ($(grep -m1 -o 'case case[0-9]: the executor command ended with exit 1' "$tmp/cmdfail.log"))"
# A bad executor name is an input error (exit 2) naming the variable.
DRAWBEND_EXECUTOR=sge "$cases" --out "$tmp/bad" > "$tmp/bad.log" 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "DRAWBEND_EXECUTOR: expected local, slurm or command" "$tmp/bad.log" || { cat "$tmp/bad.log"; fail "bad executor name: exit $rc"; }

source "$here/local_slurm.sh"
trap slurm_stop EXIT
slurm_start "$tmp/slurm_state"; rc=$?
if [ $rc -eq 77 ]; then echo "SKIPPED: the Slurm part (local, command: passed)"; exit 77; fi
[ $rc -eq 0 ] || fail "could not start the local Slurm"

t0=$(date +%s)
DRAWBEND_EXECUTOR=slurm "$cases" --out "$tmp/slurm" > "$tmp/slurm.log" 2>&1 || { cat "$tmp/slurm.log"; fail "slurm executor run"; }
same_runs "$tmp/local" "$tmp/slurm"
echo "slurm executor: byte-identical to local ($(( $(date +%s) - t0 )) s; $(ls "$tmp"/slurm/runs/*/slurm.log | wc -l) jobs)"

# Cancel one job while it runs.  Jobs are submitted held, so that the test
# decides when each starts.  The cancel run's jobs run drawbend through a
# wrapper that, after the solver ends, waits while $tmp/hold exists (60 s at
# most): the first job is released and cancelled after its solver has written
# summary.csv but before the job has ended, the moment at which a cancelled job
# could leave a summary.csv behind (CI, 2026-12-05, when the cancel came late
# by chance).  Then the others are released, with the wrapper not waiting.
printf '#!/bin/sh\n"%s" "$@"; rc=$?\ni=0; while [ -e "%s" ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done\nexit $rc\n' \
  "$drawbend" "$tmp/hold" > "$tmp/held_drawbend"
chmod +x "$tmp/held_drawbend"
touch "$tmp/hold"
DRAWBEND_BIN="$tmp/held_drawbend" DRAWBEND_EXECUTOR=slurm DRAWBEND_SLURM_ARGS=--hold \
  "$cases" --out "$tmp/cancel" > "$tmp/cancel.log" 2>&1 &
pid=$!
ids=""
for i in $(seq 1 300); do
  ids=$(squeue -h -o %i | sort -n | tr '\n' ' ')
  [ "$(echo $ids | wc -w)" -ge 3 ] && break
  sleep 0.2
done
[ "$(echo $ids | wc -w)" -ge 3 ] || { kill $pid; fail "the held jobs never appeared: $ids"; }
victim=$(echo $ids | cut -d' ' -f1)
vname=$(squeue -h -j "$victim" -o %j)
vcase=${vname#drawbend-}
scontrol release "$victim"
for i in $(seq 1 600); do
  [ -e "$tmp/cancel/runs/$vcase/summary.csv" ] && break
  sleep 0.1
done
[ -e "$tmp/cancel/runs/$vcase/summary.csv" ] || { kill $pid; fail "job $victim ($vcase) wrote no summary.csv in 60 s"; }
[ "$(squeue -h -j "$victim" -o %T)" = RUNNING ] || { kill $pid; fail "job $victim ($vcase) was not running after its solver ended"; }
scancel "$victim"
for i in $(seq 1 300); do
  [ -z "$(squeue -h -j "$victim" -o %T 2>/dev/null)" ] && break
  sleep 0.1
done
rm -f "$tmp/hold"
for id in $ids; do [ "$id" != "$victim" ] && scontrol release "$id"; done
wait $pid; rc=$?
[ $rc -ne 0 ] || { cat "$tmp/cancel.log"; fail "a cancelled job ended with exit 0"; }
grep -q "Slurm job $victim ended CANCELLED" "$tmp/cancel.log" || { cat "$tmp/cancel.log"; fail "the cancelled job is not reported"; }
grep -q "case $vcase: Slurm job $victim" "$tmp/cancel.log" || { cat "$tmp/cancel.log"; fail "the cancelled job is not named with its case $vcase"; }
[ ! -e "$tmp/cancel/runs/$vcase/summary.csv" ] || fail "the cancelled case left a summary.csv (a later run would reuse it)"
echo "slurm: job $victim ($vcase) cancelled while running, after its solver wrote summary.csv; reported: $(grep -m1 -o "case $vcase: Slurm job $victim ended CANCELLED" "$tmp/cancel.log"), exit $rc"
DRAWBEND_EXECUTOR=slurm "$cases" --out "$tmp/cancel" > "$tmp/rerun.log" 2>&1 || { cat "$tmp/rerun.log"; fail "the rerun after the cancel"; }
same_runs "$tmp/local" "$tmp/cancel"
echo "slurm: the rerun completed (the finished cases read back, $vcase run again), byte-identical to local"
echo "executors: all ok"
