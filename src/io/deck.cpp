#include "io/deck.hpp"

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "core/csv.hpp"
#include "fe/strip.hpp"
#include "io/deck_material.hpp"

namespace drawbend::io {

namespace {

using fe::Vec3;

struct Ctx {
  std::string path;
  std::string where(const toml::node& n, const std::string& key) const {
    return path + ":" + std::to_string(n.source().begin.line) + ": " + key;
  }
  [[noreturn]] void fail(const toml::node& n, const std::string& key, const std::string& msg) const {
    throw InputError(where(n, key) + ": " + msg);
  }
  void allowed(const toml::table& t, const std::string& what, std::set<std::string> keys) const {
    for (const auto& [k, v] : t)
      if (!keys.count(std::string(k.str()))) {
        std::string list;
        for (const auto& a : keys) list += (list.empty() ? "" : ", ") + a;
        fail(v, what + "." + std::string(k.str()), "unknown key (expected one of: " + list + ")");
      }
  }
  const toml::table& table(const toml::table& t, const std::string& key, const std::string& what) const {
    const auto* n = t.get(key);
    if (!n) throw InputError(path + ": " + what + ": missing required table [" + key + "]");
    if (!n->is_table()) fail(*n, what + "." + key, "expected a table");
    return *n->as_table();
  }
  double num(const toml::table& t, const std::string& key, const std::string& what, std::optional<double> def = {}) const {
    const auto* n = t.get(key);
    if (!n) {
      if (def) return *def;
      throw InputError(path + ":" + std::to_string(t.source().begin.line) + ": " + what + ": missing required key '" + key + "'");
    }
    if (auto v = n->value<double>()) return *v;
    fail(*n, what + "." + key, "expected a number");
  }
  double positive(const toml::table& t, const std::string& key, const std::string& what, std::optional<double> def = {}) const {
    const double v = num(t, key, what, def);
    if (!(v > 0)) fail(t.get(key) ? *t.get(key) : t, what + "." + key, "must be > 0, found " + fmt(v));
    return v;
  }
  std::string str(const toml::table& t, const std::string& key, const std::string& what, std::optional<std::string> def = {}) const {
    const auto* n = t.get(key);
    if (!n) {
      if (def) return *def;
      throw InputError(path + ":" + std::to_string(t.source().begin.line) + ": " + what + ": missing required key '" + key + "'");
    }
    if (auto v = n->value<std::string>()) return *v;
    fail(*n, what + "." + key, "expected a string");
  }
  bool boolean(const toml::table& t, const std::string& key, const std::string& what, bool def) const {
    const auto* n = t.get(key);
    if (!n) return def;
    if (auto v = n->value<bool>()) return *v;
    fail(*n, what + "." + key, "expected true or false");
  }
  Vec3 vec(const toml::table& t, const std::string& key, const std::string& what, std::optional<Vec3> def = {}, bool unit = false) const {
    const auto* n = t.get(key);
    if (!n) {
      if (def) return *def;
      throw InputError(path + ": " + what + ": missing required key '" + key + "'");
    }
    const auto* a = n->as_array();
    if (!a || a->size() != 3) fail(*n, what + "." + key, "expected an array of 3 numbers");
    Vec3 v{};
    for (int i = 0; i < 3; ++i) {
      auto x = (*a)[i].value<double>();
      if (!x) fail(*n, what + "." + key, "expected an array of 3 numbers");
      v[i] = *x;
    }
    if (unit) {
      const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (!(l > 0)) fail(*n, what + "." + key, "direction must not be zero");
      for (double& c : v) c /= l;
    }
    return v;
  }
  /// A history: a number (constant) or a table {t = [...], v = [...]}.
  fe::History history(const toml::table& t, const std::string& key, const std::string& what) const {
    const auto* n = t.get(key);
    if (!n) throw InputError(path + ": " + what + ": missing required key '" + key + "'");
    if (auto v = n->value<double>()) return fe::History::constant(*v);
    const auto* h = n->as_table();
    if (!h) fail(*n, what + "." + key, "expected a number or a table {t = [...], v = [...]}");
    allowed(*h, what + "." + key, {"t", "v"});
    fe::History out;
    out.t.clear();
    out.v.clear();
    for (const char* k : {"t", "v"}) {
      const auto* a = h->get(k) ? h->get(k)->as_array() : nullptr;
      if (!a || a->empty()) fail(*n, what + "." + key + "." + k, "expected a non-empty array of numbers");
      for (const auto& e : *a) {
        auto x = e.value<double>();
        if (!x) fail(*n, what + "." + key + "." + k, "expected numbers");
        (std::string(k) == "t" ? out.t : out.v).push_back(*x);
      }
    }
    try {
      out.validate((what + "." + key).c_str());
    } catch (const std::invalid_argument& e) {
      fail(*n, what + "." + key, e.what());
    }
    return out;
  }
  const toml::array* array_of_tables(const toml::table& t, const std::string& key, const std::string& what) const {
    const auto* n = t.get(key);
    if (!n) return nullptr;
    const auto* a = n->as_array();
    if (!a) fail(*n, what + "." + key, "expected an array of tables");
    for (const auto& e : *a)
      if (!e.is_table()) fail(e, what + "." + key, "expected an array of tables");
    return a;
  }
};

std::vector<double> lines(const Ctx& c, const toml::table& mesh, const std::string& axis) {
  const std::string w = "mesh." + axis;
  const auto* n = mesh.get(axis);
  if (!n || !n->is_table()) throw InputError(c.path + ": mesh: missing table '" + axis + "' (e.g. { from = 0.0, to = 10.0, n = 10 })");
  const auto& t = *n->as_table();
  c.allowed(t, w, {"from", "to", "n", "breaks", "counts"});
  if (t.get("breaks")) {
    std::vector<double> b;
    std::vector<int> k;
    for (const auto& e : *t.get("breaks")->as_array()) b.push_back(e.value<double>().value_or(NAN));
    for (const auto& e : *t.get("counts")->as_array()) k.push_back(static_cast<int>(e.value<int64_t>().value_or(0)));
    try {
      return fe::piecewise_lines(b, k);
    } catch (const std::invalid_argument& e) {
      c.fail(t, w, e.what());
    }
  }
  const double a = c.num(t, "from", w), b = c.num(t, "to", w);
  const double nn = c.positive(t, "n", w);
  if (nn != std::floor(nn)) c.fail(t, w + ".n", "expected a whole number of elements");
  if (!(b > a)) c.fail(t, w, "'to' must exceed 'from'");
  return fe::uniform_lines(a, b, static_cast<int>(nn));
}

contact::Surface surface(const Ctx& c, const toml::table& t, const std::string& w) {
  c.allowed(t, w, {"kind", "origin", "normal", "axis", "radius", "tube_radius", "inside", "r_min", "r_max", "z_min",
                   "z_max", "angle_min", "angle_max"});
  contact::Surface s;
  const std::string kind = c.str(t, "kind", w);
  s.origin = c.vec(t, "origin", w, Vec3{0, 0, 0});
  if (kind == "plane") {
    s.kind = contact::Surface::Kind::plane;
    s.axis = c.vec(t, "normal", w, {}, true);
    s.r_min = c.num(t, "r_min", w, 0.0);
    s.r_max = c.num(t, "r_max", w, 1e30);
  } else if (kind == "cylinder") {
    s.kind = contact::Surface::Kind::cylinder;
    s.axis = c.vec(t, "axis", w, {}, true);
    s.R = c.positive(t, "radius", w);
    s.inside = c.boolean(t, "inside", w, false);
    s.z_min = c.num(t, "z_min", w, -1e30);
    s.z_max = c.num(t, "z_max", w, 1e30);
  } else if (kind == "torus") {
    s.kind = contact::Surface::Kind::torus;
    s.axis = c.vec(t, "axis", w, {}, true);
    s.R = c.num(t, "radius", w);
    s.r = c.positive(t, "tube_radius", w);
    s.a_min = c.num(t, "angle_min", w, -4.0);
    s.a_max = c.num(t, "angle_max", w, 4.0);
  } else {
    c.fail(*t.get("kind"), w + ".kind", "expected \"plane\", \"cylinder\" or \"torus\", found \"" + kind + "\"");
  }
  try {
    s.validate(w);
  } catch (const std::invalid_argument& e) {
    c.fail(t, w, e.what());
  }
  return s;
}

fe::Tool::Drive drive(const Ctx& c, const toml::table& t, const std::string& key, const std::string& w) {
  const std::string d = c.str(t, key, w, std::string("fixed"));
  if (d == "fixed") return fe::Tool::Drive::fixed;
  if (d == "velocity") return fe::Tool::Drive::velocity;
  if (d == "force") return fe::Tool::Drive::force;
  c.fail(*t.get(key), w + "." + key, "expected \"fixed\", \"velocity\" or \"force\", found \"" + d + "\"");
}

}  // namespace

Deck read_deck(const std::string& path) { return parse_deck(read_file(path), path); }

Deck parse_deck(const std::string& text, const std::string& path) {
  Ctx c{path};
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << path << ":" << e.source().begin.line << ":" << e.source().begin.column << ": TOML syntax error: " << e.description();
    throw InputError(os.str());
  }
  c.allowed(root, "deck", {"case", "mesh", "material", "numerics", "tool", "contact", "step", "output"});
  Deck d;
  d.path = path;
  fe::Model& m = d.model;
  const std::string dir = std::filesystem::path(path).parent_path().string();
  if (const auto* cs = root.get("case")) {
    if (!cs->is_table()) c.fail(*cs, "case", "expected a table");
    c.allowed(*cs->as_table(), "case", {"name", "description"});
    m.name = c.str(*cs->as_table(), "name", "case", std::string("case"));
  }
  // Mesh: a structured block.
  const auto& mesh = c.table(root, "mesh", "deck");
  const std::string kind = c.str(mesh, "kind", "mesh", std::string("block"));
  if (kind == "block") {
    c.allowed(mesh, "mesh", {"kind", "x", "y", "z"});
    m.mesh = fe::structured_block(lines(c, mesh, "x"), lines(c, mesh, "y"), lines(c, mesh, "z"));
  } else if (kind == "wrapped_strip") {
    // A strip already wrapped round a pin on the y axis (fe/strip.hpp); node and
    // face sets as for a block: xmin inlet end, xmax outlet end, zmin contact face.
    c.allowed(mesh, "mesh", {"kind", "pin_radius", "wrap_deg", "thickness", "width", "inlet_length", "outlet_length",
                             "element_length", "across", "through"});
    fe::StripSpec sp;
    sp.pin_radius = c.positive(mesh, "pin_radius", "mesh");
    const double wrap = c.positive(mesh, "wrap_deg", "mesh", 90.0);
    if (!(wrap < 180.0)) c.fail(mesh, "mesh.wrap_deg", "wrap angle must lie in (0, 180) deg");
    sp.wrap = wrap * M_PI / 180.0;
    sp.thickness = c.positive(mesh, "thickness", "mesh");
    sp.width = c.positive(mesh, "width", "mesh");
    sp.inlet_length = c.num(mesh, "inlet_length", "mesh", 25.0);
    sp.outlet_length = c.num(mesh, "outlet_length", "mesh", 10.0);
    sp.element_length = c.positive(mesh, "element_length", "mesh", 0.5);
    sp.across = static_cast<int>(c.positive(mesh, "across", "mesh", 4.0));
    sp.through = static_cast<int>(c.positive(mesh, "through", "mesh", 4.0));
    try {
      m.mesh = fe::wrapped_strip(sp);
    } catch (const std::invalid_argument& e) {
      c.fail(mesh, "mesh", e.what());
    }
  } else if (kind == "quarter_disk") {
    m.mesh = make_quarter_disk(mesh, path);  // deck_material.cpp
  } else {
    c.fail(*mesh.get("kind"), "mesh.kind", "expected \"block\", \"wrapped_strip\" or \"quarter_disk\", found \"" + kind + "\"");
  }
  // Material.
  m.material = make_material(c.table(root, "material", "deck"), path, dir);
  // Numerics.
  if (const auto* nn = root.get("numerics")) {
    const auto& t = *nn->as_table();
    c.allowed(t, "numerics", {"dt_safety", "mass_scaling", "target_dt", "hourglass", "threads"});
    m.dt_safety = c.positive(t, "dt_safety", "numerics", 0.8);
    if (m.dt_safety > 1) c.fail(*t.get("dt_safety"), "numerics.dt_safety", "must not exceed 1");
    m.mass_scaling = c.num(t, "mass_scaling", "numerics", 1.0);
    if (!(m.mass_scaling >= 1)) c.fail(t, "numerics.mass_scaling", "must be >= 1");
    m.target_dt = c.num(t, "target_dt", "numerics", 0.0);
    m.hourglass = c.num(t, "hourglass", "numerics", 1.0);
    d.threads = static_cast<int>(c.num(t, "threads", "numerics", 0.0));
  }
  // Tools.
  if (const auto* tools = c.array_of_tables(root, "tool", "deck"))
    for (const auto& tn : *tools) {
      const auto& t = *tn.as_table();
      fe::Tool tool;
      tool.name = c.str(t, "name", "tool");
      const std::string w = "tool '" + tool.name + "'";
      c.allowed(t, w, {"name", "drive", "direction", "speed", "force", "mass", "surface"});
      tool.drive = drive(c, t, "drive", w);
      tool.direction = c.vec(t, "direction", w, Vec3{0, 0, 1}, true);
      if (tool.drive == fe::Tool::Drive::velocity) tool.speed = c.history(t, "speed", w);
      if (tool.drive == fe::Tool::Drive::force) {
        tool.force = c.history(t, "force", w);
        tool.mass = c.positive(t, "mass", w);
      }
      const auto* surfs = c.array_of_tables(t, "surface", w);
      if (!surfs || surfs->empty()) c.fail(t, w, "needs at least one [[tool.surface]]");
      for (const auto& s : *surfs) tool.surfaces.push_back(surface(c, *s.as_table(), w + " surface"));
      m.tools.push_back(std::move(tool));
    }
  // Contact pairs.
  if (const auto* cps = c.array_of_tables(root, "contact", "deck"))
    for (const auto& cn : *cps) {
      const auto& t = *cn.as_table();
      c.allowed(t, "contact", {"faces", "tool", "penalty", "damping", "friction", "texture_axis", "texture"});
      fe::ContactPair cp;
      cp.faces = c.str(t, "faces", "contact");
      cp.tool = c.str(t, "tool", "contact");
      cp.penalty = c.positive(t, "penalty", "contact", 0.1);
      cp.damping = c.num(t, "damping", "contact", 0.2);
      if (!(cp.damping >= 0 && cp.damping <= 1)) c.fail(t, "contact.damping", "must lie in [0, 1] (fraction of critical)");
      cp.texture_axis = c.vec(t, "texture_axis", "contact", Vec3{1, 0, 0}, true);
      const std::string tex = c.str(t, "texture", "contact", std::string("fixed"));
      if (tex != "fixed" && tex != "corotational")
        c.fail(*t.get("texture"), "contact.texture", "expected \"fixed\" or \"corotational\" (found \"" + tex + "\")");
      if (tex == "corotational") cp.texture = fe::ContactPair::Texture::corotational;
      if (const auto* f = t.get("friction")) {
        if (!f->is_table()) c.fail(*f, "contact.friction", "expected a table, e.g. { law = \"coulomb\", mu = 0.1 }");
        cp.friction = make_friction(*f->as_table(), path, dir);
      }
      if (!m.mesh.face_sets.count(cp.faces)) c.fail(t, "contact.faces", "no face set '" + cp.faces + "' (xmin, xmax, ymin, ymax, zmin, zmax)");
      m.contacts.push_back(std::move(cp));
    }
  // Steps.
  const auto* steps = c.array_of_tables(root, "step", "deck");
  if (!steps || steps->empty()) throw InputError(path + ": deck: at least one [[step]] is required");
  for (const auto& sn : *steps) {
    const auto& t = *sn.as_table();
    fe::Step s;
    s.name = c.str(t, "name", "step", std::string("step") + std::to_string(m.steps.size() + 1));
    const std::string w = "step '" + s.name + "'";
    c.allowed(t, w, {"name", "duration", "damping", "friction", "fixed", "velocity", "rotation", "force", "tool_drive"});
    s.duration = c.positive(t, "duration", w);
    s.damping = c.num(t, "damping", w, 0.0);
    s.friction = c.boolean(t, "friction", w, true);
    auto set_of = [&](const toml::table& b, const std::string& ww) {
      const std::string set = c.str(b, "set", ww);
      if (!m.mesh.node_sets.count(set)) c.fail(b, ww + ".set", "no node set '" + set + "' (all, xmin, xmax, ymin, ymax, zmin, zmax)");
      return set;
    };
    if (const auto* a = c.array_of_tables(t, "fixed", w))
      for (const auto& b : *a) {
        const auto& bt = *b.as_table();
        c.allowed(bt, w + ".fixed", {"set", "dof"});
        fe::FixedBC f;
        f.set = set_of(bt, w + ".fixed");
        if (const auto* dof = bt.get("dof")) {
          const auto* arr = dof->as_array();
          if (!arr || arr->size() != 3) c.fail(*dof, w + ".fixed.dof", "expected [bool, bool, bool] for x, y, z");
          for (int i = 0; i < 3; ++i) f.dof[i] = (*arr)[i].value<bool>().value_or(false);
        }
        s.fixed.push_back(f);
      }
    if (const auto* a = c.array_of_tables(t, "velocity", w))
      for (const auto& b : *a) {
        const auto& bt = *b.as_table();
        c.allowed(bt, w + ".velocity", {"set", "direction", "speed"});
        s.velocities.push_back({set_of(bt, w + ".velocity"), c.vec(bt, "direction", w + ".velocity", {}, true),
                                c.history(bt, "speed", w + ".velocity")});
      }
    if (const auto* a = c.array_of_tables(t, "rotation", w))
      for (const auto& b : *a) {
        const auto& bt = *b.as_table();
        c.allowed(bt, w + ".rotation", {"set", "centre", "axis", "omega"});
        s.rotations.push_back({set_of(bt, w + ".rotation"), c.vec(bt, "centre", w + ".rotation"),
                               c.vec(bt, "axis", w + ".rotation", {}, true), c.history(bt, "omega", w + ".rotation")});
      }
    if (const auto* a = c.array_of_tables(t, "force", w))
      for (const auto& b : *a) {
        const auto& bt = *b.as_table();
        c.allowed(bt, w + ".force", {"set", "direction", "magnitude"});
        s.forces.push_back({set_of(bt, w + ".force"), c.vec(bt, "direction", w + ".force", {}, true),
                            c.history(bt, "magnitude", w + ".force")});
      }
    if (const auto* a = c.array_of_tables(t, "tool_drive", w))
      for (const auto& b : *a) {
        const auto& bt = *b.as_table();
        c.allowed(bt, w + ".tool_drive", {"tool", "drive"});
        s.tool_drive.push_back({c.str(bt, "tool", w + ".tool_drive"), drive(c, bt, "drive", w + ".tool_drive")});
      }
    m.steps.push_back(std::move(s));
  }
  // Output.
  if (const auto* on = root.get("output")) {
    const auto& t = *on->as_table();
    c.allowed(t, "output", {"history_interval", "fields_per_step", "history"});
    d.output.history_interval = c.num(t, "history_interval", "output", 0.0);
    d.output.fields_per_step = static_cast<int>(c.num(t, "fields_per_step", "output", 1.0));
    if (const auto* hs = c.array_of_tables(t, "history", "output"))
      for (const auto& h : *hs) {
        const auto& ht = *h.as_table();
        c.allowed(ht, "output.history", {"name", "kind", "target", "component", "point"});
        const std::string kind = c.str(ht, "kind", "output.history");
        HistorySignal sig{c.str(ht, "name", "output.history"), kind,
                          kind == "strain" ? std::string() : c.str(ht, "target", "output.history"),
                          static_cast<int>(c.num(ht, "component", "output.history", 0.0))};
        if (kind == "strain") sig.point = c.vec(ht, "point", "output.history");
        if (sig.kind != "reaction" && sig.kind != "applied" && sig.kind != "tool_force" && sig.kind != "tool_offset" &&
            sig.kind != "displacement" && sig.kind != "strain")
          c.fail(ht, "output.history.kind", "expected reaction, applied, displacement, strain, tool_force or tool_offset");
        if (sig.component < 0 || sig.component > 2) c.fail(ht, "output.history.component", "expected 0, 1 or 2");
        d.output.history.push_back(sig);
      }
  }
  try {
    m.validate();
  } catch (const std::invalid_argument& e) {
    throw InputError(path + ": " + e.what());
  }
  return d;
}

}  // namespace drawbend::io
