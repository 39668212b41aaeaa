#!/usr/bin/env bash
# scripts/full_tier_decks.sh DRAWBEND QUICK_CHAPTERS OUT: an inventory of
# `make test-full`'s FE cases as decks, made by the builders
# without running anything (issue 56: what the cost model predicts for the
# full tier).  Draw-bend cases: every quick-tier draw-bend deck of Chapters
# 2-5 and 8 rebuilt by `drawbend drawbend-deck` with the full tier's mesh
# (0.5 mm elements, 4 across; Chapter 2's *_fine cases 0.25 mm) and, for
# Chapter 8, its mass scaling (625 at 100 mm/s: 2500 at its 50 mm/s) and
# its run's material type (combined hardening where it had it);
# Chapter 8's numerical studies (3 pins x mass scaling 10000/2500/625; 25.4
# and 42 mm pins x 2/4/8 across at the quick tier's 40000)
# and 6 more loop runs (Voce and Hill'48 after the back stress, 2 per pin).
# Strip draws and blocks: the quick tier's decks.  Cups: Chapter 6's nine
# Table 6.5 speeds refined (x2, 160000 cycles per 17 mm) and case 1 to 21 mm;
# Chapter 8's 20 coarse loop cups as in the quick tier, its refined confirm
# (cases 1 and 9 to 15.5 mm) and 2 x 2 (to 21 mm); Chapter v1's 4 cups with
# 30 rows, 150000 cycles, 50 mm.
# An estimate, not the chapters' own list: it follows their full-tier options
# as of 2026-12-02 (chapters/CMakeLists.txt FULL_ARGS, ch6_cup.cpp,
# ch8_numerics.cpp, ch8_cup.cpp, v1's FULL_ARGS); Chapter 8's adaptive loop
# is counted as its quick tier's runs plus the 6 that --next-candidates adds.
# Needs a finished quick tier (`make test`) in QUICK_CHAPTERS.  Example:
#   scripts/full_tier_decks.sh build/src/drawbend build/chapters /tmp/full-decks
#   build/src/drawbend plan /tmp/full-decks --nodes 4 --cores 2
set -eu
db=$1 quick=$2 out=$3   # drawbend binary, a quick tier's build/chapters, output folder
rm -rf "$out"; mkdir -p "$out"
n=0
deck() { n=$((n+1)); mkdir -p "$out/$1"; cat > "$out/$1/deck.toml"; }
fb() {  # fb NAME PIN SPEED SLIDE MS EL ACROSS [MATERIAL: a [material] inline table; none: J2]
  "$db" drawbend-deck --name "$1" --pin-diameter "$2" --speed "$3" --draw-length "$4" --mass-scaling "$5" \
        --element-length "$6" --across "$7" ${8:+--material "$8"} | deck "$1"
}
for d in "$quick"/ch2-fe-study/runs/*/ "$quick"/ch3-stribeck/runs/ch3_d*/ "$quick"/ch4-new-method/runs/*/ \
         "$quick"/ch5-measured/runs/*/ "$quick"/ch8-model-loop/runs/fb_*/; do
  f=$d/deck.toml; [ -f "$f" ] || continue
  name=$(basename "$d"); ch=$(basename "$(dirname "$(dirname "$d")")")
  pin=$(sed -n 2p "$f" | sed -E 's/.*Pin ([0-9.]+) mm.*/\1/')
  speed=$(sed -n 2p "$f" | sed -E 's/.*outlet speed ([0-9.e+-]+) mm\/s.*/\1/')
  slide=$(sed -n 2p "$f" | sed -E 's/.*slide ([0-9.e+-]+) mm.*/\1/')
  ms=$(grep -m1 '^mass_scaling' "$f" | sed -E 's/.*= *//')
  el=0.5; case $name in *_fine) el=0.25 ;; esac
  [ "$ch" = ch8-model-loop ] && ms=$(awk -v m="$ms" 'BEGIN{print m/16}')  # 625 at 100 mm/s instead of 1e4
  # the run's material type and back stresses (its cost: sim/cost_model.hpp material_factor); its curve is not kept
  mat=$(awk '/^\[material\]/{m=1;next} /^\[/{m=0} m&&/^(type|kinematic) = /' "$f" | paste -sd, -)
  case $mat in *j2_combined*) mat="{ $mat }" ;; *) mat= ;; esac
  fb "full_${ch}_$name" "$pin" "$speed" "$slide" "$ms" "$el" 4 "$mat"
done
f8=$(ls -d "$quick"/ch8-model-loop/runs/fb_*/ | head -1)
for pin in 12.7 25.4 42; do
  for ms in 10000 2500 625; do fb "full_ch8_ms${ms}_d$pin" $pin 50 0 $ms 0.5 4; done
  for k in 1 2; do fb "full_ch8_next${k}_d$pin" $pin 50 0 2500 0.5 4; done
done
for pin in 25.4 42; do for a in 2 4 8; do fb "full_ch8_across${a}_d$pin" $pin 50 0 40000 0.5 $a; done; done
for d in "$quick"/ch3-stribeck/runs/ch3_strip_*/ "$quick"/ch6-friction-model/runs/ch6_block_*/; do
  mkdir -p "$out/full_$(basename "$d")"; cp "$d"/deck.toml "$d"/*.csv "$out/full_$(basename "$d")/" 2>/dev/null || true
  rm -f "$out/full_$(basename "$d")"/{summary,history,reduction}.csv "$out/full_$(basename "$d")"/contact_*.csv
done
data=$(cd "$(dirname "$db")/../.." && pwd)/data
k=0
for v in 6.4 12.8 19.3 25.3 31.5 37.5 42.8 47.6 77.1; do
  k=$((k+1)); "$db" cup-deck --base "$data/cases/cup_draw.toml" --speed $v --stroke 17 --cycles 160000 --refine 2 | deck "full_ch6_cup$k"
done
"$db" cup-deck --base "$data/cases/cup_draw.toml" --speed 6.4 --stroke 21 --cycles 197647 --refine 2 | deck full_ch6_cup1_21mm
for d in $(ls -d "$quick"/ch8-model-loop/runs/cup_*/ 2>/dev/null); do mkdir -p "$out/full_ch8_$(basename "$d")"; cp "$d"/deck.toml "$d"/*.csv "$out/full_ch8_$(basename "$d")/"; rm -f "$out/full_ch8_$(basename "$d")"/{summary,history,reduction}.csv "$out/full_ch8_$(basename "$d")"/contact_*.csv; done
for v in 6.4 77.1; do "$db" cup-deck --base "$data/cases/cup_draw.toml" --speed $v --stroke 15.5 --cycles 145882 --refine 2 | deck "full_ch8_confirm_$v"; done
for k in 1 2 3 4; do "$db" cup-deck --base "$data/cases/cup_draw.toml" --speed 6.4 --stroke 21 --cycles 197647 --refine 2 | deck "full_ch8_attr$k"; done
for d in "$quick"/v1-earing-benchmark/runs/v1_cup_*/; do  # the full tier: 30 rows, 50 mm in 150000 cycles (the same dt)
  o="$out/full_$(basename "$d")"; mkdir -p "$o"
  awk '/^ring = /{print "ring = 30"; next} /^\[\[step\]\]/{s++} s==2 && /^duration = /{print "duration = 0.505"; next} {print}' "$d/deck.toml" > "$o/deck.toml"
done
echo "inventory: $(find "$out" -name deck.toml | wc -l) decks in $out"
