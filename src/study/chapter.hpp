#pragma once
// What every chapter driver shares: common options (data, output, figures,
// gnuplot), tables written with the configuration echoed in their header,
// gnuplot figures, named values for the prose, and the checks.
//
// Output layout of a chapter <id> (default build/chapters/<id>/):
//   checks.csv      id,quantity,thesis,ours,tolerance,unit,status,note
//   values.csv      key,value,unit  (numbers the prose quotes as {{key}})
//   tables/*.csv    generated tables
//   figures/*.svg   gnuplot figures
#include <array>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "core/options.hpp"
#include "study/checks.hpp"

namespace drawbend::study {

class Chapter {
 public:
  Chapter(std::string id, std::string description);

  Options& options() { return options_; }
  /// Parse the command line; false on --help.  Loads the errata list.
  bool parse(int argc, char** argv);

  std::string data(const std::string& rel) const;  ///< path under the data dir
  std::string out(const std::string& rel) const;   ///< path under the output dir

  /// A table writer whose header comments carry the source and the configuration.
  CsvWriter table(const std::vector<std::string>& header, const std::string& what) const;
  void save(const CsvWriter& w, const std::string& name) const;  ///< tables/<name>.csv

  /// A gridded surface f(x, y) for gnuplot's splot: tables/<name>.dat, one
  /// block per x value separated by blank lines (comma-separated x,y,f).
  void save_grid(const std::string& name, const std::string& what, const std::vector<double>& xs,
                 const std::vector<double>& ys, const std::function<double(double, double)>& f) const;

  /// Run figures/<script>.gp with gnuplot, writing figures/<stem>.svg.
  /// Variables are passed as gnuplot strings: outfile, tables (the tables dir),
  /// figdir (the scripts' dir, for `load figdir."/common.gp"`) and `vars`.
  void plot(const std::string& script, const std::string& stem,
            const std::map<std::string, std::string>& vars = {}) const;

  /// A number the prose quotes as {{key}}.
  void value(const std::string& key, const std::string& text, const std::string& unit = "");

  Checks& checks() { return *checks_; }

  /// Re-derive the published scalar `target` of data/thesis/scalars.csv from
  /// the published scalars `inputs` through f; the tolerance is the
  /// printed-digit rounding of inputs and target.  Returns our value.
  double rederive_scalar(const std::string& check_id, const std::string& quantity, const std::string& target,
                         const std::vector<std::string>& inputs,
                         const std::function<double(const std::vector<double>&)>& f, const std::string& unit);

  /// Write checks.csv and values.csv (with the chapter's wall time as
  /// {{chapter_wall}}), print the summary; returns the exit code
  /// (non-zero when a check that should pass fails).
  int finish();

 private:
  std::string id_, data_dir_, out_dir_, figures_dir_, gnuplot_ = "gnuplot";
  bool allow_failures_ = false;
  std::string executor_;  ///< --executor: where draw-bend cases run (not echoed: outputs do not depend on it)
  std::string figure_format_ = "svg";  ///< svg, or png/pdf written beside each SVG (the report embeds the SVG)
  std::string tier_ = "quick";  ///< mesh tier of the run: selects the disagreements that apply (quick, full)
  Options options_;
  std::unique_ptr<Checks> checks_;
  std::vector<std::array<std::string, 3>> values_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Run a chapter's body with uniform error handling: input errors print one
/// clear message and return 2; other exceptions return 3.  The body is a
/// closure over the chapter's options struct (registered on ch.options()
/// before the call), so a chapter needs no file-scope option variables.
int run_chapter(Chapter& ch, int argc, char** argv, const std::function<void(Chapter&)>& body);

}  // namespace drawbend::study
