// The answer of a run in <out>/result.toml.  See run_result.hpp.
#include "io/run_result.hpp"
#include "core/install_paths.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "analysis/rope.hpp"
#include "core/quote.hpp"
#include "core/run_output.hpp"
#include "friction/surface_law.hpp"
#include "io/deck_limits.hpp"

namespace drawbend::io {

namespace fs = std::filesystem;
using run_output::Signal;
using run_output::signal_name;

namespace {

/// The 0.2 % yield stress of Table 5.1's RD row [MPa] (Swift's estimate of F_B).
double table_5_1_yield_rd() {
  const CsvTable t = read_csv(drawbend::data_dir() + "/thesis/table_5_1.csv");
  return t.number(t.rows.front(), "YS02_MPa");
}

/// A TOML basic string (core/quote.hpp).
std::string q(const std::string& s) { return string_literal(s); }

/// A TOML float (nan for NaN, which TOML allows).
std::string num(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::string t = fmt(v, 10);
  if (t.find_first_of(".en") == std::string::npos) t += ".0";
  return t;
}

double pin_radius(const fe::Model& m, int pair) {
  for (const auto& t : m.tools)
    if (t.name == m.contacts[pair].tool)
      for (const auto& sf : t.surfaces)
        if (sf.kind == contact::Surface::Kind::cylinder) return sf.R;
  return 0;
}

double extent(const std::vector<double>& v) {
  if (v.empty()) return 0;
  const auto [a, b] = std::minmax_element(v.begin(), v.end());
  return *b - *a;
}

}  // namespace

DrawForces draw_forces(const CsvTable& h) {
  DrawForces f;
  std::vector<double> t, fy;
  for (const auto& row : h.rows)
    if (h.text(row, signal_name(Signal::step)) == "draw") {
      t.push_back(h.number(row, signal_name(Signal::time)));
      fy.push_back(-h.number(row, signal_name(Signal::outlet_force)));  // the outlet grip pulls along -z
      f.F_back = -h.number(row, signal_name(Signal::back_tension));
    }
  f.samples = t.size();
  if (t.size() < 12) throw InputError(h.path + ": too few draw-step samples (" + std::to_string(t.size()) + " < 12)");
  // Chapters 3-4: mean of the last third of the draw step.
  const std::size_t n = t.size(), i3 = n - n / 3;
  double s = 0, s2 = 0;
  for (std::size_t i = i3; i < n; ++i) s += fy[i];
  f.F_out = s / static_cast<double>(n - i3);
  for (std::size_t i = i3; i < n; ++i) s2 += (fy[i] - f.F_out) * (fy[i] - f.F_out);
  f.F_out_std = std::sqrt(s2 / static_cast<double>(n - i3));
  // Chapter 2: linear regression of the last 25 %, read at the end of the step.
  const std::size_t i4 = n - n / 4;
  double st = 0, sf = 0, stt = 0, stf = 0;
  const double m = static_cast<double>(n - i4);
  for (std::size_t i = i4; i < n; ++i) st += t[i], sf += fy[i], stt += t[i] * t[i], stf += t[i] * fy[i];
  const double slope = (m * stf - st * sf) / (m * stt - st * st);
  f.F_out_regression = sf / m + slope * (t.back() - st / m);
  return f;
}

bool is_drawbend_deck(const Deck& deck) {
  if (!has_signal(deck, Signal::outlet_force) || !has_signal(deck, Signal::back_tension)) return false;
  for (const auto& s : deck.model.steps)
    if (s.name == "draw") return pin_pair(deck.model) >= 0;
  return false;
}

double full_strip_factor(const fe::Model& m) {
  if (m.steps.empty()) return 1;
  for (const auto& s : m.steps) {
    bool sym = false;
    for (const auto& f : s.fixed) sym = sym || (f.set == "ymin" && f.dof[1]);
    if (!sym) return 1;
  }
  return 2;
}

std::vector<std::string> history_notes(const Deck& deck) {
  const double k = full_strip_factor(deck.model);
  std::vector<std::string> out;
  out.push_back(k == 2 ? "basis: the model is the half strip (set ymin held in y: symmetry plane y = 0); every force "
                         "column is on the half model unless its name ends in _full_strip_N (x 2)"
                       : "basis: the model is the whole strip; forces are as modelled");
  out.push_back("signs: global axes; reaction = force of the support on the node set, applied = the load applied, "
                "tool_force = force of the sheet on the tool; *_full_strip_N columns are tension-positive");
  for (const auto& h : deck.output.history)
    if (h.kind != "strain" && h.kind != "displacement" && h.kind != "tool_offset")
      out.push_back(h.name + ": " + h.kind + " on " + h.target + ", component " + "xyz"[h.component] +
                    (h.scale != 1 ? ", times " + fmt_shortest(h.scale) : std::string()) + " [N]");
  if (is_drawbend_deck(deck))
    out.push_back("draw-bend: F_Y = -" + std::string(signal_name(Signal::outlet_force)) + ", F_X = -" +
                  signal_name(Signal::back_tension) + " (tension positive), x " + fmt_shortest(k) +
                  " for the full strip; result.toml holds F_X, F_Y, F_B and mu");
  return out;
}

DrawBendAnswer drawbend_answer(const Deck& deck, const fe::Solver& s, const CsvTable& history,
                               const ResultOptions& opt) {
  const fe::Model& m = deck.model;
  DrawBendAnswer a;
  a.factor = full_strip_factor(m);
  const int pair = pin_pair(m);
  const DrawForces f = draw_forces(history);
  a.F_X = f.F_back;
  a.F_Y = f.F_out;
  a.F_Y_std = f.F_out_std;
  a.pin_radius = pin_radius(m, pair);
  a.full_width = a.factor * extent(m.mesh.y);
  a.thickness = extent(m.mesh.z);  // the builder's through-thickness axis
  a.frictionless = m.contacts[pair].friction == nullptr;
  double pa = 0, area = 0;
  for (const auto& c : s.contact_nodes(pair))
    if (c.pressure > 0) pa += c.pressure * c.area, area += c.area;
  a.mean_pressure = area > 0 ? pa / area : 0.0;
  const auto half = analysis::ForceBasis::half_model;
  // Eq. (2.2) on the model's width: the model's forces over its own width.
  a.eq22_pressure = analysis::average_pressure(a.factor * a.F_X, a.factor * a.F_Y, a.pin_radius, a.full_width,
                                               analysis::ForceBasis::full_strip);
  const double theta = M_PI / 2;
  if (opt.bending_force > 0) {
    a.F_B = opt.bending_force / (opt.basis == "full" ? a.factor : 1.0);
    a.F_B_source = "given (--bending-force " + fmt(opt.bending_force, 6) + " N on the " +
                   (opt.basis == "full" ? "full strip" : "half model") + ")";
  } else if (a.frictionless) {
    a.F_B = a.F_Y - a.F_X;
    a.F_B_source = "frictionless run: F_Y - F_X of this run";
  } else {
    const double ys = opt.yield_stress > 0 ? opt.yield_stress : table_5_1_yield_rd();
    a.F_B = analysis::swift_bending_force(ys, a.thickness, a.full_width, a.pin_radius, theta,
                                          a.factor == 2 ? half : analysis::ForceBasis::full_strip);
    a.F_B_source = "Swift's estimate, Eq. (2.1), yield stress " + fmt(ys, 4) + " MPa" +
                   (opt.yield_stress > 0 ? "" : " (Table 5.1, RD)") + "; a frictionless run gives a better one";
  }
  if (a.frictionless) {
    a.mu = 0;
  } else {
    try {
      a.mu = analysis::mu_rope(a.F_X, a.F_Y, a.F_B, theta);
    } catch (const std::domain_error& e) {
      a.mu = NAN;
      a.mu_note = std::string(e.what()) + "; F_B is too large for these forces";
    }
  }
  return a;
}

void print_drawbend_answer(const DrawBendAnswer& a, const std::string& basis, std::ostream& out) {
  const bool full = basis == "full";
  const double k = full ? a.factor : 1.0;
  const std::string tag = full ? "full strip" : "half model";
  const double FX = k * a.F_X, FY = k * a.F_Y;
  out << "forces on the " << tag << " (the model is the " << (a.factor == 2 ? "half strip" : "whole strip")
      << (full && a.factor == 2 ? ", doubled" : "") << "):\n"
      << "  F_X = " << fmt(FX, 6) << " N, F_Y = " << fmt(FY, 6) << " N (last third of the draw; std "
      << fmt(k * a.F_Y_std, 3) << " N), F_Y - F_X = " << fmt(FY - FX, 5) << " N\n"
      << "  mean contact pressure " << fmt(a.mean_pressure, 4) << " MPa; Eq. (2.2) P = " << fmt(a.eq22_pressure, 4)
      << " MPa\n";
  if (a.frictionless) {
    out << "  frictionless pin: the bending force F_B = F_Y - F_X = " << fmt(FY - FX, 5)
        << " N (pass it as --bending-force to a run with friction)\n";
    return;
  }
  out << "  F_B = " << fmt(k * a.F_B, 5) << " N (" << a.F_B_source << ")\n"
      << "  friction force F_Y - F_X - F_B = " << fmt(FY - FX - k * a.F_B, 5) << " N\n";
  if (std::isnan(a.mu)) out << "  mu by Eq. (2.3): not defined (" << a.mu_note << ")\n";
  else out << "  mu by Eq. (2.3) = " << fmt(a.mu, 4) << " (90 deg wrap)\n";
}

void write_run_result(const Deck& deck, const fe::Solver& s, const std::string& out_dir, const ResultOptions& opt,
                      std::ostream& log) {
  const fe::Model& m = deck.model;
  std::ostringstream o;
  o << "# The answer of this run (src/io/run_result.hpp).  Units: N, MPa, mm, s.\n"
    << "[run]\ncase = " << q(m.name) << "\ndeck = " << q(deck.path) << "\ntime_s = " << num(s.time())
    << "\ncycles = " << s.cycles() << "\n";
  // Friction laws: clamp counts and the contact area outside a tabulated law's domain at the end.
  for (int p = 0; p < s.num_contact_pairs(); ++p) {
    const auto& law = m.contacts[p].friction;
    o << "\n[[contact]]\npair = " << p << "\ntool = " << q(m.contacts[p].tool) << "\nfaces = " << q(m.contacts[p].faces)
      << "\nfriction = " << q(law ? law->describe() : "frictionless") << "\n";
    if (!law) continue;
    double evals = 0, clamped = 0;
    for (const auto& [name, n] : law->counters(s.friction_state(p))) {
      o << name << " = " << num(n) << "\n";
      if (name.size() >= 11 && name.compare(name.size() - 11, 11, "evaluations") == 0) evals = n;
      if (name.rfind("clamped", 0) == 0) clamped += n;
    }
    if (evals > 0) o << "clamped_share_of_evaluations = " << num(clamped / evals) << "\n";
    if (const auto* sl = dynamic_cast<const friction::SurfaceLaw*>(law.get())) {
      const auto& d = sl->rd();
      double area = 0, p_out = 0, v_out = 0;
      for (const auto& c : s.contact_nodes(p)) {
        if (!(c.pressure > 0)) continue;
        area += c.area;
        if (c.pressure < d.p_min || c.pressure > d.p_max) p_out += c.area;
        if (c.slip_speed < d.v_min || c.slip_speed > d.v_max) v_out += c.area;
      }
      o << "domain_pressure_MPa = [" << num(d.p_min) << ", " << num(d.p_max) << "]\ndomain_speed_mm_s = ["
        << num(d.v_min) << ", " << num(d.v_max) << "]\ncontact_area_end_mm2 = " << num(area)
        << "\narea_share_pressure_outside_domain = " << num(area > 0 ? p_out / area : 0.0)
        << "\narea_share_speed_outside_domain = " << num(area > 0 ? v_out / area : 0.0) << "\n";
      if (area > 0 && p_out > 0)
        log << "  warning: contact " << p << " (" << m.contacts[p].tool << "): " << fmt(100 * p_out / area, 3)
            << " % of the contact area at the end has a pressure outside the law's domain " << fmt(d.p_min, 4) << "-"
            << fmt(d.p_max, 4) << " MPa (friction taken at the domain edge)\n";
    }
  }
  std::optional<DrawBendAnswer> ans;
  if (is_drawbend_deck(deck)) {
    try {
      ans = drawbend_answer(deck, s, read_csv((fs::path(out_dir) / run_output::kHistoryFile).string()), opt);
    } catch (const InputError& e) {  // e.g. a draw step too short to average: the run itself is complete
      o << "\n# no draw-bend answer: " << e.what() << "\n";
      log << "  no draw-bend answer: " << e.what() << "\n";
    }
  }
  if (ans) {
    const DrawBendAnswer& a = *ans;
    o << "\n# Draw-bend forces: tension positive; the last third of the draw step (F_Y); 90 deg wrap.\n"
      << "[drawbend]\nmodel = " << q(a.factor == 2 ? "half strip (symmetry plane y = 0)" : "whole strip")
      << "\nfull_strip_factor = " << num(a.factor) << "\npin_radius_mm = " << num(a.pin_radius)
      << "\nstrip_width_mm = " << num(a.full_width) << "\nthickness_mm = " << num(a.thickness)
      << "\nF_B_source = " << q(a.F_B_source) << "\nmu_eq_2_3 = " << num(a.mu)
      << (a.mu_note.empty() ? "" : "\nmu_note = " + q(a.mu_note)) << "\nmean_contact_pressure_MPa = "
      << num(a.mean_pressure) << "\neq_2_2_pressure_MPa = " << num(a.eq22_pressure) << "\n";
    for (int b = 0; b < 2; ++b) {
      const double k = b == 0 ? a.factor : 1.0;
      o << "\n[drawbend." << (b == 0 ? "full_strip" : "half_model") << "]\nF_X_N = " << num(k * a.F_X)
        << "\nF_Y_N = " << num(k * a.F_Y) << "\nF_Y_std_N = " << num(k * a.F_Y_std)
        << "\nF_Y_minus_F_X_N = " << num(k * (a.F_Y - a.F_X)) << "\nF_B_N = " << num(k * a.F_B)
        << "\nfriction_force_N = " << num(a.frictionless ? 0.0 : k * (a.F_Y - a.F_X - a.F_B)) << "\n";
    }
    print_drawbend_answer(a, opt.basis, log);
  }
  write_file_atomic((fs::path(out_dir) / kResultFile).string(), o.str());
  log << "result: " << (fs::path(out_dir) / kResultFile).string() << "\n";
}

}  // namespace drawbend::io
