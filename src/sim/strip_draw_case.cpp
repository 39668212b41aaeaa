// The strip-draw builder: deck text, run, reduction.  See strip_draw_case.hpp.
#include "sim/strip_draw_case.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fe/contact_springs.hpp"
#include "fe/solver.hpp"
#include "sim/case_pool.hpp"
#include "sim/deck_writer.hpp"
#include "sim/material_choice.hpp"

namespace drawbend::sim {

StripDrawSpec default_strip_draw_spec(const std::string& data_dir) {
  StripDrawSpec s;
  s.hardening = data_dir + "/materials/aa5754_o_rd.csv";
  s.stribeck_table = data_dir + "/thesis/table_3_1.csv";
  return s;
}

double strip_draw_time_step(double v) { return v < 4.0 ? 1e-5 : (v > 40.0 ? 5e-7 : 2.5e-6); }

double strip_draw_duration(const StripDrawSpec& s) {
  return s.speed_ramp + std::max(s.slide / s.speed, 2.0 * s.speed_ramp);
}

namespace {

void check_spec(const StripDrawSpec& s) {
  const std::string w = "strip-draw spec: ";
  require_positive(s.length, w + "length [mm]");
  require_positive(s.width, w + "width [mm]");
  require_positive(s.thickness, w + "thickness [mm]");
  require_positive(s.pressure, w + "pressure [MPa]");
  require_positive(s.speed, w + "speed [mm/s]");
  require_positive(s.slide, w + "slide [mm]");
  require_positive(s.speed_ramp, w + "speed_ramp [s]");
  require_positive(s.force_ramp, w + "force_ramp [s]");
  require_positive(s.press_time, w + "press_time [s]");
  if (!(s.press_damping >= 0)) throw InputError(w + "press_damping [1/s] must be >= 0, found " + fmt(s.press_damping));
  if (!(s.time_step >= 0)) throw InputError(w + "time_step [s] must be >= 0 (0: by speed), found " + fmt(s.time_step));
  if (!(s.die_mass >= 0)) throw InputError(w + "die_mass [t] must be >= 0 (0: from the contact stiffness), found " + fmt(s.die_mass));
  if (s.nx < 1 || s.ny < 1 || s.nz < 1) throw InputError(w + "nx, ny and nz must be >= 1");
  if (s.interval < 1) throw InputError(w + "interval [cycles] must be >= 1, found " + std::to_string(s.interval));
  if (s.force_ramp > s.press_time) throw InputError(w + "force_ramp must not be longer than press_time");
  if (s.hardening.empty()) throw InputError(w + "no hardening curve");
  if (s.friction.empty() && s.stribeck_table.empty()) throw InputError(w + "no friction law and no Stribeck table");
}

std::string text(const StripDrawSpec& s, double dt, double die_mass) {
  const double area = s.length * s.width, FN = s.pressure * area;
  const std::string friction = s.friction.empty() ? "{ law = \"stribeck\", table = \"" + s.stribeck_table +
                                                        "\", interval = " + std::to_string(s.interval) + " }"
                                                  : s.friction;
  std::ostringstream o;
  o << "# Strip-draw friction test written by drawbend's builder (src/sim/strip_draw_case.cpp; Sec. 3.3, Fig. 3.2):\n"
    << "# a " << fmt(s.thickness) << " mm strip section pressed by a force-driven flat die at " << fmt(s.pressure)
    << " MPa (" << fmt(FN) << " N) and drawn at " << fmt(s.speed) << " mm/s; mu = (F1 - F2) / F_N.\n"
    << "# Units: mm, N, MPa, s, t/mm^3.  Run with: drawbend run deck.toml --out DIR\n"
    << "[case]\nname = \"" << s.name << "\"\ndescription = \"strip draw, " << fmt(s.pressure) << " MPa, "
    << fmt(s.speed) << " mm/s\"\n\n"
    << "[mesh]\nx = { from = 0.0, to = " << toml_float(s.length) << ", n = " << s.nx << " }\n"
    << "y = { from = 0.0, to = " << toml_float(s.width) << ", n = " << s.ny << " }\n"
    << "z = { from = 0.0, to = " << toml_float(s.thickness) << ", n = " << s.nz << " }\n\n"
    << material_section("", s.hardening) << "\n"
    << "[numerics]\ndt_safety = 0.8\ntarget_dt = " << toml_float(dt) << "\n\n"
    << "[guards]\n"
    << "# The strip slides nearly rigidly, so its internal energy stays tiny (0.01 mJ)\n"
    << "# and the hourglass energy reaches tens of times that in the slow cases (26x at\n"
    << "# 4 mm/s).  The ratio to the internal energy is not meaningful here; the guard\n"
    << "# warns instead of stopping (measured mu is unaffected; see Chapter 3).\n"
    << "hourglass_ratio = { limit = 0.5, action = \"warn\" }\n"
    << "# The same hourglass energy is not matched by work done on the strip: at\n"
    << "# 4 mm/s the balance misses by 12 % of the frictional dissipation (0.25 of\n"
    << "# 2.1 mJ).  Open question (issue 7 report); it warns until it is understood.\n"
    << "energy_balance = { limit = 0.1, action = \"warn\" }\n\n"
    << "# The die is a rigid mass on its contact springs (stiffness k = sum of penalty K A_i / L_i\n"
    << "# over its contact nodes, fe/contact_springs.hpp): mass 4 k dt^2 puts it at omega dt = 0.5.\n"
    << "[[tool]]\nname = \"die\"\ndrive = \"force\"\ndirection = [0.0, 0.0, -1.0]\nforce = "
    << toml_ramp(s.force_ramp, FN) << "\nmass = " << toml_float(die_mass) << "\n"
    << "[[tool.surface]]\nkind = \"plane\"\norigin = [0.0, 0.0, " << toml_float(s.thickness)
    << "]\nnormal = [0.0, 0.0, -1.0]\n\n"
    << "[[tool]]\nname = \"support\"\ndrive = \"fixed\"\n[[tool.surface]]\nkind = \"plane\"\n"
    << "origin = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n\n"
    << "[[contact]]\nfaces = \"zmax\"\ntool = \"die\"\nfriction = " << friction << "\n\n"
    << "[[contact]]\nfaces = \"zmin\"\ntool = \"support\"\n\n"
    << "[[step]]\nname = \"press\"\nduration = " << toml_float(s.press_time) << "\ndamping = "
    << toml_float(s.press_damping) << "\n"
    << "fixed = [ { set = \"xmin\", dof = [true, false, false] }, { set = \"ymin\", dof = [false, true, false] } ]\n\n"
    << "[[step]]\nname = \"draw\"\nduration = " << toml_float(strip_draw_duration(s)) << "\n"
    << "fixed = [ { set = \"ymin\", dof = [false, true, false] } ]\nvelocity = [\n";
  for (const char* end : {"xmin", "xmax"})
    o << "  { set = \"" << end << "\", direction = [1.0, 0.0, 0.0], speed = " << toml_ramp(s.speed_ramp, s.speed) << " },\n";
  o << "]\n\n[output]\nhistory = [\n"
    << "  { name = \"die_tangential_N\", kind = \"tool_force\", target = \"die\", component = 0 },\n"
    << "  { name = \"die_normal_N\", kind = \"tool_force\", target = \"die\", component = 2 },\n]\n";
  return o.str();
}

}  // namespace

std::string strip_draw_deck_text(const StripDrawSpec& s) {
  check_spec(s);
  const double dt = s.time_step > 0 ? s.time_step : strip_draw_time_step(s.speed);
  if (s.die_mass > 0) return text(s, dt, s.die_mass);
  // The mass needs the material's bulk modulus and the mesh: read them from the deck itself.
  const io::Deck first = io::parse_deck(text(s, dt, 1.0), s.name + ".toml");
  return text(s, dt, fe::tool_mass_half_omega_dt(fe::tool_contact_stiffness(first.model, "die"), dt));
}

io::Deck strip_draw_deck(const StripDrawSpec& s) {
  return io::parse_deck(strip_draw_deck_text(s), s.name + ".toml");
}

StripDrawResult run_strip_draw(const StripDrawSpec& spec) {
  io::Deck deck = strip_draw_deck(spec);
  fe::Model& m = deck.model;
  const double ramp = spec.speed_ramp, duration = m.steps.at(1).duration;
  const auto [xmin, xmax] = std::minmax_element(m.mesh.x.begin(), m.mesh.x.end());
  const auto [ymin, ymax] = std::minmax_element(m.mesh.y.begin(), m.mesh.y.end());
  fe::Solver s(m);
  s.run_step(0);
  // Probe: the contact node nearest the centre of the die.
  int pair = -1;
  for (std::size_t k = 0; k < m.contacts.size(); ++k)
    if (m.contacts[k].tool == "die") pair = static_cast<int>(k);
  const double cx = 0.5 * (*xmin + *xmax), cy = 0.5 * (*ymin + *ymax);
  int probe = 0;
  double best = 1e30;
  const auto& nodes = s.contact_nodes(pair);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const double dd = std::hypot(s.x()[nodes[k].node] - cx, s.y()[nodes[k].node] - cy);
    if (dd < best) {
      best = dd;
      probe = static_cast<int>(k);
    }
  }
  StripDrawResult r;
  double sft = 0, sfn = 0, sv = 0, sv2 = 0;
  long n = 0;
  r.v_min = 1e30;
  r.v_max = -1e30;
  const double t0 = s.time();
  s.run_step(1, [&](const fe::Progress& pr) {
    const double vs = s.contact_nodes(pair)[probe].slip_speed;
    if (pr.cycle % 20 == 0) r.trace.push_back({pr.time - t0, vs});
    if (pr.step_time < ramp) r.ramp_v_max = std::max(r.ramp_v_max, vs);
    if (pr.step_time < duration * 2.0 / 3.0) return;
    const auto F = s.tool_force("die");
    sft += std::abs(F[0]);  // mu = mean F_t / mean F_n over the last third
    sfn += std::abs(F[2]);
    sv += vs;
    sv2 += vs * vs;
    r.v_min = std::min(r.v_min, vs);
    r.v_max = std::max(r.v_max, vs);
    ++n;
  });
  r.mu = sfn > 0 ? sft / sfn : NAN;
  r.v_mean = sv / n;
  r.v_std = std::sqrt(std::max(0.0, sv2 / n - r.v_mean * r.v_mean));
  double pmin = 1e30, pmax = 0, psum = 0;
  for (const auto& c : s.contact_nodes(pair)) {
    r.die_map[{m.mesh.x[c.node], m.mesh.y[c.node]}] = c.pressure;
    pmin = std::min(pmin, c.pressure);
    pmax = std::max(pmax, c.pressure);
    psum += c.pressure;
  }
  r.p_mean = psum / s.contact_nodes(pair).size();
  r.p_spread = (pmax - pmin) / spec.pressure;
  r.cycles = s.cycles();
  return r;
}

std::vector<StripDrawResult> run_strip_draws(const std::vector<StripDrawSpec>& specs) {
  std::vector<StripDrawResult> out(specs.size());
  run_cases(specs.size(), [&](std::size_t k) { out[k] = run_strip_draw(specs[k]); });
  return out;
}

}  // namespace drawbend::sim
