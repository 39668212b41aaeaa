// The up-front cost of a deck and the plausibility warnings; see deck_limits.hpp.
#include "io/deck_limits.hpp"

#include "fe/contact_springs.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>
#include <cmath>

#include "core/csv.hpp"
#include "fe/hex8.hpp"
#include "fe/mesh.hpp"

namespace drawbend::io {

namespace {

// Memory of a run per node and per element [bytes]: fe::Mesh, fe::Solver and
// Solver::run_step hold about 30 doubles per node (reference and current
// positions, velocity, force, mass, reactions, the step's scratch arrays) and
// about 60 per element (connectivity, two integration points' stresses and
// states, hourglass state, corner forces, per-element step data); the
// snapshot writers add text buffers.  Calibrated on the peak resident memory
// of `drawbend run` on a 60 x 60 x 60 J2 block (226,981 nodes, 216,000
// elements, one snapshot): 223 MB measured (GNU time, 2026-11-24), 226 MB
// predicted.
constexpr double kBytesPerNode = 350;
constexpr double kBytesPerElement = 680;
// Output written by a run [bytes]: a history.csv cell is a number of up to 10
// significant digits and its comma (11.7 bytes per cell measured on the block
// deck's history, 403 rows x 13 columns, 61,222 bytes, 2026-12-01; 14 taken
// for signs and exponents); a .vtu field frame holds about 300 bytes per node
// and 300 per element (56,744 bytes for the 125 nodes and 64 elements of that
// block's frames: 300 x 189 = 56,700).  history.csv has 10 columns of its own
// (time, step, dt, energies, balance) plus one per [output] history signal.
constexpr double kBytesPerHistoryCell = 14;
constexpr double kVtuBytesPerNode = 300;
constexpr double kVtuBytesPerElement = 300;
constexpr double kHistoryOwnColumns = 10;

const toml::node* at(const toml::table& root, const std::string& table, const std::string& key) {
  const auto* t = root.get(table);
  if (!t || !t->is_table()) return nullptr;
  return key.empty() ? t : t->as_table()->get(key);
}

double limit(const DeckContext& c, const toml::table& t, const std::string& key, double def) {
  const double v = c.num(t, key, "limits", def);
  if (std::isnan(v)) return def;  // recorded
  if (!(v > 0)) {
    c.bad(*t.get(key), "limits." + key, "expected a limit > 0, found " + fmt_shortest(v));
    return def;
  }
  return v;
}

}  // namespace

void read_limits(const DeckContext& c, const toml::table& root, RunLimits& lim) {
  const auto* t = c.table(root, "limits", "deck", false);
  if (!t) return;
  c.allowed(*t, "limits", {"max_cycles", "max_memory_mb", "max_mass_factor", "max_output_mb"});
  lim.max_cycles = limit(c, *t, "max_cycles", lim.max_cycles);
  lim.max_memory_mb = limit(c, *t, "max_memory_mb", lim.max_memory_mb);
  lim.max_mass_factor = limit(c, *t, "max_mass_factor", lim.max_mass_factor);
  lim.max_output_mb = limit(c, *t, "max_output_mb", lim.max_output_mb);
}

double estimate_memory_mb(double nodes, double elements) {
  return (kBytesPerNode * nodes + kBytesPerElement * elements) / 1e6;
}

bool check_memory(const DeckContext& c, const toml::node& where, const std::string& key, double nodes,
                  double elements, const RunLimits& lim) {
  const double mb = estimate_memory_mb(nodes, elements);
  if (mb <= lim.max_memory_mb) return true;
  c.bad(where, key,
        "the mesh of " + fmt(nodes, 4) + " nodes and " + fmt(elements, 4) + " elements would need about " +
            fmt(mb, 3) + " MB, above [limits] max_memory_mb = " + fmt_shortest(lim.max_memory_mb) +
            " (raise it in [limits] if the machine has the memory)");
  return false;
}

void check_cost(const DeckContext& c, const toml::table& root, Deck& d) {
  const fe::Model& m = d.model;
  if (!m.material || m.mesh.num_elements() == 0) return;
  const fe::Mesh& mesh = m.mesh;
  const double c_wave = m.material->wave_speed();
  double dt_min = INFINITY, phys = 0, scaled = 0;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    double ex[8], ey[8], ez[8];
    fe::gather(mesh.x, mesh.y, mesh.z, mesh.hex[e], ex, ey, ez);
    fe::HexGeometry g;
    if (!fe::hex_geometry(ex, ey, ez, g)) return;  // the solver reports the inverted element
    double factor = m.mass_scaling;
    const double dt_e = fe::hex_stable_length(g) / c_wave * std::sqrt(factor);
    double dt = m.dt_safety * dt_e;
    if (m.target_dt > 0 && dt < m.target_dt) {  // as fe::Solver scales it
      factor *= std::pow(m.target_dt / dt, 2);
      dt = m.target_dt;
    }
    const double me = m.material->density() * fe::hex_volume(ex, ey, ez);
    phys += me;
    scaled += me * factor;
    dt_min = std::min(dt_min, dt);
  }
  double total = 0;
  for (const auto& s : m.steps) total += s.duration;
  d.cost.memory_mb = estimate_memory_mb(mesh.num_nodes(), mesh.num_elements());
  d.cost.mass_factor = phys > 0 ? scaled / phys : 1;
  if (!(dt_min > 0) || !std::isfinite(dt_min)) return;  // a numerical fault of the solver, naming the element
  d.cost.stable_dt = dt_min;
  d.cost.cycles = total / dt_min;
  {  // the output: history rows (200 per step or one per history_interval, at most one per cycle) and field frames
    double rows = 0;
    for (const auto& s : m.steps)
      rows += d.output.history_interval > 0 ? s.duration / d.output.history_interval : 200.0;
    rows = std::min(rows, std::max(d.cost.cycles, 1.0));
    const double cols = kHistoryOwnColumns + static_cast<double>(d.output.history.size());
    const double history_mb = kBytesPerHistoryCell * rows * cols / 1e6;
    const double frames = 1.0 + static_cast<double>(m.steps.size()) * std::max(1, d.output.fields_per_step);
    const double fields_mb =
        frames * (kVtuBytesPerNode * mesh.num_nodes() + kVtuBytesPerElement * mesh.num_elements()) / 1e6;
    d.cost.output_mb = history_mb + fields_mb;
    if (d.cost.output_mb > d.limits.max_output_mb) {
      const toml::node* n = at(root, "output", "");
      c.bad(n ? *n : root, "output",
            "the run would write about " + fmt(d.cost.output_mb, 3) + " MB (history.csv " + fmt(history_mb, 3) +
                " MB: " + fmt(rows, 3) + " rows x " + fmt(cols, 3) + " columns; " + fmt(frames, 3) +
                " field frames " + fmt(fields_mb, 3) + " MB), above [limits] max_output_mb = " +
                fmt_shortest(d.limits.max_output_mb) + " (fewer history signals, a longer history_interval or "
                "fewer fields_per_step; or raise the limit)");
    }
  }
  const auto* numerics = at(root, "numerics", "");
  const auto* first_step = root.get("step") && root.get("step")->is_array() && !root.get("step")->as_array()->empty()
                               ? &(*root.get("step")->as_array())[0]
                               : static_cast<const toml::node*>(&root);
  // Mass scaling by a factor f slows the waves by sqrt(f): for the inertia it
  // is like loading sqrt(f) times faster.  The shipped cup deck scales by
  // 8e5 (Chapter 6; its refined mesh by about 3e6), the draw-bend decks by
  // 1e4, as the thesis.  Beyond 1e9 (over 30,000 times faster) inertia
  // dominates any forming speed: an error; above 1 % of the limit (1e7, over
  // 3,000 times faster) a warning.
  const double mf = d.cost.mass_factor;
  if (mf > 0.01 * d.limits.max_mass_factor) {
    const toml::node* n = at(root, "numerics", "target_dt");
    std::string key = "numerics.target_dt";
    if (!n || m.target_dt <= 0) n = at(root, "numerics", "mass_scaling"), key = "numerics.mass_scaling";
    if (!n) n = numerics ? numerics : &root, key = "numerics";
    const std::string what = "mass scaling multiplies the mass of the model by " + fmt(mf, 3) + " (added mass " +
                             fmt(100 * (mf - 1), 3) + " %)";
    if (mf > d.limits.max_mass_factor)
      c.bad(*n, key, what + ", above [limits] max_mass_factor = " + fmt_shortest(d.limits.max_mass_factor) +
                         ": inertia would dominate the result, as loading " + fmt(std::sqrt(mf), 2) +
                         " times faster would");
    else
      d.warnings.push_back(c.where(*n, key) + ": " + what + ", above 1 % of [limits] max_mass_factor = " +
                           fmt_shortest(d.limits.max_mass_factor) + ": inertia acts as if loaded " +
                           fmt(std::sqrt(mf), 2) + " times faster; check the kinetic energy");
  }
  // A force-driven tool rides on its contact springs: explicit integration is
  // stable for omega dt <= 2 dt_safety (fe::Solver::check_force_driven_tools,
  // which refused it at set-up, without the deck's line, after a builder had
  // written the deck: strip-deck --time-step 1e-12 sized its die at 8e-19 t).
  for (const auto& tool : m.tools) {
    if (tool.drive != fe::Tool::Drive::force || !(tool.mass > 0)) continue;
    const double k = fe::tool_contact_stiffness(m, tool.name);
    const double lim = 2.0 * m.dt_safety;
    if (k > 0 && std::sqrt(k / tool.mass) * dt_min > lim) {
      const toml::table* t = tool_table(root, tool.name);
      const toml::node* n = t && t->get("mass") ? t->get("mass") : t ? static_cast<const toml::node*>(t) : &root;
      c.bad(*n, "tool '" + tool.name + "'.mass",
            fmt(tool.mass, 4) + " t is too small for the stable time step " + fmt(dt_min, 4) +
                " s on its contact stiffness " + fmt(k, 4) + " N/mm; it needs at least " +
                fmt(k * (dt_min / lim) * (dt_min / lim), 4) + " t");
    }
  }
  if (d.cost.cycles > d.limits.max_cycles) {
    const toml::node* n = at(root, "limits", "max_cycles");
    std::string key = "limits.max_cycles";
    if (!n) n = at(root, "numerics", "dt_safety"), key = "numerics.dt_safety";
    if (!n) n = first_step, key = "step.duration";
    c.bad(*n, key,
          "the run would take about " + fmt(d.cost.cycles, 3) + " cycles (end time " + fmt(total, 4) +
              " s / stable step " + fmt(dt_min, 4) + " s), above [limits] max_cycles = " +
              fmt_shortest(d.limits.max_cycles) + " (raise it in [limits] if this is intended)");
  }
}

