#pragma once
// Outputs of a loop run: tables (CSV), the Markdown page, loop_summary.json,
// and gnuplot figures of the residual against each candidate, before (base
// model) and after (final model), both held-out residuals.
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "loop/export.hpp"
#include "loop/loop.hpp"

namespace drawbend::loop {

CsvWriter candidates_table(const LoopResult& r);  ///< every round's ranking
CsvWriter effects_table(const LoopResult& r);     ///< added effects, parameters, standard errors
CsvWriter steps_table(const LoopResult& r);       ///< RMS and max before/after per step
/// Per row: candidate values (base model), held-out residual before and after.
CsvWriter residuals_table(const Design& d, const LoopResult& r);
CsvWriter problems_table(const Dataset& d);

/// Write everything under out_dir.  figures_dir: directory of the gnuplot
/// scripts (empty: no figures).  exports: "none" or a comma list of
/// lsdyna, openradioss, abaqus written next to each friction_model*.toml
/// with `eo` (loop/export.hpp) and named in loop.md.  Returns the Markdown page text.
std::string write_loop_outputs(const Design& d, const LoopResult& r, const std::string& out_dir,
                               const std::string& figures_dir, const std::string& gnuplot = "gnuplot",
                               const std::string& exports = "none", const ExportOptions& eo = {});

}  // namespace drawbend::loop
