#pragma once
// Command-line options in the style of the MFEM examples: every parameter has
// a default and a help text, `--help` lists them, unknown options are an error,
// an option given twice is an error (not "the last wins"), an option where a
// value belongs (`--out --quiet`) is an error (a value starting with "--" is
// written --name=VALUE), and `echo()` returns "name = value" lines for
// output-file headers.
#include <functional>
#include <string>
#include <vector>

namespace drawbend {

class Options {
 public:
  Options(std::string program, std::string description);
  void add(std::string& var, const std::string& name, const std::string& help);
  void add(double& var, const std::string& name, const std::string& help);
  void add(int& var, const std::string& name, const std::string& help);
  /// An on/off option that takes a value: true or false (1 or 0 also accepted,
  /// for older command lines); the help shows "true|false".
  void add(bool& var, const std::string& name, const std::string& help);
  void add_flag(bool& var, const std::string& name, const std::string& help);
  /// The values option `name` (added before) accepts: [lo, hi], or (lo, hi]
  /// etc. with `open_lo`/`open_hi`; checked as the value is parsed, so every
  /// option is range-checked before any work, and a value outside is an
  /// std::invalid_argument "--name: expected ... in [lo, hi] unit, found v".
  /// `zero_ok`: 0 is accepted too (the options where 0 means "automatic").
  Options& range(const std::string& name, double lo, double hi, const std::string& unit = "", bool open_lo = false,
                 bool open_hi = false, bool zero_ok = false);

  /// Parse argv. Returns false (after printing usage) on --help; throws
  /// std::invalid_argument with a clear message on bad input.
  bool parse(int argc, char** argv);
  std::vector<std::string> echo() const;
  /// Whether the last parse() saw option `name` on the command line.
  bool given(const std::string& name) const;
  /// Refuse the options of `names` that were given while `applies` is false:
  /// std::invalid_argument "--name: applies only WHEN (given here, it would
  /// be ignored)" for the first one (an option that does nothing is a typing
  /// error, not a silent default).
  void only_when(bool applies, const std::vector<std::string>& names, const std::string& when) const;
  /// Refuse the options of `names` (file names) given with an empty value:
  /// std::invalid_argument "--name: expected a file name, found an empty one"
  /// (without it the message came from the builder's spec, or named no option).
  void not_empty(const std::vector<std::string>& names) const;
  std::string usage() const;
  /// An example command line, shown at the end of --help under "Examples".
  /// Each must run as written from the source folder after a build, with
  /// `drawbend` standing for build/src/drawbend (tests/user/help_examples.sh runs them).
  void example(const std::string& line) { examples_.push_back(line); }

 private:
  struct Opt {
    std::string name, help;
    bool flag = false;
    std::string value = "VALUE";  ///< how the help names the value
    std::function<void(const std::string&)> set;
    std::function<std::string()> get;
    std::function<void(const std::string&)> check;  ///< range(), after set
  };
  std::string program_, description_;
  std::vector<Opt> opts_;
  std::vector<std::string> examples_;
  std::vector<std::string> given_;
};

}  // namespace drawbend
