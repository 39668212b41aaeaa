#!/usr/bin/env bash
# The sanitizer build: AddressSanitizer + UndefinedBehaviorSanitizer, -O0
# (CMakeLists.txt says why not -O1; where the tests spend their time is at
# -O1: the element kernel and the bending work, src/CMakeLists.txt; the loop's
# fits and screen, src/loop/CMakeLists.txt; two tests, tests/CMakeLists.txt).
# Configures BUILD_DIR (normally build-asan beside build) with
# DRAWBEND_SANITIZE=ON and DRAWBEND_TESTS_ONLY=ON, builds only what the tests
# need (target sanitize_tests) and runs the unit tests, the cheap verification
# problems and the fuzz corpora's replays (label asan) and the robustness tests
# (drawbend on broken decks).
# Any sanitizer report fails the run (-fno-sanitize-recover=all, ASan aborts;
# halt_on_error for the one check that recovers, float-cast-overflow, so that
# ubsan.supp can name a library's known case).
# The compiler: clang++ if installed (this script took about 65 % of g++'s
# time and CPU with it, CMakeLists.txt), else the default; DRAWBEND_SANITIZE_CXX overrides.
# Usage: run.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=$1 bld=$2
jobs=$(nproc 2>/dev/null || echo 2)
cxx=${DRAWBEND_SANITIZE_CXX:-$(command -v clang++ || true)}
cxx=${cxx:-$(command -v c++ || command -v g++)}
# CMake cannot change the compiler of a configured folder: start it afresh.
if [ -f "$bld/CMakeCache.txt" ] && ! grep -qx "CMAKE_CXX_COMPILER:[A-Z]*=$cxx" "$bld/CMakeCache.txt"; then
  rm -rf "$bld"
fi
echo "sanitize: compiler $cxx"
t0=$(date +%s)
# Linked by lld when installed: GNU ld spent about 155 of the 575 task-seconds
# of this build in linking the instrumented tests; with lld the whole build took
# 7.9 CPU-min against 9.5 (4.05 min against 4.9 on 2 cores, 2026-12-05, AMD EPYC,
# nothing else running).
ldflags=""
command -v ld.lld >/dev/null && ldflags="-fuse-ld=lld"
# Shared libraries (BUILD_SHARED_LIBS): with static ones every instrumented test
# carried its own copy of the libraries, about 70 MB each, and this folder grew
# to 3.1 GB; CI's run of 77356cd stopped here with "No space left on device"
# while linking.  Shared, the folder is 0.68 GB, and inside make test on fresh
# clones the build took 324 s against 411 s (2026-12-06, 2-core Intel Xeon),
# the same 136 tests passing.
cmake -S "$src" -B "$bld" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Debug -DDRAWBEND_SANITIZE=ON \
  -DDRAWBEND_TESTS_ONLY=ON -DBUILD_SHARED_LIBS=ON \
  -DCMAKE_EXE_LINKER_FLAGS="$ldflags" -DCMAKE_SHARED_LINKER_FLAGS="$ldflags" >/dev/null
cmake --build "$bld" --target sanitize_tests -j "$jobs" 2>&1 | grep -E "error|warning|Error" || true
cmake --build "$bld" --target sanitize_tests -j "$jobs" >/dev/null  # fails the test if the build failed
t1=$(date +%s)
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
# The tests that repeat one path over many seeds or sizes run a share of them
# here (tests/common/sanitizer_run.hpp; the option matrix: option_matrix.sh).
export DRAWBEND_SANITIZER_RUN=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$src/tests/sanitize/ubsan.supp
cd "$bld"
rm -rf tests/fuzz_replay_tmp/*  # the corpus replays' scratch folders (fuzz_replay.*, one per process)
# Not here: the cluster tests (their driver is not in sanitize_tests, and they
# start Slurm daemons) and the user-level example tests that run whole FE cases
# (help examples and the model_loop.md check that reads their output, result.toml,
# portable run folder, the ParaView frames' three strip runs: 1-5 minutes each at -O0;
# the same code paths run here through the robustness and cli tests, the binary
# frames through unit.test_vtu), and the install into a prefix (a sanitizer build
# is not what a user installs).
ctest --output-on-failure -j "$jobs" -L 'unit|asan|robustness' -LE cluster \
  -E '^cli\.(help_examples|help_examples_model_loop|model_loop_md|run_result|portable_run_folder|vtk_frames|install_prefix)$'
t2=$(date +%s)
echo "sanitize: build $((t1 - t0)) s, tests $((t2 - t1)) s"
