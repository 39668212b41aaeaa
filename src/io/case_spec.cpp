// A case as a typed value: see case_spec.hpp.
#include "io/case_spec.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <type_traits>

#include "core/csv.hpp"
#include "core/quote.hpp"
#include "core/toml_read.hpp"

namespace drawbend::io {

namespace {

// Reading: a typed field takes its key out of `rest` when the value has the
// field's form; any other form stays in `rest` as written (the deck reader
// judges it).

template <class T>
std::optional<T> take(toml::table& rest, const char* key) {
  const toml::node* n = rest.get(key);
  const bool ok = n && (std::is_same_v<T, double> ? n->is_number() : n->is<T>());
  if (!ok) return std::nullopt;
  T v = *n->value<T>();
  rest.erase(key);
  return v;
}

std::optional<std::vector<double>> numbers_of(const toml::node* n) {
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a) return std::nullopt;
  std::vector<double> v;
  for (const auto& x : *a) {
    if (!x.is_number()) return std::nullopt;
    v.push_back(*x.value<double>());
  }
  return v;
}

std::optional<Vec3Spec> take_vec3(toml::table& rest, const char* key) {
  const auto v = numbers_of(rest.get(key));
  if (!v || v->size() != 3) return std::nullopt;
  rest.erase(key);
  return Vec3Spec{(*v)[0], (*v)[1], (*v)[2]};
}

std::optional<HistorySpec> take_history(toml::table& rest, const char* key) {
  const toml::table* h = rest.get_as<toml::table>(key);
  if (!h || h->size() != 2) return std::nullopt;
  const auto t = numbers_of(h->get("t")), v = numbers_of(h->get("v"));
  if (!t || !v) return std::nullopt;
  HistorySpec s{*t, *v, h->is_inline()};
  rest.erase(key);
  return s;
}

// The tables of an array of tables `key` (taken out of `root`); InputError when it is not one.
std::vector<toml::table> take_tables(toml::table& root, const char* key, const std::string& where) {
  std::vector<toml::table> out;
  const toml::node* n = root.get(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) throw InputError(where + ": " + key + ": expected an array of tables ([[" + key + "]])");
  for (const auto& x : *a) {
    if (!x.is_table()) throw InputError(where + ": " + key + ": expected an array of tables ([[" + key + "]])");
    out.push_back(*x.as_table());
  }
  root.erase(key);
  return out;
}

toml::table take_table(toml::table& root, const char* key, const std::string& where) {
  const toml::node* n = root.get(key);
  if (!n) return {};
  if (!n->is_table()) throw InputError(where + ": " + key + ": expected a table");
  toml::table t = *n->as_table();
  root.erase(key);
  return t;
}

ToolSpec read_tool(toml::table t, const std::string& where) {
  ToolSpec s;
  const auto name = take<std::string>(t, "name");
  if (!name) throw InputError(where + ": tool: expected a name");
  s.name = *name;
  s.drive = take<std::string>(t, "drive");
  s.direction = take_vec3(t, "direction");
  s.speed = take_history(t, "speed");
  s.force = take<double>(t, "force");
  s.mass = take<double>(t, "mass");
  s.stop = take<double>(t, "stop");
  for (toml::table f : take_tables(t, "surface", where + ": tool " + s.name)) {
    SurfaceSpec u;
    u.kind = take<std::string>(f, "kind").value_or("");  // the deck reader names a missing kind
    u.origin = take_vec3(f, "origin"), u.normal = take_vec3(f, "normal"), u.axis = take_vec3(f, "axis");
    u.radius = take<double>(f, "radius"), u.tube_radius = take<double>(f, "tube_radius");
    u.r_min = take<double>(f, "r_min"), u.r_max = take<double>(f, "r_max");
    u.z_min = take<double>(f, "z_min"), u.z_max = take<double>(f, "z_max");
    u.angle_min = take<double>(f, "angle_min"), u.angle_max = take<double>(f, "angle_max");
    u.inside = take<bool>(f, "inside");
    u.rest = std::move(f);
    s.surfaces.push_back(std::move(u));
  }
  s.rest = std::move(t);
  return s;
}

// Writing.

toml::array array_of(const std::vector<double>& v) {
  toml::array a;
  for (double x : v) a.push_back(x);
  return a;
}

toml::array array_of(const Vec3Spec& v) { return toml::array{v[0], v[1], v[2]}; }

template <class T>
void put(toml::table& t, const char* key, const std::optional<T>& v) {
  if (!v) return;
  if constexpr (std::is_same_v<T, Vec3Spec>) t.insert_or_assign(key, array_of(*v));
  else t.insert_or_assign(key, *v);
}

toml::table history_table(const HistorySpec& h) {
  toml::table t{{"t", array_of(h.t)}, {"v", array_of(h.v)}};
  t.is_inline(h.written_inline);
  return t;
}

toml::table tool_table(const ToolSpec& s) {
  toml::table t = s.rest;
  t.insert_or_assign("name", s.name);
  put(t, "drive", s.drive);
  put(t, "direction", s.direction);
  if (s.speed) t.insert_or_assign("speed", history_table(*s.speed));
  put(t, "force", s.force);
  put(t, "mass", s.mass);
  put(t, "stop", s.stop);
  if (!s.surfaces.empty()) {
    toml::array a;
    for (const SurfaceSpec& u : s.surfaces) {
      toml::table f = u.rest;
      if (!u.kind.empty()) f.insert_or_assign("kind", u.kind);
      put(f, "origin", u.origin), put(f, "normal", u.normal), put(f, "axis", u.axis);
      put(f, "radius", u.radius), put(f, "tube_radius", u.tube_radius);
      put(f, "r_min", u.r_min), put(f, "r_max", u.r_max), put(f, "z_min", u.z_min), put(f, "z_max", u.z_max);
      put(f, "angle_min", u.angle_min), put(f, "angle_max", u.angle_max);
      put(f, "inside", u.inside);
      a.push_back(std::move(f));
    }
    t.insert_or_assign("surface", std::move(a));
  }
  return t;
}

}  // namespace

