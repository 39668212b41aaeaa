// OpenRadioss export: /FRICTION with the generalized viscous law and
// /FRIC_ORIENT (see export.hpp for the contract).
//
// Layout: OpenRadioss's own reader definition,
// hm_cfg_files/config/CFG/radioss2020/FRICTION/friction.cfg (format radioss2020):
//   /FRICTION/fric_ID
//   title                                              (100 characters)
//   Ifric Ifiltr Xfreq Iform                           %10d%10d%20lg%10d
//   C1 C2 C3 C4 C5                                     5 x %20lg
//   C6 Fric VIS_F                                      3 x %20lg
//   per pair: grpart_ID1 grpart_ID2 part_ID1 part_ID2 (blank) Idir
//                                                      %10d%10d%10d%10d 10 blanks %10d
//             C1..C5 and C6 Fric VIS_F of direction 1, and of direction 2 when Idir = 1.
// and fric_orient.cfg:
//   /FRIC_ORIENT/ID, title, then per part "%10d%10d" (grpart_ID, part_ID) and
//   VX VY VZ skew_ID phi Iorth as %20lg%20lg%20lg%10d%20lg%10d.
// The engine (engine/source/interfaces/int07/i7for3.F, MFROT = 1) evaluates
//   mu = Fric + (C1 + C4 P) P + (C2 + C3 P) V + C5 V^2,  mu = max(mu, 1e-30),
// with P = -F_N / (area of the main segment) and V the tangential speed.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "core/csv.hpp"
#include "loop/export.hpp"
#include "loop/export_detail.hpp"

namespace drawbend::loop {

using namespace detail;

double radioss_mu(const std::vector<double>& c, double p, double v) {
  return c[0] + (c[1] + c[4] * p) * p + (c[2] + c[3] * p) * v + c[5] * v * v;
}

namespace {

std::vector<double> printed(const std::vector<double>& c) {
  std::vector<double> r(c.size());
  for (size_t k = 0; k < c.size(); ++k) r[k] = as_printed(c[k], 20, 10);
  return r;
}

// Max relative error |poly - law| / law of printed coefficients over p in the
// domain and v in [v0, v1], on an n x n grid.
double rel_error(const std::vector<double>& c, const analysis::FrictionSurface& s, double v0, double v1, int n = 161) {
  double e = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const double p = s.p_min + (s.p_max - s.p_min) * a / (n - 1), v = v0 + (v1 - v0) * b / (n - 1);
      const double law = law_mu(s, p, v);
      e = std::max(e, std::abs(std::max(radioss_mu(c, p, v), 0.0) - law) / std::max(law, 1e-4));
    }
  return e;
}

}  // namespace

