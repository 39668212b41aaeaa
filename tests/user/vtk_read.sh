#!/bin/bash
# Issue 55, item 3: the ParaView frames read with VTK's own XML readers.
# Runs tests/user/decks/vtk_drawbend.toml three times: binary frames on 1 and
# on 2 threads (every frame must be bit-identical: the fields are summed in a
# fixed order), and ASCII frames (vtk_format = "ascii"); then vtk_read.py
# checks the frames (its header states each expected answer and its reason).
# Exit 77 (skipped) when no python3 on this machine imports vtk (Debian:
# python3-vtk9, in scripts/install-deps.sh).
# Usage: vtk_read.sh DRAWBEND DATA_DIR WORK_DIR
set -u
bin=$1 data=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
py=""
for p in /usr/bin/python3 python3; do
  if "$p" -c "import vtk" > /dev/null 2>&1; then py=$p; break; fi
done
[ -n "$py" ] || { echo "SKIP: no python3 with vtk (apt-get install python3-vtk9)"; exit 77; }
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
deck=$here/decks/vtk_drawbend.toml
"$bin" run "$deck" --out "$work/t1" --quiet --threads 1 > "$work/t1.log" 2>&1 || fail "run on 1 thread: $(tail -3 "$work/t1.log")"
"$bin" run "$deck" --out "$work/t2" --quiet --threads 2 > "$work/t2.log" 2>&1 || fail "run on 2 threads: $(tail -3 "$work/t2.log")"
n=0
for f in "$work"/t1/*.vtu "$work"/t1/*.vtp "$work"/t1/*.vtm "$work"/t1/fields.pvd; do
  cmp -s "$f" "$work/t2/$(basename "$f")" || fail "$(basename "$f") differs between 1 and 2 threads"
  n=$((n + 1))
done
sed -e "s#\"\.\./\.\./\.\./data/#\"$data/#" -e 's/^fields_per_step = 3$/fields_per_step = 3\nvtk_format = "ascii"/' "$deck" > "$work/ascii.toml"
grep -q '^vtk_format = "ascii"' "$work/ascii.toml" || fail "could not make the ascii deck"
"$bin" run "$work/ascii.toml" --out "$work/ascii" --quiet > "$work/ascii.log" 2>&1 || fail "ascii run: $(tail -3 "$work/ascii.log")"
echo "$n frame files bit-identical on 1 and 2 threads"
exec "$py" "$here/vtk_read.py" "$work/t1" "$work/ascii"
