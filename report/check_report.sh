#!/usr/bin/env bash
# Check that the report holds every chapter's checks table and every figure
# each chapter produced, and that the summary counts every chapter.
# Usage: check_report.sh study.html chapters_src chapters_out
set -euo pipefail
html=$1; src=$2; out=$3
fail=0
[ -s "$html" ] || { echo "report missing or empty: $html"; exit 1; }
grep -q 'id="summary"' "$html" || { echo "no checks summary in $html"; fail=1; }
for dir in "$src"/*/; do
  id=$(basename "$dir")
  [ -f "$dir/intro.md" ] || continue
  grep -q "id=\"checks-$id\"" "$html" || { echo "missing checks table of chapter $id"; fail=1; }
  grep -q "href=\"#checks-$id\"" "$html" || { echo "summary does not link chapter $id"; fail=1; }
  for svg in "$out/$id"/figures/*.svg; do
    [ -e "$svg" ] || continue
    stem=$(basename "$svg" .svg)
    grep -q "id=\"fig-$id-$stem\"" "$html" || { echo "figure $id/$stem.svg is not in the report"; fail=1; }
  done
done
# Every chapter shows its provenance, and none may be stale (results computed
# from inputs that have changed since).
np=$(grep -c 'class="unnumbered provenance"' "$html" || true)
nc=$(ls "$src"/*/intro.md | wc -l)
[ "$np" -eq "$nc" ] || { echo "provenance sections: $np, chapters: $nc"; fail=1; }
if grep -q 'class="stale"' "$html"; then echo "report marks stale results (see their Provenance sections)"; fail=1; fi
# Figures must be embedded (self-contained), not linked to build paths.
if grep -q 'src="/' "$html"; then echo "report links a local file instead of embedding it"; fail=1; fi
# What a reader trips over (report/check_html.py): stray numbered lists and the
# machine's absolute source or build folders fail; tables wider than the page
# are listed (they scroll in their own box).  The over-wide rule for checks
# tables (the note column out of view) warns until a full report has been
# measured with it (issue 55): then drop --wide warn.
root=$(cd "$src/.." && pwd)/
build_root=$(cd "$out/.." && pwd)/
python3 "$(dirname "$0")/check_html.py" "$html" --forbid "$root" --forbid "$build_root" --wide warn || fail=1
[ $fail -eq 0 ] && echo "report ok: $(grep -c 'id="checks-' "$html") checks tables, $(grep -o 'id="fig-' "$html" | wc -l) figures"
exit $fail