namespace {
std::uint64_t face_key(std::array<std::uint64_t, 4> n) {
  std::sort(n.begin(), n.end());
  std::uint64_t h = 1469598103934665603ull;
  for (std::uint64_t v : n) {
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 1099511628211ull;
  }
  return h;
}

/// Whether the sheet is one element thick under the contact face set `faces`:
/// every element with a face in the set has its opposite face on the mesh's
/// surface (a face of one element only), whatever the mesh kind.  Faces are
/// keyed by a 64-bit mix of their sorted node numbers, sorted and counted (two
/// faces share a key by chance with probability about n^2 / 2^64: none for
/// these sizes).  Elements one wide across the strip are not one thick: only
/// the direction through the contact face counts.
bool one_layer_under(const fe::Mesh& m, const std::vector<fe::Quad>& faces) {
  static constexpr int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}};
  auto key = [&](const std::array<int, 8>& e, int f) {
    std::array<std::uint64_t, 4> n{};
    for (int i = 0; i < 4; ++i) n[i] = static_cast<std::uint64_t>(e[kFaces[f][i]]);
    return face_key(n);
  };
  std::vector<std::uint64_t> keys, contact;
  keys.reserve(6 * m.hex.size());
  for (const auto& e : m.hex)
    for (int f = 0; f < 6; ++f) keys.push_back(key(e, f));
  std::sort(keys.begin(), keys.end());
  for (const auto& q : faces)
    contact.push_back(face_key({static_cast<std::uint64_t>(q[0]), static_cast<std::uint64_t>(q[1]),
                                static_cast<std::uint64_t>(q[2]), static_cast<std::uint64_t>(q[3])}));
  std::sort(contact.begin(), contact.end());
  auto on_surface = [&](std::uint64_t k) {
    const auto r = std::equal_range(keys.begin(), keys.end(), k);
    return r.second - r.first == 1;
  };
  bool any = false;
  for (const auto& e : m.hex)
    for (int f = 0; f < 6; ++f)
      if (std::binary_search(contact.begin(), contact.end(), key(e, f))) {
        any = true;
        if (!on_surface(key(e, f ^ 1))) return false;  // faces 2k and 2k+1 are opposite
      }
  return any;
}
}  // namespace

