#!/bin/bash
# Issue 55, item 4: a report you can navigate (report/check_html.py).
#  1. The checker catches what it is for, on a page made to have each fault:
#     a stray numbered list (<ol start="10">), an absolute path, a table with a
#     note column of eight 20-letter words (8 x (20 x 0.55 + 1) x 0.88 = 84 em >
#     56 em) -> exit 1, three findings; a clean page (a list from 1, a two-column
#     table, a wide table without a note column, which scrolls) -> exit 0.
#  2. drawbend-report on a small study laid out as the real one (repo/chapters/chz,
#     repo/build/chapters/chz) whose prose wraps "(22 instead of\n  10) brought"
#     and a value "6" at the start of a list item's line, and whose values name an
#     absolute build path: the HTML passes the checker (no stray list, no absolute
#     path of repo/, no over-wide table), and its contents list the sections
#     (toc-depth 2: a link to the section heading, not only the chapter).
#  3. The same study as pages (see 3. below).
# Usage: report_html.sh DRAWBEND_REPORT PANDOC CSS CHECK_HTML WORK_DIR
set -u
report=$1 pandoc=$2 css=$3 check=$4 work=$5
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
w20=aaaaaaaaaaaaaaaaaaaa
{
  printf -- '- item over the\n  10) stray\n\n/work/not-here/build/x\n\n'
  printf '| a | b | c | d | e | f | g | note |\n|---|---|---|---|---|---|---|---|\n'
  printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n\n: Too wide\n' $w20 $w20 $w20 $w20 $w20 $w20 $w20 $w20
} | "$pandoc" -s --metadata title=bad -o "$work/bad.html" || fail "pandoc"
python3 "$check" "$work/bad.html" --forbid /work/not-here/ > "$work/bad.out"
rc=$?
[ $rc -eq 1 ] || fail "bad page: exit $rc, expected 1: $(cat "$work/bad.out")"
grep -q 'stray numbered list (starts at 10)' "$work/bad.out" || fail "stray list not caught"
grep -q 'absolute path /work/not-here/' "$work/bad.out" || fail "absolute path not caught"
grep -q "table 'Too wide' needs 84 em, the page has 56 em: its note column is out of view" "$work/bad.out" ||
  fail "wide table not caught: $(cat "$work/bad.out")"
{
  printf '1. one\n2. two\n\n| id | note |\n|---|---|\n| x | a note |\n\n: Narrow\n\n'
  printf '| a | b | c | d | e | f | g | h |\n|---|---|---|---|---|---|---|---|\n'  # wide, no note: it scrolls
  printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n\n: Wide data\n' $w20 $w20 $w20 $w20 $w20 $w20 $w20 $w20
} |
  "$pandoc" -s --metadata title=good -o "$work/good.html" || fail "pandoc"
python3 "$check" "$work/good.html" --forbid /work/not-here/ > "$work/good.out" || fail "clean page failed: $(cat "$work/good.out")"

repo="$work/repo" && src="$repo/chapters/chz" && out="$repo/build/chapters/chz"
mkdir -p "$src" "$out/tables" || exit 1
cat > "$src/intro.md" <<'MD'
# Chapter Z {#chz}

## What it does

- Rows 1.8 mm apart (22 instead of
  10) brought the ratio to 3.4 %.
- It holds for all of the
  {{n}}. combinations.
MD
cat > "$src/results.md" <<'MD'
## Results

The maps came from {{maps}}.

@table tables/t.csv | A table with a note column

@checks
MD
printf 'key,value,unit\nn,6,\nmaps,%s/build/chapters/ch4/maps,\n' "$repo" > "$out/values.csv"
printf 'id,kind,quantity,thesis,ours,tolerance,unit,status,note\n' > "$out/checks.csv"
printf 'chz.a,thesis,mu at 12.7 mm,0.1,0.1,0.01,-,pass,a note that explains the check in a sentence of some length\n' >> "$out/checks.csv"
printf 'pin_mm,mu,note\n12.7,0.1,read from %s/build/chapters/ch4/maps/pin_12.7mm.csv\n' "$repo" > "$out/tables/t.csv"
"$report" --chapters-src "$repo/chapters" --chapters-out "$repo/build/chapters" --out "$work/study.html" --css "$css" \
  --pandoc "$pandoc" > "$work/report.out" 2>&1 || fail "drawbend-report: $(cat "$work/report.out")"
