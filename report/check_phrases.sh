#!/usr/bin/env bash
# Fail when a chapter page (chapters/*/*.md) still says that its work comes
# "later" ("later issue", "later work"): stale once the results are there.
# Usage: check_phrases.sh chapters_src
set -euo pipefail
src=$1
ls "$src"/*/*.md >/dev/null
if grep -rniE 'later (issue|work)' "$src"/*/*.md; then
  echo "stale phrase in a chapter page (above): say what the page shows now"
  exit 1
fi
echo "no stale phrases in $(ls "$src"/*/*.md | wc -l) chapter pages"
