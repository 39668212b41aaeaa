#!/usr/bin/env bash
# contact-sheet.sh: look at figures before calling a report change done.
# Lays out the given SVG/PNG figures two per row on one HTML page and
# screenshots it with headless Chromium (Debian package chromium; not installed
# by scripts/install-deps.sh, since neither make nor make test needs it).
#   scripts/contact-sheet.sh OUT.png FIG1.svg [FIG2.svg ...]
# Example (Chapter 5's figures after `make test`):
#   scripts/contact-sheet.sh /tmp/ch5.png build/chapters/ch5-measured/figures/fig_5_1[234].svg
# The page is 1280 px wide; each figure is 620 px wide, 320 px tall per row.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 OUT.png FIGURE [FIGURE ...]" >&2
  exit 2
fi
out=$1
shift
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "$0: chromium not found (install the Debian package: sudo apt-get install chromium)" >&2; exit 2; }
page=$(mktemp --suffix=.html)
trap 'rm -f "$page"' EXIT
{
  echo '<!doctype html><html><body style="margin:0;background:#fff;font:12px sans-serif">'
  echo '<div style="display:grid;grid-template-columns:repeat(2,630px);gap:8px;padding:6px">'
  for f in "$@"; do
    [ -r "$f" ] || { echo "$0: $f: cannot read" >&2; exit 2; }
    echo "<figure style=\"margin:0\"><img src=\"file://$(realpath "$f")\" style=\"width:620px;height:300px;object-fit:contain\">"
    echo "<figcaption>$(basename "$f")</figcaption></figure>"
  done
  echo '</div></body></html>'
} >"$page"
rows=$((($# + 1) / 2))
timeout 120 "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --virtual-time-budget=5000 \
  --window-size=1280,$((rows * 340 + 20)) --screenshot="$out" "file://$page" >/dev/null 2>&1
[ -s "$out" ] || { echo "$0: no screenshot written" >&2; exit 1; }
echo "$out: $# figures"
