#!/usr/bin/env bash
# Check that the report holds every chapter's checks table and every figure
# each chapter produced, and that the summary counts every chapter.
# With PAGES_DIR, the report as pages too (drawbend-report --pages): the front
# page index.html, each chapter's page with its checks table and figures, and
# no broken link among them.
# Usage: check_report.sh study.html chapters_src chapters_out [PAGES_DIR]
set -euo pipefail
html=$1; src=$2; out=$3; pages=${4:-}
fail=0
# chapter_in PAGE FRONT ID LINK: chapter ID's checks table and every figure it
# produced are in PAGE, and the summary on FRONT links its checks table as LINK.
chapter_in() {
  local page=$1 front=$2 id=$3 link=$4 svg stem
  grep -q "id=\"checks-$id\"" "$page" || { echo "$page: missing checks table of chapter $id"; fail=1; }
  grep -q "href=\"$link\"" "$front" || { echo "$front: the summary does not link chapter $id ($link)"; fail=1; }
  for svg in "$out/$id"/figures/*.svg; do
    [ -e "$svg" ] || continue
    stem=$(basename "$svg" .svg)
    grep -q "id=\"fig-$id-$stem\"" "$page" || { echo "figure $id/$stem.svg is not in $page"; fail=1; }
  done
}
[ -s "$html" ] || { echo "report missing or empty: $html"; exit 1; }
grep -q 'id="summary"' "$html" || { echo "no checks summary in $html"; fail=1; }
for dir in "$src"/*/; do
  id=$(basename "$dir")
  [ -f "$dir/intro.md" ] || continue
  chapter_in "$html" "$html" "$id" "#checks-$id"
done
# Every chapter shows its provenance, and none may be stale (results computed
# from inputs that have changed since).
np=$(grep -c 'class="unnumbered provenance"' "$html" || true)
nc=$(ls "$src"/*/intro.md | wc -l)
[ "$np" -eq "$nc" ] || { echo "provenance sections: $np, chapters: $nc"; fail=1; }
if grep -q 'class="stale"' "$html"; then echo "report marks stale results (see their Provenance sections)"; fail=1; fi
# Figures must be embedded (self-contained), not linked to build paths.
if grep -q 'src="/' "$html"; then echo "report links a local file instead of embedding it"; fail=1; fi
# What a reader trips over (report/check_html.py): stray numbered lists, the
# machine's absolute source or build folders, broken links and checks tables
# whose note column is pushed out of view fail; other tables wider than the
# page are listed (they scroll in their own box).  Measured on a full quick-tier
# report (2026-12-02): 89 tables, 12 wider than the page, none of them a checks
# table (7 were before check ids and notes could break after '_').
root=$(cd "$src/.." && pwd)/
build_root=$(cd "$out/.." && pwd)/
python3 "$(dirname "$0")/check_html.py" "$html" --forbid "$root" --forbid "$build_root" || fail=1
if [ -n "$pages" ]; then
  [ -s "$pages/index.html" ] || { echo "no front page $pages/index.html"; fail=1; }
  grep -q 'id="summary"' "$pages/index.html" || { echo "no checks summary in $pages/index.html"; fail=1; }
  for dir in "$src"/*/; do
    id=$(basename "$dir")
    [ -f "$dir/intro.md" ] || continue
    [ -s "$pages/$id.html" ] || { echo "no page $pages/$id.html"; fail=1; continue; }
    chapter_in "$pages/$id.html" "$pages/index.html" "$id" "$id.html#checks-$id"
  done
  python3 "$(dirname "$0")/check_html.py" "$pages"/*.html --forbid "$root" --forbid "$build_root" || fail=1
fi
[ $fail -eq 0 ] && echo "report ok: $(grep -c 'id="checks-' "$html") checks tables, $(grep -o 'id="fig-' "$html" | wc -l) figures"
exit $fail
