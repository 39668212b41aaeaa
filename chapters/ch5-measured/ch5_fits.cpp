// Chapter 5 steps 1-4: load the printed tables, re-derive the pure friction
// fits (Tables 5.11/5.12) and the friction forces of Table 5.14, and evaluate
// the conventional friction coefficient (Eq. 5.1) at F_back = 1700 N.
#include <cmath>
#include <map>

#include "analysis/linear_fit.hpp"
#include "analysis/rope.hpp"
#include "ch5_steps.hpp"

namespace ch5 {

using namespace drawbend;
using namespace drawbend::analysis;
using drawbend::study::find_case;
using drawbend::study::find_fit;
using drawbend::study::same;

std::string key(const std::string& dir, double v, double pin) {
  return dir + ".v" + fmt(v) + ".d" + fmt(pin);
}

double Inputs::back_tension(double pin) const {
  for (const auto& [d, f] : fback)
    if (same(d, pin)) return f.value;
  throw std::out_of_range("no Table 5.13 back tension for pin " + fmt(pin));
}

Inputs load_inputs(Chapter& c) {
  Inputs in;
  in.bending = study::load_fits(c.data("thesis/table_5_3.csv"), "Table 5.3");
  for (int t = 5; t <= 10; ++t) {
    auto f = study::load_fits(c.data("thesis/table_5_" + std::to_string(t) + ".csv"), "Table 5." + std::to_string(t));
    in.fric_bend.insert(in.fric_bend.end(), f.begin(), f.end());
  }
  for (int t : {11, 12}) {
    auto f = study::load_fits(c.data("thesis/table_5_" + std::to_string(t) + ".csv"), "Table 5." + std::to_string(t));
    in.pure.insert(in.pure.end(), f.begin(), f.end());
  }
  const CsvTable t513 = read_csv(c.data("thesis/table_5_13.csv"));
  for (const auto& r : t513.rows)
    in.fback.emplace_back(t513.number(r, "pin_diameter_mm"), study::printed(t513, r, "fback_N"));
  in.ffric_diluted = study::load_cases(c.data("thesis/table_5_14.csv"), "ffric_N");
  in.c_diluted = study::load_cases(c.data("thesis/table_5_15.csv"), "c");
  in.ffric_undiluted = study::load_cases(c.data("thesis/table_5_17.csv"), "ffric_N");
  in.c_undiluted = study::load_cases(c.data("thesis/table_5_18.csv"), "c");
  const CsvTable t516 = read_csv(c.data("thesis/table_5_16.csv"));
  for (const auto& r : t516.rows)
    in.lines.push_back({t516.text(r, "direction"), t516.number(r, "speed_mm_s"), study::printed(t516, r, "a0"),
                        study::printed(t516, r, "a1_per_MPa")});
  in.fback_conventional = study::scalar(c.data("thesis/scalars.csv"), "ch5_conventional_fback");
  in.theta = study::scalar(c.data("thesis/scalars.csv"), "ch2_wrap_angle").value * M_PI / 180.0;  // 90 deg (Sec. 5.6)
  for (const auto& [pin, f] : in.fback) c.value("fback_d" + fmt(pin), f.text, "N");
  return in;
}

// Step 2.  F_fric = F_fric+bend - F_bend (Sec. 5.5): slopes and intercepts
// subtract; the validity range is the intersection of the two ranges.
void rederive_pure_friction(Chapter& c, const Inputs& in) {
  auto w = c.table({"direction", "speed_mm_s", "pin_mm", "slope_thesis", "slope_ours", "intercept_thesis_N",
                    "intercept_ours_N", "valid_from_N", "valid_to_N"},
                   "Tables 5.11/5.12 re-derived: Tables 5.5-5.10 minus Table 5.3 (full-strip forces, N)");
  int agree = 0, total = 0;
  for (const char* dir : kDirs)
    for (double v : kSpeeds)
      for (double pin : kPins) {
        const FitEntry& fb = find_fit(in.fric_bend, dir, v, pin);
        const FitEntry& b = find_fit(in.bending, "RD", 0.0, pin);
        const FitEntry& printed = find_fit(in.pure, dir, v, pin);
        const LinearFit d = subtract(fb.fit(), b.fit());
        const std::string table = std::string(dir) == "RD" ? "T5.11" : "T5.12";
        const std::string id = "ch5." + table + "." + key(dir, v, pin);
        const std::string why = kFromPrinted;
        agree += c.checks().rederive(id + ".slope", table + " slope " + dir + " " + fmt(v) + " mm/s " + fmt(pin) + " mm",
                            printed.slope.value, d.slope,
                            printed.slope.half_ulp, "-", why)
                     .status == study::Status::pass;
        agree += c.checks().rederive(id + ".intercept",
                            table + " intercept " + dir + " " + fmt(v) + " mm/s " + fmt(pin) + " mm",
                            printed.intercept.value, d.intercept,
                            printed.intercept.half_ulp, "N", why)
                     .status == study::Status::pass;
        total += 2;
        w.row({dir, fmt(v), fmt(pin), printed.slope.text, fmt(d.slope, 6), printed.intercept.text,
               fmt(d.intercept, 8), fmt(d.range->lo), fmt(d.range->hi)});
      }
  c.save(w, "table_5_11_12");
  c.value("t511_agree", std::to_string(agree));
  c.value("t511_total", std::to_string(total));
}

// Step 3.  Table 5.14: the printed pure-friction fits at the Table 5.13 back
// tensions, with every extrapolation beyond the measured ranges flagged.
void rederive_table_5_14(Chapter& c, const Inputs& in) {
  auto w = c.table({"direction", "speed_mm_s", "pin_mm", "F_back_N", "F_fric_thesis_N", "F_fric_ours_N",
                    "extrapolated", "valid_range_N"},
                   "Table 5.14 re-derived: Tables 5.11/5.12 at the Table 5.13 back tensions (full strip, N)");
  int extrapolations = 0, agree514 = 0, total514 = 0;
  for (const char* dir : kDirs)
    for (double v : kSpeeds)
      for (double pin : {12.7, 25.4}) {
        const FitEntry& f = find_fit(in.pure, dir, v, pin);
        const double Fb = in.back_tension(pin);
        // The validity range comes from the measured fits the pure fit was made of.
        const LinearFit measured =
            subtract(find_fit(in.fric_bend, dir, v, pin).fit(), find_fit(in.bending, "RD", 0.0, pin).fit());
        const Evaluation e = evaluate(LinearFit{f.slope.value, f.intercept.value, measured.range, f.fit().label}, Fb);
        extrapolations += e.extrapolated;
        const CaseValue& t = find_case(in.ffric_diluted, dir, v, pin);
        agree514 += c.checks().rederive("ch5.T5.14." + key(dir, v, pin), "T5.14 friction force", t.value.value,
                                        e.value, t.value.half_ulp, "N", kFromPrinted)
                        .status == study::Status::pass;
        ++total514;
        w.row({dir, fmt(v), fmt(pin), fmt(Fb), t.value.text, fmt_fixed(e.value, 2), e.extrapolated ? "yes" : "no",
               fmt(measured.range->lo) + "-" + fmt(measured.range->hi)});
      }
  c.save(w, "table_5_14");
  c.value("t514_extrapolations", std::to_string(extrapolations) + (extrapolations == 1 ? " of them lies" : " of them lie"));
  c.value("t514_agree", std::to_string(agree514));
  c.value("t514_total", std::to_string(total514));
}

// Step 4.  Eq. (5.1) at F_back = 1700 N (Figs. 5.19/5.20) and the claims of Sec. 5.6.
void conventional_mu(Chapter& c, const Inputs& in) {
  const double Fb = in.fback_conventional.value;
  auto w = c.table({"direction", "speed_mm_s", "pin_mm", "F_fric_N", "mu", "extrapolated"},
                   "Conventional friction coefficient, Eq. (5.1), at F_back = " + fmt(Fb) + " N (Figs. 5.19/5.20)");
  std::map<std::string, double> mu;
  int extrapolations = 0;
  for (const char* dir : kDirs)
    for (double v : kSpeeds)
      for (double pin : kPins) {
        const FitEntry& f = find_fit(in.pure, dir, v, pin);
        const LinearFit measured =
            subtract(find_fit(in.fric_bend, dir, v, pin).fit(), find_fit(in.bending, "RD", 0.0, pin).fit());
        const bool extrap = !measured.range->contains(Fb);
        extrapolations += extrap;
        const double F = f.slope.value * Fb + f.intercept.value;
        mu[key(dir, v, pin)] = mu_from_friction(F, Fb, in.theta);
        w.row({dir, fmt(v), fmt(pin), fmt_fixed(F, 2), fmt_fixed(mu[key(dir, v, pin)], 4), extrap ? "yes" : "no"});
      }
  c.save(w, "conventional_mu_1700N");
  c.value("conv_extrapolations", std::to_string(extrapolations));
  c.value("conv_fback", fmt(Fb), "N");
  c.value("conv_total", std::to_string(mu.size()));
  // Wide table for the figure: one row per pin, one column per speed.
  for (const char* dir : kDirs) {
    auto fig = c.table({"pin_mm", "v6.35", "v25.4", "v101.6"}, std::string("mu by Eq. (5.1), ") + dir + " strips");
    for (double pin : kPins)
      fig.row({fmt(pin), fmt(mu[key(dir, 6.35, pin)], 5), fmt(mu[key(dir, 25.4, pin)], 5),
               fmt(mu[key(dir, 101.6, pin)], 5)});
    c.save(fig, std::string("conventional_mu_") + dir);
    c.plot("conventional_mu", std::string("fig_5_") + (std::string(dir) == "RD" ? "19" : "20"),
           {{"dir", dir}, {"datafile", c.out(std::string("tables/conventional_mu_") + dir + ".csv")}});
  }
  // Sec. 5.6: "Except for the case with the 42 mm diameter pin, the obtained
  // friction coefficients show ... that the friction coefficient decreases as
  // the pin diameter increases."
  int dec = 0, brk = 0, rdtd = 0;
  for (const char* dir : kDirs)
    for (double v : kSpeeds) {
      const std::string k = std::string(dir) + ".v" + fmt(v);
      dec += mu[key(dir, v, 12.7)] > mu[key(dir, v, 25.4)];
      brk += mu[key(dir, v, 42)] > mu[key(dir, v, 25.4)];
      c.checks().claim(study::Kind::rederived, "ch5.conv.decreases_12.7_to_25.4." + k,
                       std::string("mu(12.7 mm) > mu(25.4 mm), ") + dir + " " + fmt(v) + " mm/s (Sec. 5.6)",
                       mu[key(dir, v, 12.7)] > mu[key(dir, v, 25.4)], "sign of a difference of Eq. (5.1) values");
      c.checks().claim(study::Kind::rederived, "ch5.conv.42mm_breaks_trend." + k,
                       std::string("mu(42 mm) > mu(25.4 mm), ") + dir + " " + fmt(v) + " mm/s (Sec. 5.6, Fig. 5.21)",
                       mu[key(dir, v, 42)] > mu[key(dir, v, 25.4)], "sign of a difference of Eq. (5.1) values");
    }
  // Sec. 5.9.1: "the friction coefficient is higher in rolling direction than
  // transverse direction" -- tested pin by pin on the conventional values.
  for (double v : kSpeeds)
    for (double pin : kPins) {
      rdtd += mu[key("RD", v, pin)] > mu[key("TD", v, pin)];
      c.checks().claim(study::Kind::rederived, "ch5.conv.RD_above_TD.v" + fmt(v) + ".d" + fmt(pin),
                       "mu_RD > mu_TD at " + fmt(v) + " mm/s, " + fmt(pin) + " mm pin (Sec. 5.9.1)",
                       mu[key("RD", v, pin)] > mu[key("TD", v, pin)], "sign of a difference of Eq. (5.1) values");
    }
  c.value("claim_decreasing", std::to_string(dec));
  c.value("claim_combinations", std::to_string(std::size(kDirs) * std::size(kSpeeds)));
  c.value("claim_cases", std::to_string(std::size(kSpeeds) * std::size(kPins)));
  c.value("claim_42_breaks", std::to_string(brk));
  c.value("claim_rd_above_td", std::to_string(rdtd));
}

}  // namespace ch5
