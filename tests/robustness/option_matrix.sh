#!/usr/bin/env bash
# Issue 53: every numeric option of every command (read from its --help: the
# options whose default is a number) given 0, -1, nan, inf, 1e300, 0x10 (hexadecimal,
# which std::stod reads as 16: accepted as 16 by every real-valued option before) and a word.
# Prints one table row per case:  | command | --option value | exit | first line |
# With --check, every case not listed in option_valid.txt (values a command
# accepts, such as --threads 0) must end with exit 2 and a first message line
# naming the option, within the time limit; the accepted values are not run.
# Usage: option_matrix.sh DRAWBEND WORKDIR [--check]
set -u
# A 2 GB address-space cap on each run (a bad value must not eat the machine);
# not under AddressSanitizer (tests/sanitize/run.sh sets ASAN_OPTIONS), which
# reserves terabytes of address space for its shadow memory and aborts under it.
cap_memory() { [ -n "${ASAN_OPTIONS:-}" ] || ulimit -v 2000000; }
drawbend=$1 work=$2 check=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
limit=${OPTION_MATRIX_SECONDS:-20}
rm -rf "$work"
mkdir -p "$work"
"$drawbend" synth --effect none --seed 1 --tests-per-pin 2 --rows-per-test 5 --out "$work/synth" >/dev/null
printf 'pin_diameter_mm,back_tension_N,bending_force_N\n12.7,1000,200\n25.4,1000,150\n' >"$work/ml.csv"
mkdir -p "$work/model"
printf '[friction]\nlaw = "surface"\nnodes = "nodes.csv"\n' >"$work/model/friction_model.toml"
valid=$here/option_valid.txt
# In the sanitizer step (DRAWBEND_SANITIZER_RUN, tests/sanitize/run.sh) four
# values of the seven, one per path of the readers: -1 (a range check), nan (a
# non-finite number), 1e300 (a double cast to an integer: UBSan's
# float-cast-overflow) and a word (a read that fails); the main run of
# `make test` gives all seven.
values="0 -1 nan inf 1e300 0x10 word"
[ -n "${DRAWBEND_SANITIZER_RUN:-}" ] && values="-1 nan 1e300 word"
failed=0
base_args() {  # the command line of a command before the option under test
  case $1 in
    run) echo "run $here/decks/restart_block.toml --out $work/o_run --quiet" ;;
    drawbend-deck) echo "drawbend-deck" ;;
    block-deck) echo "block-deck --out $work/o_block.toml" ;;
    strip-deck) echo "strip-deck --out $work/o_strip.toml" ;;
    cup-deck) echo "cup-deck" ;;
    loop) echo "loop $work/synth/data.csv --out $work/o_loop --figures=" ;;
    model-loop) echo "model-loop $work/ml.csv --out $work/o_ml" ;;
    synth) echo "synth --out $work/o_synth" ;;
    export) echo "export $work/model/friction_model.toml --to openradioss --parts 1,2 --out $work/o_f.rad" ;;
    calibrate) echo "calibrate $here/../../data/materials/aa6016_t4_esaform2021.csv --out $work/o_cal" ;;
    plan) echo "plan $here/decks/restart_block.toml" ;;
  esac
}
help_args() {
  case $1 in
    run) echo "run --help" ;;
    loop) echo "loop --help" ;;
    model-loop) echo "model-loop --help" ;;
    export) echo "export x.toml --help" ;;
    *) echo "$1 --help" ;;
  esac
}
echo "| command | option | exit | first line of the message |"
echo "|---|---|---|---|"
for cmd in run drawbend-deck block-deck strip-deck cup-deck loop model-loop synth export calibrate plan; do
  # "  --name VALUE" then "      help (default: D)": the options whose default is a number.
  opts=$("$drawbend" $(help_args $cmd) 2>/dev/null | awk '
    /^  --[a-z]/ { name = $1; takes = (NF >= 2 && $2 != "true|false") ; next }
    /\(default: / && name != "" { d = $0; sub(/.*\(default: /, "", d); sub(/\)$/, "", d);
      if (takes && d ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) print name; name = "" }')
  for o in $opts; do
    for v in $values; do
      if [ -n "$check" ] && grep -qxF "$cmd $o $v" "$valid"; then continue; fi
      out=$( (cap_memory; timeout -k 5 "$limit" "$drawbend" $(base_args $cmd) "$o" "$v") 2>&1 </dev/null)
      rc=$?
      first=$(printf '%s\n' "$out" | grep -m1 -E '^(input error|numerical fault|error|data problem)' | cut -c1-150)
      [ -z "$first" ] && first=$(printf '%s\n' "$out" | grep -m1 . | cut -c1-150)
      printf '| %s | %s %s | %s | %s |\n' "$cmd" "$o" "$v" "$rc" "${first//|/\\|}"
      if [ -n "$check" ]; then
        if [ "$rc" != 2 ] || ! printf '%s' "$first" | grep -qF -- "$o"; then
          echo "FAILED: $cmd $o $v: exit $rc, expected 2 and a message naming $o"
          failed=1
        fi
      fi
    done
  done
done
exit $failed
