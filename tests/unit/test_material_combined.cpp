// CombinedPlasticity (Chaboche / split kinematic hardening, von Mises or Hill'48)
// and Hill48, against closed forms.  E = 70000 MPa, nu = 0.33.
//
// Closed-form answers:
//  - Split form, monotonic uniaxial tension (any beta): sigma_xx = sigma(eps_p), the
//    isotropic curve, to round-off (relative 1e-9: the lateral-stress iteration's tolerance).
//  - Split form, reversal after eps_p: compression re-yields at sigma(eps_p) - 2 R(eps_p),
//    R = sigma_0 + (1 - beta)(sigma(eps_p) - sigma_0).
//  - One Armstrong-Frederick term on a constant isotropic yield sigma_0 (perfectly plastic
//    curve), uniaxial: X = (C/gamma)(1 - exp(-gamma eps_p)), sigma = sigma_0 + X; after a
//    reversal at eps_p1, compression yields at X(eps_p1) - sigma_0.  Backward Euler is first
//    order: with plastic steps dp = 2e-5 and gamma = 20 the relative error is below
//    gamma dp = 4e-4, so the check is 1e-3 of C/gamma.
//  - A strain-controlled uniaxial cycle (+-2 %, two AF terms) matches an independent RK4
//    integration of the 1D equations (sigma = E(eps - eps_p), |sigma - X| = sigma_0,
//    dX_k = C_k d eps_p - gamma_k X_k |d eps_p|) within 0.5 MPa (first-order return mapping at
//    strain steps 1e-5).
//  - Hill'48 from r-values: uniaxial tension at 0, 45 and 90 deg to RD returns r0, r45, r90
//    (from the plastic strain increments: perfectly plastic, so no elastic part) and
//    sigma_t/sigma_0 = Hill48::uniaxial_ratio(t) (closed form in hill48.hpp), relative 1e-8.
//  - Hill'48 from stress ratios returns s45, s90 and sb (equibiaxial) exactly.
//  - A rotated sheet (RD, TD, ND turned by an arbitrary rotation, loading turned with them)
//    gives the rotated stress of the unrotated problem, relative 1e-10.
//  - Invalid parameters (r <= 0, gamma < 0, C < 0, beta outside [0, 1], 4 terms) throw.
#define BOOST_TEST_MODULE material_combined
#include <boost/test/unit_test.hpp>
#include <array>
#include <cmath>
#include <vector>

#include "material/combined_plasticity.hpp"
#include "material/hill48.hpp"
#include "material/sheet_frame.hpp"

using namespace drawbend::material;
using V6 = std::array<double, 6>;

namespace {
constexpr double E = 70000.0, NU = 0.33, RHO = 2.7e-9;

HardeningCurve perfect(double s0) { return HardeningCurve({0.0}, {s0}); }
HardeningCurve curve() { return HardeningCurve({0.0, 0.02, 0.1, 0.3}, {100.0, 150.0, 220.0, 280.0}); }

// Solve A x = b (n <= 6) by Gaussian elimination with partial pivoting.
void solve(int n, double A[6][6], double b[6]) {
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(A[i][k]) > std::abs(A[p][k])) p = i;
    std::swap(A[k], A[p]);
    std::swap(b[k], b[p]);
    for (int i = k + 1; i < n; ++i) {
      const double f = A[i][k] / A[k][k];
      for (int j = k; j < n; ++j) A[i][j] -= f * A[k][j];
      b[i] -= f * b[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    for (int j = k + 1; j < n; ++j) b[k] -= A[k][j] * b[j];
    b[k] /= A[k][k];
  }
}

// One mixed-control increment: strain increment e along x, and the 5 other strain
// increments by Newton (finite-difference Jacobian) such that the other stress components
// vanish (uniaxial), or, with `biaxial`, such that sigma_yy = sigma_xx and the rest vanish.
// Returns the accepted strain increment.
V6 mixed_step(const Material& m, double e, V6& s, std::vector<double>& st, bool biaxial) {
  V6 d{};
  d[0] = e;
  d[1] = biaxial ? e : -0.5 * e;
  d[2] = biaxial ? -2 * e : -0.5 * e;
  auto eval = [&](const V6& dd, double r[5], double& sxx) {
    V6 out = s;
    std::vector<double> tmp = st;
    m.update(dd.data(), out.data(), tmp.data());
    r[0] = biaxial ? out[1] - out[0] : out[1];
    for (int k = 2; k < 6; ++k) r[k - 1] = out[k];
    sxx = out[0];
  };
  for (int it = 0; it < 50; ++it) {
    double r[5], sxx;
    eval(d, r, sxx);
    double err = 0;
    for (double v : r) err = std::max(err, std::abs(v));
    if (err < 1e-11 * (1.0 + std::abs(sxx))) break;
    double J[6][6], b[6];
    for (int j = 1; j < 6; ++j) {
      V6 dp = d;
      const double h = 1e-9;
      dp[j] += h;
      double rp[5], sp;
      eval(dp, rp, sp);
      for (int i = 0; i < 5; ++i) J[i][j - 1] = (rp[i] - r[i]) / h;
    }
    for (int i = 0; i < 5; ++i) b[i] = -r[i];
    solve(5, J, b);
    for (int j = 1; j < 6; ++j) d[j] += b[j - 1];
  }
  m.update(d.data(), s.data(), st.data());
  return d;
}
V6 uniaxial_step(const Material& m, double e, V6& s, std::vector<double>& st) { return mixed_step(m, e, s, st, false); }

std::vector<double> fresh(const Material& m, const SheetAxes& a = SheetAxes{}) {
  std::vector<double> st(m.state_size());
  m.init_state(st.data(), a);
  return st;
}
}  // namespace

