#!/usr/bin/env bash
# Checkpoint/restart, bit for bit.  Runs DECK once straight through, and once
# interrupted twice (halted right after a checkpoint in the first step, then in
# the second step) and restarted from the checkpoint each time.  history.csv,
# summary.csv (less its wall-time row), fields.pvd and every snapshot (.vtu,
# contact maps) must be byte-identical.
# Usage: restart_check.sh DRAWBEND DECK WORKDIR
set -euo pipefail
drawbend=$1 deck=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
a=$work/straight b=$work/restarted
"$drawbend" run "$deck" --out "$a" --quiet >/dev/null
"$drawbend" run "$deck" --out "$b" --quiet --checkpoint-every 700 --halt-after-cycles 1400 | grep "halted after cycle 1400"
"$drawbend" run "$deck" --out "$b" --quiet --restart "$b/checkpoint.bin" --checkpoint-every 1e-4s \
  --halt-after-cycles 4000 | grep -E "restarted from|halted after cycle"
"$drawbend" run "$deck" --out "$b" --quiet --restart "$b/checkpoint.bin" | grep "restarted from"
cmp "$a/history.csv" "$b/history.csv"
cmp <(grep -v '^wall_time,' "$a/summary.csv") <(grep -v '^wall_time,' "$b/summary.csv")
cmp "$a/fields.pvd" "$b/fields.pvd"
n=0
for f in "$a"/*.vtu "$a"/contact_*.csv; do
  cmp "$f" "$b/$(basename "$f")"
  n=$((n + 1))
done
rows=$(grep -vc '^#' "$a/history.csv")
echo "restart: history.csv ($rows lines), summary.csv, fields.pvd and $n snapshot files bit-identical"
