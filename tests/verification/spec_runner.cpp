// `verify`: the runner of a verification spec (tests/verification/spec.toml,
// MOOSE style: one spec per folder, one entry per problem).
//
//   verify SPEC.toml --drawbend EXE --out DIR [--check-only]
//
// 1. Reads the spec; a bad entry is `spec.toml:line: key: problem` (exit 2).
// 2. Ties every entry to its test: a deck entry's deck must exist; a program
//    entry's program (test_<name>.cpp beside the spec) and each of its test
//    cases must exist; and every test case of every test_*.cpp and every
//    decks/*.toml of the folder must be named by some entry.  An orphan on
//    either side is an error (exit 1).
// 3. Runs each deck entry's deck once with `drawbend run` (one thread) into
//    DIR/<deck name>/ (emptied first; its console output in DIR/<deck name>.log), reads
//    its quantity from the run output (history.csv, summary.csv or the last
//    contact map), compares it with the stated answer and tolerance, prints a
//    table and exits 1 on any miss.  Program entries are listed with the CTest
//    test that computes them (verification.<program>).
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "core/run_output.hpp"
#include "core/toml_read.hpp"

namespace fs = std::filesystem;
using namespace drawbend;

namespace {

struct Measure {
  std::string file;    ///< history.csv, summary.csv or contact_map
  std::string row = "last";  ///< last (history) or all (contact map: every node)
  std::string of = "value";  ///< value, ratio or angle_deg
  std::string column;
  std::vector<std::string> numerator, denominator;
  std::string x, y;
  int pair = 0;
};

struct Problem {
  std::string id, requirement, quantity, answer, unit, reason, tolerance_kind;
  double tolerance = 0, value = NAN;
  bool has_value = false;
  std::vector<std::string> decks;  ///< one deck, or several that must each meet the answer
  std::string program, why_program;
  std::vector<std::string> cases;
  Measure measure;
  bool runs() const { return program.empty(); }
  std::string test() const { return runs() ? "verification.spec" : "verification." + program; }
};

struct Reader {
  std::string path;
  std::vector<std::string> problems;
  std::string at(const toml::node& n) const { return path + ":" + std::to_string(n.source().begin.line); }
  void bad(const toml::node& n, const std::string& key, const std::string& what) {
    problems.push_back(at(n) + ": " + key + ": " + what);
  }
  std::string text(const toml::table& t, const std::string& key, const std::string& w, bool required = true) {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) bad(t, w + "." + key, "missing required key");
      return "";
    }
    if (!n->is_string() || n->value<std::string>()->empty()) {
      bad(*n, w + "." + key, "expected a non-empty string");
      return "";
    }
    return *n->value<std::string>();
  }
  double number(const toml::table& t, const std::string& key, const std::string& w, bool required, bool& found) {
    const toml::node* n = t.get(key);
    found = n != nullptr;
    if (!n) {
      if (required) bad(t, w + "." + key, "missing required key");
      return NAN;
    }
    const auto v = n->value<double>();
    if (!v || !std::isfinite(*v)) {
      bad(*n, w + "." + key, "expected a finite number");
      found = false;
      return NAN;
    }
    return *v;
  }
  std::vector<std::string> strings(const toml::table& t, const std::string& key, const std::string& w) {
    std::vector<std::string> out;
    const toml::node* n = t.get(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a || a->empty()) bad(*n, w + "." + key, "expected a non-empty array of strings");
    else
      for (const auto& e : *a)
        if (e.is_string()) out.push_back(*e.value<std::string>());
        else bad(e, w + "." + key, "expected a string");
    return out;
  }
  void allowed(const toml::table& t, const std::string& w, const std::set<std::string>& keys) {
    for (const auto& [k, v] : t)
      if (!keys.count(std::string(k.str()))) bad(v, w + "." + std::string(k.str()), "unknown key");
  }
};

