#pragma once
// Reading one TOML deck: typed access to keys with located messages
// (file:line: key: expected ..., found ...), and the collection of every
// problem of the file in one pass.
//
// Two kinds of problem.  A value that is missing, of the wrong type or out of
// range is recorded (InputProblems) and a fallback is returned, so reading
// goes on and the next problems are found too.  A problem after which a
// section cannot be read on (a section that is not a table, an unknown kind)
// throws InputError; the deck reader runs each section in
// InputProblems::attempt, so the other sections are still read.
#include <optional>
#include <set>
#include <string>

#include <toml++/toml.h>

#include "core/input_problems.hpp"
#include "fe/history.hpp"
#include "fe/model.hpp"

namespace drawbend::io {

class DeckContext {
 public:
  DeckContext(std::string path, InputProblems& problems) : path(std::move(path)), problems_(problems) {}

  const std::string path;

  /// "file:line: key".
  std::string where(const toml::node& n, const std::string& key) const;
  /// Record a problem at node n (reading goes on).
  void bad(const toml::node& n, const std::string& key, const std::string& msg) const;
  /// A problem after which the current section cannot be read on.
  [[noreturn]] void fail(const toml::node& n, const std::string& key, const std::string& msg) const;
  /// Number of problems recorded so far (to tell whether a block read cleanly).
  std::size_t count() const { return problems_.size(); }
  InputProblems& problems() const { return problems_; }

  /// Records each key of t not in `keys`.
  void allowed(const toml::table& t, const std::string& what, const std::set<std::string>& keys) const;
  /// A sub-table; throws if it is missing (when required) or not a table.
  const toml::table* table(const toml::table& t, const std::string& key, const std::string& what, bool required) const;

  /// A number; missing and required, or not a number: recorded, returns NaN.
  double num(const toml::table& t, const std::string& key, const std::string& what, std::optional<double> def = {}) const;
  /// A number > 0 (fallback 1 after a problem).
  double positive(const toml::table& t, const std::string& key, const std::string& what, std::optional<double> def = {}) const;
  /// A number >= lo (and <= hi when given); fallback `def` (or lo) after a problem.
  double in_range(const toml::table& t, const std::string& key, const std::string& what, double def, double lo,
                  std::optional<double> hi = {}) const;
  /// A whole number >= lo (fallback lo after a problem).
  int count_of(const toml::table& t, const std::string& key, const std::string& what, std::optional<int> def, int lo) const;
  std::string str(const toml::table& t, const std::string& key, const std::string& what,
                  std::optional<std::string> def = {}) const;
  bool boolean(const toml::table& t, const std::string& key, const std::string& what, bool def) const;
  /// t's "name" (a case, tool, step or history column): a string without control characters
  /// (a line break in a name broke history.csv's comment lines and columns), and not empty unless
  /// `empty_ok` (an empty tool name ended a finished run with an error about fields_0.vtm).
  std::string name(const toml::table& t, const std::string& what, std::optional<std::string> def = {},
                   bool empty_ok = false) const;
  /// An array of 3 numbers; `unit`: normalised, and zero is a problem.
  fe::Vec3 vec(const toml::table& t, const std::string& key, const std::string& what, std::optional<fe::Vec3> def = {},
               bool unit = false) const;
  /// A number (constant) or a table {t = [...], v = [...]} with increasing t.
  fe::History history(const toml::table& t, const std::string& key, const std::string& what) const;
  /// An array of tables, or nullptr if the key is absent.
  const toml::array* array_of_tables(const toml::table& t, const std::string& key, const std::string& what) const;

 private:
  void missing(const toml::table& t, const std::string& key, const std::string& what, const std::string& expected) const;
  InputProblems& problems_;
};

/// The [[tool]] table of `root` named `name` (for its line), or nullptr.
const toml::table* tool_table(const toml::table& root, const std::string& name);

/// A file a deck names: a relative path is taken from the deck's folder `dir`.
std::string deck_relative(const std::string& dir, const std::string& file);
/// Whether `path` is a regular file (not a folder, FIFO or device).
bool readable_file(const std::string& path);
/// "cannot open FILE" with the rule that found it (a relative path is the deck
/// folder's), or what the path is when it is there but not a regular file (a
/// folder, a FIFO, a device): the message for a file a deck names (a flow
/// curve, a friction table).
std::string missing_file(const std::string& file, const std::string& dir);

}  // namespace drawbend::io
