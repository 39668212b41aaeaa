#!/usr/bin/env bash
# robustness-table.sh: the table of issue 53's closing note, entry point x
# class of bad input -> exit code and first line of the message, for two
# binaries side by side (before and after a change), written as Markdown.
#   [BEFORE_LABEL=...] [AFTER_LABEL=...] scripts/robustness-table.sh BEFORE_DRAWBEND AFTER_DRAWBEND OUT.md [WORK_DIR]
# (the labels name the two binaries in the page, e.g. their commits).
# It runs the three matrices of tests/robustness (without --check, so every
# case is run and shown, also the values a command accepts):
#   entry_matrix.sh   every path a command reads: missing file, folder, device, FIFO;
#                     every file it writes pointed at a FIFO or a folder
#   option_matrix.sh  every numeric option of every command: 0, -1, nan, 1e300, a word
#   hostile_matrix.sh the other classes: options twice or without a value, units in
#                     values, CRLF, duplicated keys, absurd table values, options
#                     that do nothing in the mode chosen, unwritable folders, ...
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
for m in entry_matrix option_matrix hostile_matrix; do
  for side in before after; do
    bin=$before
    [ $side = after ] && bin=$after
    bash "$here/$m.sh" "$bin" "$work/$m.$side" >"$work/$m.$side.md" 2>&1
  done
done
python3 - "$work" "$out" "${BEFORE_LABEL:-$before}" "${AFTER_LABEL:-$after}" <<'PY'
import sys, re
work, out, before, after = sys.argv[1:5]

def rows(path):
    """Table rows of a matrix's output: (key, exit, first line), in order."""
    r = []
    for line in open(path, encoding="utf-8", errors="replace"):
        if not line.startswith("| ") or line.startswith("| command |") or line.startswith("| entry point |"):
            continue
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]
        if len(cells) < 4:
            continue
        r.append(((cells[0], cells[1]), cells[2], " | ".join(cells[3:])))
    return r

def short(text, n=140):
    text = text.replace(work, "WORK")
    return text if len(text) <= n else text[:n - 1] + "…"

titles = {
    "entry_matrix": "Paths: every file a command reads or writes, given a missing file, a folder, a device (/dev/zero) or a FIFO",
    "option_matrix": "Numbers: every numeric option of every command, given 0, -1, nan, 1e300 and a word",
    "hostile_matrix": "Other classes: a careless user and a hostile script",
}
md = ["# Robustness: entry point x bad input, before and after", "",
      "Written by `scripts/robustness-table.sh` (do not edit by hand). Each row is one run of `drawbend` "
      "under a time limit and a 2 GB memory cap; *exit* 2 is an input error, 3 a numerical fault, 124 the "
      "time limit (for accepted values that start a real run), 134/136/139 a crash. The message is the first line "
      "starting with `input error`, `error`, `numerical fault`, `data problem` or `warning` (else the first line). "
      "`make test` holds the same cases with their expected answers: `robustness.entry_points_bad_paths`, "
      "`robustness.numeric_options` (values listed in `tests/robustness/option_valid.txt` are accepted on "
      "purpose) and `robustness.hostile_inputs`.", "",
      f"- before: `{before}`", f"- after: `{after}`", ""]
changed_total = 0
for m in ("entry_matrix", "option_matrix", "hostile_matrix"):
    b = {k: (e, f) for k, e, f in rows(f"{work}/{m}.before.md")}
    a = rows(f"{work}/{m}.after.md")
    seen = set()
    body = []
    changed = 0
    for k, e, f in a:
        if k in seen:
            continue
        seen.add(k)
        be, bf = b.get(k, ("-", ""))
        diff = (be != e) or (short(bf) != short(f))
        changed += diff
        body.append(f"| {k[0]} | {k[1]} | {be} | {short(bf)} | {'**' + e + '**' if be != e else e} | {short(f)} |")
    for k, (be, bf) in b.items():
        if k not in seen:
            body.append(f"| {k[0]} | {k[1]} | {be} | {short(bf)} | - | |")
            changed += 1
    changed_total += changed
    md += [f"## {titles[m]}", "", f"{len(body)} cases, {changed} of them answered differently after.", "",
           "| entry point | input | exit before | first line before | exit after | first line after |",
           "|---|---|---|---|---|---|"] + body + [""]
open(out, "w", encoding="utf-8").write("\n".join(md))
print(f"wrote {out}: {changed_total} cases answered differently")
PY
