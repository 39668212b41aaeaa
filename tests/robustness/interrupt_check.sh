#!/usr/bin/env bash
# Issue 17: SIGINT and SIGTERM during `drawbend run`.  Runs DECK once straight
# through; then runs it, sends SIGINT once the first progress line is out,
# checks exit 130 and the message
#   interrupted at t = ..., cycle ...; continue with: drawbend run DECK --out DIR --restart DIR/checkpoint.bin
# runs that command, interrupts it with SIGTERM (exit 143) as soon as it has
# restarted, runs the command
# printed then to the end, and compares every output with the straight run byte
# for byte (as restart_check.sh).  It also checks the progress line's
# prediction "cycle N of ~M" against the cycles of the straight run.
# Usage: interrupt_check.sh DRAWBEND DECK WORKDIR
set -euo pipefail
drawbend=$1 deck=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
a=$work/straight b=$work/interrupted
"$drawbend" run "$deck" --out "$a" --quiet >/dev/null
total=$(grep '^cycles,' "$a/summary.csv" | cut -d, -f2)

# Run CMD (a command line) in the background, signal it once its output
# matches WAIT (a grep pattern), and check its exit code; leaves its output in
# $work/log.
interrupt() {
  local sig=$1 want=$2 wait_for=$3
  shift 3
  "$@" >"$work/log" 2>&1 &
  local pid=$! i rc
  for i in $(seq 1 1200); do
    grep -q "$wait_for" "$work/log" && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.05
  done
  kill -"$sig" $pid 2>/dev/null || true
  set +e
  wait $pid
  rc=$?
  set -e
  tr '\r' '\n' <"$work/log" | grep -v '^ *$' | tail -3
  if [ "$rc" != "$want" ]; then echo "FAILED: SIG$sig gave exit $rc, expected $want"; exit 1; fi
  # The run folder as literal text in the pattern: a path may hold + or . (say, build-g++).
  local eb
  eb=$(printf '%s' "$b" | sed 's/[][\.*^$+?(){}|]/\\&/g')
  grep -qE "^interrupted at t = [0-9.e+-]+ s, cycle [0-9]+; continue with: drawbend run .* --out $eb --restart $eb/checkpoint.bin\$" \
    "$work/log" || { echo "FAILED: no 'interrupted at ...; continue with: ...' line"; exit 1; }
  echo "SIG$sig: exit $rc as expected"
}
# The command the message gives, with the real path of the binary.
continue_cmd() { sed -n 's/^interrupted at .*; continue with: drawbend //p' "$work/log"; }

# SIGINT after the first progress line (printed after 0.1 s of wall time here).
interrupt INT 130 'cycle [0-9]* of ~[0-9]*' "$drawbend" run "$deck" --out "$b" --progress-every 0.1
# The progress line: "cycle N of ~M" predicts the cycles of the whole run.
pred=$(tr '\r' '\n' <"$work/log" | grep -oE 'cycle [0-9]+ of ~[0-9]+' | head -1 | sed 's/.*~//')
echo "progress line predicted ~$pred cycles; the straight run took $total"
awk -v p="$pred" -v t="$total" 'BEGIN { exit !(p >= 0.8 * t && p <= 1.25 * t) }' ||
  { echo "FAILED: the prediction is off by more than 25 %"; exit 1; }
read -r -a next <<<"$(continue_cmd)"
# SIGTERM as soon as the continued run has restarted.
interrupt TERM 143 'restarted from' "$drawbend" "${next[@]}"
read -r -a next <<<"$(continue_cmd)"
"$drawbend" "${next[@]}" --quiet | grep "restarted from"
cmp "$a/history.csv" "$b/history.csv"
cmp <(grep -v '^wall_time,' "$a/summary.csv") <(grep -v '^wall_time,' "$b/summary.csv")
cmp "$a/fields.pvd" "$b/fields.pvd"
n=0
for f in "$a"/*.vtu "$a"/contact_*.csv; do
  cmp "$f" "$b/$(basename "$f")"
  n=$((n + 1))
done
echo "interrupt: SIGINT (130) and SIGTERM (143) checkpointed and continued; history.csv, summary.csv, fields.pvd and $n snapshot files bit-identical"
