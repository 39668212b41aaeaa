#!/bin/bash
# Issue 55, item 8 (in part): installing and citing.
#  - scripts/install-deps.sh --print, with every package reported missing (a
#    dpkg-query stand-in first on PATH), prints the apt-get line naming them,
#    exits 1 and calls neither apt-get nor sudo (stand-ins record any call);
#  - CITATION.cff states the version of CMakeLists.txt's project(VERSION) and a
#    date-released in YYYY-MM-DD form.
# Usage: install_cite.sh SOURCE_DIR WORK_DIR
set -u
src=$1 work=$2
rm -rf "$work" && mkdir -p "$work/shim" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
printf '#!/bin/sh\nexit 1\n' > "$work/shim/dpkg-query"
for c in apt-get sudo; do printf '#!/bin/sh\necho "%s $*" >> "%s/calls"\n' "$c" "$work" > "$work/shim/$c"; done
chmod +x "$work/shim/"*
PATH="$work/shim:$PATH" bash "$src/scripts/install-deps.sh" --print > "$work/out" 2>&1
rc=$?
[ $rc -eq 1 ] || fail "install-deps --print with packages missing: exit $rc, expected 1"
grep -q '^  apt-get update && apt-get install -y --no-install-recommends cmake g++ make ' "$work/out" || fail "no apt-get line: $(cat "$work/out")"
[ -e "$work/calls" ] && fail "install-deps --print called: $(cat "$work/calls")"
v=$(sed -n 's/^project(drawbend VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
[ -n "$v" ] || fail "no project VERSION in CMakeLists.txt"
grep -q "^version: \"$v\"$" "$src/CITATION.cff" || fail "CITATION.cff: no version \"$v\""
grep -Eq '^date-released: "[0-9]{4}-[0-9]{2}-[0-9]{2}"$' "$src/CITATION.cff" || fail "CITATION.cff: no date-released"
echo "install-deps prints 'apt-get install' without calling it; CITATION.cff version $v"
