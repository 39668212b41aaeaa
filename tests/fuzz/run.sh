#!/usr/bin/env bash
# Build the parser fuzzers with clang (libFuzzer + ASan + UBSan) in BUILD_DIR
# and run each on its seed corpus (tests/fuzz/corpus/<target>) for SECONDS
# seconds.  New inputs go to a scratch copy of the corpus, so the repository's
# seeds stay as they are.  Without clang the test is skipped (exit 77, which
# CTest reports as "Skipped" through SKIP_RETURN_CODE).
# Usage: run.sh SOURCE_DIR BUILD_DIR [SECONDS [TARGET...]]   (targets: deck csv
#   loop material export calibrate plan, all seven when none is given; only
#   the given ones and what they link are built)
set -euo pipefail
src=$1 bld=$2 secs=${3:-5}
shift $(( $# < 3 ? $# : 3 ))
targets=${*:-deck csv loop material export calibrate plan}
if ! command -v clang++ >/dev/null; then
  echo "fuzz: SKIPPED: clang++ not found (scripts/install-deps.sh installs clang)"
  exit 77
fi
ldflags=""  # lld when installed, as tests/sanitize/run.sh
command -v ld.lld >/dev/null && ldflags="-fuse-ld=lld"
cmake -S "$src/tests/fuzz" -B "$bld" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_EXE_LINKER_FLAGS="$ldflags" >/dev/null
cmake --build "$bld" -j "$(nproc 2>/dev/null || echo 2)" --target $(printf 'fuzz_%s ' $targets) >/dev/null
# fuzz_loop writes its outputs under the temporary folder: keep them in the
# build folder (emptied each time), not one /tmp/fuzz_loop_PID per run.
rm -rf "$bld/tmp"
mkdir -p "$bld/tmp"
for t in $targets; do
  work=$bld/corpus_$t
  rm -rf "$work"
  mkdir -p "$work"
  cp "$src/tests/fuzz/corpus/$t"/* "$work"/
  set +e
  dict=$src/tests/fuzz/$t.dict
  [ -f "$dict" ] || dict=$src/tests/fuzz/csv.dict  # the loop reads CSV
  # calibrate runs the Yld2004-18p fit (15 starts) on each input: about 0.2 s
  # of CPU on a 4-row file in this build, 23 s on a 5-row file with a
  # plane-strain row (1.4 s for 10 rows in the Release build); shorter inputs
  # and a longer time limit keep a slow fit from counting as a hang.  export's
  # OpenRadioss fit splits the speed range into up to 8 bands of 300 Lawson
  # iterations: 0.24 s of CPU in the Release build on a model that needs all
  # 8 (2026-12-02), over 30 s in this build on a loaded machine.
  limits="-timeout=10 -max_len=4096"
  [ "$t" = calibrate ] && limits="-timeout=120 -max_len=400"
  [ "$t" = export ] && limits="-timeout=120 -max_len=4096"
  TMPDIR="$bld/tmp" "$bld/fuzz_$t" -max_total_time="$secs" $limits -close_fd_mask=1 -rss_limit_mb=2048 \
    -artifact_prefix="$bld/crash_$t-" -dict="$dict" "$work" >"$bld/fuzz_$t.log" 2>&1
  rc=$?
  set -e
  grep -E "^#[0-9]+ +DONE|^Done [0-9]+ runs" "$bld/fuzz_$t.log" | sed "s/^/fuzz_$t: /" || true
  if [ $rc -ne 0 ]; then
    tail -40 "$bld/fuzz_$t.log"
    echo "fuzz_$t: FAILED (exit $rc); the input is saved as $bld/crash_$t-*"
    exit 1
  fi
done
echo "fuzz: ok"
