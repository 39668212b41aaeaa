// Chapter 3, Sec. 3.3: the strip-draw verification of the Stribeck law in our
// solver, run from data/cases/strip_draw.toml with per-case overrides (die
// force = pressure x die area, drawing speed, durations, time step).
//   - Table 3.2 / Fig. 3.8: mu = (F1 - F2)/F_N at steady sliding against the
//     input curve, Eq. (3.2), for the five pressure/speed cases.
//   - Figs. 3.5-3.7 and the choice of update interval: the speed of a node
//     under the die with mu updated every cycle and every 10, 100, 1000 cycles.
#include <algorithm>
#include <cmath>

#include "analysis/stribeck.hpp"
#include "ch3_steps.hpp"
#include "fe/solver.hpp"
#include "friction/stribeck_law.hpp"
#include "io/deck.hpp"

namespace ch3 {

using namespace drawbend;

namespace {

struct DrawResult {
  double mu = 0, p_mean = 0, p_spread = 0;  ///< mu over the last third; pressure under the die [MPa]
  double v_mean = 0, v_std = 0, v_min = 0, v_max = 0;  ///< slip speed of the probe node over the last third [mm/s]
  long cycles = 0;
  std::vector<std::pair<double, double>> trace;  ///< (time in draw step, probe slip speed)
};

DrawResult draw(const std::string& deck_path, double p, double v, int interval) {
  io::Deck deck = io::read_deck(deck_path);
  fe::Model& m = deck.model;
  const auto [xmin, xmax] = std::minmax_element(m.mesh.x.begin(), m.mesh.x.end());
  const auto [ymin, ymax] = std::minmax_element(m.mesh.y.begin(), m.mesh.y.end());
  const double area = (*xmax - *xmin) * (*ymax - *ymin);  // the die covers the whole top face
  // Speed ramp 10 ms; the last third of the draw, where mu is read, starts after it.
  const double FN = p * area, slide = 0.4, ramp = 0.01;
  for (auto& t : m.tools)
    if (t.name == "die") t.force = {{0.0, 0.02}, {0.0, FN}};
  for (auto& cp : m.contacts)
    if (cp.tool == "die") {
      const auto* law = dynamic_cast<const friction::Stribeck*>(cp.friction.get());
      if (!law) throw InputError(deck_path + ": the die contact must use the Stribeck law");
      cp.friction = std::make_shared<friction::Stribeck>(law->params(), interval);
    }
  fe::Step& d = m.steps.at(1);
  d.duration = ramp + std::max(slide / v, 2.0 * ramp);
  for (auto& vb : d.velocities) vb.speed = {{0.0, ramp}, {0.0, v}};
  // Time step (and so mass scaling): seconds per case while the contact dynamics
  // settle; the fastest case needs less mass scaling, as in the thesis (Sec. 3.3.3:
  // case 5 ran with mass scaling 10 instead of 1000 "to avoid possible dynamic effects").
  m.target_dt = v < 4.0 ? 1e-5 : (v > 40.0 ? 5e-7 : 2.5e-6);
  // The force-driven die is a mass on the contact springs (total stiffness
  // k = alpha K A / L over its area): explicit integration needs omega dt < 2.
  // A mass giving omega dt = 0.5 is stable and settles quickly.
  double L = 1e30;
  for (double zz : m.mesh.z) L = std::min(L, zz > 0 ? zz : 1e30);  // thickness of the top layer
  for (auto& t : m.tools)
    if (t.name == "die") {
      double alpha = 0.1;
      for (const auto& cp : m.contacts)
        if (cp.tool == "die") alpha = cp.penalty;
      const double k = alpha * m.material->bulk_modulus() * area / L;
      t.mass = 4.0 * k * m.target_dt * m.target_dt;
    }
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
  DrawResult r;
  double sft = 0, sfn = 0, sv = 0, sv2 = 0;
  long n = 0;
  r.v_min = 1e30;
  r.v_max = -1e30;
  const double t0 = s.time();
  s.run_step(1, [&](const fe::Progress& pr) {
    const double vs = s.contact_nodes(pair)[probe].slip_speed;
    if (pr.cycle % 20 == 0) r.trace.push_back({pr.time - t0, vs});
    if (pr.step_time < d.duration * 2.0 / 3.0) return;
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
    pmin = std::min(pmin, c.pressure);
    pmax = std::max(pmax, c.pressure);
    psum += c.pressure;
  }
  r.p_mean = psum / s.contact_nodes(pair).size();
  r.p_spread = (pmax - pmin) / p;
  r.cycles = s.cycles();
  return r;
}

}  // namespace

void strip_draw(study::Chapter& c, const analysis::StribeckParams& s31, const CsvTable& t32) {
  const std::string deck = c.data("cases/strip_draw.toml");
  // Table 3.2 / Fig. 3.8.
  auto w = c.table({"case", "pressure_MPa", "velocity_mm_s", "L", "mu_input", "mu_simulated", "error_pct",
                    "pressure_spread_pct", "cycles"},
                   "Strip-draw verification of the Stribeck law (Table 3.2, Fig. 3.8); mu = (F1 - F2)/F_N");
  double worst = 0;
  for (const auto& row : t32.rows) {
    const double p = t32.number(row, "pressure_MPa"), v = t32.number(row, "velocity_mm_s");
    const DrawResult r = draw(deck, p, v, 100);
    const double L = analysis::lubricant_number(v, p, s31), mu_in = analysis::stribeck_mu(L, s31);
    const double err = (r.mu - mu_in) / mu_in;
    worst = std::max(worst, std::abs(err));
    const std::string id = t32.text(row, "case");
    c.checks().agree(study::Kind::verification, "ch3.strip_draw.case" + id + ".mu", "strip-draw mu vs Eq. (3.2), case " + id + " (Fig. 3.8)",
                     mu_in, r.mu, 0.02 * mu_in, "-",
                     "steady sliding at uniform pressure: 2 % for explicit dynamics and penalty contact");
    w.row({id, fmt(p), fmt(v), fmt(L, 4), fmt_fixed(mu_in, 5), fmt_fixed(r.mu, 5), fmt_fixed(100 * err, 2),
           fmt_fixed(100 * r.p_spread, 1), std::to_string(r.cycles)});
  }
  c.save(w, "strip_draw");
  c.value("strip_draw_worst", fmt_fixed(100 * worst, 2), "%");
  c.plot("stribeck_sim", "fig_3_8",
         {{"curvefile", c.out("tables/stribeck_curves.csv")}, {"simfile", c.out("tables/strip_draw.csv")}});

  // Figs. 3.5-3.7: the update interval, on the first case of Table 3.2.
  const double p = t32.number(t32.rows.front(), "pressure_MPa"), v = t32.number(t32.rows.front(), "velocity_mm_s");
  const double mu_in = analysis::stribeck_mu(v, p, s31);
  c.value("iv_speed", fmt(v), "mm/s");
  c.value("iv_case", "case " + t32.text(t32.rows.front(), "case") + ", " + fmt(p) + "\u00a0MPa, " + fmt(v) + "\u00a0mm/s");
  auto iv = c.table({"interval_cycles", "mu_simulated", "mu_error_pct", "probe_speed_mean_mm_s",
                     "probe_speed_std_mm_s", "probe_speed_min_mm_s", "probe_speed_max_mm_s"},
                    "Stribeck update interval: Table 3.2 case " + t32.text(t32.rows.front(), "case") + " (" + fmt(p) +
                        " MPa, " + fmt(v) + " mm/s), probe node under the die centre");
  std::vector<std::vector<std::pair<double, double>>> traces;
  for (int interval : {1, 10, 100, 1000}) {
    const DrawResult r = draw(deck, p, v, interval);
    iv.row({std::to_string(interval), fmt_fixed(r.mu, 5), fmt_fixed(100 * (r.mu - mu_in) / mu_in, 2),
            fmt_fixed(r.v_mean, 3), fmt_fixed(r.v_std, 3), fmt_fixed(r.v_min, 3), fmt_fixed(r.v_max, 3)});
    c.value("iv" + std::to_string(interval) + "_std", fmt(r.v_std, 2), "mm/s");
    c.value("iv" + std::to_string(interval) + "_err", fmt_fixed(100 * (r.mu - mu_in) / mu_in, 2), "%");
    if (interval == 1 || interval == 100) traces.push_back(r.trace);
  }
  c.save(iv, "stribeck_interval");
  auto tr = c.table({"time_s", "speed_interval_1", "speed_interval_100"}, "Probe node slip speed in the draw step [mm/s]");
  for (std::size_t k = 0; k < std::min(traces[0].size(), traces[1].size()); ++k)
    tr.row({fmt(traces[0][k].first, 6), fmt(traces[0][k].second, 6), fmt(traces[1][k].second, 6)});
  c.save(tr, "stribeck_probe_speed");
  c.plot("probe_speed", "fig_3_5_3_7", {{"datafile", c.out("tables/stribeck_probe_speed.csv")}});
}

}  // namespace ch3
