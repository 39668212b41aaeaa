#include "io/deck.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "core/csv.hpp"
#include "core/hash.hpp"
#include "core/input_problems.hpp"
#include "core/run_output.hpp"
#include "fe/disk.hpp"
#include "fe/strip.hpp"
#include "io/case_reduction.hpp"
#include "io/deck_context.hpp"
#include "io/deck_limits.hpp"
#include "io/deck_friction.hpp"
#include "io/deck_overlap.hpp"
#include "io/deck_sections.hpp"
#include "io/material_spec.hpp"
#include "core/toml_read.hpp"

namespace drawbend::io {

namespace {

using fe::Vec3;

// The largest mesh a deck may ask for: far beyond what an explicit run on one
// machine can do, and a guard against a typo allocating all memory.  The
// fuzzers build with a small value so that each input stays fast.
#ifndef DRAWBEND_DECK_MAX_NODES
#define DRAWBEND_DECK_MAX_NODES 5e7
#endif
constexpr double kMaxNodes = DRAWBEND_DECK_MAX_NODES;

std::vector<double> lines(const DeckContext& c, const toml::table& mesh, const std::string& axis) {
  const std::string w = "mesh." + axis;
  const auto* n = mesh.get(axis);
  if (!n || !n->is_table()) {
    c.problems().add(c.path + ":" + std::to_string(mesh.source().begin.line) + ": " + w +
                     ": missing table (expected e.g. { from = 0.0, to = 10.0, n = 10 })");
    return {0.0, 1.0};
  }
  const auto& t = *n->as_table();
  const std::size_t before = c.count();
  c.allowed(t, w, {"from", "to", "n", "breaks", "counts"});
  if (t.get("breaks") || t.get("counts")) {
    const auto* b = t.get("breaks") ? t.get("breaks")->as_array() : nullptr;
    const auto* k = t.get("counts") ? t.get("counts")->as_array() : nullptr;
    if (!b || !k) {
      c.bad(t, w, "expected both 'breaks' (array of numbers) and 'counts' (array of whole numbers)");
      return {0.0, 1.0};
    }
    // { from, to, n } beside { breaks, counts } was ignored with exit 0 before 2026-12-04.
    for (const char* key : {"from", "to", "n"})
      if (const auto* u = t.get(key))
        c.bad(*u, w + "." + key, "not used with 'breaks' and 'counts' (give either { from, to, n } or { breaks, counts })");
    std::vector<double> bv;
    std::vector<int> kv;
    for (const auto& e : *b) {
      const auto v = e.value<double>();
      if (!v || !std::isfinite(*v)) c.bad(e, w + ".breaks", "expected finite numbers");
      else if (!bv.empty() && !(*v > bv.back()))  // named here, not by fe::piecewise_lines's "uniform_lines: need ..."
        c.bad(e, w + ".breaks", "expected increasing coordinates, found " + fmt_shortest(*v) + " after " + fmt_shortest(bv.back()));
      bv.push_back(v.value_or(0.0));
    }
    if (b->size() < 2 || k->size() + 1 != b->size())
      c.bad(*t.get("counts"), w + ".counts", "expected at least 2 breaks and one count per segment between them, found " +
                                                 std::to_string(b->size()) + " breaks and " + std::to_string(k->size()) + " counts");
    for (const auto& e : *k) {
      const auto v = e.value<int64_t>();
      if (!v || *v < 1 || *v > 100000000) c.bad(e, w + ".counts", "expected whole numbers of elements >= 1");
      kv.push_back(static_cast<int>(v.value_or(1)));
    }
    double total = 0;
    for (int n : kv) total += n;
    if (total > kMaxNodes) c.bad(*t.get("counts"), w + ".counts", "expected at most " + fmt(kMaxNodes) + " elements in all, found " + fmt(total));
    if (c.count() > before) return {0.0, 1.0};
    try {
      auto v = fe::piecewise_lines(bv, kv);
      for (std::size_t i = 1; i < v.size(); ++i)
        if (!std::isfinite(v[i]) || !(v[i] > v[i - 1])) {
          c.bad(t, w, "expected elements of finite, non-zero size, found line " + std::to_string(i) + " at " +
                          fmt_shortest(v[i]) + " mm");
          return {0.0, 1.0};
        }
      return v;
    } catch (const std::invalid_argument& e) {
      c.bad(t, w, e.what());
      return {0.0, 1.0};
    }
  }
  const double a = c.num(t, "from", w), b = c.num(t, "to", w);
  const int nn = c.count_of(t, "n", w, {}, 1);
  if (nn > kMaxNodes) c.bad(*t.get("n"), w + ".n", "expected at most " + fmt(kMaxNodes) + " elements, found " + std::to_string(nn));
  if (std::isfinite(a) && std::isfinite(b) && !(b > a))
    c.bad(t, w, "expected 'to' > 'from', found from = " + fmt_shortest(a) + ", to = " + fmt_shortest(b));
  else if (std::isfinite(a) && std::isfinite(b) && !std::isfinite(b - a))
    c.bad(t, w, "expected coordinates whose span to - from is a finite number of mm, found from = " +
                    fmt_shortest(a) + ", to = " + fmt_shortest(b));
  if (c.count() > before) return {0.0, 1.0};
  auto v = fe::uniform_lines(a, b, nn);
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!std::isfinite(v[i]) || !(v[i] > v[i - 1])) {
      c.bad(t, w, "expected " + std::to_string(nn) + " elements of finite, non-zero size between from = " +
                      fmt_shortest(a) + " and to = " + fmt_shortest(b) + " mm, found line " + std::to_string(i) +
                      " at " + fmt_shortest(v[i]) + " mm");
      return {0.0, 1.0};
    }
  return v;
}

/// [mesh] kind = "quarter_disk": radius, thickness [mm], core, ring, through
/// (element counts), core_fraction, polar_radius (fe/disk.hpp).  Problems are
/// recorded in c's collector; returns an empty mesh if it could not be built.
fe::Mesh make_quarter_disk(const DeckContext& c, const toml::table& t) {
  const std::size_t before = c.count();
  c.allowed(t, "mesh", {"kind", "radius", "thickness", "core_fraction", "core", "ring", "through",
                          "polar_radius"});
  fe::QuarterDiskSpec s;
  s.radius = c.positive(t, "radius", "mesh");
  s.thickness = c.positive(t, "thickness", "mesh");
  s.core_fraction = c.positive(t, "core_fraction", "mesh", s.core_fraction);
  s.core = c.count_of(t, "core", "mesh", s.core, 1);
  s.ring = c.count_of(t, "ring", "mesh", s.ring, 1);
  s.through = c.count_of(t, "through", "mesh", s.through, 1);
  if (t.contains("polar_radius")) s.polar_radius = c.positive(t, "polar_radius", "mesh");
  if (c.count() > before) return {};
  try {
    return fe::quarter_disk(s);
  } catch (const std::invalid_argument& e) {
    c.fail(t, "mesh", e.what());
  }
}

/// The mesh, or nothing if a value problem (recorded) prevents building it.
std::optional<fe::Mesh> read_mesh(const DeckContext& c, const toml::table& mesh, const RunLimits& lim) {
  const std::string kind = c.str(mesh, "kind", "mesh", std::string("block"));
  if (kind == "block") {
    c.allowed(mesh, "mesh", {"kind", "x", "y", "z"});
    const std::size_t before = c.count();
    const auto x = lines(c, mesh, "x"), y = lines(c, mesh, "y"), z = lines(c, mesh, "z");
    if (c.count() > before) return std::nullopt;
    const double nodes = static_cast<double>(x.size()) * y.size() * z.size();
    if (nodes > kMaxNodes)
      c.fail(mesh, "mesh", "expected at most " + fmt(kMaxNodes) + " nodes, found " + fmt(nodes));
    const double elements = static_cast<double>(x.size() - 1) * (y.size() - 1) * (z.size() - 1);
    if (!check_memory(c, mesh, "mesh", nodes, elements, lim)) return std::nullopt;  // before building it
    return fe::structured_block(x, y, z);
  }
  if (kind == "quarter_disk") {
    fe::Mesh disk = make_quarter_disk(c, mesh);
    if (disk.num_nodes() == 0) return std::nullopt;
    return disk;
  }
  if (kind != "wrapped_strip")
    c.fail(*mesh.get("kind"), "mesh.kind",
           "expected \"block\", \"wrapped_strip\" or \"quarter_disk\", found \"" + kind + "\"");
  // A strip already wrapped round a pin on the y axis (fe/strip.hpp); node and
  // face sets as for a block: xmin inlet end, xmax outlet end, zmin contact face.
  c.allowed(mesh, "mesh", {"kind", "pin_radius", "wrap_deg", "thickness", "width", "inlet_length", "outlet_length",
                           "element_length", "across", "through"});
  const std::size_t before = c.count();
  fe::StripSpec sp;
  sp.pin_radius = c.positive(mesh, "pin_radius", "mesh");
  const double wrap = c.in_range(mesh, "wrap_deg", "mesh", 90.0, -1e300);
  if (!(wrap > 0 && wrap < 180.0))
    c.bad(*mesh.get("wrap_deg"), "mesh.wrap_deg", "expected a wrap angle in (0, 180) deg, found " + fmt_shortest(wrap));
  sp.wrap = wrap * M_PI / 180.0;
  sp.thickness = c.positive(mesh, "thickness", "mesh");
  sp.width = c.positive(mesh, "width", "mesh");
  sp.inlet_length = c.positive(mesh, "inlet_length", "mesh", 25.0);
  sp.outlet_length = c.positive(mesh, "outlet_length", "mesh", 10.0);
  sp.element_length = c.positive(mesh, "element_length", "mesh", 0.5);
  sp.across = c.count_of(mesh, "across", "mesh", 4, 1);
  sp.through = c.count_of(mesh, "through", "mesh", 4, 1);
  if (c.count() > before) return std::nullopt;
  const double nodes = ((sp.inlet_length + sp.outlet_length + sp.pin_radius * sp.wrap) / sp.element_length + 3) *
                       (sp.across + 1) * (sp.through + 1);
  if (!(nodes <= kMaxNodes)) c.fail(mesh, "mesh", "expected at most " + fmt(kMaxNodes) + " nodes, found about " + fmt(nodes));
  return fe::wrapped_strip(sp);
}

void read_numerics(const DeckContext& c, const toml::table& t, Deck& d) {
  fe::Model& m = d.model;
  c.allowed(t, "numerics", {"dt_safety", "mass_scaling", "target_dt", "hourglass", "threads"});
  m.dt_safety = c.positive(t, "dt_safety", "numerics", 0.8);
  if (m.dt_safety > 1) {
    c.bad(*t.get("dt_safety"), "numerics.dt_safety",
          "expected a fraction of the critical time step in (0, 1], found " + fmt_shortest(m.dt_safety));
    m.dt_safety = 0.8;
  }
  m.mass_scaling = c.in_range(t, "mass_scaling", "numerics", 1.0, 1.0);
  m.target_dt = c.in_range(t, "target_dt", "numerics", 0.0, 0.0);
  m.hourglass = c.in_range(t, "hourglass", "numerics", 1.0, 0.0);
  d.threads = c.count_of(t, "threads", "numerics", 0, 0);
  if (d.threads > kMaxThreads) {
    c.bad(*t.get("threads"), "numerics.threads",
          "expected at most " + std::to_string(kMaxThreads) + " OpenMP threads, found " + std::to_string(d.threads));
    d.threads = 0;
  }
}

void read_output(const DeckContext& c, const toml::table& t, OutputSpec& out, const fe::Model& m, bool mesh_ok) {
  c.allowed(t, "output", {"history_interval", "fields_per_step", "vtk_format", "history", "reduce"});
  if (const auto* rt = c.table(t, "reduce", "output", false)) {
    c.allowed(*rt, "output.reduce", {"kind", "tool", "step", "ramp", "holder", "every", "stroke"});
    out.reduce.kind = c.str(*rt, "kind", "output.reduce");
    const auto& kinds = reduction_kinds();
    if (std::find(kinds.begin(), kinds.end(), out.reduce.kind) == kinds.end())
      c.bad(*rt, "output.reduce.kind", "expected block_slide, strip_draw, cup_draw or earing_cup, found \"" + out.reduce.kind + "\"");
    out.reduce.tool = c.str(*rt, "tool", "output.reduce");
    out.reduce.step = c.str(*rt, "step", "output.reduce");
    out.reduce.ramp = c.in_range(*rt, "ramp", "output.reduce", 0.0, 0.0);
    out.reduce.holder = c.str(*rt, "holder", "output.reduce", std::string());
    out.reduce.every = c.count_of(*rt, "every", "output.reduce", 1, 1);
    out.reduce.stroke = c.in_range(*rt, "stroke", "output.reduce", 0.0, 0.0);
  }
  out.history_interval = c.in_range(t, "history_interval", "output", 0.0, 0.0);
  out.fields_per_step = c.count_of(t, "fields_per_step", "output", 1, 1);
  const std::string vtk = c.str(t, "vtk_format", "output", std::string("binary"));
  if (vtk != "binary" && vtk != "ascii")
    c.bad(*t.get("vtk_format"), "output.vtk_format", "expected \"binary\" or \"ascii\", found \"" + vtk + "\"");
  out.vtk_ascii = vtk == "ascii";
  if (const auto* hs = c.array_of_tables(t, "history", "output"))
    for (const auto& h : *hs) {
      const auto& ht = *h.as_table();
      c.allowed(ht, "output.history", {"name", "kind", "target", "component", "point", "scale"});
      const std::string kind = c.str(ht, "kind", "output.history");
      // kind "strain" names a point (the nearest element), the others a node set or tool.
      HistorySignal sig{c.name(ht, "output.history"), kind,
                        kind == "strain" ? std::string() : c.str(ht, "target", "output.history"),
                        c.count_of(ht, "component", "output.history", 0, 0)};
      if (kind == "strain") sig.point = c.vec(ht, "point", "output.history");
      // The point lies in the sheet: the strain is that of the element whose centre is nearest,
      // so a point far outside the mesh (a typing or unit error) wrote some edge element's
      // strain under its name with exit 0 (before 2026-12-05).
      if (kind == "strain" && mesh_ok && ht.get("point") &&
          std::isfinite(sig.point[0] + sig.point[1] + sig.point[2])) {
        double dist = 0, size = 0;
        const int e = fe::nearest_element(m.mesh, sig.point[0], sig.point[1], sig.point[2], &dist, &size);
        if (e >= 0 && dist > size)
          c.bad(*ht.get("point"), "output.history.point",
                "expected a point in the sheet, found [" + fmt_shortest(sig.point[0]) + ", " +
                    fmt_shortest(sig.point[1]) + ", " + fmt_shortest(sig.point[2]) + "], " + fmt(dist) +
                    " mm from the centre of the nearest element (element " + std::to_string(e) + ", " + fmt(size) +
                    " mm across)");
      }
      sig.scale = c.num(ht, "scale", "output.history", 1.0);
      if (!(std::isfinite(sig.scale) && sig.scale != 0))
        c.bad(ht, "output.history.scale", "expected a finite nonzero factor, found " + fmt_shortest(sig.scale));
      if (sig.kind != "reaction" && sig.kind != "applied" && sig.kind != "tool_force" && sig.kind != "tool_offset" &&
          sig.kind != "displacement" && sig.kind != "strain")
        c.bad(ht, "output.history.kind",
              "expected reaction, applied, displacement, strain, tool_force or tool_offset, found \"" + sig.kind + "\"");
      if (sig.component > 2) c.bad(ht, "output.history.component", "expected 0, 1 or 2, found " + std::to_string(sig.component));
      // The target exists (an unknown node set wrote a column of zeros with exit 0; an
      // unknown tool ended the run with "no tool named", without the deck's line).
      if (const auto* target = ht.get("target"); target && kind != "strain") {
        if (sig.kind == "tool_force" || sig.kind == "tool_offset") {
          bool found = false;
          for (const auto& tool : m.tools) found = found || tool.name == sig.target;
          if (!found) c.bad(*target, "output.history.target", "expected the name of a [[tool]], found '" + sig.target + "'");
        } else if (mesh_ok && !m.mesh.node_sets.count(sig.target)) {
          std::string sets;
          for (const auto& [name, nodes] : m.mesh.node_sets) sets += (sets.empty() ? "" : ", ") + name;
          c.bad(*target, "output.history.target", "expected a node set (" + sets + "), found '" + sig.target + "'");
        }
      }
      // Each name is a column of history.csv: unique, and none of the run's own
      // columns (a name twice ended the run with exit 3 from the CSV writer).
      const auto own = run_output::run_history_columns();
      for (const auto& o : out.history)
        if (!sig.name.empty() && o.name == sig.name)
          c.bad(*ht.get("name"), "output.history.name", "expected a unique column name, found '" + sig.name + "' twice");
      if (std::find(own.begin(), own.end(), sig.name) != own.end())
        c.bad(*ht.get("name"), "output.history.name", "'" + sig.name + "' is a column every run writes; choose another name");
      out.history.push_back(sig);
    }
}

/// The reduction's step, tool and holder exist, said at their lines (before
/// 2026-12-05 "output.reduce.step: no step named" without the deck's line, and an
/// unknown holder passed `plan` and `cup-deck --base` and stopped `run`).
void check_reduction_names(const DeckContext& c, const toml::table& root, const ReductionSpec& r,
                           const fe::Model& m) {
  const toml::table* rt = nullptr;
  if (const auto* o = root.get_as<toml::table>("output")) rt = o->get_as<toml::table>("reduce");
  if (!rt) return check_reduction(r, m);
  const auto at = [&](const char* key) -> const toml::node& { return rt->get(key) ? *rt->get(key) : *rt; };
  std::string steps, tools, contact_tools;
  bool step = false, contact = false, holder = false;
  for (const auto& s : m.steps) steps += (steps.empty() ? "" : ", ") + s.name, step = step || s.name == r.step;
  for (const auto& t : m.tools) tools += (tools.empty() ? "" : ", ") + t.name, holder = holder || t.name == r.holder;
  for (const auto& p : m.contacts) {
    if (contact_tools.find("'" + p.tool + "'") == std::string::npos)
      contact_tools += (contact_tools.empty() ? "'" : ", '") + p.tool + "'";
    contact = contact || p.tool == r.tool;
  }
  if (!step) c.bad(at("step"), "output.reduce.step", "expected the name of a [[step]] (" + steps + "), found '" + r.step + "'");
  if (!contact)
    c.bad(at("tool"), "output.reduce.tool",
          "expected a tool with a [[contact]] (" + (contact_tools.empty() ? "none here" : contact_tools) + "), found '" +
              r.tool + "'");
  if ((r.kind == "cup_draw" || rt->get("holder")) && !holder)
    c.bad(at("holder"), "output.reduce.holder",
          "expected the name of a [[tool]] (" + tools + "), found '" + r.holder + "'" +
              (r.holder.empty() && !rt->get("holder") ? " (kind cup_draw reads the blank holder's force)" : ""));
}

}  // namespace

