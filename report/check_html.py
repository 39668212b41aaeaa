#!/usr/bin/env python3
"""Check the generated report HTML for what a reader trips over (issue 55).

  python3 check_html.py PAGE.html... [--forbid PATH]... [--width-em W] [--wide warn|fail]

1. Stray list numbers: an <ol> with a start attribute other than 1.  The
   report's numbered lists all start at 1; an <ol start="10"> is a wrapped
   line that began with "10) " or "6. " inside a list item.
2. Absolute paths: any --forbid string (the source and build folders) in the text.
3. Over-wide tables: a table whose narrowest layout is wider than the page.
   The narrowest layout of a column is its widest unbreakable piece: a word of
   a cell (split at spaces and <wbr>), or the whole cell when it may not wrap (td.num), at least
   the style sheet's min-width (td.note 16em, td.quantity 9em, others 3em),
   plus 1em of padding.  Text is taken at 0.55 em per character (Helvetica's
   mean advance for digits and lower case is 0.50-0.56 em) at the table's
   font size (0.88 em; checks tables 0.8 em).  The page is --width-em wide
   (56 em: a 1280 px window at 16 px minus the 21 em contents sidebar).
   Such a table scrolls in its own box (report/style.css); that fails only
   when the table has a note column (the checks tables), which must stay in
   view.  --wide warn lists them all without failing.
4. Broken links: an href="#id" with no such id on its page, or an
   href="PAGE.html#id" to a page beside it without that id or that is missing
   (the report as pages, drawbend-report --pages, links across its pages).
Each page given is checked; links are checked among the pages of one folder.
Exit 0 when nothing fails, 1 otherwise; every finding is printed.
"""
import argparse
import html.parser
import os
import re
import sys

CHAR_EM = 0.55
MIN_EM = {"note": 16.0, "quantity": 9.0}
NOWRAP = {"num"}


class Scan(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ols = []          # (start, line)
        self.tables = []       # dicts: caption, checks, rows [[(classes, text)]], line
        self.stack = []        # open tables
        self.cell = None       # (classes, [text])
        self.in_caption = False
        self.checks_depth = 0  # inside a div.checks
        self.div_stack = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        cls = set((a.get("class") or "").split())
        if tag == "div":
            is_checks = "checks" in cls
            self.div_stack.append(is_checks)
            self.checks_depth += is_checks
        elif tag == "ol" and a.get("start") not in (None, "1"):
            self.ols.append((a.get("start"), self.getpos()[0]))
        elif tag == "table":
            self.stack.append({"caption": "", "checks": self.checks_depth > 0 or "checks-table" in cls,
                               "rows": [], "line": self.getpos()[0], "id": a.get("id", "")})
        elif tag == "tr" and self.stack:
            self.stack[-1]["rows"].append([])
        elif tag in ("td", "th") and self.stack:
            self.cell = (cls, [])
        elif tag == "caption":
            self.in_caption = True
        elif tag == "wbr" and self.cell is not None:
            self.cell[1].append(" ")  # a break opportunity

    def handle_endtag(self, tag):
        if tag == "div" and self.div_stack:
            self.checks_depth -= self.div_stack.pop()
        elif tag in ("td", "th") and self.cell is not None and self.stack:
            if self.stack[-1]["rows"]:
                self.stack[-1]["rows"][-1].append((self.cell[0], "".join(self.cell[1])))
            self.cell = None
        elif tag == "table" and self.stack:
            self.tables.append(self.stack.pop())
        elif tag == "caption":
            self.in_caption = False

    def handle_data(self, data):
        if self.cell is not None:
            self.cell[1].append(data)
        elif self.in_caption and self.stack:
            self.stack[-1]["caption"] += data


def has_note(table):
    """A table with a note column (the checks tables): its last column must stay in view."""
    return any("note" in cls or text.strip() == "note" for row in table["rows"][:1] for cls, text in row) or \
        any("note" in cls for row in table["rows"] for cls, _ in row)


def min_width_em(table):
    font = 0.8 if table["checks"] else 0.88
    cols = {}
    for row in table["rows"]:
        for k, (cls, text) in enumerate(row):
            text = " ".join(text.split())
            piece = len(text) if cls & NOWRAP else max((len(w) for w in text.split()), default=0)
            floor = max([MIN_EM[c] for c in cls if c in MIN_EM] or [3.0])
            w = max(floor, piece * CHAR_EM) * font + 1.0 * font
            cols[k] = max(cols.get(k, 0.0), w)
    return sum(cols.values())


def check_page(path, o):
    """Checks 1-3 on one page: (number of failures, tables, tables wider than the page)."""
    text = open(path, encoding="utf-8").read()
    s = Scan()
    s.feed(text)
    bad = 0
    for start, line in s.ols:
        print(f"{path}:{line}: stray numbered list (starts at {start}): a wrapped line began with a number")
        bad += 1
    for f in o.forbid:
        if f and f in text:
            n = text.count(f)
            print(f"{path}: {n} occurrence(s) of the absolute path {f}")
            bad += 1
    wide = [(min_width_em(t), t) for t in s.tables]
    over = [(w, t) for w, t in wide if w > o.width_em]
    hidden = 0
    for w, t in over:
        name = " ".join((t["id"] or t["caption"][:60] or "(no caption)").split())
        noted = has_note(t)
        hidden += noted
        print(f"{path}:{t['line']}: table '{name}' needs {w:.0f} em, the page has {o.width_em:.0f} em: "
              + ("its note column is out of view" if noted else "it scrolls in its own box"))
    if o.wide == "fail":
        bad += hidden
    print(f"check_html: {path}: {len(s.tables)} tables ({len(over)} wider than {o.width_em:.0f} em, {hidden} of them "
          f"with a note column out of view), "
          f"{len(s.ols)} stray numbered lists, {sum(f in text for f in o.forbid if f)} absolute paths")
    return bad


ID = re.compile(r' id="([^"]*)"')
HREF = re.compile(r'href="([^"#:]*\.html)?#([^"]*)"|href="([^"#:/]+\.html)"')


def ids_of(path, cache):
    if path not in cache:
        cache[path] = set(ID.findall(open(path, encoding="utf-8").read())) if os.path.isfile(path) else None
    return cache[path]


def check_links(path, cache):
    """Check 4: every link to an anchor or a page beside this one leads somewhere."""
    text = open(path, encoding="utf-8").read()
    folder = os.path.dirname(path)
    bad, n = 0, 0
    for m in HREF.finditer(text):
        page, anchor, bare = m.group(1), m.group(2), m.group(3)
        target = os.path.join(folder, page or bare) if (page or bare) else path
        ids = ids_of(target, cache)
        n += 1
        if ids is None:
            print(f"{path}: link to {page or bare}: no such page")
            bad += 1
        elif anchor is not None and anchor not in ids:
            print(f"{path}: link to {(page or '')}#{anchor}: no such id" + (f" in {page}" if page else " on the page"))
            bad += 1
    print(f"check_html: {path}: {n} links, {bad} broken")
    return bad


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("html", nargs="+")
    ap.add_argument("--forbid", action="append", default=[])
    ap.add_argument("--width-em", type=float, default=56.0)
    ap.add_argument("--wide", choices=["warn", "fail"], default="fail")
    o = ap.parse_args()
    bad, cache = 0, {}
    for path in o.html:
        bad += check_page(path, o)
        bad += check_links(path, cache)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