// The first contact pair on a tool with a cylinder surface (the pin); -1 if none.
int pin_pair(const fe::Model& m) {
  for (std::size_t p = 0; p < m.contacts.size(); ++p)
    for (const auto& t : m.tools)
      if (t.name == m.contacts[p].tool)
        for (const auto& sf : t.surfaces)
          if (sf.kind == contact::Surface::Kind::cylinder) return static_cast<int>(p);
  return -1;
}

bool has_signal(const Deck& d, run_output::Signal s) {
  for (const auto& h : d.output.history)
    if (h.name == run_output::signal_name(s)) return true;
  return false;
}

namespace {

std::string drawbend_step_missing(const Deck& deck) {
  if (!has_signal(deck, run_output::Signal::outlet_force) || !has_signal(deck, run_output::Signal::back_tension) ||
      pin_pair(deck.model) < 0)
    return "";
  std::string names;
  for (const auto& s : deck.model.steps) {
    if (s.name == "draw") return "";
    names += (names.empty() ? "'" : ", '") + s.name + "'";
  }
  return "the deck records outlet_force_N and back_tension_N over a pin, as a draw-bend case, but has no step "
         "named 'draw' (its steps: " + (names.empty() ? std::string("none") : names) +
         "): F_X, F_Y and mu are read from the step named 'draw', so result.toml gets no [drawbend] answer; "
         "name the drawing step 'draw' to have them";
}

}  // namespace

