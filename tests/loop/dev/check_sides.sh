#!/bin/bash
# Side-by-side check of a loop change (heldout_record.md's bars): runs
# blind_dev.sh over whole seed blocks (48 sets each) for two builds at once,
# one core each, and writes OUT/TAG_S0.txt per side and block. Compare with
# cmp_sides.py. Development seeds only: blind_dev.sh refuses held-out ones.
# usage: check_sides.sh BIN_MAIN BIN_BRANCH OUT "S0 GEN" ["S0 GEN" ...]
#   e.g. check_sides.sh main/drawbend branch/drawbend /tmp/chk "76700000 blind" "76800000 wild"
#   BIN "-": that side is not run (e.g. main's side run earlier)
#   tags: OUT/main_S0.txt and OUT/branch_S0.txt; sets in OUT/sets/{main,branch}/S0
set -u
if [ $# -lt 4 ]; then sed -n 2,9p "$0"; exit 2; fi
BM=$1; BB=$2; OUT=$3; shift 3
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$OUT"
side() {  # TAG BIN blocks...
  local tag=$1 bin=$2; shift 2
  for b in "$@"; do
    set -- $b
    bash "$HERE/blind_dev.sh" "$bin" "$1" 48 "$OUT/sets/$tag/$1" 20000 0 "$2" > "$OUT/${tag}_$1.txt" 2> "$OUT/${tag}_$1.err"
  done
}
[ "$BB" = - ] || side branch "$BB" "$@" &
[ "$BM" = - ] || side main "$BM" "$@" &
wait