python3 "$check" "$work/study.html" --forbid "$repo/" > "$work/study.out" || fail "the report fails the checker: $(cat "$work/study.out")"
grep -q 'href="#what-it-does"' "$work/study.html" || fail "the contents do not list the sections"
grep -q 'build/chapters/ch4/maps' "$work/study.html" || fail "the relative path is not shown"
# 3. The report as pages (--pages): a second chapter, chy; the front page is
#    index.html, each chapter a page with the shared contents (its own entry
#    marked current, the other chapter's sections linked into its page), a bar
#    to the neighbours and the front page, and no broken link anywhere (the
#    front page's links to each chapter's checks table point into its page).
#    A link to an id on no page is caught by the checker.
ysrc="$repo/chapters/chy" && yout="$repo/build/chapters/chy"
mkdir -p "$ysrc" "$yout" || exit 1
printf '# Chapter Y \xe2\x80\x94 the other one {#chy}\n\n## Its only section\n\nSee [Z](#chz).\n\n@checks\n' > "$ysrc/intro.md"
printf '## More\n\nText.\n' > "$ysrc/results.md"
printf 'id,kind,quantity,thesis,ours,tolerance,unit,status,note\nchy.a,thesis,x,1,1,0.1,-,pass,fine\n' > "$yout/checks.csv"
"$report" --chapters-src "$repo/chapters" --chapters-out "$repo/build/chapters" --out '' --pages "$work/pages" \
  --css "$css" --pandoc "$pandoc" > "$work/pages.out" 2>&1 || fail "drawbend-report --pages: $(cat "$work/pages.out")"
for p in index chy chz; do [ -s "$work/pages/$p.html" ] || fail "no page $p.html"; done
[ -e "$work/study.html" ] || fail "the single file went missing"
python3 "$check" "$work/pages/"*.html --forbid "$repo/" > "$work/pages.check" ||
  fail "the pages fail the checker: $(cat "$work/pages.check")"
grep -q 'href="chz.html#checks-chz"' "$work/pages/index.html" || fail "the front page does not link into chz.html"
grep -q 'href="chy.html#its-only-section"' "$work/pages/chz.html" || fail "chz's contents do not list chy's sections"
grep -q '<li class="current"><a aria-current="page" href="#chz">' "$work/pages/chz.html" || fail "chz's own entry is not marked"
grep -q 'href="#chz"' "$work/pages/chy.html" && fail "chy links #chz on its own page"
grep -q 'href="chz.html#chz"' "$work/pages/chy.html" || fail "chy's link to Z does not lead into chz.html"
[ "$(grep -c 'class="pagenav"' "$work/pages/chy.html")" = 2 ] || fail "chy.html lacks its two page bars"
grep -q '<a class="next" href="chz.html">Chapter Z' "$work/pages/chy.html" || fail "chy.html does not lead on to Chapter Z"
grep -q '<a class="index" href="index.html">Front page</a>' "$work/pages/chz.html" || fail "chz.html does not lead back"
sed 's/href="chz.html#chz"/href="chz.html#nowhere"/' "$work/pages/chy.html" > "$work/pages/broken.html"
python3 "$check" "$work/pages/broken.html" > "$work/broken.out" && fail "a broken link passed the checker"
grep -q 'link to chz.html#nowhere: no such id in chz.html' "$work/broken.out" || fail "broken link not named: $(cat "$work/broken.out")"
echo "report: checker catches stray lists, absolute paths, wide tables, broken links; a report assembled from a small study passes it, as one file and as pages"
