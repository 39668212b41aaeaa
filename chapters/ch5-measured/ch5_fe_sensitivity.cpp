// Chapter 5 step 11: how much of the difference between our coefficients and
// Table 5.16 each modelling choice can explain.
//
// Sources, each changed alone from our baseline (base map, printed c):
//   mesh      finer maps: half the element length along the strip (where the
//             entry and exit peaks are); twice the elements across (the edge
//             peaks; `full` label only);
//   penalty   a stiffer contact penalty;
//   hardening the TD instead of the RD hardening curve;
//   c (Eq. 2.2)      c recomputed by Eq. (2.2) from the measured forces;
//   c (Eq. 2.2, sim) c with our simulated rotating-pin force in the denominator.
// For each of the 12 diluted lines: da0, da1 = variant - baseline, beside
// ours - Table 5.16.  Then the map moments that Table 5.16 implies: for each
// pin, the six printed lines and Tables 5.14/5.15 give six equations
// F = c a0 S1 + c^2 a1 S2 in the two unknowns S1 (normal force) and S2 of the
// thesis's map, solved by least squares, beside ours.
// Forces N (full strip), pressures MPa.
#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "ch5_steps.hpp"

namespace ch5 {

using namespace drawbend;
using namespace drawbend::analysis;

namespace {

struct Source {
  std::string key, label, variant;
  CDef cdef;
};

const std::vector<Source> kSources{{"mesh_along", "finer map along the strip", "fine_along", CDef::printed},
                                   {"mesh_across", "finer map across the width", "fine_across", CDef::printed},
                                   {"penalty", "stiffer contact penalty", "penalty", CDef::printed},
                                   {"hardening", "TD hardening curve", "td_curve", CDef::printed},
                                   {"c_eq22", "c by Eq. (2.2), measured forces", "base", CDef::eq22},
                                   {"c_eq22sim", "c by Eq. (2.2), our rotating-pin force", "base", CDef::eq22sim}};

double rms(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v * v;
  return std::sqrt(s / x.size());
}
double max_abs(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s = std::max(s, std::abs(v));
  return s;
}

/// The diluted lines' changes: ours - Table 5.16 and each source's from our baseline.
struct Changes {
  std::vector<double> d0_thesis, d1_thesis;
  std::map<std::string, std::vector<double>> d0, d1;
};

/// One Table 5.16 line (Sec. 5.7.1 conditions).
struct LineIn {
  std::string dir;
  double v, a0, a1;
};

/// The sources whose runs this tier made.
std::vector<Source> sources_run(const FeMaps& m) {
  std::vector<Source> sources;
  for (const auto& s : kSources)
    if (m.has(s.variant, 12.7) && m.has(s.variant, 25.4)) sources.push_back(s);
  return sources;
}

/// The tables sensitivity_a0 and sensitivity_a1.
Changes sensitivity_tables(Chapter& c, const Inputs& in, const FeMaps& m, const std::vector<double>& pins,
                           const std::vector<Source>& sources) {
  Changes ch;
  std::vector<std::string> head{"direction", "speed_mm_s", "ours_minus_T5.16"};
  for (const auto& s : sources) head.push_back(s.key);
  auto t0 = c.table(head, "sensitivity of a0: ours - Table 5.16, and each source's change from our baseline "
                          "(variant - baseline; dimensionless)");
  auto t1 = c.table(head, "sensitivity of a1 [1/MPa]: ours - Table 5.16, and each source's change from our baseline");
  std::vector<double>& d0_thesis = ch.d0_thesis;
  std::vector<double>& d1_thesis = ch.d1_thesis;
  std::map<std::string, std::vector<double>>& d0 = ch.d0;
  std::map<std::string, std::vector<double>>& d1 = ch.d1;
  for (const char* dir : kDirs)
    for (double v : kSpeeds) {
      const Polynomial base = identify(in, m, "base", CDef::printed, dir, v, pins, 1, false).mu;
      const Line516* L = nullptr;
      for (const auto& l : in.lines)
        if (l.direction == dir && study::same(l.speed_mm_s, v)) L = &l;
      d0_thesis.push_back(base.a[0] - L->a0.value);
      d1_thesis.push_back(base.a[1] - L->a1.value);
      std::vector<std::string> r0{dir, fmt(v), fmt_fixed(d0_thesis.back(), 4)},
          r1{dir, fmt(v), fmt_fixed(d1_thesis.back(), 5)};
      for (const auto& s : sources) {
        const Polynomial q = identify(in, m, s.variant, s.cdef, dir, v, pins, 1, false).mu;
        d0[s.key].push_back(q.a[0] - base.a[0]);
        d1[s.key].push_back(q.a[1] - base.a[1]);
        r0.push_back(fmt_fixed(d0[s.key].back(), 4));
        r1.push_back(fmt_fixed(d1[s.key].back(), 5));
      }
      t0.row(r0);
      t1.row(r1);
    }
  c.save(t0, "sensitivity_a0");
  c.save(t1, "sensitivity_a1");
  return ch;
}

/// The table sensitivity_summary and its values.
void sensitivity_summary(Chapter& c, const std::vector<Source>& sources, const Changes& ch) {
  const std::vector<double>& d0_thesis = ch.d0_thesis;
  const std::vector<double>& d1_thesis = ch.d1_thesis;
  const std::map<std::string, std::vector<double>>& d0 = ch.d0;
  const std::map<std::string, std::vector<double>>& d1 = ch.d1;
  auto sum = c.table({"source", "rms_da0", "max_abs_da0", "rms_da1_per_MPa", "max_abs_da1_per_MPa"},
                     "sensitivity summary over the 12 diluted lines (RD, TD x 3 speeds): RMS and largest change");
  auto add = [&](const std::string& key, const std::string& label, const std::vector<double>& a,
                 const std::vector<double>& b) {
    sum.row({label, fmt_fixed(rms(a), 4), fmt_fixed(max_abs(a), 4), fmt_fixed(rms(b), 5), fmt_fixed(max_abs(b), 5)});
    c.value("sens_rms_a0_" + key, fmt_fixed(rms(a), 4));
    c.value("sens_rms_a1_" + key, fmt_fixed(rms(b), 5), "1/MPa");
    c.value("sens_max_a0_" + key, fmt_fixed(max_abs(a), 4));
    c.value("sens_max_a1_" + key, fmt_fixed(max_abs(b), 5), "1/MPa");
  };
  add("thesis", "ours - Table 5.16", d0_thesis, d1_thesis);
  for (const auto& s : sources) add(s.key, s.label, d0.at(s.key), d1.at(s.key));
  for (const auto& s : kSources)  // sources whose runs this tier did not make: "not run" in the page's table
    if (std::none_of(sources.begin(), sources.end(), [&](const Source& x) { return x.key == s.key; }))
      for (const char* q : {"sens_rms_a0_", "sens_rms_a1_", "sens_max_a0_", "sens_max_a1_"}) c.value(q + s.key, "not run");
  c.save(sum, "sensitivity_summary");
}

/// Table 5.16's lines.
std::vector<LineIn> thesis_lines(const Inputs& in) {
  std::vector<LineIn> lines;
  for (const char* dir : kDirs)
    for (double v : kSpeeds)
      for (const auto& l : in.lines)
        if (l.direction == dir && study::same(l.speed_mm_s, v)) lines.push_back({dir, v, l.a0.value, l.a1.value});
  return lines;
}

/// Least-squares (S1, S2) of one pin from the lines, leaving out line `skip` (-1: none).
struct Implied {
  const Inputs& in;
  const FeMaps& m;
  const std::vector<LineIn>& lines;

