// Friction-model export to LS-DYNA, OpenRadioss and Abaqus; see export.hpp.
//
// Manual pages the formats follow:
//  * LS-DYNA Keyword User's Manual Vol. I, *CONTACT, Card 2: FS = -2 takes the
//    friction coefficient from the table FD (*DEFINE_TABLE: one value per
//    curve, here the contact pressure; each *DEFINE_CURVE mu against the
//    relative sliding speed); *DEFINE_FRICTION_ORIENTATION for direction-dependent
//    coefficients.  Keyword summary used: https://2021.help.altair.com/2021/hwsolvers/
//    rad/topics/solvers/rad/contact_automatic_surface_to_surface_lsdyna_r.htm and
//    https://2021.help.altair.com/2021/hwdesktop/hm/topics/pre_processing/entities/frictions_r.htm
//  * OpenRadioss / Radioss Starter /FRICTION (Ifric, Idir, C1-C6, Fric, VISF):
//    https://2021.help.altair.com/2021/hwsolvers/rad/topics/solvers/rad/friction_starter_r.htm
//    and the friction formulations of the interfaces (generalized viscous law,
//    Ifric = 1): https://2021.help.altair.com/2021/hwsolvers/rad/topics/solvers/rad/friction_interface_r.htm
//    orthotropic directions: .../fric_orient_starter_r.htm (/FRIC_ORIENT).
//  * Abaqus Keywords Reference, *FRICTION (ANISOTROPIC: data lines mu_1, mu_2,
//    slip rate, contact pressure, temperature, field variables; linear
//    interpolation between tabulated points).
#include "loop/export.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <Eigen/Dense>
#include <toml++/toml.h>

#include "core/file_gate.hpp"
#include "core/csv.hpp"
#include "core/toml_read.hpp"
#include "friction/surface_law.hpp"

namespace drawbend::loop {

namespace {

std::string num(double v, int prec = 6) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", prec, v);
  return b;
}

std::string field(double v, int width) {  // fixed-width field (one blank at least) with the most digits
  for (int prec = width - 1; prec >= 1; --prec) {
    const std::string s = num(v, prec);
    if (static_cast<int>(s.size()) < width) return std::string(width - s.size(), ' ') + s;
  }
  return num(v, 1);
}

std::vector<double> grid(double a, double b, int n) {
  std::vector<double> g(n);
  for (int k = 0; k < n; ++k) g[k] = n > 1 ? a + (b - a) * k / (n - 1) : a;
  return g;
}

// Bilinear interpolation in a table mu[i][j] over ps[i], vs[j] (both solvers
// interpolate linearly between tabulated points).
double bilinear(const std::vector<double>& ps, const std::vector<double>& vs,
                const std::vector<std::vector<double>>& mu, double p, double v) {
  auto locate = [](const std::vector<double>& x, double t, size_t& i, double& w) {
    i = 0;
    while (i + 2 < x.size() && t > x[i + 1]) ++i;
    w = (t - x[i]) / (x[i + 1] - x[i]);
  };
  size_t i, j;
  double a, b;
  locate(ps, p, i, a);
  locate(vs, v, j, b);
  return (1 - a) * ((1 - b) * mu[i][j] + b * mu[i][j + 1]) + a * ((1 - b) * mu[i + 1][j] + b * mu[i + 1][j + 1]);
}

// Max error of a representation f against the law on a grid 4x finer than n.
template <class F>
double check_error(const analysis::FrictionSurface& s, F f, int n = 11) {
  double e = 0;
  for (double p : grid(s.p_min, s.p_max, 4 * (n - 1) + 1))
    for (double v : grid(s.v_min, s.v_max, 4 * (n - 1) + 1)) e = std::max(e, std::abs(f(p, v) - s(p, v)));
  return e;
}

std::vector<std::vector<double>> tabulate(const analysis::FrictionSurface& s, const std::vector<double>& ps,
                                          const std::vector<double>& vs, int prec) {
  std::vector<std::vector<double>> t(ps.size(), std::vector<double>(vs.size()));
  for (size_t i = 0; i < ps.size(); ++i)
    for (size_t j = 0; j < vs.size(); ++j) t[i][j] = std::stod(num(s(ps[i], vs[j]), prec));  // as printed
  return t;
}

}  // namespace

