// Chapter 5 step 7: the friction-coefficient lines mu(p) of Table 5.16
// (Figs. 5.26/5.27) and the surfaces mu(p, v) built from them with the
// nine-node interpolation of Chapter 6 (Figs. 5.28/5.29).  These use the
// printed Table 5.16; a later chapter replaces it with our own pressure maps.
#include <cmath>

#include "analysis/friction_surface.hpp"
#include "ch5_steps.hpp"

namespace ch5 {

using namespace drawbend;
using namespace drawbend::analysis;

namespace {
std::vector<SpeedLine> lines_of(const Inputs& in, const std::string& dir) {
  std::vector<SpeedLine> out;
  for (const auto& l : in.lines)
    if (l.direction == dir) out.push_back({l.speed_mm_s, Polynomial{{l.a0.value, l.a1.value}}});
  if (out.size() != 3) throw InputError("Table 5.16: expected three speeds for " + dir);
  return out;
}
}  // namespace

void friction_lines_and_surfaces(Chapter& c, const Inputs& in) {
  const double p_max = study::scalar(c.data("thesis/scalars.csv"), "ch6_p_max").value;  // MPa, Sec. 6.3
  for (const char* dir : kDirs) {
    const auto lines = lines_of(in, dir);
    auto w = c.table({"p_MPa", "v6.35", "v25.4", "v101.6"},
                     std::string("mu(p) of Table 5.16, ") + dir + " strips, diluted lubricant (p in MPa)");
    for (double p = 0; p <= p_max + 1e-9; p += 2.0)
      w.row({fmt(p), fmt(lines[0].mu(p), 5), fmt(lines[1].mu(p), 5), fmt(lines[2].mu(p), 5)});
    c.save(w, std::string("mu_lines_") + dir);
    const bool rd = std::string(dir) == "RD";
    c.plot("mu_lines", rd ? "fig_5_26" : "fig_5_27",
           {{"dir", dir}, {"datafile", c.out(std::string("tables/mu_lines_") + dir + ".csv")}});

    const FrictionSurface S = surface_from_lines(lines, 0.0, p_max);
    std::vector<double> ps, vs;
    for (int i = 0; i <= 20; ++i) ps.push_back(p_max * i / 20.0);
    for (int j = 0; j <= 20; ++j) vs.push_back(S.v_min + (S.v_max - S.v_min) * j / 20.0);
    c.save_grid(std::string("mu_surface_") + dir, std::string("mu(p [MPa], v [mm/s]) nine-node surface, ") + dir, ps,
                vs, [&S](double p, double v) { return S(p, v); });
    c.plot("mu_surface", rd ? "fig_5_28" : "fig_5_29",
           {{"dir", dir},
            {"gridfile", c.out(std::string("tables/mu_surface_") + dir + ".dat")},
            {"linesfile", c.out(std::string("tables/mu_lines_") + dir + ".csv")}});

    // Sec. 5.9.1: "At higher sliding speeds the friction coefficients become
    // more pressure independent": the slope a1 falls with speed.
    c.checks().claim(study::Kind::rederived, std::string("ch5.T5.16.") + dir + ".slope_falls_with_speed",
                     std::string("a1 decreases with speed, ") + dir + " (Sec. 5.9.1)",
                     lines[0].mu.a[1] > lines[1].mu.a[1] && lines[1].mu.a[1] > lines[2].mu.a[1],
                     "order of printed slopes");
  }
  // "... and the difference between RD and TD strips is also reduced" -- |RD-TD|
  // at the mid pressure 40 MPa falls with speed; "RD strips show higher friction
  // coefficient values than TD strips in general" -- tested at the two lower speeds.
  const auto rd = lines_of(in, "RD"), td = lines_of(in, "TD");
  double gap[3];
  for (int k = 0; k < 3; ++k) gap[k] = std::abs(rd[k].mu(40) - td[k].mu(40));
  c.checks().claim(study::Kind::rederived, "ch5.T5.16.RD_TD_gap_falls_with_speed", "|mu_RD - mu_TD| at 40 MPa falls with speed (Sec. 5.9.1)",
                   gap[0] > gap[1] && gap[1] > gap[2], "values of Table 5.16 lines at 40 MPa");
  // "In general" is read as: over most of the (p, v) domain of the surfaces.
  const FrictionSurface Srd = surface_from_lines(rd, 0.0, p_max), Std = surface_from_lines(td, 0.0, p_max);
  int above = 0, total = 0;
  for (int i = 0; i <= 80; ++i)
    for (int j = 0; j <= 80; ++j, ++total) {
      const double p = p_max * i / 80.0, v = Srd.v_min + (Srd.v_max - Srd.v_min) * j / 80.0;
      above += Srd(p, v) > Std(p, v);
    }
  const double fraction = static_cast<double>(above) / total;
  c.checks().claim(study::Kind::rederived, "ch5.T5.16.RD_above_TD_in_general", "mu_RD > mu_TD over most of the (p, v) domain (Sec. 5.9.1)",
                   fraction > 0.5, "share of an 81 x 81 grid of the surfaces where RD > TD");
  c.value("rd_above_td_percent", fmt_fixed(100.0 * fraction, 0), "%");
  // Where the RD and TD lines cross, and how well the printed digits fix it:
  // the crossing p = (a0_TD - a0_RD)/(a1_RD - a1_TD) over every rounding of
  // the four printed coefficients.
  auto line = [&in](const std::string& dir, double v) -> const Line516& {
    for (const auto& l : in.lines)
      if (l.direction == dir && study::same(l.speed_mm_s, v)) return l;
    throw InputError("Table 5.16: no line for " + dir + " at " + fmt(v) + " mm/s");
  };
  for (double v : kSpeeds) {
    const Line516& R = line("RD", v);
    const Line516& T = line("TD", v);
    double lo = INFINITY, hi = -INFINITY;
    bool undetermined = false;
    for (int m = 0; m < 16; ++m) {
      const double r0 = R.a0.value + ((m & 1) ? 1 : -1) * R.a0.half_ulp;
      const double r1 = R.a1.value + ((m & 2) ? 1 : -1) * R.a1.half_ulp;
      const double t0 = T.a0.value + ((m & 4) ? 1 : -1) * T.a0.half_ulp;
      const double t1 = T.a1.value + ((m & 8) ? 1 : -1) * T.a1.half_ulp;
      if (r1 - t1 <= 0) undetermined = true;  // slopes may be equal: no crossing guaranteed
      else {
        lo = std::min(lo, (t0 - r0) / (r1 - t1));
        hi = std::max(hi, (t0 - r0) / (r1 - t1));
      }
    }
    const double pc = (T.a0.value - R.a0.value) / (R.a1.value - T.a1.value);
    c.value("t516_cross_v" + fmt(R.speed_mm_s), fmt_fixed(pc, 1), "MPa");
    c.value("t516_cross_range_v" + fmt(R.speed_mm_s),
            undetermined ? "above " + fmt_fixed(lo, 0) + "\u00a0MPa, or nowhere: the printed slopes differ by no more than their rounding"
                         : fmt_fixed(lo, 1) + "\u2013" + fmt_fixed(hi, 1) + "\u00a0MPa");
  }
}

}  // namespace ch5