  std::pair<Eigen::Vector2d, double> operator()(double pin, int skip) const {
    Eigen::MatrixXd A(lines.size() - (skip >= 0), 2);
    Eigen::VectorXd F(A.rows());
    int i = 0;
    for (int k = 0; k < static_cast<int>(lines.size()); ++k) {
      if (k == skip) continue;
      const double cc = c_of(CDef::printed, in, m, "base", lines[k].dir, lines[k].v, pin, false);
      A(i, 0) = cc * lines[k].a0;
      A(i, 1) = cc * cc * lines[k].a1;
      F(i) = ffric_of(in, lines[k].dir, lines[k].v, pin, false);
      ++i;
    }
    const Eigen::Vector2d S = A.colPivHouseholderQr().solve(F);
    return std::make_pair(S, std::sqrt((A * S - F).squaredNorm() / A.rows()));
  }
};

/// The table implied_map_moments.
void implied_moments(Chapter& c, const FeMaps& m, const std::vector<double>& pins, const Implied& implied) {
  auto mo = c.table({"pin_mm", "S1_implied_N", "S1_ours_N", "pbar_implied_MPa", "pbar_ours_MPa", "rms_residual_N"},
                    "map moments implied by Table 5.16 with Tables 5.14/5.15 (least squares over its six lines; "
                    "full strip, N; pbar = S2/S1, MPa) and ours");
  for (double pin : pins) {
    const auto [S, res] = implied(pin, -1);
    const PressureMap ours = m.full_strip_map("base", pin);
    const double pbar_i = S(1) / S(0), pbar_o = ours.moment(2) / ours.moment(1);
    mo.row({fmt(pin), fmt_fixed(S(0), 0), fmt_fixed(ours.moment(1), 0), fmt_fixed(pbar_i, 1), fmt_fixed(pbar_o, 1),
            fmt_fixed(res, 1)});
    c.value("implied_S1_d" + fmt(pin), fmt_fixed(S(0), 0), "N");
    c.value("ours_S1_d" + fmt(pin), fmt_fixed(ours.moment(1), 0), "N");
    c.value("implied_pbar_d" + fmt(pin), fmt_fixed(pbar_i, 1), "MPa");
    c.value("ours_pbar_d" + fmt(pin), fmt_fixed(pbar_o, 1), "MPa");
    c.value("implied_res_d" + fmt(pin), fmt_fixed(res, 1), "N");
  }
  c.save(mo, "implied_map_moments");
}

/// The table table_5_16_leave_one_out.
void leave_one_out(Chapter& c, const Inputs& in, const FeMaps& m, const std::vector<double>& pins,
                   const std::vector<LineIn>& lines, const Implied& implied) {
  // Each line from the maps that the other five lines imply (leave one out):
  // what the thesis's own maps give for that line, if the table is consistent.
  auto loo = c.table({"direction", "speed_mm_s", "a0_T5.16", "a0_from_other_lines", "a0_ours", "a1_T5.16_per_MPa",
                      "a1_from_other_lines", "a1_ours"},
                     "each Table 5.16 line re-identified with the map moments implied by the other five lines "
                     "(Tables 5.14/5.15 inputs), beside the printed line and ours");
  for (int k = 0; k < static_cast<int>(lines.size()); ++k) {
    Eigen::Matrix2d M;
    Eigen::Vector2d F;
    for (int j = 0; j < 2; ++j) {
      const Eigen::Vector2d S = implied(pins[j], k).first;
      const double cc = c_of(CDef::printed, in, m, "base", lines[k].dir, lines[k].v, pins[j], false);
      M(j, 0) = cc * S(0);
      M(j, 1) = cc * cc * S(1);
      F(j) = ffric_of(in, lines[k].dir, lines[k].v, pins[j], false);
    }
    const Eigen::Vector2d a = M.fullPivLu().solve(F);
    const Polynomial ours = identify(in, m, "base", CDef::printed, lines[k].dir, lines[k].v, pins, 1, false).mu;
    loo.row({lines[k].dir, fmt(lines[k].v), fmt(lines[k].a0), fmt_fixed(a(0), 4), fmt_fixed(ours.a[0], 4),
             fmt(lines[k].a1), fmt_fixed(a(1), 5), fmt_fixed(ours.a[1], 5)});
    const std::string key = lines[k].dir + "_v" + fmt(lines[k].v);
    c.value("loo_a0_" + key, fmt_fixed(a(0), 4));
    c.value("loo_a1_" + key, fmt_fixed(a(1), 5), "1/MPa");
  }
  c.save(loo, "table_5_16_leave_one_out");
}

}  // namespace

void map_sensitivity(Chapter& c, const Inputs& in, const FeMaps& m) {
  const std::vector<double> pins{12.7, 25.4};
  const std::vector<Source> sources = sources_run(m);
  const Changes ch = sensitivity_tables(c, in, m, pins, sources);
  sensitivity_summary(c, sources, ch);
  // Map moments implied by Table 5.16 (the thesis's maps are not printed).
  // Rows: the 6 lines; for pin j, F_j = c_j a0 S1_j + c_j^2 a1 S2_j.
  const std::vector<LineIn> lines = thesis_lines(in);
  const Implied implied{in, m, lines};
  implied_moments(c, m, pins, implied);
  leave_one_out(c, in, m, pins, lines, implied);
}

}  // namespace ch5
