#include "io/deck_sections.hpp"

#include <cmath>

#include "core/csv.hpp"
#include "io/deck_friction.hpp"

namespace drawbend::io {

namespace {

using fe::Vec3;

contact::Surface surface(const DeckContext& c, const toml::table& t, const std::string& w) {
  c.allowed(t, w, {"kind", "origin", "normal", "axis", "radius", "tube_radius", "inside", "r_min", "r_max", "z_min",
                   "z_max", "angle_min", "angle_max"});
  contact::Surface s;
  const std::string kind = c.str(t, "kind", w);
  if (kind.empty()) return s;  // missing or not a string: recorded
  s.origin = c.vec(t, "origin", w, Vec3{0, 0, 0});
  const std::size_t before = c.count();
  if (kind == "plane") {
    s.kind = contact::Surface::Kind::plane;
    s.axis = c.vec(t, "normal", w, {}, true);
    s.r_min = c.in_range(t, "r_min", w, 0.0, 0.0);
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
    s.R = c.in_range(t, "radius", w, 0.0, 0.0);
    s.r = c.positive(t, "tube_radius", w);
    s.a_min = c.num(t, "angle_min", w, -4.0);
    s.a_max = c.num(t, "angle_max", w, 4.0);
  } else {
    c.fail(t.get("kind") ? *t.get("kind") : static_cast<const toml::node&>(t), w + ".kind",
           "expected \"plane\", \"cylinder\" or \"torus\", found \"" + kind + "\"");
  }
  if (c.count() == before) try {
      s.validate(w);
    } catch (const std::invalid_argument& e) {  // its message starts with w: said once
      const std::string m = e.what();
      c.bad(t, w, m.rfind(w + ": ", 0) == 0 ? m.substr(w.size() + 2) : m);
    }
  return s;
}

fe::Tool::Drive drive(const DeckContext& c, const toml::table& t, const std::string& key, const std::string& w) {
  const std::string d = c.str(t, key, w, std::string("fixed"));
  if (d == "fixed") return fe::Tool::Drive::fixed;
  if (d == "velocity") return fe::Tool::Drive::velocity;
  if (d == "force") return fe::Tool::Drive::force;
  c.bad(*t.get(key), w + "." + key, "expected \"fixed\", \"velocity\" or \"force\", found \"" + d + "\"");
  return fe::Tool::Drive::fixed;
}

void guard(const DeckContext& c, const toml::table& t, const std::string& key, fe::Guard& g, bool fraction) {
  const auto* n = t.get(key);
  if (!n) return;
  const std::string w = "guards." + key;
  double limit = g.limit;
  if (const auto* tt = n->as_table()) {
    c.allowed(*tt, w, {"limit", "action"});
    limit = c.num(*tt, "limit", w, g.limit);
    const std::string a = c.str(*tt, "action", w, std::string("error"));
    if (a != "error" && a != "warn") c.bad(*tt->get("action"), w + ".action", "expected \"error\" or \"warn\", found \"" + a + "\"");
    g.error = a != "warn";
  } else {
    limit = c.num(t, key, "guards", g.limit);
  }
  if (std::isnan(limit)) return;
  if (!(limit > 0) || (fraction && !(limit < 1)))
    c.bad(*n, w, std::string("expected a limit ") + (fraction ? "in (0, 1)" : "> 0") + ", found " + fmt_shortest(limit));
  else
    g.limit = limit;
}

}  // namespace

void read_guards(const DeckContext& c, const toml::table& t, fe::Guards& g) {
  c.allowed(t, "guards", {"dt_collapse", "penetration", "hourglass_ratio", "kinetic_ratio", "energy_balance"});
  guard(c, t, "dt_collapse", g.dt_collapse, true);
  guard(c, t, "penetration", g.penetration, false);
  guard(c, t, "hourglass_ratio", g.hourglass_ratio, false);
  guard(c, t, "kinetic_ratio", g.kinetic_ratio, false);
  guard(c, t, "energy_balance", g.energy_balance, false);
}

void read_tools(const DeckContext& c, const toml::table& root, fe::Model& m) {
  const toml::array* tools = nullptr;
  if (!c.problems().attempt([&] { tools = c.array_of_tables(root, "tool", "deck"); }) || !tools) return;
  for (const auto& tn : *tools)
    c.problems().attempt([&] {
      const auto& t = *tn.as_table();
      fe::Tool tool;
      tool.name = c.name(t, "tool");
      const std::string w = "tool '" + tool.name + "'";
      c.allowed(t, w, {"name", "drive", "direction", "speed", "force", "mass", "stop", "surface"});
      for (const auto& other : m.tools)
        if (other.name == tool.name) c.bad(t, w, "expected a unique tool name, found it twice");
      tool.drive = drive(c, t, "drive", w);
      tool.direction = c.vec(t, "direction", w, Vec3{0, 0, 1}, true);
      if (tool.drive == fe::Tool::Drive::velocity) tool.speed = c.history(t, "speed", w);
      if (tool.drive == fe::Tool::Drive::force) {
        tool.force = c.history(t, "force", w);
        tool.mass = c.positive(t, "mass", w);
        if (t.get("stop")) tool.stop = c.num(t, "stop", w);
      } else if (t.get("stop")) {
        c.bad(t, w, "stop: only a force-driven tool (drive = \"force\") has a stop");
      }
      const auto* surfs = c.array_of_tables(t, "surface", w);
      if (!surfs || surfs->empty()) c.bad(t, w, "expected at least one [[tool.surface]], found none");
      if (surfs)
        for (const auto& s : *surfs)
          c.problems().attempt([&] { tool.surfaces.push_back(surface(c, *s.as_table(), w + " surface")); });
      m.tools.push_back(std::move(tool));
    });
}

namespace {
/// Whether a friction law is anisotropic (mu_1 != mu_2 somewhere): probed at
/// pressures 1 to 100 MPa and speeds 1 to 100 mm/s, fresh state each time.
bool anisotropic_law(const friction::FrictionLaw& law) {
  for (double p : {1.0, 10.0, 100.0})
    for (double v : {1.0, 10.0, 100.0}) {
      std::vector<double> st(static_cast<std::size_t>(std::max(0, law.state_size())), 0.0);
      friction::ContactState s;
      s.pressure = p;
      s.slip_speed = v;
      s.slip_dir = {1, 0, 0};
      s.state = st.empty() ? nullptr : st.data();
      try {
        const friction::Limit l = law.limit(s);
        if (l.mu1 != l.mu2) return true;
      } catch (const std::exception&) {
        return false;  // outside the law's domain: no verdict from this probe
      }
    }
  return false;
}

/// Whether the rolling direction is along the normal of every face of a set
/// (within 1e-6 rad): the sheet plane then holds no texture axis.
bool rd_along_normal(const fe::Mesh& mesh, const std::vector<fe::Quad>& faces, const Vec3& rd) {
  const double rl = std::sqrt(rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2]);
  if (faces.empty() || !(rl > 0)) return false;
  for (const auto& q : faces) {
    const Vec3 a{mesh.x[q[2]] - mesh.x[q[0]], mesh.y[q[2]] - mesh.y[q[0]], mesh.z[q[2]] - mesh.z[q[0]]};
    const Vec3 b{mesh.x[q[3]] - mesh.x[q[1]], mesh.y[q[3]] - mesh.y[q[1]], mesh.z[q[3]] - mesh.z[q[1]]};
    const Vec3 n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(nl > 0)) return false;
    const double cosang = std::abs(n[0] * rd[0] + n[1] * rd[1] + n[2] * rd[2]) / (nl * rl);
    if (cosang < 1 - 1e-12) return false;
  }
  return true;
}
}  // namespace

