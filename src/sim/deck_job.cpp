// A builder's deck as a file-level job.  See deck_job.hpp.
#include "sim/deck_job.hpp"

#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "core/csv.hpp"
#include "io/deck.hpp"
#include "io/portable_paths.hpp"
#include "io/run_case.hpp"
#include "sim/case_pool.hpp"
#include "sim/cost_model.hpp"
#include "sim/executor.hpp"

namespace drawbend::sim {

namespace fs = std::filesystem;

bool finished_run_of(const std::string& deck_text, const std::string& dir) {
  const fs::path deck_path = fs::path(dir) / "deck.toml";
  return fs::exists(deck_path) && fs::exists(fs::path(dir) / "summary.csv") &&
         read_file(deck_path.string()) == io::portable_deck(deck_text) && io::portable_inputs_current(deck_text, dir);
}

bool run_deck_job(const std::string& name, const std::string& deck_text, const std::string& dir, bool reuse, bool quiet,
                  const io::ResultOptions& result, const std::string& run_args) {
  if (reuse && finished_run_of(deck_text, dir)) return false;
  // The run folder's deck names its tables by file name, copied beside it (io/portable_paths.hpp).
  const std::string text = io::portable_deck(deck_text);
  const fs::path deck_path = fs::path(dir) / "deck.toml";
  fs::create_directories(dir);
  fs::remove(fs::path(dir) / "summary.csv");
  io::portable_deck(deck_text, dir);  // copies the tables
  write_file_atomic(deck_path.string(), text);
  io::Deck deck = io::parse_deck(text, deck_path.string());
  if (const ExecutorConfig& e = executor(); e.kind != ExecutorKind::local) {
    run_deck_external(e, name, dir, job_needs(predict_case(deck), 1), run_args);
  } else {
    io::RunOptions ro;
    ro.out_dir = dir;
    ro.quiet = quiet;
    ro.result = result;
    std::ostringstream log;
    io::run_case(deck, ro, quiet ? static_cast<std::ostream&>(log) : std::cout);
    write_file_atomic((fs::path(dir) / "run.log").string(), log.str());
  }
  return true;
}

std::vector<std::string> run_jobs(const std::vector<std::string>& names, const std::vector<std::string>& texts,
                                  const std::string& runs, bool reuse, const std::string& what) {
  std::map<std::string, std::size_t> first;  // name -> the case that runs it
  std::vector<std::size_t> unique;
  std::vector<std::string> dirs;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& n = names[k];
    if (n.empty() || n.find('/') != std::string::npos || n == "." || n == "..")
      throw InputError(what + ": case name '" + n + "' cannot name a run folder");
    const auto [it, fresh] = first.emplace(n, k);
    if (fresh) unique.push_back(k);
    else if (texts[it->second] != texts[k])
      throw InputError(what + ": two different cases named '" + n + "' would share one run folder");
    dirs.push_back((fs::path(runs) / n).string());
  }
  run_cases(unique.size(), [&](std::size_t u) {
    const std::size_t k = unique[u];
    run_deck_job(names[k], texts[k], dirs[k], reuse);
  }, {}, executor_jobs(executor(), default_case_jobs()));
  return dirs;
}

}  // namespace drawbend::sim