Measure read_measure(Reader& r, const toml::table& m, const std::string& w) {
  Measure out;
  r.allowed(m, w, {"file", "row", "of", "column", "numerator", "denominator", "x", "y", "pair"});
  out.file = r.text(m, "file", w);
  if (!out.file.empty() && out.file != "history.csv" && out.file != "summary.csv" && out.file != "contact_map")
    r.bad(*m.get("file"), w + ".file", "expected history.csv, summary.csv or contact_map, found '" + out.file + "'");
  if (m.get("row")) out.row = r.text(m, "row", w);
  if (out.row != "last" && out.row != "all") r.bad(m, w + ".row", "expected last or all, found '" + out.row + "'");
  if (out.file == "contact_map" && out.row != "all") r.bad(m, w + ".row", "a contact map is read at every node: row = \"all\"");
  if (m.get("of")) out.of = r.text(m, "of", w);
  if (out.of == "value") out.column = r.text(m, "column", w);
  else if (out.of == "ratio") {
    out.numerator = r.strings(m, "numerator", w);
    out.denominator = r.strings(m, "denominator", w);
    if (out.numerator.empty() || out.denominator.empty()) r.bad(m, w, "a ratio needs numerator and denominator columns");
  } else if (out.of == "angle_deg") {
    out.x = r.text(m, "x", w);
    out.y = r.text(m, "y", w);
  } else
    r.bad(m, w + ".of", "expected value, ratio or angle_deg, found '" + out.of + "'");
  if (const auto* p = m.get("pair")) {
    const auto v = p->value<int64_t>();
    if (!v || *v < 0) r.bad(*p, w + ".pair", "expected a contact pair index >= 0");
    else out.pair = static_cast<int>(*v);
  }
  return out;
}

std::vector<Problem> read_spec(const std::string& path, std::vector<std::string>& problems) {
  Reader r{path, {}};
  toml::table root;
  if (!fs::is_regular_file(path)) {
    problems.push_back(path + ": cannot be read (no such file)");
    return {};
  }
  try {
    root = parse_toml_file(path);
  } catch (const InputError& e) {
    problems.push_back(e.what());
    return {};
  }
  r.allowed(root, "spec", {"problem"});
  std::vector<Problem> out;
  const toml::array* arr = root["problem"].as_array();
  if (!arr || arr->empty()) {
    problems.push_back(path + ":1: problem: expected [[problem]] entries");
    return {};
  }
  std::set<std::string> ids;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const std::string w = "problem[" + std::to_string(i + 1) + "]";
    const toml::table* t = (*arr)[i].as_table();
    if (!t) {
      r.bad((*arr)[i], w, "expected a table ([[problem]])");
      continue;
    }
    r.allowed(*t, w, {"id", "requirement", "quantity", "answer", "value", "unit", "tolerance", "tolerance_kind", "reason",
                      "deck", "measure", "program", "cases", "why_program"});
    Problem p;
    p.id = r.text(*t, "id", w);
    if (!p.id.empty() && !ids.insert(p.id).second) r.bad(*t, w + ".id", "'" + p.id + "' appears twice");
    for (auto [key, dst] : {std::pair{"requirement", &p.requirement}, {"quantity", &p.quantity}, {"answer", &p.answer},
                            {"unit", &p.unit}, {"reason", &p.reason}, {"tolerance_kind", &p.tolerance_kind}})
      *dst = r.text(*t, key, w);
    const bool exact = p.tolerance_kind == "exact";  // bit-identical, or an exact outcome (a refusal, a count)
    if (!p.tolerance_kind.empty() && !exact && p.tolerance_kind != "relative" && p.tolerance_kind != "absolute")
      r.bad(*t, w + ".tolerance_kind", "expected relative, absolute or exact, found '" + p.tolerance_kind + "'");
    bool found = false;
    p.tolerance = exact ? 0.0 : r.number(*t, "tolerance", w, true, found);
    if (exact && t->get("tolerance")) r.bad(*t->get("tolerance"), w + ".tolerance", "an exact answer has no tolerance");
    if (found && !(p.tolerance > 0)) r.bad(*t->get("tolerance"), w + ".tolerance", "must be > 0");
    p.program = r.text(*t, "program", w, false);
    if (const toml::node* d = t->get("deck"))
      p.decks = d->is_string() ? std::vector<std::string>{r.text(*t, "deck", w)} : r.strings(*t, "deck", w);
    p.value = r.number(*t, "value", w, p.runs(), p.has_value);
    if (p.runs()) {
      if (p.decks.empty()) r.bad(*t, w, "expected either deck (with measure) or program (with cases)");
      const toml::table* m = t->get_as<toml::table>("measure");
      if (!m) r.bad(*t, w + ".measure", "missing required table (what to read from the run output)");
      else p.measure = read_measure(r, *m, w + ".measure");
      if (p.has_value && p.tolerance_kind == "relative" && p.value == 0)
        r.bad(*t, w + ".tolerance_kind", "a relative tolerance on the answer 0 can never pass");
      if (t->get("cases") || t->get("why_program")) r.bad(*t, w, "cases and why_program belong to program entries");
    } else {
      p.cases = r.strings(*t, "cases", w);
      if (p.cases.empty()) r.bad(*t, w + ".cases", "missing required key (the program's test cases)");
      p.why_program = r.text(*t, "why_program", w);
      if (t->get("measure")) r.bad(*t, w + ".measure", "a program entry is computed by its program, not measured");
    }
    out.push_back(p);
  }
  problems.insert(problems.end(), r.problems.begin(), r.problems.end());
  return out;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Ties entries to tests in both directions; returns the orphans found.