void read_contacts(const DeckContext& c, const toml::table& root, fe::Model& m, const std::string& dir, bool mesh_ok,
                   bool sheet_rd) {
  bool axis_seen = false;
  const toml::array* cps = nullptr;
  if (!c.problems().attempt([&] { cps = c.array_of_tables(root, "contact", "deck"); }) || !cps) return;
  for (const auto& cn : *cps)
    c.problems().attempt([&] {
      const auto& t = *cn.as_table();
      c.allowed(t, "contact", {"faces", "tool", "penalty", "damping", "friction", "texture_axis", "texture"});
      fe::ContactPair cp;
      cp.faces = c.str(t, "faces", "contact");
      cp.tool = c.str(t, "tool", "contact");
      cp.penalty = c.positive(t, "penalty", "contact", 0.1);
      // The builders' --penalty bound (kPenalty, cli/option_bounds.hpp): a scale of 1e300 ran and ended
      // in exit 3, an element inverted at cycle 7, without the deck's line (before 2026-12-05).
      if (constexpr double kMaxPenalty = 1e6; cp.penalty > kMaxPenalty && t.get("penalty"))
        c.bad(*t.get("penalty"), "contact.penalty",
              "expected a penalty scale in (0, " + fmt(kMaxPenalty) + "] (0.1 by default; k = penalty x K x A / L), found " +
                  fmt_shortest(cp.penalty));
      cp.damping = c.in_range(t, "damping", "contact", 0.2, 0.0, 1.0);
      if (const auto* ax = t.get("texture_axis")) {
        const Vec3 rd = c.vec(t, "texture_axis", "contact", Vec3{1, 0, 0}, true);
        if (sheet_rd)
          c.bad(*ax, "contact.texture_axis", "the rolling direction is stated in [sheet] rolling_direction; state it once");
        else if (axis_seen && rd != m.rolling_direction)
          c.bad(*ax, "contact.texture_axis",
                "differs from another contact's texture_axis: one sheet has one rolling direction "
                "(state it once in [sheet] rolling_direction)");
        m.rolling_direction = rd;
        axis_seen = true;
      }
      const std::string tex = c.str(t, "texture", "contact", std::string("fixed"));
      if (tex != "fixed" && tex != "corotational")
        c.bad(*t.get("texture"), "contact.texture", "expected \"fixed\" or \"corotational\", found \"" + tex + "\"");
      if (tex == "corotational") cp.texture = fe::ContactPair::Texture::corotational;
      bool tool_found = false;
      for (const auto& tool : m.tools) tool_found = tool_found || tool.name == cp.tool;
      if (!tool_found && !cp.tool.empty()) c.bad(t, "contact.tool", "expected the name of a [[tool]], found '" + cp.tool + "'");
      if (mesh_ok && !cp.faces.empty() && !m.mesh.face_sets.count(cp.faces))
        c.bad(t, "contact.faces", "expected a face set (xmin, xmax, ymin, ymax, zmin, zmax), found '" + cp.faces + "'");
      if (const auto* f = t.get("friction")) {
        if (!f->is_table()) c.fail(*f, "contact.friction", "expected a table, e.g. { law = \"coulomb\", mu = 0.1 }");
        cp.friction = make_friction(c, *f->as_table(), dir);
        // No silent substitution (issue 53): an anisotropic law on a sheet
        // whose rolling direction is its normal has no texture axis; the
        // contact code would take a global axis instead, without a word.
        if (cp.friction && mesh_ok && m.mesh.face_sets.count(cp.faces) && anisotropic_law(*cp.friction) &&
            rd_along_normal(m.mesh, m.mesh.face_sets.at(cp.faces), m.rolling_direction))
          c.bad(*f, "contact.friction",
                "an anisotropic friction law (mu differs along RD and TD), but the rolling direction (" +
                    fmt(m.rolling_direction[0]) + ", " + fmt(m.rolling_direction[1]) + ", " +
                    fmt(m.rolling_direction[2]) + ") is along the normal of every face of '" + cp.faces +
                    "': state an in-plane direction in [sheet] rolling_direction");
      }
      m.contacts.push_back(std::move(cp));
    });
}

