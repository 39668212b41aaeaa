#!/usr/bin/env bash
# Issue 53: every entry point x every class of bad path (a missing file, a
# folder, a device, a FIFO) and of bad output target (a FIFO, a folder), each
# under a time limit and a 2 GB memory limit.  Prints one table row per case:
#   | entry point | input | exit code | first line of the message |
# Exit 124 is the time limit (a hang), 134/136/139 a crash.  With --check the
# script exits 1 unless every case ended with exit 2 and a message naming the
# path (the robustness test); without it, it only prints (the before/after table).
# Usage: entry_matrix.sh DRAWBEND WORKDIR [--check]
set -u
# A 2 GB address-space cap on each run (a bad value must not eat the machine);
# not under AddressSanitizer (tests/sanitize/run.sh sets ASAN_OPTIONS), which
# reserves terabytes of address space for its shadow memory and aborts under it.
cap_memory() { [ -n "${ASAN_OPTIONS:-}" ] || ulimit -v 2000000; }
drawbend=$1 work=$2 check=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
decks=$here/decks
limit=${ENTRY_MATRIX_SECONDS:-30}
rm -rf "$work"
mkdir -p "$work/folder" "$work/out"
fifo=$work/fifo
mkfifo "$fifo"
"$drawbend" synth --effect none --seed 1 --tests-per-pin 2 --rows-per-test 5 --out "$work/synth" >/dev/null
good_deck=$decks/restart_block.toml
cal=$here/../../data/materials/aa6016_t4_esaform2021.csv
printf 'pin_diameter_mm,back_tension_N,bending_force_N\n12.7,1000,200\n25.4,1000,150\n' >"$work/ml.csv"
mkdir -p "$work/good_model"
grep -v '^#' "$here/../../data/thesis/table_6_1.csv" >"$work/good_model/nodes.csv"
printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\n' >"$work/good_model/friction_model.toml"
failed=0
# run_case LABEL INPUT-DESCRIPTION PATH-THAT-MUST-BE-NAMED CMD...
run_case() {
  local label=$1 what=$2 named=$3
  shift 3
  local out rc first
  out=$( (cap_memory; timeout -k 5 "$limit" "$@") 2>&1 </dev/null)
  rc=$?
  first=$(printf '%s\n' "$out" | grep -m1 -E '^(input error|numerical fault|error|data problem|warning)' | cut -c1-400)
  [ -z "$first" ] && first=$(printf '%s\n' "$out" | grep -m1 . | cut -c1-400)
  printf '| %s | %s | %s | %s |\n' "$label" "$what" "$rc" "${first//|/\\|}"
  if [ -n "$check" ]; then
    if [ "$rc" != 2 ] || ! printf '%s' "$first" | grep -qF -- "$named"; then
      echo "FAILED: $label with $what: exit $rc, expected 2 and a message naming '$named'"
      failed=1
    fi
  fi
}
echo "| entry point | input | exit | first line of the message |"
echo "|---|---|---|---|"
for kind in missing folder device fifo; do
  case $kind in
    missing) p=$work/no_such_file ;;
    folder) p=$work/folder ;;
    device) p=/dev/zero ;;
    fifo) p=$fifo ;;
  esac
  run_case "run DECK" $kind "$p" "$drawbend" run "$p" --out "$work/out/run" --quiet
  run_case "run --restart" $kind "$p" "$drawbend" run "$good_deck" --restart "$p" --out "$work/out/restart" --quiet
  run_case "drawbend-deck --material" $kind "$p" "$drawbend" drawbend-deck --material "$p"
  run_case "drawbend-deck --hardening" $kind "$p" "$drawbend" drawbend-deck --hardening "$p"
  run_case "block-deck --hardening" $kind "$p" "$drawbend" block-deck --hardening "$p" --out "$work/out/block.toml"
  run_case "block-deck --surface-nodes" $kind "$p" "$drawbend" block-deck --surface-nodes "$p" --out "$work/out/block.toml"
  run_case "strip-deck --stribeck-table" $kind "$p" "$drawbend" strip-deck --stribeck-table "$p" --out "$work/out/strip.toml"
  run_case "strip-deck --hardening" $kind "$p" "$drawbend" strip-deck --hardening "$p" --out "$work/out/strip.toml"
  run_case "cup-deck --base" $kind "$p" "$drawbend" cup-deck --base "$p"
  run_case "cup-deck --material" $kind "$p" "$drawbend" cup-deck --material "$p"
  run_case "loop DATA" $kind "$p" "$drawbend" loop "$p" --out "$work/out/loop" --figures=
  run_case "loop --maps" $kind "$p" "$drawbend" loop "$work/synth/data.csv" --maps "$p" --out "$work/out/loop" --figures=
  run_case "model-loop DATA" $kind "$p" "$drawbend" model-loop "$p" --out "$work/out/ml"
  run_case "model-loop --hardening" $kind "$p" "$drawbend" model-loop "$work/ml.csv" --hardening "$p" --out "$work/out/ml"
  run_case "export MODEL" $kind "$p" "$drawbend" export "$p" --to lsdyna --out "$work/out/f.k"
  run_case "loop --figures" $kind "$p" "$drawbend" loop "$work/synth/data.csv" --figures "$p" --out "$work/out/loop"
  run_case "calibrate TESTS" $kind "$p" "$drawbend" calibrate "$p" --out "$work/out/cal"
  run_case "calibrate --compare" $kind "$p" "$drawbend" calibrate "$cal" --compare "$p" --out "$work/out/cal"
  run_case "plan DECK" $kind "$p" "$drawbend" plan "$p"
  run_case "drawbend-deck --friction" $kind "$p" "$drawbend" drawbend-deck --friction "$p"
  run_case "block-deck --friction" $kind "$p" "$drawbend" block-deck --friction "$p" --out "$work/out/block.toml"
  run_case "strip-deck --friction" $kind "$p" "$drawbend" strip-deck --friction "$p" --out "$work/out/strip.toml"
  run_case "cup-deck --friction" $kind "$p" "$drawbend" cup-deck --friction "$p"
  run_case "synth --maps" $kind "$p" "$drawbend" synth --maps "$p" --out "$work/out/synth"
  # A path inside a deck: the hardening curve a deck names.
  sed "s|^hardening = .*|hardening = \"$p\"|" "$decks/bom_deck.toml" >"$work/deck_$kind.toml"
  run_case "run: deck's hardening" $kind "$p" "$drawbend" run "$work/deck_$kind.toml" --out "$work/out/run_h" --quiet
  # export's nodes file: a friction model whose [friction] nodes names the path.
  mkdir -p "$work/model_$kind"
  printf '[friction]\nlaw = "surface"\nnodes = "%s"\n' "$p" >"$work/model_$kind/friction_model.toml"
  run_case "export nodes" $kind "$p" "$drawbend" export "$work/model_$kind/friction_model.toml" --to lsdyna --out "$work/out/f.k"
done
# Output targets: a FIFO and a folder where a file is to be written.
for kind in fifo folder; do
  case $kind in
    fifo) p=$fifo ;;
    folder) p=$work/folder ;;
  esac
  run_case "block-deck --out" "out=$kind" "$p" "$drawbend" block-deck --out "$p"
  run_case "strip-deck --out" "out=$kind" "$p" "$drawbend" strip-deck --out "$p"
  run_case "export --out" "out=$kind" "$p" "$drawbend" export "$work/good_model/friction_model.toml" --to lsdyna --out "$p"
  [ -p "$fifo" ] || { echo "| (the FIFO was replaced by a file) | | | |"; rm -f "$fifo"; mkfifo "$fifo"; }
done
leftovers=$(find "$work" -name '*.tmp*' | wc -l)
echo
echo "temporary files left behind: $leftovers"
[ -n "$check" ] && [ "$leftovers" != 0 ] && failed=1
exit $failed