SurfaceSpec* ToolSpec::surface(const std::string& kind) {
  for (auto& s : surfaces)
    if (s.kind == kind) return &s;
  return nullptr;
}

ToolSpec& CaseSpec::tool(const std::string& name, const std::string& where) {
  for (auto& t : tools)
    if (t.name == name) return t;
  throw InputError(where + ": no tool named '" + name + "'");
}

void set_threads(CaseSpec& c, int64_t n) {
  if (n <= 0) return;
  if (!c.numerics) c.numerics.emplace();
  c.numerics->threads = n;
}

FrictionSpec read_friction(toml::table t) {
  FrictionSpec f;
  f.law = take<std::string>(t, "law");
  f.nodes = take<std::string>(t, "nodes");
  f.mu = take<double>(t, "mu");
  f.rest = std::move(t);
  return f;
}

FrictionSpec coulomb_friction(double mu) {
  FrictionSpec f;
  f.law = "coulomb", f.mu = mu;
  return f;
}

FrictionSpec stribeck_friction(const std::string& table, int64_t interval) {
  FrictionSpec f;
  f.law = "stribeck", f.rest = toml::table{{"table", table}, {"interval", interval}};
  return f;
}

FrictionSpec surface_friction(const std::string& nodes, int64_t interval) {
  FrictionSpec f;
  f.law = "surface", f.nodes = nodes, f.rest = toml::table{{"interval", interval}};
  return f;
}

namespace {
/// A TOML value as deck text: strings double-quoted, floats in their shortest exact form, tables inline.
std::string value_text(const toml::node& v) {
  if (const auto* s = v.as_string()) return string_literal(s->get());
  if (const auto* i = v.as_integer()) return std::to_string(i->get());
  if (const auto* f = v.as_floating_point()) {
    std::string t = fmt_shortest(f->get());
    if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
    return t;
  }
  if (const auto* b = v.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* a = v.as_array()) {
    std::string o = "[";
    for (std::size_t k = 0; k < a->size(); ++k) o += (k ? ", " : "") + value_text(*a->get(k));
    return o + "]";
  }
  if (const auto* t = v.as_table()) {
    std::string o = "{ ";
    bool first = true;
    for (auto&& [k, x] : *t) {
      o += (first ? "" : ", ") + std::string(k.str()) + " = " + value_text(x);
      first = false;
    }
    return o + " }";
  }
  std::ostringstream o;
  v.visit([&o](const auto& x) { o << x; });
  return o.str();
}

/// The friction as its deck table (the writer's structure; inline).
toml::table friction_table(const FrictionSpec& s) {
  toml::table f = s.rest;
  put(f, "law", s.law);
  put(f, "nodes", s.nodes);
  put(f, "mu", s.mu);
  f.is_inline(true);
  return f;
}
}  // namespace