BOOST_AUTO_TEST_CASE(split_form_monotonic_tension_is_the_curve) {
  for (double beta : {0.0, 0.3, 0.7, 1.0}) {
    KinematicHardening k;
    k.beta = beta;
    const CombinedPlasticity m(E, NU, RHO, curve(), k);
    V6 s{};
    auto st = fresh(m);
    for (int i = 0; i < 400; ++i) {
      uniaxial_step(m, 1e-3 * (i < 10 ? 0.1 : 1.0), s, st);
      const double ep = st[0];
      if (ep > 0) BOOST_TEST(std::abs(s[0] - curve().stress(ep)) <= 1e-9 * s[0], "beta " << beta << " ep " << ep);
    }
    BOOST_TEST(st[0] > 0.3);  // past the last table point: the extrapolated slope too
  }
}

BOOST_AUTO_TEST_CASE(split_form_reversal_yields_at_sigma_minus_2R) {
  const double beta = 0.4;
  KinematicHardening k;
  k.beta = beta;
  const CombinedPlasticity m(E, NU, RHO, curve(), k);
  V6 s{};
  auto st = fresh(m);
  for (int i = 0; i < 60; ++i) uniaxial_step(m, 1e-3, s, st);
  const double ep = st[0], sig = curve().stress(ep);
  const double R = 100.0 + (1 - beta) * (sig - 100.0);
  // Unload elastically in small steps until plastic strain grows again.
  double prev = s[0];
  for (int i = 0; i < 100000; ++i) {
    prev = s[0];
    uniaxial_step(m, -2e-6, s, st);
    if (st[0] > ep + 1e-12) break;
  }
  // The reverse yield lies between the last elastic and the first plastic stress.
  const double expect = sig - 2 * R;
  BOOST_TEST(prev >= expect - 1e-6);
  BOOST_TEST(std::abs(s[0] - expect) < 2e-6 * E);
}

BOOST_AUTO_TEST_CASE(armstrong_frederick_closed_form_and_reversal) {
  const double C = 8000, g = 20, s0 = 100;
  KinematicHardening k;
  k.chaboche = {{C, g}};
  const CombinedPlasticity m(E, NU, RHO, perfect(s0), k);
  V6 s{};
  auto st = fresh(m);
  for (int i = 0; i < 5000; ++i) {
    uniaxial_step(m, 2e-5, s, st);
    const double p = st[0];
    if (p <= 0) continue;
    const double X = C / g * (1 - std::exp(-g * p));
    BOOST_TEST(std::abs(s[0] - (s0 + X)) < 1e-3 * C / g, "p " << p);
    // The back stress of the state: X = (3/2) alpha_xx.
    double a[6];
    m.back_stress(st.data(), a);
    BOOST_TEST(std::abs(1.5 * a[0] - (s[0] - s0)) < 1e-6 * s0);
  }
  const double p1 = st[0], X1 = C / g * (1 - std::exp(-g * p1));
  double prev = s[0];
  for (int i = 0; i < 100000; ++i) {
    prev = s[0];
    uniaxial_step(m, -2e-6, s, st);
    if (st[0] > p1 + 1e-12) break;
  }
  BOOST_TEST(prev >= X1 - s0 - 1e-6);
  BOOST_TEST(std::abs(s[0] - (X1 - s0)) < 2e-6 * E + 1e-3 * C / g);
}

