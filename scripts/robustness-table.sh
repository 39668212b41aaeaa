#!/usr/bin/env bash
# robustness-table.sh: the table of issue 53's closing note, entry point x
# class of bad input -> exit code and first line of the message, for two
# binaries side by side (before and after a change), written as Markdown.
#   [BEFORE_LABEL=...] [AFTER_LABEL=...] scripts/robustness-table.sh BEFORE_DRAWBEND AFTER_DRAWBEND OUT.md [WORK_DIR]
# (the labels name the two binaries in the page, e.g. their commits).
# It runs the five matrices of tests/robustness (without --check, so every
# case is run and shown, also the values a command accepts):
#   entry_matrix.sh   every path a command reads: missing file, folder, device, FIFO;
#                     every file it writes pointed at a FIFO or a folder
#   option_matrix.sh  every numeric option of every command: 0, -1, nan, 1e300, a word
#   hostile_matrix.sh the other classes: options twice or without a value, units in
#                     values, CRLF, duplicated keys, absurd table values, options
#                     that do nothing in the mode chosen, unwritable folders, ...
#   option_lists.sh   every list-valued option: empty items, spaces, an item twice, NaN
#   edited_decks.sh   a builder's deck with one key edited by hand; the commands swept
#                     least (calibrate, plan, export, synth, model-loop, cup-deck --base)
# and joins each matrix's rows of the two binaries by (entry point, input).
# A case only one binary's matrix has shows "-" for the other.  Takes about
# 5 minutes on 2 cores (the accepted values of option_matrix run for real, up
# to 20 s each).  Example, from the source folder after a build:
#   scripts/robustness-table.sh /tmp/drawbend-old build/src/drawbend docs/robustness-table.md
set -uo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 BEFORE_DRAWBEND AFTER_DRAWBEND OUT.md [WORK_DIR]" >&2
  exit 2
fi
before=$(realpath "$1") after=$(realpath "$2") out=$3 work=${4:-$(mktemp -d)}
here=$(cd "$(dirname "$0")/../tests/robustness" && pwd)
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
mkdir -p "$work"
for m in entry_matrix option_matrix hostile_matrix option_lists edited_decks; do
  for side in before after; do
    bin=$before
    [ $side = after ] && bin=$after
    bash "$here/$m.sh" "$bin" "$work/$m.$side" >"$work/$m.$side.md" 2>&1
  done
done
python3 - "$work" "$out" "${BEFORE_LABEL:-$before}" "${AFTER_LABEL:-$after}" "$here/option_valid.txt" <<'PY'
import sys, re, collections
work, out, before, after, valid_path = sys.argv[1:6]
valid = {l.strip() for l in open(valid_path) if l.strip()}

def rows(m, side):
    """Table rows of a matrix's output: (key, exit, first line), in order; the key
    is (entry point, input, n) with n counting repeats of the same pair."""
    r, seen = [], collections.Counter()
    for line in open(f"{work}/{m}.{side}.md", encoding="utf-8", errors="replace"):
        if not line.startswith("| ") or line.startswith("| command |") or line.startswith("| entry point |"):
            continue
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]
        if len(cells) < 4:
            continue
        first = " | ".join(cells[3:]).replace(f"{work}/{m}.{side}", "WORK").replace(work, "WORK")
        seen[(cells[0], cells[1])] += 1
        r.append(((cells[0], cells[1], seen[(cells[0], cells[1])]), cells[2], first))
    return r

def short(text, n=140):
    return text if len(text) <= n else text[:n - 1] + "…"

def accepted(m, k):
    return m == "option_matrix" and f"{k[0]} {k[1]}" in valid

titles = {
    "entry_matrix": "Paths: every file a command reads or writes, given a missing file, a folder, a device (/dev/zero) or a FIFO",
    "option_matrix": "Numbers: every numeric option of every command, given 0, -1, nan, 1e300 and a word",
    "hostile_matrix": "Other classes: a careless user and a hostile script",
    "option_lists": "Lists: every list-valued option, given empty items, spaces, an item twice, NaN and hexadecimal",
    "edited_decks": "Edited decks and the least-swept commands: a builder's deck with one key changed by hand, calibrate, plan, export, synth, model-loop, cup-deck --base, --help and an unknown option first",
}
md = ["# Robustness: entry point x bad input, before and after", "",
      "Written by `scripts/robustness-table.sh` (do not edit by hand). Each row is one run of `drawbend` "
      "under a time limit and a 2 GB memory cap; *exit* 2 is an input error, 3 a numerical fault, 124 the "
      "time limit, 134/136/139 a crash. The message is the first line starting with `input error`, `error`, "
      "`numerical fault`, `data problem` or `warning` (else the first line); WORK is the scratch folder. "
      "`make test` holds the same cases with their expected answers: `robustness.entry_points_bad_paths`, "
      "`robustness.numeric_options`, `robustness.hostile_inputs`, `robustness.option_lists` and `robustness.edited_decks` (the CSV dialects: "
      "`robustness.csv_dialects_and_encoding`). Values a command accepts on purpose "
      "(`tests/robustness/option_valid.txt`, e.g. `--threads 0`) are marked *valid*; they start real "
      "work, so 124 there is the table's 20 s limit, not a hang. Rows in bold changed their exit code. "
      "Inputs that parse but are physically nonsense (loop, model-loop, calibrate, export, plan): "
      "`docs/robustness-nonsense.md` (hand-written; `robustness.nonsense_physics`).", "",
      f"- before: `{before}`", f"- after: `{after}`", "",
      "## Summary", "",
      "| matrix | cases | before: exit 2 or 3 | before: exit 0 | before: other | after: exit 2 or 3 | after: exit 0 | after: other |",
      "|---|---|---|---|---|---|---|---|"]
sections = []
for m in ("entry_matrix", "option_matrix", "hostile_matrix", "option_lists", "edited_decks"):
    b = {k: (e, f) for k, e, f in rows(m, "before")}
    a = rows(m, "after")
    body, count = [], {"before": collections.Counter(), "after": collections.Counter()}
    for k, e, f in a:
        be, bf = b.get(k, ("-", ""))
        ok = accepted(m, k)
        for side, code in (("before", be), ("after", e)):
            if ok or code == "-":
                continue
            count[side]["23" if code in ("2", "3") else "0" if code == "0" else "x"] += 1
        mark = " (valid)" if ok else ""
        ae = f"**{e}**" if (be != e and be != "-") else e
        body.append(f"| {k[0]} | {k[1]} | {be}{mark} | {short(bf)} | {ae}{mark} | {short(f)} |")
    n = sum(1 for k, _, _ in a if not accepted(m, k))
    md.append(f"| {m} (bad inputs) | {n} | " + " | ".join(str(count[s][c]) for s in ("before", "after") for c in ("23", "0", "x")) + " |")
    sections += [f"## {titles[m]}", "",
                 "| entry point | input | exit before | first line before | exit after | first line after |",
                 "|---|---|---|---|---|---|"] + body + [""]
md += ["", "Exit 0 among bad inputs after: the hostile, list and edited-deck matrices' valid cases (CRLF files, a "
       "warning that lets the run finish, `help help`, a valid list, `--help` of every command, `plan` warning "
       "of a summary.csv it leaves out), which expect exit 0; every other bad input ends with exit 2.", ""]
open(out, "w", encoding="utf-8").write("\n".join(md + sections))
print(f"wrote {out}")
PY