std::vector<std::string> tie_to_tests(const std::vector<Problem>& ps, const fs::path& dir, const std::string& spec) {
  std::vector<std::string> err;
  std::map<std::string, std::set<std::string>> cases;  // program -> its BOOST_AUTO_TEST_CASE names
  const std::regex re(R"(BOOST_(?:AUTO|DATA|FIXTURE)_TEST_CASE\(\s*(\w+))");
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("test_", 0) != 0 || e.path().extension() != ".cpp") continue;
    auto& set = cases[e.path().stem().string()];
    const std::string src = slurp(e.path());
    for (std::sregex_iterator it(src.begin(), src.end(), re), end; it != end; ++it) set.insert((*it)[1]);
  }
  std::set<std::pair<std::string, std::string>> named;
  std::set<std::string> decks;
  for (const auto& p : ps) {
    for (const auto& d : p.decks) {
      decks.insert(fs::weakly_canonical(dir / d).string());
      if (!fs::exists(dir / d)) err.push_back(spec + ": " + p.id + ": deck '" + d + "' does not exist");
    }
    if (p.runs()) continue;
    const auto it = cases.find(p.program);
    if (it == cases.end()) {
      err.push_back(spec + ": " + p.id + ": program '" + p.program + "' does not exist (no " + p.program + ".cpp)");
      continue;
    }
    for (const auto& c : p.cases) {
      if (!it->second.count(c))
        err.push_back(spec + ": " + p.id + ": test case '" + c + "' does not exist in " + p.program + ".cpp");
      named.insert({p.program, c});
    }
  }
  for (const auto& [prog, set] : cases) {
    if (set.empty()) err.push_back(prog + ".cpp: no test case found");
    for (const auto& c : set)
      if (!named.count({prog, c}))
        err.push_back(prog + ".cpp: test case '" + c + "' has no entry in " + spec + " (an orphan test)");
  }
  if (fs::is_directory(dir / "decks"))
    for (const auto& e : fs::directory_iterator(dir / "decks"))
      if (e.path().extension() == ".toml" && !decks.count(fs::weakly_canonical(e.path()).string()))
        err.push_back("decks/" + e.path().filename().string() + ": named by no entry of " + spec + " (an orphan deck)");
  return err;
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// The measured quantity, one value per row read (one for row = last).
std::vector<double> measure(const Measure& m, const fs::path& out) {
  if (m.file == "summary.csv") {
    const CsvTable t = read_csv((out / "summary.csv").string());
    for (const auto& r : t.rows)
      if (t.text(r, "quantity") == m.column) return {t.number(r, "value")};
    throw InputError((out / "summary.csv").string() + ": no quantity '" + m.column + "'");
  }
  const CsvTable t = read_csv(m.file == "contact_map" ? run_output::last_contact_map(out.string(), m.pair)
                                                      : (out / m.file).string());
  if (t.rows.empty()) throw InputError(t.path + ": no rows");
  auto norm = [&](const CsvRow& r, const std::vector<std::string>& cols) {
    double s = 0;
    for (const auto& c : cols) s += t.number(r, c) * t.number(r, c);
    return std::sqrt(s);
  };
  std::vector<double> v;
  for (std::size_t i = m.row == "last" ? t.rows.size() - 1 : 0; i < t.rows.size(); ++i) {
    const CsvRow& r = t.rows[i];
    if (m.of == "value") v.push_back(t.number(r, m.column));
    else if (m.of == "ratio") v.push_back(norm(r, m.numerator) / norm(r, m.denominator));
    else v.push_back(std::atan2(t.number(r, m.y), t.number(r, m.x)) * 180 / M_PI);
  }
  return v;
}

double error_of(const Problem& p, double q) {
  const double d = p.measure.of == "angle_deg" ? std::remainder(q - p.value, 360.0) : q - p.value;
  return p.tolerance_kind == "relative" ? std::abs(d) / std::abs(p.value) : std::abs(d);
}

std::string g(double v) {
  std::ostringstream s;
  s << std::setprecision(5) << v;
  return s.str();
}

/// An error or a tolerance as the entry states it: "1 %" (relative), "0.001" (absolute), "exact".
std::string in_kind(const Problem& p, double v) {
  if (p.tolerance_kind == "exact") return v == 0 ? "exact" : g(v);
  return p.tolerance_kind == "relative" ? g(100 * v) + " %" : g(v);
}