std::string friction_text(const FrictionSpec& s) {
  toml::table t = friction_table(s);
  std::string o = "{ ";
  bool first = true;
  auto key = [&](const std::string& k) {
    if (const toml::node* v = t.get(k)) {
      o += (first ? "" : ", ") + k + " = " + value_text(*v);
      first = false;
      t.erase(k);
    }
  };
  for (const char* k : {"law", "nodes", "lines", "table"}) key(k);
  while (!t.empty()) key(std::string(t.begin()->first.str()));  // the rest by name (a table is sorted)
  return o + " }";
}

CaseSpec from_toml(const toml::table& deck, const std::string& where) {
  toml::table root = deck;
  CaseSpec c;
  if (root.get("mesh")) {
    MeshSpec m;
    m.rest = take_table(root, "mesh", where);
    m.radius = take<double>(m.rest, "radius"), m.thickness = take<double>(m.rest, "thickness");
    m.core_fraction = take<double>(m.rest, "core_fraction"), m.polar_radius = take<double>(m.rest, "polar_radius");
    m.core = take<int64_t>(m.rest, "core"), m.ring = take<int64_t>(m.rest, "ring"), m.through = take<int64_t>(m.rest, "through");
    c.mesh = std::move(m);
  }
  if (root.get("material")) c.material = read_material(take_table(root, "material", where), where);
  if (root.get("numerics")) {
    NumericsSpec n;
    n.rest = take_table(root, "numerics", where);
    n.dt_safety = take<double>(n.rest, "dt_safety"), n.target_dt = take<double>(n.rest, "target_dt");
    n.threads = take<int64_t>(n.rest, "threads");
    c.numerics = std::move(n);
  }
  for (toml::table& t : take_tables(root, "tool", where)) c.tools.push_back(read_tool(std::move(t), where));
  for (toml::table& t : take_tables(root, "contact", where)) {
    ContactSpec s;
    if (t.get("friction")) s.friction = read_friction(take_table(t, "friction", where + ": contact"));
    s.rest = std::move(t);
    c.contacts.push_back(std::move(s));
  }
  for (toml::table& t : take_tables(root, "step", where)) {
    StepSpec s;
    s.name = take<std::string>(t, "name").value_or("");
    s.duration = take<double>(t, "duration"), s.damping = take<double>(t, "damping");
    s.rest = std::move(t);
    c.steps.push_back(std::move(s));
  }
  c.output = take_table(root, "output", where);
  if (c.output.get("reduce")) {
    toml::table r = take_table(c.output, "reduce", where + ": output");
    ReduceSpec s;
    s.written_inline = r.is_inline();
    s.kind = take<std::string>(r, "kind").value_or(""), s.tool = take<std::string>(r, "tool").value_or("");
    s.step = take<std::string>(r, "step").value_or(""), s.holder = take<std::string>(r, "holder");
    s.stroke = take<double>(r, "stroke"), s.ramp = take<double>(r, "ramp"), s.every = take<int64_t>(r, "every");
    if (!r.empty()) throw InputError(where + ": output.reduce: unexpected key '" + std::string(r.begin()->first.str()) + "'");
    c.reduce = std::move(s);
  }
  c.rest = std::move(root);
  return c;
}

CaseSpec read_case(const std::string& path) { return from_toml(parse_toml_file(path), path); }