void drawbend_step_warning(const DeckContext& c, const toml::table& root, Deck& d) {
  if (const std::string w = drawbend_step_missing(d); !w.empty()) {
    const toml::node* n = root.get("step");
    d.warnings.push_back((n ? c.where(*n, "step") : c.path + ": step") + ": " + w);
  }
}

void mesh_warnings(const DeckContext& c, const toml::table& root, Deck& d) {
  const fe::Model& m = d.model;
  if (m.mesh.num_elements() > 2000000) return;
  for (const auto& cp : m.contacts) {
    const fe::Tool* tool = nullptr;
    for (const auto& t : m.tools)
      if (t.name == cp.tool) tool = &t;
    bool curved = false;
    for (const auto& s : tool ? tool->surfaces : std::vector<contact::Surface>{})
      curved = curved || s.kind != contact::Surface::Kind::plane;
    if (!curved || !m.mesh.face_sets.count(cp.faces) || !one_layer_under(m.mesh, m.mesh.face_set(cp.faces))) continue;
    // The draw-bend case (12.7 mm frictionless pin, the quick mesh): F_B = 298 N
    // with one element through the thickness, 343 N with 2 and 337 N with 4
    // (2026-12-01, issue 53): one element bends about 11 % too softly.
    const toml::node* n = root.get("mesh");
    d.warnings.push_back((n ? c.where(*n, "mesh") : c.path + ": mesh") +
                         ": one element through the thickness under the face set '" + cp.faces +
                         "', and the sheet bends over the curved surface of tool '" + cp.tool +
                         "': the bending force comes out about 11 % low (frictionless 12.7 mm pin: 298 N against "
                         "337 N with 4 elements); use 2 or more elements through the thickness (4 in the thesis's meshes)");
    return;  // once per deck
  }
}

}  // namespace drawbend::io
