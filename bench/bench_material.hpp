#pragma once
// make bench: the material update alone, ns per integration-point update, for
// each constitutive model (bench_material.cpp).
#include <string>

#include "core/csv.hpp"

/// Appends rows (case "material_<model>", elements = points, threads = 1,
/// ns per point update) to w and prints them.
void bench_material(drawbend::CsvWriter& w, bool quick);
