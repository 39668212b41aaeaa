#pragma once
// make bench: cost of the mu(p, v) surface law against Coulomb (see bench_friction.cpp).
#include <string>

#include "core/csv.hpp"

/// Times the block-sliding deck with Coulomb and with the surface law (fixed and
/// corotational texture); writes out_csv and appends rows to `results`.
void bench_friction(const std::string& deck_path, const std::string& out_csv, drawbend::CsvWriter& results, bool quick);
