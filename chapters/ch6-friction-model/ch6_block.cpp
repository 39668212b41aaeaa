// Chapter 6, Sec. 6.5: verification of the mu(p, v) law in our solver by block
// sliding (Fig. 6.7), built by src/sim/block_case (the model of
// data/cases/block_surface.toml; `drawbend block-deck` writes any case) with
// the pressure, sliding speed and direction of each case, each a file-level
// job (runs/ch6_block_*: deck.toml, reduction.csv) through the case pool.
//   - Tables 6.2 / 6.3, Figs. 6.8 / 6.9: the block slid along RD (x) and TD (y)
//     at 10, 40, 70 MPa and 10-100 mm/s; retrieved mu_x = F_x/F_N, mu_y = F_y/F_N
//     (forces on the floor, mean over the last third of the slide) against the
//     input surfaces mu_RD(p, v), mu_TD(p, v).
//   - Table 6.4, Fig. 6.10: directions 0-90 deg at 10 MPa, 50 mm/s against the
//     ellipse: steady sliding at phi from RD under the radial return gives
//     (mu_x, mu_y) = mu(phi) (cos phi, sin phi), mu(phi) = mu1 mu2 /
//     sqrt(mu2^2 cos^2 phi + mu1^2 sin^2 phi) (friction::ellipse_mu).
#include <algorithm>
#include <cmath>

#include "ch6_steps.hpp"
#include "friction/surface_law.hpp"
#include "sim/block_case.hpp"
#include "study/thesis_data.hpp"