ExportModel read_friction_model(const std::string& path) {
  const toml::table t = parse_toml_file(path);
  const auto* f = t["friction"].as_table();
  if (!f) throw InputError(path + ": no [friction] table (write it with `drawbend loop`)");
  const auto law = (*f)["law"].value<std::string>();
  if (!law || *law != "surface")
    throw InputError(path + ": [friction] law must be \"surface\" (the nine-node surface) for export");
  const auto nodes = (*f)["nodes"].value<std::string>();
  if (!nodes) throw InputError(path + ": [friction] has no 'nodes' file");
  friction::SurfaceDomain d;
  d.p_min = (*f)["p_min"].value<double>().value_or(d.p_min);
  d.p_max = (*f)["p_max"].value<double>().value_or(d.p_max);
  d.v_min = (*f)["v_min"].value<double>().value_or(d.v_min);
  d.v_max = (*f)["v_max"].value<double>().value_or(d.v_max);
  const std::filesystem::path file = std::filesystem::path(path).parent_path() / *nodes;
  ExportModel m;
  name_input(file.string(), path + ": [friction] nodes");  // read through the file gate (core/file_gate.hpp)
  std::tie(m.rd, m.td) = friction::load_surface_nodes(file.string(), d);
  m.source = path;
  return m;
}

std::vector<double> radioss_fit(const analysis::FrictionSurface& s) {
  const auto ps = grid(s.p_min, s.p_max, 21), vs = grid(s.v_min, s.v_max, 21);
  Eigen::MatrixXd A(ps.size() * vs.size(), 6);
  Eigen::VectorXd b(A.rows());
  int k = 0;
  for (double p : ps)
    for (double v : vs) {
      A.row(k) << 1, p, v, p * v, p * p, v * v;
      b[k++] = s(p, v);
    }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  return {c[0], c[1], c[2], c[3], c[4], c[5]};
}

double radioss_mu(const std::vector<double>& c, double p, double v) {
  return c[0] + c[1] * p + c[2] * v + c[3] * p * v + c[4] * p * p + c[5] * v * v;
}

ExportResult export_lsdyna(const ExportModel& m, int n_p, int n_v) {
  ExportResult r;
  r.format = "lsdyna";
  const auto ps = grid(m.rd.p_min, m.rd.p_max, n_p), vs = grid(m.rd.v_min, m.rd.v_max, n_v);
  std::ostringstream o;
  int curve = 9001;
  for (int dir = 0; dir < 2; ++dir) {
    const auto& s = dir == 0 ? m.rd : m.td;
    const auto tab = tabulate(s, ps, vs, 7);
    r.max_error = std::max(r.max_error, check_error(s, [&](double p, double v) { return bilinear(ps, vs, tab, p, v); }, n_p));
    const int table = dir == 0 ? 9000 : 9100;
    o << "$ mu(p, v) " << (dir == 0 ? "RD" : "TD") << ": table " << table << ", values = contact pressure [MPa], "
      << "curves = mu against sliding speed [mm/s]\n*DEFINE_TABLE\n$     TBID\n" << field(table, 10) << "\n";
    for (double p : ps) o << field(p, 20) << "\n";
    for (size_t i = 0; i < ps.size(); ++i) {
      o << "*DEFINE_CURVE\n$     LCID\n" << field(curve++, 10) << "\n";
      for (size_t j = 0; j < vs.size(); ++j) o << field(vs[j], 20) << field(tab[i][j], 20) << "\n";
    }
  }
  std::ostringstream h;
  h << "$ drawbend export: friction model " << m.source << " (units N, mm, s, MPa)\n"
    << "$ *CONTACT card 2: FS = -2, FD = 9000 (the RD table); TD table 9100 for the orthotropic pair\n"
    << "$ (*DEFINE_FRICTION_ORIENTATION, angle 90 deg from the rolling direction).\n"
    << "$ Linear interpolation of this table differs from the nine-node law by at most " << num(r.max_error, 3)
    << " in mu over p " << num(m.rd.p_min) << "-" << num(m.rd.p_max) << " MPa, v " << num(m.rd.v_min) << "-"
    << num(m.rd.v_max) << " mm/s.\n";
  r.text = h.str() + o.str();
  return r;
}

