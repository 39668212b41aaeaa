#!/bin/bash
# Issue 55, item 3: help that teaches.
#  - every command answers --help, -h and `drawbend help CMD` with exit 0 and
#    the same text, which ends with two or three example lines;
#  - `drawbend help` and `drawbend version` exit 0;
#  - every example line runs as written (exit 0), in order, in a fresh folder
#    per command whose `data` is the source tree's data/ (the examples are
#    written for the source folder), with `drawbend` the built binary.
# Usage: help_examples.sh DRAWBEND DATA_DIR WORK_DIR [COMMAND...]
#   (the commands whose examples to run; default every command but model-loop,
#   whose examples run FE cases for minutes and have their own test)
set -u
bin=$1 data=$2 work=$3
shift 3
all=(run drawbend-deck block-deck strip-deck cup-deck loop model-loop synth export calibrate plan)
run_cmds=("$@")
[ ${#run_cmds[@]} -eq 0 ] && run_cmds=(run drawbend-deck block-deck strip-deck cup-deck loop synth export calibrate plan)
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
"$bin" help > "$work/help.txt" || fail "drawbend help: exit $?"
grep -q '^  help \[COMMAND\]' "$work/help.txt" || fail "drawbend help does not list help"
"$bin" version | grep -q '^drawbend [0-9]' || fail "drawbend version"
# Every command drawbend help lists is in the list above (a new command gets its examples run too).
for c in $(sed -n '2,/^  help \[COMMAND\]/p' "$work/help.txt" | awk '/^  [a-z]/ {print $1}' | grep -vx help); do
  printf ' %s ' "${all[@]}" | grep -q " $c " || fail "drawbend help lists '$c', which this test does not check"
done
for c in "${all[@]}"; do
  "$bin" "$c" --help > "$work/$c.help" 2>&1 || fail "$c --help: exit $?"
  "$bin" "$c" -h > "$work/$c.h" 2>&1 || fail "$c -h: exit $?"
  "$bin" help "$c" > "$work/$c.helpcmd" 2>&1 || fail "help $c: exit $?"
  cmp -s "$work/$c.help" "$work/$c.h" || fail "$c: -h differs from --help"
  cmp -s "$work/$c.help" "$work/$c.helpcmd" || fail "$c: help $c differs from --help"
  n=$(sed -n '/^Examples/,$p' "$work/$c.help" | grep -c '^  drawbend ')
  [ "$n" -ge 2 ] && [ "$n" -le 3 ] || fail "$c --help: $n example lines (expected 2 or 3)"
  tail -1 "$work/$c.help" | grep -q '^  drawbend ' || fail "$c --help does not end with its examples"
done
# A wrapper named drawbend, so that the lines run exactly as printed.
mkdir -p "$work/bin" && printf '#!/bin/sh\nexec "%s" "$@"\n' "$bin" > "$work/bin/drawbend" && chmod +x "$work/bin/drawbend"
export PATH="$work/bin:$PATH"
for c in "${run_cmds[@]}"; do
  d="$work/run-$c" && mkdir -p "$d" && ln -s "$data" "$d/data" || exit 1
  while IFS= read -r line; do
    (cd "$d" && bash -c "$line" > "$d/last.out" 2>&1) || fail "$c example exited $?: $line
$(tail -5 "$d/last.out")"
    echo "ok: $line"
  done < <(sed -n '/^Examples/,$p' "$work/$c.help" | sed -n 's/^  \(drawbend .*\)$/\1/p')
done
echo "help: ${#all[@]} commands with -h, --help, help CMD and 2-3 examples; the examples of ${run_cmds[*]} ran"
