#!/usr/bin/env bash
# Install the Debian packages drawbend needs, only those missing.
# Idempotent and non-interactive; safe to run on every `make`.
# Usage: install-deps.sh [--bench]   (--bench: also what `make bench` uses)
set -euo pipefail
# clang and libclang-rt-dev: libFuzzer for the parser fuzzers (tests/fuzz); with
# libomp-dev (OpenMP for clang) also the sanitizer build (tests/sanitize/run.sh).
PKGS=(cmake g++ make libeigen3-dev libboost-test-dev libtomlplusplus-dev gnuplot-nox pandoc clang libclang-rt-dev libomp-dev)
# slurmctld, slurmd, slurm-client and munge: the test cluster.executors starts
# a single-node Slurm on this machine to run cases through the slurm executor
# (tests/cluster/; never started outside that test).
PKGS+=(slurmctld slurmd slurm-client munge)
# --bench (`make bench`): calculix-ccx, CalculiX's solver (Debian 2.20-1 on
# bookworm), an independent peer that the bench times on the same bar as ours
# (bench/bench_calculix.cpp).  Only there: it pulls in OpenMPI and SPOOLES,
# which `make` and `make test` do not need; the bench says so and carries on
# without it.
if [ "${1:-}" = "--bench" ]; then PKGS+=(calculix-ccx); fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
