#include "core/options.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "core/csv.hpp"
#include "core/file_gate.hpp"

namespace drawbend {

Options::Options(std::string program, std::string description)
    : program_(std::move(program)), description_(std::move(description)) {}

void Options::add(std::string& var, const std::string& name, const std::string& help) {
  opts_.push_back({name, help, false, "VALUE", [&var](const std::string& s) { var = s; }, [&var] { return var; }});
}

namespace {
// Setter for a numeric option: the whole text must parse and be finite.
template <class T>
std::function<void(const std::string&)> numeric_setter(T& var, const std::string& name, const char* what) {
  return [&var, name, what](const std::string& s) {
    std::size_t used = 0;
    T v{};
    try {
      if constexpr (std::is_integral_v<T>) v = std::stoi(s, &used);
      else v = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    // Hexadecimal (0x10) is read by std::stod but meant by no one: refused as
    // the integers' std::stoi refuses it.
    if (s.empty() || used != s.size() || hex_number(s) || !std::isfinite(static_cast<double>(v)))
      throw std::invalid_argument("--" + name + ": expected " + what + ", found '" + clip_for_message(s) + "'");
    var = v == 0 ? T{} : v;  // -0 as 0 (echoed and compared as the user means it)
  };
}
}  // namespace

void Options::add(double& var, const std::string& name, const std::string& help) {
  opts_.push_back({name, help, false, "VALUE", numeric_setter(var, name, "a number"), [&var] { return fmt(var, 10); }});
}

void Options::add(int& var, const std::string& name, const std::string& help) {
  opts_.push_back({name, help, false, "VALUE", numeric_setter(var, name, "an integer"),
                   [&var] { return std::to_string(var); }});
}

void Options::add(bool& var, const std::string& name, const std::string& help) {
  auto set = [&var, name](const std::string& s) {
    if (s == "true" || s == "1") var = true;
    else if (s == "false" || s == "0") var = false;
    else throw std::invalid_argument("--" + name + ": expected true or false, found '" + s + "'");
  };
  opts_.push_back({name, help, false, "true|false", set, [&var] { return std::string(var ? "true" : "false"); }});
}

void Options::add_flag(bool& var, const std::string& name, const std::string& help) {
  opts_.push_back({name, help, true, "", [&var](const std::string&) { var = true; },
                   [&var] { return std::string(var ? "true" : "false"); }});
}

Options& Options::range(const std::string& name, double lo, double hi, const std::string& unit, bool open_lo,
                        bool open_hi, bool zero_ok) {
  Opt* opt = nullptr;
  for (auto& o : opts_)
    if (o.name == name) opt = &o;
  if (!opt) throw std::logic_error("Options::range: no option --" + name);
  auto get = opt->get;
  opt->check = [=](const std::string& text) {
    const double v = std::stod(get());  // the value just set, as the option holds it
    const bool in = (open_lo ? v > lo : v >= lo) && (open_hi ? v < hi : v <= hi);
    if (in || (zero_ok && v == 0)) return;
    const std::string u = unit.empty() ? "" : " " + unit;
    throw std::invalid_argument("--" + name + ": expected " + (zero_ok ? "0 or " : "") + "a value in " +
                                (open_lo ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + (open_hi ? ")" : "]") + u +
                                ", found " + clip_for_message(text));
  };
  return *this;
}

std::string Options::usage() const {
  std::ostringstream os;
  os << "Usage: " << program_ << " [options]\n" << description_ << "\n\nOptions:\n";
  for (const auto& o : opts_)
    os << "  --" << o.name << (o.flag ? "" : " " + o.value) << "\n      " << o.help << " (default: " << o.get()
       << ")\n";
  os << "  --help, -h\n      Print this message.\n";
  if (!examples_.empty()) {
    os << "\nExamples (from the source folder after make or make test; drawbend is build/src/drawbend):\n";
    for (const auto& e : examples_) os << "  " << e << "\n";
  }
  return os.str();
}

bool Options::parse(int argc, char** argv) {
  std::vector<std::string> seen;  // each option once: a second value is a typing error, not "the last wins"
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage();
      return false;
    }
    if (a.rfind("--", 0) != 0)
      throw std::invalid_argument("unexpected argument '" + clip_for_message(a) + "' (see --help)");
    std::string name = a.substr(2), value;
    const auto eq = name.find('=');
    if (eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    Opt* opt = nullptr;
    for (auto& o : opts_)
      if (o.name == name) opt = &o;
    if (!opt) throw std::invalid_argument("unknown option '--" + clip_for_message(name) + "' (see --help)");
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      throw std::invalid_argument("option '--" + name + "' given twice (give each option once)");
    seen.push_back(name);
    // A flag takes no value: --from-thesis=false set the flag (exit 0 with the opposite of what was asked,
    // before 2026-12-05), so any value written after '=' is refused.
    if (opt->flag && eq != std::string::npos)
      throw std::invalid_argument("--" + name + ": a flag takes no value (write --" + name + " alone, or leave it out), found '" +
                                  clip_for_message(value) + "'");
    if (!opt->flag && eq == std::string::npos) {
      if (i + 1 >= argc) throw std::invalid_argument("option '--" + name + "' needs a value");
      // "--out --quiet": the next word is an option, not this one's value
      // (a value that starts with "--" is written --name=VALUE).
      const std::string next = argv[i + 1];
      if (next.size() > 2 && next.rfind("--", 0) == 0 && std::isalpha(static_cast<unsigned char>(next[2])))
        throw std::invalid_argument("option '--" + name + "' needs a value, found the option '" +
                                    clip_for_message(next) + "' (write --" + name + "=VALUE for a value starting with --)");
      value = argv[++i];
    }
    opt->set(value);
    if (opt->check) opt->check(value);
  }
  given_ = seen;
  return true;
}

bool Options::given(const std::string& name) const {
  return std::find(given_.begin(), given_.end(), name) != given_.end();
}

void Options::only_when(bool applies, const std::vector<std::string>& names, const std::string& when) const {
  if (applies) return;
  for (const auto& n : names)
    if (given(n)) throw std::invalid_argument("--" + n + ": applies only " + when + " (given here, it would be ignored)");
}

void Options::not_empty(const std::vector<std::string>& names) const {
  for (const auto& n : names)
    for (const auto& o : opts_)
      if (o.name == n && given(n) && o.get().empty())
        throw std::invalid_argument("--" + n + ": expected a file name, found an empty one");
}

std::vector<std::string> Options::echo() const {
  std::vector<std::string> lines;
  for (const auto& o : opts_) lines.push_back(o.name + " = " + o.get());
  return lines;
}

}  // namespace drawbend
