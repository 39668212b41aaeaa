#include "io/deck_context.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/file_gate.hpp"
#include "core/csv.hpp"

namespace drawbend::io {

namespace {
std::string found(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "the string \"" + *n.value<std::string>() + "\"";
    case toml::node_type::integer:
    case toml::node_type::floating_point: return fmt_shortest(*n.value<double>());
    case toml::node_type::boolean: return *n.value<bool>() ? "true" : "false";
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    default: return "a date or time";
  }
}
}  // namespace

std::string DeckContext::where(const toml::node& n, const std::string& key) const {
  return path + ":" + std::to_string(n.source().begin.line) + ": " + key;
}

void DeckContext::bad(const toml::node& n, const std::string& key, const std::string& msg) const {
  problems_.add(where(n, key) + ": " + msg);
}

void DeckContext::fail(const toml::node& n, const std::string& key, const std::string& msg) const {
  throw InputError(where(n, key) + ": " + msg);
}

void DeckContext::missing(const toml::table& t, const std::string& key, const std::string& what,
                          const std::string& expected) const {
  problems_.add(path + ":" + std::to_string(t.source().begin.line) + ": " + what + ": missing required key '" + key +
                "' (expected " + expected + ")");
}

void DeckContext::allowed(const toml::table& t, const std::string& what, const std::set<std::string>& keys) const {
  for (const auto& [k, v] : t)
    if (!keys.count(std::string(k.str()))) {
      std::string list;
      for (const auto& a : keys) list += (list.empty() ? "" : ", ") + a;
      bad(v, what + "." + clip_for_message(std::string(k.str())), "unknown key (expected one of: " + list + ")");
    }
}

const toml::table* DeckContext::table(const toml::table& t, const std::string& key, const std::string& what,
                                      bool required) const {
  const auto* n = t.get(key);
  if (!n) {
    if (required) throw InputError(path + ": " + what + ": missing required table [" + key + "]");
    return nullptr;
  }
  if (!n->is_table()) fail(*n, key, "expected a table, found " + found(*n));
  return n->as_table();
}

double DeckContext::num(const toml::table& t, const std::string& key, const std::string& what,
                        std::optional<double> def) const {
  const auto* n = t.get(key);
  if (!n) {
    if (def) return *def;
    missing(t, key, what, "a number");
    return NAN;
  }
  if (auto v = n->value<double>(); v && (n->is_integer() || n->is_floating_point())) {
    if (std::isfinite(*v)) return *v;
  }
  bad(*n, what + "." + key, "expected a finite number, found " + found(*n));
  return NAN;
}

double DeckContext::positive(const toml::table& t, const std::string& key, const std::string& what,
                             std::optional<double> def) const {
  const double v = num(t, key, what, def);
  if (std::isnan(v)) return 1.0;  // already recorded
  if (!(v > 0)) {
    bad(*t.get(key), what + "." + key, "expected a number > 0, found " + fmt_shortest(v));
    return 1.0;
  }
  return v;
}

double DeckContext::in_range(const toml::table& t, const std::string& key, const std::string& what, double def,
                             double lo, std::optional<double> hi) const {
  const double v = num(t, key, what, def);
  if (std::isnan(v)) return def;
  if (!(v >= lo) || (hi && !(v <= *hi))) {
    bad(*t.get(key), what + "." + key,
        "expected a number in [" + fmt_shortest(lo) + ", " + (hi ? fmt_shortest(*hi) : std::string("inf")) + "], found " +
            fmt_shortest(v));
    return def;
  }
  return v;
}

int DeckContext::count_of(const toml::table& t, const std::string& key, const std::string& what,
                          std::optional<int> def, int lo) const {
  const double v = num(t, key, what, def ? std::optional<double>(*def) : std::nullopt);
  if (std::isnan(v)) return lo;
  if (!(v >= lo && v <= 1e8 && v == std::floor(v))) {
    bad(*t.get(key), what + "." + key,
        "expected a whole number >= " + std::to_string(lo) + " (at most 1e8), found " + fmt_shortest(v));
    return lo;
  }
  return static_cast<int>(v);
}

std::string DeckContext::str(const toml::table& t, const std::string& key, const std::string& what,
                             std::optional<std::string> def) const {
  const auto* n = t.get(key);
  if (!n) {
    if (def) return *def;
    missing(t, key, what, "a string");
    return "";
  }
  if (auto v = n->value<std::string>(); v && n->is_string()) return *v;
  bad(*n, what + "." + key, "expected a string, found " + found(*n));
  return def.value_or("");
}

std::string DeckContext::name(const toml::table& t, const std::string& what, std::optional<std::string> def,
                              bool empty_ok) const {
  const std::string v = str(t, "name", what, std::move(def));
  const auto* n = t.get("name");
  if (!n || !n->is_string()) return v;
  if (v.empty() && !empty_ok) bad(*n, what + ".name", "expected a name, found an empty one");
  auto control = [](char ch) { return static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f; };
  if (std::none_of(v.begin(), v.end(), control)) return v;
  std::string shown;  // the name with its control characters escaped, so the message stays one line
  for (const char ch : clip_for_message(v)) {
    const auto u = static_cast<unsigned char>(ch);
    static const char* hex = "0123456789abcdef";
    shown += !control(ch) ? std::string(1, ch)
             : ch == '\n' ? std::string("\\n")
             : ch == '\t' ? std::string("\\t")
                          : std::string("\\x") + hex[u >> 4] + hex[u & 15];
  }
  bad(*n, what + ".name", "expected a name without control characters (line breaks, tabs), found \"" + shown + "\"");
  return v;
}