toml::table to_toml_table(const CaseSpec& c) {
  toml::table root = c.rest;
  if (c.mesh) {
    toml::table t = c.mesh->rest;
    put(t, "radius", c.mesh->radius), put(t, "thickness", c.mesh->thickness);
    put(t, "core_fraction", c.mesh->core_fraction), put(t, "polar_radius", c.mesh->polar_radius);
    put(t, "core", c.mesh->core), put(t, "ring", c.mesh->ring), put(t, "through", c.mesh->through);
    root.insert_or_assign("mesh", std::move(t));
  }
  if (c.material) {  // the material's one writer, then its sub-tables' layout
    toml::table m = *parse_toml(to_toml(*c.material), "[material]")["material"].as_table();
    for (const std::string& k : c.material_sections)
      if (auto* s = m.get_as<toml::table>(k)) s->is_inline(false);
    root.insert_or_assign("material", std::move(m));
  }
  if (c.numerics) {
    toml::table t = c.numerics->rest;
    put(t, "dt_safety", c.numerics->dt_safety), put(t, "target_dt", c.numerics->target_dt);
    put(t, "threads", c.numerics->threads);
    root.insert_or_assign("numerics", std::move(t));
  }
  toml::array tools, contacts, steps;
  for (const ToolSpec& s : c.tools) tools.push_back(tool_table(s));
  for (const ContactSpec& s : c.contacts) {
    toml::table t = s.rest;
    if (s.friction) t.insert_or_assign("friction", friction_table(*s.friction));
    contacts.push_back(std::move(t));
  }
  for (const StepSpec& s : c.steps) {
    toml::table t = s.rest;
    if (!s.name.empty()) t.insert_or_assign("name", s.name);
    put(t, "duration", s.duration), put(t, "damping", s.damping);
    steps.push_back(std::move(t));
  }
  if (!tools.empty()) root.insert_or_assign("tool", std::move(tools));
  if (!contacts.empty()) root.insert_or_assign("contact", std::move(contacts));
  if (!steps.empty()) root.insert_or_assign("step", std::move(steps));
  if (!c.output.empty() || c.reduce) {
    toml::table o = c.output;
    if (const auto& r = c.reduce) {
      toml::table t{{"kind", r->kind}, {"tool", r->tool}, {"step", r->step}};
      put(t, "holder", r->holder), put(t, "stroke", r->stroke), put(t, "ramp", r->ramp), put(t, "every", r->every);
      t.is_inline(r->written_inline);
      o.insert_or_assign("reduce", std::move(t));
    }
    root.insert_or_assign("output", std::move(o));
  }
  return root;
}

namespace {

/// `text` (toml++'s print) with every float outside strings and comments in the
/// shortest form that reads back to the same double (toml++ prints 17 digits:
/// 0.8 as 0.80000000000000004), a '.' or an exponent kept so it stays a float.
/// Integers, keys (r45, hill48) and strings are left as they are.
std::string shortest_floats(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  const std::size_t n = text.size();
  char quote = 0;  // inside '...' or "..."
  auto number_char = [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)) || std::strchr("eE+-.", ch); };
  for (std::size_t i = 0; i < n;) {
    const char ch = text[i];
    if (quote) {
      out += ch;
      if (quote == '"' && ch == '\\' && i + 1 < n) out += text[++i];
      else if (ch == quote) quote = 0;
      ++i;
      continue;
    }
    if (ch == '#') {  // a comment, to the end of its line
      const std::size_t e = std::min(text.find('\n', i), n);
      out.append(text, i, e - i);
      i = e;
      continue;
    }
    const char prev = i ? text[i - 1] : ' ';
    const bool starts = (std::isdigit(static_cast<unsigned char>(ch)) ||
                         ((ch == '-' || ch == '+') && i + 1 < n && std::isdigit(static_cast<unsigned char>(text[i + 1])))) &&
                        !(std::isalnum(static_cast<unsigned char>(prev)) || prev == '_' || prev == '.' || prev == '-');
    if (!starts) {
      if (ch == '\'' || ch == '"') quote = ch;
      out += ch;
      ++i;
      continue;
    }
    std::size_t e = i + 1;
    while (e < n && number_char(text[e])) ++e;
    std::string token = text.substr(i, e - i);
    if (token.find_first_of(".eE") != std::string::npos) {
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      std::string t = fmt_shortest(v);
      if (t.find_first_of(".eE") == std::string::npos) t += ".0";
      if (end == token.c_str() + token.size() && std::isfinite(v) && std::strtod(t.c_str(), nullptr) == v) token = t;
    }
    out += token;
    i = e;
  }
  return out;
}

}  // namespace

std::string to_toml(const CaseSpec& c) {
  std::ostringstream o;
  for (const std::string& line : c.comment) o << (line.empty() ? "#" : "# " + line) << "\n";
  o << to_toml_table(c) << "\n";  // a text file's last line ends with a line break
  return shortest_floats(o.str());
}

}  // namespace drawbend::io
