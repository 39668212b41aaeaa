#pragma once
// make bench: the machine and kernel, and the quick draw-bend deck
// (`drawbend drawbend-deck --run` with its defaults) on 1 and 2 threads
// (bench_deck.cpp).
#include <string>

#include "core/csv.hpp"

/// The CPU's model name (/proc/cpuinfo), or "unknown".
std::string cpu_model();

/// Runs the quick draw-bend deck in a scratch folder under `dir` on 1 and, if
/// the machine has them, 2 threads; appends rows (case "drawbend_deck_wall_s",
/// elements, threads, wall seconds) and prints whether 2 threads were slower
/// than 1 beyond 10 % (noise).  Returns false if they were.
bool bench_deck(const std::string& dir, drawbend::CsvWriter& w);