// The 1D equations by RK4 in strain, independent of the return mapping.
static double rk4_cycle_stress(const std::vector<double>& path, double C1, double g1, double C2, double g2, double s0,
                               std::vector<double>& out) {
  double sig = 0, X1 = 0, X2 = 0;
  auto rate = [&](double sg, double x1, double x2, double de, double d[3]) {
    const double xi = sg - x1 - x2;
    const double sgn = xi >= 0 ? 1.0 : -1.0;
    const bool plastic = std::abs(xi) >= s0 - 1e-9 && sgn * de > 0;
    if (!plastic) {
      d[0] = E * de;
      d[1] = d[2] = 0;
      return;
    }
    const double h = C1 - g1 * x1 * sgn + C2 - g2 * x2 * sgn;  // dX/d eps_p
    const double dep = E * de / (E + h);                       // plastic strain increment
    d[0] = E * (de - dep);
    d[1] = C1 * dep - g1 * x1 * std::abs(dep);
    d[2] = C2 * dep - g2 * x2 * std::abs(dep);
  };
  out.clear();
  double eps = 0;
  for (double target : path) {
    const int n = static_cast<int>(std::ceil(std::abs(target - eps) / 1e-7));
    const double de = (target - eps) / n;
    for (int i = 0; i < n; ++i) {
      double k1[3], k2[3], k3[3], k4[3];
      rate(sig, X1, X2, de, k1);
      rate(sig + k1[0] / 2, X1 + k1[1] / 2, X2 + k1[2] / 2, de, k2);
      rate(sig + k2[0] / 2, X1 + k2[1] / 2, X2 + k2[2] / 2, de, k3);
      rate(sig + k3[0], X1 + k3[1], X2 + k3[2], de, k4);
      sig += (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]) / 6;
      X1 += (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]) / 6;
      X2 += (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]) / 6;
      // Keep on the yield surface (the rates are first order at its edge).
      const double xi = sig - X1 - X2;
      if (std::abs(xi) > s0) sig = X1 + X2 + (xi > 0 ? s0 : -s0);
    }
    eps = target;
    out.push_back(sig);
  }
  return sig;
}

BOOST_AUTO_TEST_CASE(strain_controlled_cycle_matches_independent_integration) {
  const double C1 = 20000, g1 = 200, C2 = 2000, g2 = 5, s0 = 90;
  KinematicHardening k;
  k.chaboche = {{C1, g1}, {C2, g2}};
  const CombinedPlasticity m(E, NU, RHO, perfect(s0), k);
  // Total axial strain path: 0 -> +2 % -> -2 % -> +2 %, sampled every 0.1 %.
  std::vector<double> path;
  for (int i = 1; i <= 20; ++i) path.push_back(1e-3 * i);
  for (int i = 19; i >= -20; --i) path.push_back(1e-3 * i);
  for (int i = -19; i <= 20; ++i) path.push_back(1e-3 * i);
  std::vector<double> ref;
  rk4_cycle_stress(path, C1, g1, C2, g2, s0, ref);
  V6 s{};
  auto st = fresh(m);
  double eps = 0;
  for (std::size_t j = 0; j < path.size(); ++j) {
    const int n = static_cast<int>(std::lround(std::abs(path[j] - eps) / 1e-5));
    const double de = (path[j] - eps) / n;
    for (int i = 0; i < n; ++i) uniaxial_step(m, de, s, st);
    eps = path[j];
    BOOST_TEST(std::abs(s[0] - ref[j]) < 0.5, "strain " << eps << ": ours " << s[0] << ", RK4 " << ref[j]);
  }
}

