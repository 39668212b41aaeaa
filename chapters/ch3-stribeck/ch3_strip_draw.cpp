// Chapter 3, Sec. 3.3: the strip-draw verification of the Stribeck law in our
// solver, built by src/sim/strip_draw_case (the model of
// data/cases/strip_draw.toml; `drawbend strip-deck` writes any case) with the
// die pressure, drawing speed and update interval of each case, each a
// file-level job (runs/ch3_strip_*: deck.toml, reduction.csv) through the case pool.
//   - Table 3.2 / Fig. 3.8: mu = (F1 - F2)/F_N at steady sliding against the
//     input curve, Eq. (3.2), for the five pressure/speed cases; Fig. 3.4:
//     the pressure under the die at the end of case 1 (Fig. 3.3, the map
//     before the thesis's contact fix, has no counterpart: see results.md).
//   - Figs. 3.5-3.7 and the choice of update interval: the speed of a node
//     under the die with mu updated every cycle and every 10, 100, 1000 cycles,
//     and with Coulomb friction (Fig. 3.6).
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "analysis/stribeck.hpp"
#include "ch3_steps.hpp"
#include "sim/strip_draw_case.hpp"
#include "study/thesis_data.hpp"

namespace ch3 {

using namespace drawbend;

namespace {

/// The update intervals of Figs. 3.5-3.7 [cycles], run on the first case of Table 3.2.
const std::vector<int> kIntervals{1, 10, 100, 1000};

/// Every run of this section, side by side in the case pool: the cases of
/// Table 3.2 (interval 100), then the first case updated every 1, 10, 100 and
/// 1000 cycles (Figs. 3.5-3.7), then with Coulomb friction (Fig. 3.6).
std::vector<sim::StripDrawResult> run_section(study::Chapter& c, const CsvTable& t32, double mu_coulomb, bool reuse) {
  sim::StripDrawSpec base;
  base.hardening = c.data("materials/aa5754_o_rd.csv");
  base.stribeck_table = c.data("thesis/table_3_1.csv");
  auto spec = [&](double p, double v, int interval, const std::optional<io::FrictionSpec>& friction = std::nullopt) {
    sim::StripDrawSpec s = base;
    s.name = "ch3_strip_p" + fmt(p) + "_v" + fmt(v) + "_i" + std::to_string(interval) + (friction ? "_coulomb" : "");
    s.pressure = p;
    s.speed = v;
    s.interval = interval;
    s.friction = friction;
    return s;
  };
  const double p1 = t32.number(t32.rows.front(), "pressure_MPa"), v1 = t32.number(t32.rows.front(), "velocity_mm_s");
  std::vector<sim::StripDrawSpec> specs;
  for (const auto& row : t32.rows) specs.push_back(spec(t32.number(row, "pressure_MPa"), t32.number(row, "velocity_mm_s"), 100));
  for (int interval : kIntervals) specs.push_back(spec(p1, v1, interval));
  specs.push_back(spec(p1, v1, 1, io::coulomb_friction(mu_coulomb)));
  return sim::run_strip_draws(specs, c.out("runs"), reuse);
}

/// Fig. 3.4: the pressure under the die at the end of the draw of Table 3.2's
/// case `id` (p [MPa], v [mm/s]), over the strip's top face (reference positions).
void die_pressure(study::Chapter& c, const std::string& id, double p, double v, const sim::StripDrawResult& r) {
  std::set<double> xs, ys;
  for (const auto& [xy, pr] : r.die_map) xs.insert(xy.first), ys.insert(xy.second);
  c.save_grid("die_pressure", "pressure under the die [MPa] at the end of the draw, Table 3.2 case " + id + " (" +
                                  fmt(p) + " MPa, " + fmt(v) +
                                  " mm/s): x, y reference position on the strip's top face [mm]",
              {xs.begin(), xs.end()}, {ys.begin(), ys.end()}, [&](double x, double y) { return r.die_map.at({x, y}); });
  // Mean over the row at each end of the strip (x = min and max).
  for (double xe : {*xs.begin(), *xs.rbegin()}) {
    double sum = 0;
    for (double y : ys) sum += r.die_map.at({xe, y});
    c.value(xe == *xs.begin() ? "die_p_xmin" : "die_p_xmax", fmt_fixed(sum / ys.size(), 2), "MPa");
  }
  c.plot("die_pressure", "fig_3_4", {{"gridfile", c.out("tables/die_pressure.dat")},
                                     {"title_text", "Pressure under the die, target " + fmt(p) + " MPa (Fig. 3.4)"}});
}

/// Table 3.2 / Fig. 3.8: mu = (F1 - F2)/F_N of each case against Eq. (3.2),
/// with Fig. 3.4 from the first case; `runs` starts with the table's cases.
void table_3_2(study::Chapter& c, const analysis::StribeckParams& s31, const CsvTable& t32,
               const std::vector<sim::StripDrawResult>& runs) {
  auto w = c.table({"case", "pressure_MPa", "velocity_mm_s", "L", "mu_input", "mu_simulated", "error_pct",
                    "pressure_spread_pct", "cycles"},
                   "Strip-draw verification of the Stribeck law (Table 3.2, Fig. 3.8); mu = (F1 - F2)/F_N");
  double worst = 0, spread_max = 0;
  for (const auto& row : t32.rows) {
    const double p = t32.number(row, "pressure_MPa"), v = t32.number(row, "velocity_mm_s");
    const sim::StripDrawResult& r = runs[&row - &t32.rows[0]];
    spread_max = std::max(spread_max, r.p_spread);
    if (&row == &t32.rows.front()) die_pressure(c, t32.text(row, "case"), p, v, r);
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
  c.value("strip_draw_spread_max", fmt_fixed(100 * spread_max, 1), "%");
  c.plot("stribeck_sim", "fig_3_8",
         {{"curvefile", c.out("tables/stribeck_curves.csv")}, {"simfile", c.out("tables/strip_draw.csv")}});
}

/// The probe speed traces the Coulomb step compares with: the Stribeck law
/// updated every cycle and every 100 cycles, and the every-cycle std [mm/s].
struct IntervalTraces {
  std::vector<std::pair<double, double>> every_cycle, every_100;
  double every_cycle_std = 0;
};

/// Figs. 3.5-3.7: the update interval on the first case of Table 3.2 (p [MPa],
/// v [mm/s]); the runs of kIntervals follow the table's cases in `runs`.
IntervalTraces update_interval(study::Chapter& c, const analysis::StribeckParams& s31, const CsvTable& t32,
                               double p, double v, const std::vector<sim::StripDrawResult>& runs) {
  const double mu_in = analysis::stribeck_mu(v, p, s31);
  c.value("iv_speed", fmt(v), "mm/s");
  c.value("iv_case", "case " + t32.text(t32.rows.front(), "case") + ", " + fmt(p) + "\u00a0MPa, " + fmt(v) + "\u00a0mm/s");
  auto iv = c.table({"interval_cycles", "mu_simulated", "mu_error_pct", "probe_speed_mean_mm_s",
                     "probe_speed_std_mm_s", "probe_speed_min_mm_s", "probe_speed_max_mm_s"},
                    "Stribeck update interval: Table 3.2 case " + t32.text(t32.rows.front(), "case") + " (" + fmt(p) +
                        " MPa, " + fmt(v) + " mm/s), probe node under the die centre");
  IntervalTraces out;
  for (std::size_t k = 0; k < kIntervals.size(); ++k) {
    const int interval = kIntervals[k];
    const sim::StripDrawResult& r = runs[t32.rows.size() + k];
    iv.row({std::to_string(interval), fmt_fixed(r.mu, 5), fmt_fixed(100 * (r.mu - mu_in) / mu_in, 2),
            fmt_fixed(r.v_mean, 3), fmt_fixed(r.v_std, 3), fmt_fixed(r.v_min, 3), fmt_fixed(r.v_max, 3)});
    c.value("iv" + std::to_string(interval) + "_std", fmt(r.v_std, 2), "mm/s");
    c.value("iv" + std::to_string(interval) + "_err", fmt_fixed(100 * (r.mu - mu_in) / mu_in, 2), "%");
    if (interval == 100) out.every_100 = r.trace;
    if (interval == 1) {
      out.every_cycle = r.trace;
      out.every_cycle_std = r.v_std;
      c.value("iv1_max", fmt_fixed(r.v_max, 1), "mm/s");
    }
  }
  c.save(iv, "stribeck_interval");
  auto tr = c.table({"time_s", "speed_interval_1", "speed_interval_100"}, "Probe node slip speed in the draw step [mm/s]");
  for (std::size_t k = 0; k < std::min(out.every_cycle.size(), out.every_100.size()); ++k)
    tr.row({fmt(out.every_cycle[k].first, 6), fmt(out.every_cycle[k].second, 6), fmt(out.every_100[k].second, 6)});
  c.save(tr, "stribeck_probe_speed");
  c.plot("probe_speed", "fig_3_5_3_7", {{"datafile", c.out("tables/stribeck_probe_speed.csv")}});
  return out;
}

/// Fig. 3.6: the first case of Table 3.2 (p [MPa], v [mm/s]) with Coulomb
/// mu = mu_coulomb on the die, where the thesis saw no fluctuation ("not
/// observed with the Coulomb friction model"; a minor one shows only when the
/// plot is enlarged), against the Stribeck law updated every cycle.
void coulomb_draw(study::Chapter& c, double mu_coulomb, double p, double v, const sim::StripDrawResult& rc,
                  const IntervalTraces& stribeck) {
  c.checks().agree(study::Kind::verification, "ch3.strip_draw.coulomb.mu",
                   "strip-draw mu with Coulomb mu = " + fmt(mu_coulomb) + " on the die (Fig. 3.6 run)", mu_coulomb,
                   rc.mu, 0.02 * mu_coulomb, "-",
                   "steady sliding at uniform pressure: 2 % for explicit dynamics and penalty contact, as the "
                   "Stribeck cases");
  // Stated before the run: the probe's speed over the last third varies by a
  // standard deviation below 1 % of the span of the thesis's Stribeck
  // fluctuation (-10 to 30 mm/s, Sec. 3.3.2), i.e. 0.4 mm/s: a line's width
  // on a plot that shows that fluctuation, which is what "not observed" (and a
  // minor fluctuation seen only when enlarged) means for Fig. 3.6.  And it
  // varies less than with the Stribeck law updated every cycle, the contrast of
  // Figs. 3.5 and 3.6.
  const std::string sc = c.data("thesis/scalars.csv");
  const double span = study::scalar(sc, "ch3_velocity_fluctuation_max").value -
                      study::scalar(sc, "ch3_velocity_fluctuation_min").value;
  const double std1 = stribeck.every_cycle_std;
  c.checks().claim(study::Kind::verification, "ch3.strip_draw.coulomb.speed_steady",
                   "probe speed steady with Coulomb friction: std < 1 % of the thesis's Stribeck fluctuation span "
                   "and below the every-cycle Stribeck std (Sec. 3.3.2, Figs. 3.5-3.6)",
                   rc.v_std < 0.01 * span && rc.v_std < std1,
                   "std " + fmt(rc.v_std, 3) + " mm/s (Coulomb) against " + fmt(0.01 * span, 3) +
                       " mm/s (1 % of the " + fmt(span) + " mm/s span) and " + fmt(std1, 3) +
                       " mm/s (Stribeck, every cycle)");
  c.value("coulomb_mu_in", fmt(mu_coulomb));
  c.value("coulomb_std", fmt(rc.v_std, 2), "mm/s");
  c.value("coulomb_ramp_max", fmt_fixed(rc.ramp_v_max, 1), "mm/s");
  c.value("coulomb_mu", fmt_fixed(rc.mu, 4));
  c.value("coulomb_range", fmt_fixed(rc.v_min, 2) + "–" + fmt_fixed(rc.v_max, 2), "mm/s");
  const auto& trace1 = stribeck.every_cycle;
  auto tc = c.table({"time_s", "speed_coulomb", "speed_stribeck_interval_1"},
                    "Probe node slip speed in the draw step [mm/s], Coulomb mu = " + fmt(mu_coulomb) +
                        " and the Stribeck law updated every cycle");
  for (std::size_t k = 0; k < std::min(rc.trace.size(), trace1.size()); ++k)
    tc.row({fmt(rc.trace[k].first, 6), fmt(rc.trace[k].second, 6), fmt(trace1[k].second, 6)});
  c.save(tc, "coulomb_probe_speed");
  c.plot("probe_speed_coulomb", "fig_3_6", {{"datafile", c.out("tables/coulomb_probe_speed.csv")},
                                            {"title_text", "Nodal sliding speed, Coulomb μ = " + fmt(mu_coulomb) +
                                                               ", " + fmt(p) + " MPa, " + fmt(v) + " mm/s (Fig. 3.6)"}});
}

}  // namespace

void strip_draw(study::Chapter& c, const analysis::StribeckParams& s31, const CsvTable& t32, double mu_coulomb,
                bool reuse) {
  const std::vector<sim::StripDrawResult> runs = run_section(c, t32, mu_coulomb, reuse);
  table_3_2(c, s31, t32, runs);
  const double p1 = t32.number(t32.rows.front(), "pressure_MPa"), v1 = t32.number(t32.rows.front(), "velocity_mm_s");
  const IntervalTraces stribeck = update_interval(c, s31, t32, p1, v1, runs);
  coulomb_draw(c, mu_coulomb, p1, v1, runs.back(), stribeck);
}

}  // namespace ch3
