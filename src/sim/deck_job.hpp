#pragma once
// A builder's deck as a file-level job: the one path every FE case of the
// chapters takes (draw-bend, strip draw, block; issue 56).
//
// Contract
// - The deck text (table files named by absolute path, as the builders write
//   it) goes to DIR/deck.toml as a portable deck (its tables copied beside it,
//   io/portable_paths.hpp) and runs there as `drawbend run DIR/deck.toml --out
//   DIR`: in this process for the `local` executor (its log kept as
//   DIR/run.log), else as one job of the executor (sim/executor.hpp), which
//   returns when DIR holds a complete run.
// - A run folder is complete when it holds summary.csv (written last); the old
//   one is removed before a case starts.  With `reuse`, a folder that already
//   holds the byte-identical deck and a summary.csv is not run again.
// - The chapter then reduces the folder (each builder's reader).
#include <string>
#include <vector>

#include "io/run_result.hpp"

namespace drawbend::sim {

/// Run `deck_text` as the job `name` in `dir` (see above); true if it ran,
/// false if the folder was reused.  `run_args`: more `drawbend run` options
/// for an external job (words without shell quoting), matching `result`.
bool run_deck_job(const std::string& name, const std::string& deck_text, const std::string& dir, bool reuse,
                  bool quiet = true, const io::ResultOptions& result = {}, const std::string& run_args = "");

/// Whether `dir` holds `deck_text` (made portable) byte for byte, the tables it
/// reads (io::portable_inputs_current) and a summary.csv.
bool finished_run_of(const std::string& deck_text, const std::string& dir);

/// A chapter's cases as jobs: deck `texts[k]` in `runs`/<names[k]>, run
/// side by side through the case pool (sim/case_pool.hpp; as many in flight as
/// the executor takes).  Cases with the same name must have the same deck and
/// run once.  Returns each case's folder, in order.  Throws InputError
/// ("<what>: ...") on a name that cannot name a folder or one name with two decks.
std::vector<std::string> run_jobs(const std::vector<std::string>& names, const std::vector<std::string>& texts,
                                  const std::string& runs, bool reuse, const std::string& what);

}  // namespace drawbend::sim