bool DeckContext::boolean(const toml::table& t, const std::string& key, const std::string& what, bool def) const {
  const auto* n = t.get(key);
  if (!n) return def;
  if (auto v = n->value<bool>(); v && n->is_boolean()) return *v;
  bad(*n, what + "." + key, "expected true or false, found " + found(*n));
  return def;
}

fe::Vec3 DeckContext::vec(const toml::table& t, const std::string& key, const std::string& what,
                          std::optional<fe::Vec3> def, bool unit) const {
  const fe::Vec3 fallback = def.value_or(fe::Vec3{0, 0, 1});
  const auto* n = t.get(key);
  if (!n) {
    if (!def) missing(t, key, what, "an array of 3 numbers");
    return fallback;
  }
  const auto* a = n->as_array();
  fe::Vec3 v{};
  bool ok = a && a->size() == 3;
  for (int i = 0; ok && i < 3; ++i) {
    const auto& e = (*a)[static_cast<std::size_t>(i)];
    const auto x = e.value<double>();
    ok = x && (e.is_integer() || e.is_floating_point()) && std::isfinite(*x);
    if (ok) v[i] = *x;
  }
  if (!ok) {
    bad(*n, what + "." + key, "expected an array of 3 finite numbers, found " +
                                  (a ? "an array of " + std::to_string(a->size()) + " elements" : found(*n)));
    return fallback;
  }
  if (unit) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(l > 0) || !std::isfinite(l)) {
      bad(*n, what + "." + key, "expected a non-zero direction, found [0, 0, 0]");
      return fallback;
    }
    for (double& c : v) c /= l;
  }
  return v;
}

fe::History DeckContext::history(const toml::table& t, const std::string& key, const std::string& what) const {
  const auto* n = t.get(key);
  const fe::History fallback = fe::History::constant(0.0);
  if (!n) {
    missing(t, key, what, "a number or a table {t = [...], v = [...]}");
    return fallback;
  }
  if (n->is_integer() || n->is_floating_point()) {
    const double v = *n->value<double>();
    if (std::isfinite(v)) return fe::History::constant(v);
  }
  const auto* h = n->as_table();
  if (!h) {
    bad(*n, what + "." + key, "expected a number or a table {t = [...], v = [...]}, found " + found(*n));
    return fallback;
  }
  const std::size_t before = count();
  allowed(*h, what + "." + key, {"t", "v"});
  fe::History out;
  out.t.clear();
  out.v.clear();
  for (const char* k : {"t", "v"}) {
    const auto* a = h->get(k) ? h->get(k)->as_array() : nullptr;
    if (!a || a->empty()) {
      bad(*n, what + "." + key + "." + k, "expected a non-empty array of numbers");
      continue;
    }
    for (const auto& e : *a) {
      const auto x = e.value<double>();
      if (!x || !(e.is_integer() || e.is_floating_point()) || !std::isfinite(*x)) {
        bad(e, what + "." + key + "." + k, "expected finite numbers, found " + found(e));
        break;
      }
      (std::string(k) == "t" ? out.t : out.v).push_back(*x);
    }
  }
  if (count() > before) return fallback;
  try {
    out.validate((what + "." + key).c_str());
  } catch (const std::invalid_argument& e) {  // its message starts with the key: said once
    const std::string m = e.what(), w = what + "." + key + ": ";
    bad(*n, what + "." + key, m.rfind(w, 0) == 0 ? m.substr(w.size()) : m);
    return fallback;
  }
  return out;
}

const toml::array* DeckContext::array_of_tables(const toml::table& t, const std::string& key,
                                                 const std::string& what) const {
  const auto* n = t.get(key);
  if (!n) return nullptr;
  const auto* a = n->as_array();
  if (!a) fail(*n, what + "." + key, "expected an array of tables, found " + found(*n));
  for (const auto& e : *a)
    if (!e.is_table()) fail(e, what + "." + key, "expected an array of tables, found " + found(e));
  return a;
}

std::string deck_relative(const std::string& dir, const std::string& file) {
  std::filesystem::path p(file);
  if (p.is_relative()) p = std::filesystem::path(dir) / p;
  return p.string();
}

bool readable_file(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string missing_file(const std::string& file, const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(deck_relative(dir, file), ec);
  std::string what = "cannot open '" + file + "' for reading";
  if (!ec && fs::exists(st) && !fs::is_regular_file(st))
    what = "'" + file + "': expected a regular file, found " +
           (fs::is_directory(st) ? "a folder" : fs::is_fifo(st) ? "a FIFO (named pipe)"
            : fs::is_character_file(st) || fs::is_block_file(st) ? "a device" : "something else");
  if (!fs::path(file).is_relative()) return what;
  return what + " (relative paths are resolved against the deck's folder, " + (dir.empty() ? std::string(".") : dir) +
         ")";
}

const toml::table* tool_table(const toml::table& root, const std::string& name) {
  const auto* tools = root.get_as<toml::array>("tool");
  if (!tools) return nullptr;
  for (const auto& t : *tools)
    if (const auto* tt = t.as_table(); tt && tt->get("name") && tt->get("name")->value<std::string>() == name) return tt;
  return nullptr;
}

}  // namespace drawbend::io
