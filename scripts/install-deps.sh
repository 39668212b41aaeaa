#!/usr/bin/env bash
# Install the Debian packages drawbend needs, only those missing.
# Idempotent and non-interactive; safe to run on every `make`.
# Usage: install-deps.sh [--bench] [--print]   (--bench: also what `make bench` uses;
#   --print: only print the apt-get line, as it does whenever it is not run as root)
set -euo pipefail
print_only=0
for a in "$@"; do if [ "$a" = "--print" ]; then print_only=1; fi; done
# clang and libclang-rt-dev: libFuzzer for the parser fuzzers (tests/fuzz); with
# libomp-dev (OpenMP for clang) also the sanitizer build (tests/sanitize/run.sh);
# lld links both (a sixth less CPU for the sanitizer build; without it GNU ld does).
PKGS=(cmake g++ make libeigen3-dev libboost-test-dev libtomlplusplus-dev gnuplot-nox pandoc clang libclang-rt-dev libomp-dev lld)
# slurmctld, slurmd, slurm-client and munge: the test cluster.executors starts
# a single-node Slurm on this machine to run cases through the slurm executor
# (tests/cluster/; never started outside that test).
PKGS+=(slurmctld slurmd slurm-client munge)
# zlib1g-dev: the compressed binary ParaView frames (io/vtu.hpp; without it they
# are written uncompressed).  python3-vtk9: the test that reads a run's frames
# with VTK's own XML readers (tests/user/vtk_read.py; skipped without it).
PKGS+=(zlib1g-dev python3-vtk9)
# --bench (`make bench`): calculix-ccx, CalculiX's solver (Debian 2.20-1 on
# bookworm), an independent peer that the bench times on the same bar as ours
# (bench/bench_calculix.cpp).  Only there: it pulls in OpenMPI and SPOOLES,
# which `make` and `make test` do not need; the bench says so and carries on
# without it.
for a in "$@"; do if [ "$a" = "--bench" ]; then PKGS+=(calculix-ccx); fi; done
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
# Not root (or --print): print the line to run instead of calling sudo, and stop,
# so that nothing is installed behind the user's back.
if [ "$(id -u)" -ne 0 ] || [ "$print_only" = 1 ]; then
  echo "install-deps: missing Debian packages: ${missing[*]}"
  echo "install-deps: install them with (as root):"
  echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}"
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