// Uniaxial tension at angle t to RD: the sheet axes are turned by -t about ND = z, the load is along x.
static void hill_uniaxial(const Hill48& h, double t, double& ratio, double& r) {
  KinematicHardening none;
  const CombinedPlasticity m(E, NU, RHO, perfect(100.0), none, h);
  const SheetAxes a = sheet_axes({std::cos(t), -std::sin(t), 0.0}, {0.0, 0.0, 1.0});
  V6 s{};
  auto st = fresh(m, a);
  V6 d{};
  for (int i = 0; i < 40; ++i) d = uniaxial_step(m, 1e-3, s, st);
  ratio = s[0] / 100.0;
  r = d[1] / d[2];  // perfectly plastic at constant stress: the increments are all plastic
}

BOOST_AUTO_TEST_CASE(hill48_from_r_values_returns_them) {
  for (const auto& rv : {std::array<double, 3>{0.69, 0.73, 0.87}, std::array<double, 3>{0.66, 0.86, 0.72},
                         std::array<double, 3>{0.525, 0.248, 0.429}}) {
    const Hill48 h = Hill48::from_r_values(rv[0], rv[1], rv[2]);
    const double ang[3] = {0.0, M_PI / 4, M_PI / 2};
    for (int i = 0; i < 3; ++i) {
      double ratio, r;
      hill_uniaxial(h, ang[i], ratio, r);
      BOOST_TEST(std::abs(r - rv[i]) < 1e-8 * rv[i], "angle " << i * 45 << ": r " << r << " vs " << rv[i]);
      BOOST_TEST(std::abs(ratio - h.uniaxial_ratio(ang[i])) < 1e-8);
      BOOST_TEST(std::abs(h.r_value(ang[i]) - rv[i]) < 1e-12);
    }
    double ratio, r;
    hill_uniaxial(h, 0.0, ratio, r);
    BOOST_TEST(std::abs(ratio - 1.0) < 1e-9);  // normalised to RD
  }
}

BOOST_AUTO_TEST_CASE(hill48_from_stress_ratios_returns_them_and_equibiaxial) {
  const double s45 = 0.867, s90 = 0.926, sb = 0.975;
  const Hill48 h = Hill48::from_stress_ratios(s45, s90, sb);
  BOOST_TEST(std::abs(h.uniaxial_ratio(M_PI / 4) - s45) < 1e-12);
  BOOST_TEST(std::abs(h.uniaxial_ratio(M_PI / 2) - s90) < 1e-12);
  BOOST_TEST(std::abs(h.biaxial_ratio() - sb) < 1e-12);
  double ratio, r;
  hill_uniaxial(h, M_PI / 4, ratio, r);
  BOOST_TEST(std::abs(ratio - s45) < 1e-8);
  hill_uniaxial(h, M_PI / 2, ratio, r);
  BOOST_TEST(std::abs(ratio - s90) < 1e-8);
  // Equibiaxial stress (sigma_xx = sigma_yy, x = RD, y = TD, the rest zero): yield at sb sigma_0.
  KinematicHardening none;
  const CombinedPlasticity m(E, NU, RHO, perfect(100.0), none, h);
  V6 s{};
  auto st = fresh(m);
  for (int i = 0; i < 40; ++i) mixed_step(m, 1e-3, s, st, true);
  BOOST_TEST(std::abs(s[0] - sb * 100.0) < 1e-6);
  BOOST_TEST(std::abs(s[1] - sb * 100.0) < 1e-6);
}