void read_steps(const DeckContext& c, const toml::table& root, fe::Model& m, bool mesh_ok) {
  const toml::array* steps = nullptr;
  if (!c.problems().attempt([&] { steps = c.array_of_tables(root, "step", "deck"); })) return;
  if (!steps || steps->empty()) {
    c.problems().add(c.path + ": deck: expected at least one [[step]], found none");
    return;
  }
  for (const auto& sn : *steps)
    c.problems().attempt([&] {
      const auto& t = *sn.as_table();
      fe::Step s;
      s.name = c.name(t, "step", std::string("step") + std::to_string(m.steps.size() + 1));
      const std::string w = "step '" + s.name + "'";
      c.allowed(t, w, {"name", "duration", "damping", "friction", "quasi_static", "fixed", "velocity", "rotation",
                       "force", "tool_drive"});
      for (const auto& other : m.steps)  // messages and logs name a step by its name
        if (other.name == s.name)
          c.bad(t.get("name") ? *t.get("name") : static_cast<const toml::node&>(t), w + ".name",
                "expected a unique step name, found it twice");
      s.duration = c.positive(t, "duration", w);
      s.damping = c.in_range(t, "damping", w, 0.0, 0.0);
      if (const toml::node* dn = t.get("damping")) s.damping_where = c.where(*dn, w + ".damping");
      s.friction = c.boolean(t, "friction", w, true);
      s.quasi_static = c.boolean(t, "quasi_static", w, false);
      auto set_of = [&](const toml::table& b, const std::string& ww) {
        const std::string set = c.str(b, "set", ww);
        if (mesh_ok && !set.empty() && !m.mesh.node_sets.count(set))
          c.bad(b, ww + ".set", "expected a node set (all, xmin, xmax, ymin, ymax, zmin, zmax), found '" + set + "'");
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
            bool ok = arr && arr->size() == 3;
            for (int i = 0; ok && i < 3; ++i) {
              const auto v = (*arr)[static_cast<std::size_t>(i)].value<bool>();
              ok = v.has_value();
              if (ok) f.dof[i] = *v;
            }
            if (!ok) c.bad(*dof, w + ".fixed.dof", "expected [bool, bool, bool] for x, y, z");
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
          const std::string tool = c.str(bt, "tool", w + ".tool_drive");
          bool found = false;
          for (const auto& tl : m.tools) found = found || tl.name == tool;
          if (!found) c.bad(bt, w + ".tool_drive.tool", "expected the name of a [[tool]], found '" + tool + "'");
          s.tool_drive.push_back({tool, drive(c, bt, "drive", w + ".tool_drive")});
        }
      m.steps.push_back(std::move(s));
    });
}

}  // namespace drawbend::io