Deck read_deck(const std::string& path) { return parse_deck(read_file(path), path); }

Deck parse_deck(const std::string& text_in, const std::string& path) {
  // A UTF-8 byte-order mark, as editors on Windows write it, is not part of the TOML.
  const bool bom = text_in.rfind("\xEF\xBB\xBF", 0) == 0;
  const std::string& text = bom ? text_in.substr(3) : text_in;
  const toml::table root = parse_toml(text, path);
  InputProblems problems(path);
  const DeckContext c(path, problems);
  c.allowed(root, "deck", {"case", "mesh", "material", "sheet", "numerics", "guards", "tool", "contact", "step",
                           "output", "limits"});
  Deck d;
  d.path = path;
  d.hash = fnv1a64(text);
  fe::Model& m = d.model;
  const std::string dir = std::filesystem::path(path).parent_path().string();
  problems.attempt([&] {
    if (const auto* cs = c.table(root, "case", "deck", false)) {
      c.allowed(*cs, "case", {"name", "description"});
      m.name = c.name(*cs, "case", std::string("case"), true);
      c.str(*cs, "description", "case", std::string());
    }
  });
  // Sections that refer to node and face sets check them only if the mesh was read.
  bool mesh_ok = false;
  problems.attempt([&] { read_limits(c, root, d.limits); });
  problems.attempt([&] {
    const toml::table& mt = *c.table(root, "mesh", "deck", true);
    if (auto mesh = read_mesh(c, mt, d.limits)) {
      m.mesh = std::move(*mesh);
      mesh_ok = check_memory(c, mt, "mesh", m.mesh.num_nodes(), m.mesh.num_elements(), d.limits);
    }
  });
  problems.attempt([&] { m.material = make_material(c, *c.table(root, "material", "deck", true), dir, &d.cost.material); });
  problems.attempt([&] {
    if (const auto* t = c.table(root, "numerics", "deck", false)) read_numerics(c, *t, d);
  });
  problems.attempt([&] {
    if (const auto* t = c.table(root, "guards", "deck", false)) read_guards(c, *t, m.guards);
  });
  // The sheet frame, stated once: friction texture and material axes both use it.
  bool sheet_rd = false;
  problems.attempt([&] {
    if (const auto* t = c.table(root, "sheet", "deck", false)) {
      c.allowed(*t, "sheet", {"rolling_direction"});
      m.rolling_direction = c.vec(*t, "rolling_direction", "sheet", fe::Vec3{1, 0, 0}, true);
      sheet_rd = t->get("rolling_direction") != nullptr;
    }
  });
  read_tools(c, root, m);
  read_contacts(c, root, m, dir, mesh_ok, sheet_rd);
  read_steps(c, root, m, mesh_ok);
  problems.attempt([&] {
    if (const auto* t = c.table(root, "output", "deck", false)) read_output(c, *t, d.output, m, mesh_ok);
  });
  if (problems.empty())
    problems.attempt([&] { m.validate(); });
  if (problems.empty() && !d.output.reduce.kind.empty())  // its tool and step exist
    problems.attempt([&] { check_reduction_names(c, root, d.output.reduce, m); });
  if (problems.empty()) problems.attempt([&] { check_initial_overlap(c, root, m); });
  if (problems.empty()) {
    problems.attempt([&] { check_cost(c, root, d); });
    if (const auto* mt = root.get_as<toml::table>("material")) material_warnings(c, *mt, d.warnings);
    mesh_warnings(c, root, d);
    drawbend_step_warning(c, root, d);
  }
  problems.throw_if_any();
  return d;
}

}  // namespace drawbend::io