namespace ch6 {

using namespace drawbend;

namespace {

const double tol = 0.01;
const std::string reason = "steady sliding at uniform pressure: 1 % for explicit dynamics and penalty contact";

/// The block model of every case and the input law it must reproduce.
struct BlockSetup {
  sim::BlockSpec base;
  io::Deck deck;                             ///< the base case, read: it owns the law
  const friction::SurfaceLaw* law = nullptr;  ///< the floor contact's mu(p, v)
};

BlockSetup block_setup(study::Chapter& c) {
  BlockSetup b;
  b.base.hardening = c.data("materials/aa5754_o_rd.csv");
  b.base.surface_nodes = c.data("thesis/table_6_1.csv");
  b.deck = sim::block_deck(b.base);
  b.law = dynamic_cast<const friction::SurfaceLaw*>(b.deck.model.contacts.at(0).friction.get());
  if (!b.law) throw InputError("block builder: the floor contact must use the surface law");
  return b;
}

/// The case at pressure p [MPa], speed v [mm/s] and direction [deg from RD]; its run folder is runs/<name>.
sim::BlockSpec block_spec(const sim::BlockSpec& base, double p, double v, double direction_deg) {
  sim::BlockSpec s = base;
  s.name = "ch6_block_a" + fmt(direction_deg) + "_p" + fmt(p) + "_v" + fmt(v);
  s.pressure = p;
  s.speed = v;
  s.direction_deg = direction_deg;
  return s;
}

/// Tables 6.2 and 6.3: along RD and TD.
void rd_td_slides(study::Chapter& c, const BlockSetup& B, bool reuse) {
  const friction::SurfaceLaw* law = B.law;
  auto spec = [&](double p, double v, double direction_deg) { return block_spec(B.base, p, v, direction_deg); };
  auto w = c.table({"direction", "pressure_MPa", "speed_mm_s", "mu_input", "mu_retrieved", "mu_cross", "error_pct",
                    "pressure_spread_pct", "cycles"},
                   "Block sliding along RD / TD (Tables 6.2, 6.3; Figs. 6.8, 6.9): mu = F_t/F_N against the input "
                   "surface of Table 6.1; mu_cross = the other component");
  double worst = 0;
  std::string worst_case;
  struct Case {
    std::string dir;
    double p, v;
  };
  std::vector<Case> cases;
  std::vector<sim::BlockSpec> specs;
  for (const std::string table : {"table_6_2", "table_6_3"}) {
    const CsvTable t = read_csv(c.data("thesis/" + table + ".csv"));
    for (const auto& row : t.rows) {
      const std::string dir = t.text(row, "direction");
      if (dir != "RD" && dir != "TD") throw InputError(t.where(row, "direction") + ": expected RD or TD");
      cases.push_back({dir, t.number(row, "pressure_MPa"), t.number(row, "speed_mm_s")});
      specs.push_back(spec(cases.back().p, cases.back().v, dir == "RD" ? 0.0 : 90.0));
    }
  }
  const std::vector<sim::BlockResult> slides = sim::run_blocks(specs, c.out("runs"), reuse);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string& dir = cases[k].dir;
    const double p = cases[k].p, v = cases[k].v;
    const bool rd = dir == "RD";
    const sim::BlockResult& r = slides[k];
    const auto in = law->at(p, v);
    const double mu_in = rd ? in.mu1 : in.mu2, mu = rd ? r.mu_x : r.mu_y, cross = rd ? r.mu_y : r.mu_x;
    const double err = (mu - mu_in) / mu_in;
    if (std::abs(err) > worst) {
      worst = std::abs(err);
      worst_case = dir + ", " + fmt(p) + "\u00a0MPa, " + fmt(v) + "\u00a0mm/s";
    }
    const std::string id = "ch6.block." + dir + ".p" + fmt(p) + ".v" + fmt(v);
    c.checks().agree(study::Kind::verification, id, "block sliding mu_" + std::string(rd ? "x" : "y") + " vs input surface, " + dir + " " +
                             fmt(p) + " MPa " + fmt(v) + " mm/s (T6." + (rd ? "2" : "3") + ")",
                     mu_in, mu, tol * mu_in, "-", reason);
    w.row({dir, fmt(p), fmt(v), fmt_fixed(mu_in, 5), fmt_fixed(mu, 5), fmt_fixed(cross, 6), fmt_fixed(100 * err, 3),
           fmt_fixed(100 * (r.p_max - r.p_min) / p, 2), std::to_string(r.cycles)});
  }
  c.save(w, "block_rd_td");
  c.value("block_worst_pct", fmt_fixed(100 * worst, 3), "%");
  c.value("block_worst_case", worst_case);
}

/// Input lines for Figs. 6.8 / 6.9: mu(p) at the four sliding speeds.
void input_lines(study::Chapter& c, const friction::SurfaceLaw* law) {
  auto lines = c.table({"p_MPa", "RD_v10", "RD_v40", "RD_v70", "RD_v100", "TD_v10", "TD_v40", "TD_v70", "TD_v100"},
                       "Input surfaces of Table 6.1 at the block-sliding speeds");
  for (double p = 0; p <= 80.0 + 1e-9; p += 2.0) {
    std::vector<std::string> row{fmt(p)};
    for (int k = 0; k < 2; ++k)
      for (double v : {10.0, 40.0, 70.0, 100.0}) row.push_back(fmt(k == 0 ? law->at(p, v).mu1 : law->at(p, v).mu2, 6));
    lines.row(row);
  }
  c.save(lines, "block_input_lines");
  for (const std::string dir : {"RD", "TD"})
    c.plot("block_sliding", dir == "RD" ? "fig_6_8" : "fig_6_9",
           {{"dir", dir}, {"linesfile", c.out("tables/block_input_lines.csv")},
            {"simfile", c.out("tables/block_rd_td.csv")}});
}

/// Table 6.4: directions at one pressure and speed, against the ellipse.
void direction_slides(study::Chapter& c, const BlockSetup& B, bool reuse) {
  const friction::SurfaceLaw* law = B.law;
  auto spec = [&](double p, double v, double direction_deg) { return block_spec(B.base, p, v, direction_deg); };
  const CsvTable t64 = read_csv(c.data("thesis/table_6_4.csv"));
  auto d = c.table({"direction_deg", "pressure_MPa", "speed_mm_s", "mu_x_input", "mu_y_input", "mu_x", "mu_y",
                    "magnitude_error_pct", "force_angle_deg"},
                   "Block sliding in directions 0-90 deg from RD (Table 6.4, Fig. 6.10) against the ellipse of "
                   "Eq. (6.3b) under the radial return");
  double worst_d = 0, p64 = 0, v64 = 0, worst_angle = 0;
  std::vector<sim::BlockSpec> dir_specs;
  for (const auto& row : t64.rows)
    dir_specs.push_back(spec(t64.number(row, "pressure_MPa"), t64.number(row, "speed_mm_s"),
                             t64.number(row, "direction_deg")));
  const std::vector<sim::BlockResult> dir_slides = sim::run_blocks(dir_specs, c.out("runs"), reuse);
  for (const auto& row : t64.rows) {
    const double a = t64.number(row, "direction_deg");
    p64 = t64.number(row, "pressure_MPa");
    v64 = t64.number(row, "speed_mm_s");
    const sim::BlockResult& r = dir_slides[&row - &t64.rows[0]];
    const double phi = a * M_PI / 180.0, mu = friction::ellipse_mu(law->at(p64, v64), phi);
    const double mx = mu * std::cos(phi), my = mu * std::sin(phi);
    const double err = (std::hypot(r.mu_x, r.mu_y) - mu) / mu, ang = std::atan2(r.mu_y, r.mu_x) * 180 / M_PI;
    worst_d = std::max(worst_d, std::abs(err));
    worst_angle = std::max(worst_angle, std::abs(ang - a));
    const std::string id = "ch6.block.dir" + fmt(a);
    c.checks().agree(study::Kind::verification, id + ".mu_x", "block sliding mu_x vs ellipse, " + fmt(a) + " deg (T6.4)", mx, r.mu_x, tol * mu, "-",
                     reason + " (of |mu|)");
    c.checks().agree(study::Kind::verification, id + ".mu_y", "block sliding mu_y vs ellipse, " + fmt(a) + " deg (T6.4)", my, r.mu_y, tol * mu, "-",
                     reason + " (of |mu|)");
    d.row({fmt(a), fmt(p64), fmt(v64), fmt_fixed(mx, 5), fmt_fixed(my, 5), fmt_fixed(r.mu_x, 5), fmt_fixed(r.mu_y, 5),
           fmt_fixed(100 * err, 3), fmt_fixed(ang, 3)});
  }
  c.save(d, "block_directions");
  const auto l64 = law->at(p64, v64);
  auto ell = c.table({"mu_x", "mu_y"}, "Elliptical limit of Eq. (6.3b) at " + fmt(p64) + " MPa, " + fmt(v64) + " mm/s");
  for (int k = 0; k <= 90; ++k) {
    const double t = k * M_PI / 180.0;
    ell.row({fmt(l64.mu1 * std::cos(t), 6), fmt(l64.mu2 * std::sin(t), 6)});
  }
  c.save(ell, "block_ellipse");
  c.plot("block_directions", "fig_6_10",
         {{"ellipsefile", c.out("tables/block_ellipse.csv")}, {"simfile", c.out("tables/block_directions.csv")},
          {"label", fmt(p64) + " MPa, " + fmt(v64) + " mm/s"}});
  c.value("dir_p", fmt(p64), "MPa");
  c.value("dir_v", fmt(v64), "mm/s");
  c.value("dir_mu_rd", fmt_fixed(l64.mu1, 4));
  c.value("dir_mu_td", fmt_fixed(l64.mu2, 4));
  c.value("dir_worst_pct", fmt_fixed(100 * worst_d, 3), "%");
  c.value("dir_worst_angle", fmt_fixed(worst_angle, 3), "deg");
  c.value("cost_thesis", fmt(study::scalar(c.data("thesis/scalars.csv"), "ch6_cost_increase").value), "%");
}

}  // namespace

void block_sliding(study::Chapter& c, bool reuse) {
  const BlockSetup B = block_setup(c);
  rd_td_slides(c, B, reuse);
  input_lines(c, B.law);
  direction_slides(c, B, reuse);
}

}  // namespace ch6