/// One line of the table: each cell padded to its column, and never run into the next.
void row(const std::string& id, const std::string& measured, const std::string& answer, const std::string& unit,
         const std::string& error, const std::string& tolerance, const std::string& status) {
  std::string line;
  auto cell = [&line](const std::string& s, std::size_t w) { line += s + std::string(s.size() < w ? w - s.size() : 1, ' '); };
  cell(id, 52);
  cell(measured, 13);
  cell(answer, 12);
  cell(unit, 6);
  cell(error, 12);
  cell(tolerance, 11);
  std::cout << line << status << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string spec, exe, out;
  bool check_only = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--drawbend" && i + 1 < argc) exe = argv[++i];
    else if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a == "--check-only") check_only = true;
    else if (spec.empty() && a.rfind("--", 0) != 0) spec = a;
    else {
      std::cerr << "verify: unknown argument '" << a << "'\n"
                << "usage: verify SPEC.toml --drawbend EXE --out DIR [--check-only]\n";
      return 2;
    }
  }
  if (spec.empty() || (!check_only && (exe.empty() || out.empty()))) {
    std::cerr << "usage: verify SPEC.toml --drawbend EXE --out DIR [--check-only]\n";
    return 2;
  }
  std::vector<std::string> problems;
  const std::vector<Problem> ps = read_spec(spec, problems);
  if (!problems.empty()) {
    for (const auto& p : problems) std::cerr << p << "\n";
    return 2;
  }
  const fs::path dir = fs::path(spec).parent_path().empty() ? fs::path(".") : fs::path(spec).parent_path();
  const std::vector<std::string> orphans = tie_to_tests(ps, dir, fs::path(spec).filename().string());
  for (const auto& o : orphans) std::cout << "error: " << o << "\n";
  int runs = 0, programs = 0, misses = 0;
  std::map<std::string, std::string> ran;  // deck -> "" (ran) or the failure
  std::vector<std::string> missed;         // what each missed entry asked for
  row("problem", "measured", "answer", "unit", "error", "tolerance", "status");
  for (const auto& p : ps) {
    if (!p.runs()) {
      ++programs;
      row(p.id, "-", p.has_value ? g(p.value) : "-", p.unit, "-", in_kind(p, p.tolerance),
          "program: ctest -R '^" + p.test() + "$'");
      continue;
    }
    for (const auto& d : p.decks) {
      ++runs;
      const fs::path deck = dir / d;
      const fs::path run_dir = fs::path(out) / deck.stem();
      std::string status;
      if (check_only) {
        status = "not run (--check-only)";
      } else {
        if (!ran.count(d)) {
          fs::create_directories(out);
          fs::remove_all(run_dir);  // no stale contact map of an earlier run may be read as the last one
          const std::string log = (fs::path(out) / (deck.stem().string() + ".log")).string();
          const std::string cmd = quote(exe) + " run " + quote(deck.string()) + " --out " + quote(run_dir.string()) +
                                  " --quiet --threads 1 > " + quote(log) + " 2>&1";
          const int rc = std::system(cmd.c_str());
          ran[d] = rc == 0 ? "" : "drawbend run failed (see " + log + ")";
        }
        status = ran[d];
      }
      double worst_q = NAN, worst = -1;
      if (status.empty()) {
        try {
          for (double q : measure(p.measure, run_dir)) {
            const double e = std::isfinite(q) ? error_of(p, q) : INFINITY;
            if (e > worst) worst = e, worst_q = q;
          }
          status = worst <= p.tolerance ? "pass" : "MISS";
        } catch (const std::exception& e) {
          status = std::string("error: ") + e.what();
        }
      }
      const std::string name = p.decks.size() > 1 ? p.id + " [" + deck.stem().string() + "]" : p.id;
      if (status != "pass" && status.rfind("not run", 0) != 0) {
        ++misses;
        missed.push_back(name + ": " + p.requirement + "\n    quantity: " + p.quantity + "\n    answer: " + p.answer +
                         "\n    tolerance: " + p.reason);
      }
      row(name, g(worst_q), g(p.value), p.unit, worst >= 0 ? in_kind(p, worst) : "-", in_kind(p, p.tolerance), status);
    }
  }
  for (const auto& m : missed) std::cout << "missed " << m << "\n";
  std::cout << ps.size() << " problems: " << runs << " deck measurements run here (" << misses << " missed), " << programs
            << " computed by their programs; " << orphans.size() << " orphan(s)\n";
  return misses || !orphans.empty() ? 1 : 0;
}