ExportResult export_openradioss(const ExportModel& m) {
  ExportResult r;
  r.format = "openradioss";
  std::vector<double> c[2];
  for (int dir = 0; dir < 2; ++dir) {
    const auto& s = dir == 0 ? m.rd : m.td;
    c[dir] = radioss_fit(s);
    for (double& x : c[dir]) x = std::stod(field(x, 10));  // as printed
    r.max_error = std::max(r.max_error, check_error(s, [&](double p, double v) { return radioss_mu(c[dir], p, v); }));
  }
  std::ostringstream o;
  o << "# drawbend export: friction model " << m.source << " (unit system N, mm, s, MPa: declare it with /UNIT)\n"
    << "# generalized viscous law (Ifric = 1): mu = Fric + C1 p + C2 v + C3 p v + C4 p^2 + C5 v^2,\n"
    << "# p contact pressure [MPa], v sliding speed [mm/s]; least-squares fit to the nine-node surface,\n"
    << "# max |error| " << num(r.max_error, 3) << " in mu over p " << num(m.rd.p_min) << "-" << num(m.rd.p_max)
    << " MPa, v " << num(m.rd.v_min) << "-" << num(m.rd.v_max) << " mm/s.\n"
    << "# Idir = 1: first coefficient block direction 1 = RD, second = TD (orient with /FRIC_ORIENT).\n"
    << "# Replace the part IDs (0) with yours.\n"
    << "/FRICTION/1\ndrawbend friction model\n"
    << "#    Ifric    Ifiltr     Xfreq     Iform\n         1         0         0         0\n";
  auto block = [&](const std::vector<double>& k) {
    o << "#       C1        C2        C3        C4        C5\n"
      << field(k[1], 10) << field(k[2], 10) << field(k[3], 10) << field(k[4], 10) << field(k[5], 10) << "\n"
      << "#       C6      Fric      VISF\n" << field(0, 10) << field(k[0], 10) << field(1, 10) << "\n";
  };
  block(c[0]);  // default (RD)
  o << "#grpart_ID1grpart_ID2  part_ID1  part_ID2      Idir\n         0         0         0         0         1\n";
  block(c[0]);
  block(c[1]);
  r.text = o.str();
  return r;
}

ExportResult export_abaqus(const ExportModel& m, int n_p, int n_v) {
  ExportResult r;
  r.format = "abaqus";
  const auto ps = grid(m.rd.p_min, m.rd.p_max, n_p), vs = grid(m.rd.v_min, m.rd.v_max, n_v);
  const auto trd = tabulate(m.rd, ps, vs, 7), ttd = tabulate(m.td, ps, vs, 7);
  r.max_error = std::max(check_error(m.rd, [&](double p, double v) { return bilinear(ps, vs, trd, p, v); }, n_p),
                         check_error(m.td, [&](double p, double v) { return bilinear(ps, vs, ttd, p, v); }, n_p));
  std::ostringstream o;
  o << "** drawbend export: friction model " << m.source << " (units N, mm, s, MPa)\n"
    << "** mu_1 along the first local slip direction (RD), mu_2 across it (TD); slip rate [mm/s], contact pressure\n"
    << "** [MPa]; linear interpolation differs from the nine-node law by at most " << num(r.max_error, 3) << " in mu.\n"
    << "** Put under your *SURFACE INTERACTION; orient direction 1 with the contact's local axes (RD).\n"
    << "*FRICTION, ANISOTROPIC\n";
  for (size_t i = 0; i < ps.size(); ++i)
    for (size_t j = 0; j < vs.size(); ++j)
      o << num(trd[i][j], 7) << ", " << num(ttd[i][j], 7) << ", " << num(vs[j], 7) << ", " << num(ps[i], 7) << "\n";
  r.text = o.str();
  return r;
}

}  // namespace drawbend::loop
