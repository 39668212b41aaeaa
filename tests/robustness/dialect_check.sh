#!/usr/bin/env bash
# Issue 53: what spreadsheets write, through `drawbend loop` end to end
# (core/csv_dialect.hpp).  From a small synthetic data set (drawbend synth):
#   trailing_empty  two empty columns at the right of every line, and a column
#                   named in Windows-1252 ('F_\xB5')  -> exit 0, every output UTF-8
#   quoted_break    a quoted cell holding a line break -> exit 0, 0 rows dropped
#   tab             tab-separated                      -> exit 0, "read with a tab"
#   utf16           UTF-16LE with a byte-order mark    -> exit 2 naming UTF-16
#   no_gnuplot      a missing gnuplot                  -> exit 0, a warning, repeated in loop.md
# Usage: dialect_check.sh DRAWBEND WORKDIR
set -u
drawbend=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
"$drawbend" synth --effect none --seed 1 --tests-per-pin 2 --rows-per-test 5 --out "$work/synth" >/dev/null || exit 1
base=$work/synth/data.csv
failed=0
check() {  # check NAME WANT_RC PATTERN FILE [ARGS...]
  local name=$1 want=$2 pattern=$3 file=$4
  shift 4
  local out rc
  local figures=--figures=  # no figures unless the case names them (an option is given once)
  case " $* " in *" --figures"*) figures= ;; esac
  out=$(timeout 120 "$drawbend" loop "$file" --out "$work/out_$name" --permutations 19 $figures "$@" 2>&1)
  rc=$?
  if [ "$rc" != "$want" ] || ! printf '%s\n' "$out" | grep -q -- "$pattern"; then
    printf '%s\n' "$out" | tail -5
    echo "FAILED: $name: exit $rc (expected $want), pattern '$pattern'"
    failed=1
  else
    echo "ok: $name: exit $rc; $(printf '%s\n' "$out" | grep -m1 -- "$pattern")"
  fi
}
utf8_outputs() {  # every text output of a run is valid UTF-8
  local f
  for f in $(find "$1" -type f \( -name '*.md' -o -name '*.csv' -o -name '*.json' -o -name '*.toml' -o -name '*.dat' \)); do
    if ! iconv -f UTF-8 -t UTF-8 "$f" >/dev/null 2>&1; then echo "FAILED: $f is not valid UTF-8"; failed=1; fi
  done
}
awk -F, 'BEGIN{OFS=","} /^#/ {print; next} !h {print $0",F_\xb5,,"; h=1; next} {print $0",1,,"}' "$base" >"$work/trailing.csv"
check trailing_empty 0 "75 rows read, 75 used, 0 dropped" "$work/trailing.csv"
utf8_outputs "$work/out_trailing_empty"
grep -q 'F_µ' "$work/out_trailing_empty/loop.md" || { echo "FAILED: loop.md does not name the column F_µ"; failed=1; }
awk -F, 'BEGIN{OFS=","} /^#/ {print; next} !h {print $0",note"; h=1; next} NR%7==0 {print $0",\"two"; print "lines\""; next} {print $0",x"}' "$base" >"$work/quoted.csv"
check quoted_break 0 "75 rows read, 75 used, 0 dropped, 0 problems" "$work/quoted.csv"
grep -v '^#' "$base" | tr ',' '\t' >"$work/tab.csv"
check tab 0 "read with a tab between cells" "$work/tab.csv"
{ printf '\xff\xfe'; iconv -f UTF-8 -t UTF-16LE "$base"; } >"$work/utf16.csv"
check utf16 2 "input error: .*utf16.csv: the file is UTF-16 text" "$work/utf16.csv"
check no_gnuplot 0 "warning: .* figures could not be drawn" "$base" --figures="$(dirname "$0")/../../figures" --gnuplot=/nonexistent/gnuplot
grep -q 'figures could not be drawn' "$work/out_no_gnuplot/loop.md" || { echo "FAILED: loop.md does not repeat the figure warning"; failed=1; }
[ "$failed" = 0 ] && echo "verdict: every dialect as expected"
exit $failed