BOOST_AUTO_TEST_CASE(rotated_sheet_gives_the_rotated_answer) {
  const Hill48 h = Hill48::from_r_values(0.69, 0.73, 0.87);
  KinematicHardening k;
  k.chaboche = {{5000, 30}};
  const CombinedPlasticity m(E, NU, RHO, curve(), k, h);
  // An arbitrary rotation Q (rows: the turned x, y, z axes).
  const double a = 0.7, b = -0.4, c = 1.1;
  const double Rz[3][3] = {{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}};
  const double Ry[3][3] = {{std::cos(b), 0, std::sin(b)}, {0, 1, 0}, {-std::sin(b), 0, std::cos(b)}};
  const double Rx[3][3] = {{1, 0, 0}, {0, std::cos(c), -std::sin(c)}, {0, std::sin(c), std::cos(c)}};
  double T[3][3] = {}, Q[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k2 = 0; k2 < 3; ++k2) T[i][j] += Rz[i][k2] * Ry[k2][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k2 = 0; k2 < 3; ++k2) Q[i][j] += T[i][k2] * Rx[k2][j];
  auto rot = [&](const V6& v, bool strain) {  // Q A Q^T; strain: engineering shears
    const double f = strain ? 0.5 : 1.0;
    const double A[3][3] = {{v[0], f * v[3], f * v[5]}, {f * v[3], v[1], f * v[4]}, {f * v[5], f * v[4], v[2]}};
    double B[3][3] = {};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k2 = 0; k2 < 3; ++k2)
          for (int l = 0; l < 3; ++l) B[i][j] += Q[i][k2] * A[k2][l] * Q[j][l];
    return V6{B[0][0], B[1][1], B[2][2], B[0][1] / f, B[1][2] / f, B[2][0] / f};
  };
  SheetAxes a0;  // RD = x, TD = y, ND = z
  SheetAxes a1;
  for (int i = 0; i < 3; ++i) {
    a1.rd[i] = Q[i][0];
    a1.td[i] = Q[i][1];
    a1.nd[i] = Q[i][2];
  }
  auto s0 = fresh(m, a0), s1 = fresh(m, a1);
  V6 x0{}, x1{};
  const V6 d{1.2e-3, -0.3e-3, -0.5e-3, 0.8e-3, -0.2e-3, 0.4e-3};  // engineering shears
  for (int i = 0; i < 50; ++i) {
    const V6 di = i < 25 ? d : V6{-d[0], -d[1], -d[2], -d[3], -d[4], -d[5]};
    m.update(di.data(), x0.data(), s0.data());
    const V6 dr = rot(di, true);
    m.update(dr.data(), x1.data(), s1.data());
  }
  const V6 x0r = rot(x0, false);
  for (int k2 = 0; k2 < 6; ++k2) BOOST_TEST(std::abs(x1[k2] - x0r[k2]) < 1e-10 * 300.0, "component " << k2);
  BOOST_TEST(std::abs(s1[0] - s0[0]) < 1e-12);
  BOOST_TEST(s0[0] > 0.01);  // it did flow
}

BOOST_AUTO_TEST_CASE(non_physical_parameters_are_refused) {
  BOOST_CHECK_THROW(Hill48::from_r_values(0.0, 1, 1), std::invalid_argument);
  BOOST_CHECK_THROW(Hill48::from_r_values(1, -0.5, 1), std::invalid_argument);
  BOOST_CHECK_THROW(Hill48::from_stress_ratios(1, 1, 0), std::invalid_argument);
  KinematicHardening k;
  k.beta = 1.2;
  BOOST_CHECK_THROW(CombinedPlasticity(E, NU, RHO, curve(), k), std::invalid_argument);
  k.beta = 0;
  k.chaboche = {{1000, -1}};
  BOOST_CHECK_THROW(CombinedPlasticity(E, NU, RHO, curve(), k), std::invalid_argument);
  k.chaboche = {{-1000, 1}};
  BOOST_CHECK_THROW(CombinedPlasticity(E, NU, RHO, curve(), k), std::invalid_argument);
  k.chaboche = {{1, 1}, {1, 1}, {1, 1}, {1, 1}};
  BOOST_CHECK_THROW(CombinedPlasticity(E, NU, RHO, curve(), k), std::invalid_argument);
  BOOST_CHECK_THROW(HardeningCurve::voce(-1, 10, 5), std::invalid_argument);
  BOOST_CHECK_THROW(HardeningCurve::swift(500, 0, 0.2), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(voce_and_swift_tables_follow_their_formulas) {
  const HardeningCurve v = HardeningCurve::voce(140.2, 190, 12.4);
  const HardeningCurve w = HardeningCurve::swift(498.8, 0.0089, 0.285);
  for (double e : {0.0, 1e-4, 0.003, 0.02, 0.1, 0.4, 1.2}) {
    BOOST_TEST(std::abs(v.stress(e) - (140.2 + 190 * (1 - std::exp(-12.4 * e)))) < 0.01);
    BOOST_TEST(std::abs(w.stress(e) - 498.8 * std::pow(0.0089 + e, 0.285)) < 0.01);
  }
}