// Lawson's algorithm: weighted least squares whose weights grow where the
// relative residual is large converges to the minimax (Chebyshev) fit.  In
// scaled coordinates x, y in [-1, 1] (the same quadratic space), converted to
// the monomials of p and v at the end.
std::vector<double> radioss_fit(const analysis::FrictionSurface& s, double v0, double v1) {
  const int n = 41;
  const double a = 2 / (s.p_max - s.p_min), b = -(s.p_max + s.p_min) / (s.p_max - s.p_min);
  const double c = 2 / (v1 - v0), d = -(v1 + v0) / (v1 - v0);
  Eigen::MatrixXd A(n * n, 6);
  Eigen::VectorXd rhs(n * n), w = Eigen::VectorXd::Constant(n * n, 1.0 / (n * n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -1 + 2.0 * i / (n - 1), y = -1 + 2.0 * j / (n - 1);
      const double p = (x - b) / a, v = (y - d) / c;
      // Residuals relative to the law, the law floored at 1e-4 as rel_error floors it: where
      // mu < 1e-4 (a frictionless model, mu = 0) the fit aims at mu itself, not at 1e-4 (which
      // missed mu = 0 by "100 %" and refused it); elsewhere the target is 1, bit for bit as before.
      const double mu = law_mu(s, p, v), law = std::max(mu, 1e-4);
      A.row(i * n + j) << 1 / law, x / law, y / law, x * y / law, x * x / law, y * y / law;
      rhs[i * n + j] = mu / law;
    }
  Eigen::VectorXd best;
  double best_err = INFINITY;
  for (int it = 0; it < 300; ++it) {
    const Eigen::VectorXd sw = w.cwiseSqrt();
    const Eigen::VectorXd k = (sw.asDiagonal() * A).colPivHouseholderQr().solve(sw.asDiagonal() * rhs);
    const Eigen::VectorXd r = (A * k - rhs).cwiseAbs();
    if (r.maxCoeff() < best_err) best_err = r.maxCoeff(), best = k;
    w = w.cwiseProduct(r);
    const double sum = w.sum();
    if (!(sum > 0)) break;
    w /= sum;
  }
  const Eigen::VectorXd& k = best;
  // mu = k0 + k1 x + k2 y + k3 x y + k4 x^2 + k5 y^2 with x = a p + b, y = c v + d
  return {k[0] + k[1] * b + k[2] * d + k[3] * b * d + k[4] * b * b + k[5] * d * d,
          k[1] * a + k[3] * a * d + 2 * k[4] * a * b,
          k[2] * c + k[3] * b * c + 2 * k[5] * c * d,
          k[3] * a * c,
          k[4] * a * a,
          k[5] * c * c};
}

namespace {

// The speed bands of the export: edges[k] to edges[k + 1] with the printed
// coefficients coef[k][direction] and their largest relative error err[k].
struct Bands {
  std::vector<double> edges;
  std::vector<std::vector<std::vector<double>>> coef;  // [band][direction]
  std::vector<double> err;                              // per band
  double worst = 0;
};

// Speed bands: the data's edges are band edges when the fitted range crosses
// them (the law is flat in v beyond them, with a kink at the edge); then the
// worst band is halved until every band is within the bound (at most 8).
// Throws when even 8 bands miss the bound.
Bands fit_bands(const ExportModel& m, const ExportOptions& o, const std::vector<analysis::FrictionSurface>& dirs,
                double v0, double v1) {
  Bands b;
  std::vector<double>& edges = b.edges;
  edges.push_back(v0);
  for (double e : {m.rd.v_min, m.rd.v_max})
    if (e > v0 && e < v1) edges.push_back(e);
  edges.push_back(v1);
  auto fit_band = [&](size_t k) {
    std::vector<std::vector<double>> c;
    double e = 0;
    for (const auto& s : dirs) {
      c.push_back(printed(radioss_fit(s, edges[k], edges[k + 1])));
      e = std::max(e, rel_error(c.back(), s, edges[k], edges[k + 1]));
    }
    return std::make_pair(c, e);
  };
  for (size_t k = 0; k + 1 < edges.size(); ++k) {
    auto [c, e] = fit_band(k);
    b.coef.push_back(c);
    b.err.push_back(e);
  }
  b.worst = *std::max_element(b.err.begin(), b.err.end());
  while (b.worst > o.max_rel_error && b.coef.size() < 8) {
    const size_t k = std::max_element(b.err.begin(), b.err.end()) - b.err.begin();
    edges.insert(edges.begin() + k + 1, std::stod(num(0.5 * (edges[k] + edges[k + 1]), 6)));
    b.coef.insert(b.coef.begin() + k + 1, std::vector<std::vector<double>>());
    b.err.insert(b.err.begin() + k + 1, 0.0);
    for (size_t j : {k, k + 1}) std::tie(b.coef[j], b.err[j]) = fit_band(j);
    b.worst = *std::max_element(b.err.begin(), b.err.end());
  }
  if (b.worst > o.max_rel_error)
    throw std::runtime_error("OpenRadioss: the generalized viscous law misses the friction model by " +
                             fmt(100 * b.worst, 3) + " % (relative) even in " + std::to_string(b.coef.size()) + " speed bands; the bound is " +
                             fmt(100 * o.max_rel_error, 3) + " % (--max-rel-error), or narrow --speed-band");
  return b;
}

// Largest |mu - law| of the bands' polynomials, as a reader picks the band,
// over p 0 to 2 p_max and v 0 to 5 v_max of each direction (extrapolated).
double error_outside(const std::vector<analysis::FrictionSurface>& dirs, const Bands& b) {
  const int bands = static_cast<int>(b.coef.size());
  auto poly_at = [&](int dir, double p, double v) {  // the band's polynomial as a reader picks it
    int k = 0;
    while (k + 1 < bands && v > b.edges[k + 1]) ++k;
    return std::max(radioss_mu(b.coef[k][dir], p, v), 0.0);
  };
  double e = 0;
  for (size_t dd = 0; dd < dirs.size(); ++dd)
    for (int a = 0; a <= 60; ++a)
      for (int bb = 0; bb <= 60; ++bb) {
        const double p = 2 * dirs[dd].p_max * a / 60, v = 5 * dirs[dd].v_max * bb / 60;
        e = std::max(e, std::abs(poly_at(static_cast<int>(dd), p, v) - law_mu(dirs[dd], p, v)));
      }
  return e;
}

// What the orthotropic pair does in OpenRadioss bd4557b (docs/exports.md).
const char* const kOrthoNote =
    "# direction: orthotropic pair, Idir = 1 (direction 1 = RD, direction 2 = TD, /FRIC_ORIENT below).\n"
    "#   DOES NOT GIVE THE LAW in OpenRadioss bd4557b (its engine, block slide on a TYPE7 interface,\n"
    "#   Iform = 2, real density and mass-scaled, docs/exports.md of drawbend):\n"
    "#   - direction 1 loses C1-C5: the engine reads them one pair block past where the starter puts\n"
    "#     them (engine/source/interfaces/int07/frictionparts_model.F line 202, FRICTIONPARTS_MODEL_ORTHO:\n"
    "#     TABCOEF_FRIC(LENC+2*LENC*ADRCOEF+J+2) for (ADRCOEF-1)); measured F_T/F_N along RD 0.404, 3.13,\n"
    "#     0.0101 where the law is 0.053, 0.043, 0.030 (and TD -32 % in the 2nd band).  With that one\n"
    "#     index corrected (a local build) RD gave the law within 1.2 % (the polynomial within 0.15 %).\n"
    "#   - direction k's speed terms take the SIGNED speed v . dir_k floored at 1e-30 (int07/i7for3.F),\n"
    "#     and dir_2 = n x dir_1 (n: the main segment's normal): sliding against dir_k drops C2, C3, C5\n"
    "#     (along -dir_2: Fric + C1 p + C4 p^2 exactly, +6 to +45 % against the law; along -dir_1 with the\n"
    "#     index corrected: +16 to +311 %).  So a sheet sliding both ways cannot get the speed terms in both.\n"
    "#   - the starter puts the directions on the shells of the interface's MAIN surface\n"
    "#     (interf1/inintr_orthdirfric.F): for the sheet's RD the sheet must be the main surface\n"
    "#     (/FRIC_ORIENT on the solid secondary part instead: -38 %); with Iform = 1 the test blew up.\n"
    "#   Use the isotropic form (--direction rd|td|mean): it gave the law in the same engine.\n";

// The '#' header of the file: provenance, the law written, its error inside
// and outside the fitted range, the bands, the direction and what to set by hand.
std::string radioss_header(const ExportModel& m, const ExportOptions& o, const Bands& b, const ExportResult& r,
                           double v0, double v1) {
  std::ostringstream h;
  const std::string rel = fmt(std::ceil(1000 * 100 * b.worst) / 1000, 4);
  h << "# drawbend export to OpenRadioss (format radioss2020: friction.cfg, fric_orient.cfg)\n"
    << provenance(m, "#", o.direction)
    << "# law written: /FRICTION Ifric = 1 (generalized viscous), Iform = 2 (stiffness, incremental),\n"
    << "#   mu = Fric + C1 p + C2 v + C3 p v + C4 p^2 + C5 v^2, p contact pressure [MPa], v sliding speed [mm/s];\n"
    << "#   fitted to the law over p " << fmt_shortest(m.rd.p_min) << " to " << fmt_shortest(m.rd.p_max) << " MPa, v "
    << fmt_shortest(v0) << " to " << fmt_shortest(v1) << " mm/s (--speed-band), minimising the largest relative error.\n"
    << "# max relative error inside the fitted range: " << rel << " %\n"
    << "# outside it the polynomial EXTRAPOLATES (OpenRadioss has no clamp; the law holds the edge value):\n"
    << "#   max |mu - law| over p 0 to " << fmt_shortest(2 * m.rd.p_max) << " MPa, v 0 to " << fmt_shortest(5 * m.rd.v_max)
    << " mm/s: " << fmt(r.max_error_outside, 3) << "; keep p and v in the range above.\n";
  if (r.bands > 1) {
    h << "# one quadratic misses the law by more than " << fmt(100 * o.max_rel_error, 3) << " %: " << r.bands
      << " speed bands, one /FRICTION each; point your interface (fric_ID) at the band of your process speeds:\n";
  }
  for (int k = 0; k < r.bands; ++k)
    h << "# band " << k + 1 << ": /FRICTION/" << o.friction_id + k << " for v " << fmt_shortest(b.edges[k]) << " to "
      << fmt_shortest(b.edges[k + 1]) << " mm/s\n";
  if (o.direction == "ortho") h << kOrthoNote;
  else h << "# direction: isotropic pair law for " << o.direction << " (--direction rd|td|mean|ortho).\n";
  h << "# interfaces that honour /FRICTION: /INTER/TYPE7, TYPE24, TYPE25 (also 11, 19): set fric_ID (columns\n"
    << "#   91-100 of the Ifric card of /INTER/TYPE7) to the /FRICTION ID.  Units of the deck: N, mm, s (/BEGIN).\n"
    << "# parts: sheet " << o.sheet_part << ", tool " << o.tool_part
    << " (--parts); the engine takes p = nodal normal force / area of the main\n"
    << "#   (tool) segment: mesh the tool about as fine as the sheet.\n"
    << "# Iform = 2 (written) is the form that gave the law.  Iform = 0 or 1 (viscous, total; the starter\n"
    << "#   reads 0 as 1) caps the friction force per node at sqrt(2 K m VIS_F) v (K contact stiffness, m\n"
    << "#   nodal mass; int07/i7for3.F): measured on a block of real density at 10 mm/s, F_T/F_N 0.0267,\n"
    << "#   0.0133, 0.0082 at 4, 8, 13 MPa (-50, -80, -90 % against the law: one force for every p); the\n"
    << "#   polynomial within 0.15 % at 50 and 95 mm/s, and at 10 mm/s with the mass scaled x1000.\n"
    << "# SET BY HAND: fric_ID of your interface = the /FRICTION of your speed band (above);\n#   "
    << (o.parts_placeholder ? "part IDs " + std::to_string(o.sheet_part) + " (sheet) and " + std::to_string(o.tool_part) +
                                  " (tool) are drawbend loop's PLACEHOLDERS: put yours (drawbend export --parts);\n#   "
                            : std::string())
    << "/FRIC_ORIENT VX VY VZ = the rolling direction in your deck's axes (--rd-vector); /BEGIN units Mg, mm, s.\n";
  return h.str();
}

// The cards: one /FRICTION per band (the default law, then the sheet-tool
// pair, per direction), and /FRIC_ORIENT with the rolling direction.
std::string radioss_cards(const ExportModel& m, const ExportOptions& o, const Bands& b) {
  const bool ortho = o.direction == "ortho";
  std::ostringstream o_;
  auto block = [&](const std::vector<double>& c) {
    o_ << "#                 C1                  C2                  C3                  C4                  C5\n"
       << field(c[1], 20, 10) << field(c[2], 20, 10) << field(c[3], 20, 10) << field(c[4], 20, 10) << field(c[5], 20, 10) << "\n"
       << "#                 C6                FRIC               VIS_F\n"
       << field(0, 20) << field(c[0], 20, 10) << field(1, 20) << "\n";
  };
  for (size_t k = 0; k < b.coef.size(); ++k) {
    o_ << "/FRICTION/" << o.friction_id + static_cast<int>(k) << "\n"
       << "drawbend " << (m.lubricant.empty() ? std::string("friction model") : m.lubricant) << " " << o.direction
       << " v " << fmt_shortest(b.edges[k]) << "-" << fmt_shortest(b.edges[k + 1]) << " mm/s\n"
       << "#    Ifric    Ifiltr               Xfreq     Iform\n"
       << ifield(1, 10) << ifield(0, 10) << field(0, 20) << ifield(2, 10) << "\n";
    block(b.coef[k][0]);  // default law of the pairs not listed
    o_ << "#grpartID1 grpartID2   partID1   partID2                IDIR\n"
       << ifield(0, 10) << ifield(0, 10) << ifield(o.sheet_part, 10) << ifield(o.tool_part, 10) << std::string(10, ' ')
       << ifield(ortho ? 1 : 0, 10) << "\n";
    block(b.coef[k][0]);
    if (ortho) block(b.coef[k][1]);
  }
  const double vn = std::hypot(o.rd_vector[0], o.rd_vector[1], o.rd_vector[2]);
  o_ << "/FRIC_ORIENT/" << o.friction_id << "\nrolling direction of the sheet part " << o.sheet_part << "\n"
     << "#GRPART_ID   PART_ID\n" << ifield(0, 10) << ifield(o.sheet_part, 10) << "\n"
     << "#                 VX                  VY                  VZ   SKEW_ID                 PHI     IORTH\n"
     << field(o.rd_vector[0] / vn, 20) << field(o.rd_vector[1] / vn, 20) << field(o.rd_vector[2] / vn, 20)
     << ifield(0, 10) << field(0, 20) << ifield(0, 10) << "\n";
  return o_.str();
}

}  // namespace

ExportResult export_openradioss(const ExportModel& m, const ExportOptions& o) {
  o.validate("openradioss");
  ExportResult r;
  r.format = "openradioss";
  std::vector<analysis::FrictionSurface> dirs;
  if (o.direction == "ortho") dirs = {m.rd, m.td};
  else dirs = {direction_surface(m, o.direction)};
  const double v0 = o.band_v_min != 0 || o.band_v_max != 0 ? o.band_v_min : m.rd.v_min;
  const double v1 = o.band_v_min != 0 || o.band_v_max != 0 ? o.band_v_max : m.rd.v_max;
  // A band outside the model's measured speeds fits the surface where the
  // solver clamps it to its edge: a valid polynomial, but not from data.
  if (v0 < m.rd.v_min || v1 > m.rd.v_max)
    std::cerr << "warning: --speed-band " << fmt_shortest(v0) << "," << fmt_shortest(v1)
              << " mm/s reaches outside the model's measured speeds (" << fmt_shortest(m.rd.v_min) << " to "
              << fmt_shortest(m.rd.v_max) << " mm/s); there mu is the surface's edge value, not a measurement\n";
  const Bands b = fit_bands(m, o, dirs, v0, v1);
  r.bands = static_cast<int>(b.coef.size());
  r.max_error = b.worst;
  r.max_error_outside = error_outside(dirs, b);
  r.text = radioss_header(m, o, b, r, v0, v1) + radioss_cards(m, o, b);
  return r;
}

}  // namespace drawbend::loop
