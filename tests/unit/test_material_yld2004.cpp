// Yld2004-18p (material/yld2004.hpp) and its plasticity (material/
// yld2004_plasticity.hpp) against closed forms.  E = 70000 MPa, nu = 0.33.
//
// Closed-form answers:
//  - Eigenvalues of Q diag(l) Q^T for rotations Q, with distinct, double
//    (gap 0), near-double (1e-12 to 1e-6 apart) and triple roots, a large
//    mean and 2,000 random spectra: l, within 1e-13 of the largest |l|
//    (material/principal_values.hpp resolves coincident pairs to round-off).
//  - All coefficients 1 (C' = C'' = identity on deviators), a = 2: von Mises,
//    sigma_bar = sqrt(3 J2) and n = (3/2) s / sigma_bar for any stress (1e-12);
//    uniaxial ratio 1 and r = 1 at every angle, sigma_b/sigma_0 = 1, rb = 1,
//    pure shear yields at 1/sqrt(3), plane strain at 2/sqrt(3).
//  - The same with a = 8: uniaxial 1 at every angle, sigma_b = sigma_0
//    (Phi is even), pure shear (1, -1, 0) has Phi = 2 (2^8 + 1 + 1) = 516, so
//    tau/sigma_0 = (516/4)^(-1/8) = 129^(-1/8) = 0.544398...
//  - C' = C'' = c (any c), a = 2: sigma_bar^2 = (3/2)|dev(C s)|^2, the Hill'48
//    quadratic with F, G, H from its values at unit tension along 1, 2 and at
//    equibiaxial tension (F + H, G + H, F + G) and N = 3/2 c66^2: uniaxial
//    ratio and r-value at 0..90 deg equal Hill48's closed forms (1e-9).
//  - Anisotropic a = 8: the analytic gradient equals central differences of
//    sigma_bar (step 1e-6 of the stress, error O(1e-11)) within 1e-6, also at
//    points where two principal values coincide (equibiaxial, through-
//    thickness uniaxial); r(theta) from the gradient equals r(theta) from
//    numerical differentiation of sigma_bar within 1e-6.
//  - Return map, von Mises (all 1, a = 2): the stress and eps_p of a random
//    multiaxial strain path equal J2Isotropic's radial return within 1e-6
//    relative (the normal does not turn in the return, so the iteration
//    reaches the same point, to its tolerance of 1e-6 R on f).
//  - Return maps are backward Euler: the flow direction is the normal of the
//    returned point, so the plastic strain ratios below are exact.
//  - Return map, anisotropic a = 8, perfectly plastic at 100 MPa: uniaxial
//    tension at 0..90 deg (mixed control) yields at uniaxial_ratio(t) x 100 MPa
//    (1e-6 relative: the return's tolerance on f) with the plastic strain
//    ratio r_value(t) within 1e-4: the normal is converged to
//    |n' - n| <= 1e-6 R / (2 G x) = 1e-5 at these steps (x = 2e-4, 2 G x =
//    10.5 MPa, R = 100 MPa), and r = n_ww / n_33 with |n_33| >= 0.2 moves by at
//    most about 5 times that;
//    equibiaxial tension yields at biaxial_ratio() x 100 MPa (1e-6) with the
//    plastic strain ratio biaxial_r() (1e-4, as above), and every return lands
//    on f = 0 within 1e-6 R (the return's tolerance).
//  - Set-up check: a < 2, a non-finite coefficient and a surface that is not
//    closed (c1 = c2 = 0 on the normals) are refused.
#define BOOST_TEST_MODULE material_yld2004
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "material/hill48.hpp"
#include "material/j2_isotropic.hpp"
#include "material/yld2004.hpp"
#include "material/yld2004_plasticity.hpp"

using namespace drawbend::material;
using V6 = std::array<double, 6>;

namespace {
constexpr double E = 70000.0, NU = 0.33, RHO = 2.7e-9;

// A strongly anisotropic convex set (coefficients of the order of Barlat et al. 2005's AA2090-T3).
Yld2004 aniso() {
  Yld2004 y;
  y.a = 8;
  y.c1 = {-0.0698, 0.9364, 0.0791, 1.0030, 0.5247, 1.3631, 1.0238, 1.0000, 0.9543};
  y.c2 = {0.9811, 0.4767, 0.5753, 0.8668, 1.1450, -0.0792, 1.0516, 1.1471, 1.4046};
  return y.normalised();
}

void rotate(const double Q[3][3], const double l[3], double v[6]) {  // Q diag(l) Q^T
  constexpr int I[6] = {0, 1, 2, 0, 1, 2}, J[6] = {0, 1, 2, 1, 2, 0};
  for (int n = 0; n < 6; ++n) {
    v[n] = 0;
    for (int k = 0; k < 3; ++k) v[n] += Q[I[n]][k] * l[k] * Q[J[n]][k];
  }
}

void numeric_gradient(const Yld2004& y, const double s[6], double n[6]) {
  double scale = 0;
  for (int i = 0; i < 6; ++i) scale = std::max(scale, std::abs(s[i]));
  const double h = 1e-6 * scale;
  for (int i = 0; i < 6; ++i) {
    double p[6], m[6];
    for (int k = 0; k < 6; ++k) p[k] = m[k] = s[k];
    p[i] += h, m[i] -= h;
    n[i] = (y.equivalent(p) - y.equivalent(m)) / (2 * h);
    if (i >= 3) n[i] *= 0.5;  // d/d(s_ij) of a symmetric pair moves both: tensor component is half
  }
}

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

// Mixed control: strain increment e along x; the other 5 by Newton so that the other stresses vanish
// (uniaxial) or sigma_yy = sigma_xx and the rest vanish (biaxial).
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

std::vector<double> fresh(const Material& m, const SheetAxes& a = SheetAxes{}) {
  std::vector<double> st(m.state_size());
  m.init_state(st.data(), a);
  return st;
}
}  // namespace

BOOST_AUTO_TEST_CASE(eigenvalues_closed_form_with_coincident_roots) {
  // Spectra l rotated by Q (the rounding of Q diag(l) Q^T moves the eigenvalues by a few 1e-16 of the largest
  // |l|, Weyl), with pairs 0, 1e-12, 1e-9, 1e-6 apart, triple roots, a mean 1e6 times the spread and 2,000
  // random spectra, each under two rotations: every root within 1e-13 of the largest |l|, coincident or not.
  std::vector<std::array<double, 3>> spectra = {
      {3.0, -1.0, 0.5},  {2.0, 2.0, -4.0},        {2.0, 2.0 + 1e-9, -4.0}, {2.0, 2.0 + 1e-12, -4.0},
      {1.0, 1.0 + 1e-6, -3.0}, {-1.0, -1.0, 5.0}, {-1.0, -1.0 - 1e-9, 5.0}, {7.0, 7.0, 7.0},
      {7.0, 7.0 + 1e-12, 7.0}, {1e-3, 0.0, 0.0}, {1e6 + 1.0, 1e6, 1e6 - 2.0}, {0.0, 0.0, 0.0},
      {1.0, 0.0, -1.0},  {2.0, -1.0, -1.0},       {-2.0, 1.0, 1.0}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 2000; ++k) spectra.push_back({U(rng), U(rng), U(rng)});
  double worst = 0;
  for (const double t : {0.7, 2.3})
    for (const auto& l : spectra) {
      const double u = -1.1 + t;
      const double Q[3][3] = {{std::cos(t), -std::sin(t), 0},
                              {std::sin(t) * std::cos(u), std::cos(t) * std::cos(u), -std::sin(u)},
                              {std::sin(t) * std::sin(u), std::cos(t) * std::sin(u), std::cos(u)}};
      double v[6], lam[3];
      rotate(Q, l.data(), v);
      sym_eigenvalues(v, lam);
      std::array<double, 3> want = l;
      std::sort(want.begin(), want.end(), std::greater<double>());
      const double big = std::max({std::abs(l[0]), std::abs(l[1]), std::abs(l[2]), 1e-300});
      for (int i = 0; i < 3; ++i) {
        BOOST_TEST(std::abs(lam[i] - want[i]) <= 1e-13 * big, "root " << i << ": " << lam[i] << " vs " << want[i]);
        worst = std::max(worst, std::abs(lam[i] - want[i]) / big);
      }
      BOOST_TEST((lam[0] >= lam[1] && lam[1] >= lam[2]));
    }
  BOOST_TEST_MESSAGE("principal values: worst error " << worst << " of the largest |l|");
  // Diagonal tensors with exactly coincident entries give them back exactly apart from round-off.
  const double eb[6] = {1.5, 1.5, -3.0, 0, 0, 0};
  double lam[3];
  sym_eigenvalues(eb, lam);
  BOOST_TEST(std::abs(lam[0] - lam[1]) <= 1e-15 * 3.0);
}

BOOST_AUTO_TEST_CASE(identity_a2_is_von_mises) {
  const Yld2004 y = Yld2004::isotropic(2.0);
  y.validate();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-300, 300);
  for (int k = 0; k < 200; ++k) {
    const double s[6] = {U(rng), U(rng), U(rng), U(rng), U(rng), U(rng)};
    const double vm = von_mises(s);
    double n[6];
    BOOST_TEST(std::abs(y.equivalent(s) - vm) <= 1e-12 * vm);
    BOOST_TEST(std::abs(y.gradient(s, n) - vm) <= 1e-12 * vm);
    const double m = (s[0] + s[1] + s[2]) / 3;
    for (int i = 0; i < 6; ++i) BOOST_TEST(std::abs(n[i] - 1.5 * (s[i] - (i < 3 ? m : 0.0)) / vm) <= 1e-12);
  }
  for (double t = 0; t <= M_PI / 2 + 1e-12; t += M_PI / 12) {
    BOOST_TEST(std::abs(y.uniaxial_ratio(t) - 1.0) <= 1e-12);
    BOOST_TEST(std::abs(y.r_value(t) - 1.0) <= 1e-12);
    BOOST_TEST(std::abs(y.plane_strain_ratio(t) - 2.0 / std::sqrt(3.0)) <= 1e-10);
  }
  BOOST_TEST(std::abs(y.biaxial_ratio() - 1.0) <= 1e-12);
  BOOST_TEST(std::abs(y.biaxial_r() - 1.0) <= 1e-12);
  const double shear[6] = {0, 0, 0, 1, 0, 0};
  BOOST_TEST(std::abs(1.0 / y.equivalent(shear) - 1.0 / std::sqrt(3.0)) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(identity_a8_uniaxial_biaxial_and_shear_points) {
  const Yld2004 y = Yld2004::isotropic(8.0);
  y.validate();
  for (double t = 0; t <= M_PI / 2 + 1e-12; t += M_PI / 12) {
    BOOST_TEST(std::abs(y.uniaxial_ratio(t) - 1.0) <= 1e-12);
    BOOST_TEST(std::abs(y.r_value(t) - 1.0) <= 1e-9);
  }
  BOOST_TEST(std::abs(y.biaxial_ratio() - 1.0) <= 1e-12);
  BOOST_TEST(std::abs(y.biaxial_r() - 1.0) <= 1e-9);
  const double shear[6] = {0.5, -0.5, 0, 0, 0, 0};  // principal (1/2, -1/2, 0): tau = 1/2 per unit
  BOOST_TEST(std::abs(0.5 / y.equivalent(shear) - std::pow(129.0, -1.0 / 8)) <= 1e-12);
  const double xy[6] = {0, 0, 0, 1, 0, 0};
  BOOST_TEST(std::abs(1.0 / y.equivalent(xy) - std::pow(129.0, -1.0 / 8)) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(equal_transforms_a2_are_hill48) {
  Yld2004 y;
  y.a = 2;
  y.c1 = y.c2 = {0.8, 1.1, 0.9, 1.2, 1.05, 0.7, 1.0, 1.0, 1.3};
  y = y.normalised();
  // Hill'48 of the same function: F + H, G + H, F + G from tension along 2, 1 and equibiaxial.
  const double u1[6] = {1, 0, 0, 0, 0, 0}, u2[6] = {0, 1, 0, 0, 0, 0}, b[6] = {1, 1, 0, 0, 0, 0};
  const double gh = std::pow(y.equivalent(u1), 2), fh = std::pow(y.equivalent(u2), 2), fg = std::pow(y.equivalent(b), 2);
  Hill48 h;
  h.F = 0.5 * (fh + fg - gh), h.G = 0.5 * (gh + fg - fh), h.H = 0.5 * (gh + fh - fg);
  h.N = 1.5 * y.c1[8] * y.c1[8];
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 50; ++k) {  // the whole function, with its shears: sigma_bar^2 = (3/2)|dev(C s)|^2
    const double s[6] = {U(rng), U(rng), U(rng), U(rng), U(rng), U(rng)};
    const double m = (s[0] + s[1] + s[2]) / 3, d[3] = {s[0] - m, s[1] - m, s[2] - m};
    const auto& c = y.c1;
    double X[6] = {-(c[0] * d[1] + c[1] * d[2]), -(c[2] * d[0] + c[3] * d[2]), -(c[4] * d[0] + c[5] * d[1]),
                   c[8] * s[3], c[6] * s[4], c[7] * s[5]};
    const double xm = (X[0] + X[1] + X[2]) / 3;
    const double dev2 = std::pow(X[0] - xm, 2) + std::pow(X[1] - xm, 2) + std::pow(X[2] - xm, 2) +
                        2 * (X[3] * X[3] + X[4] * X[4] + X[5] * X[5]);
    BOOST_TEST(std::abs(y.equivalent(s) - std::sqrt(1.5 * dev2)) <= 1e-12 * std::sqrt(1.5 * dev2));
  }
  for (double t = 0; t <= M_PI / 2 + 1e-12; t += M_PI / 12) {
    BOOST_TEST(std::abs(y.uniaxial_ratio(t) - h.uniaxial_ratio(t) / h.uniaxial_ratio(0)) <= 1e-9, "t " << t);
    BOOST_TEST(std::abs(y.r_value(t) - h.r_value(t)) <= 1e-9 * h.r_value(t), "t " << t);
  }
  BOOST_TEST(std::abs(y.biaxial_ratio() - h.biaxial_ratio() / h.uniaxial_ratio(0)) <= 1e-9);
}

BOOST_AUTO_TEST_CASE(gradient_matches_numerical_differentiation_also_at_double_roots) {
  const Yld2004 y = aniso();
  y.validate();
  std::vector<V6> pts = {{1, 1, 0, 0, 0, 0}, {0, 0, 1, 0, 0, 0}, {1, 0, 0, 0, 0, 0}, {2, 1, 0, 0, 0, 0},
                         {1, 1, 0, 0.3, 0, 0}, {0.2, -0.7, 0.1, 0.3, -0.4, 0.25}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 40; ++k) pts.push_back({U(rng), U(rng), U(rng), U(rng), U(rng), U(rng)});
  const Yld2004 iso = Yld2004::isotropic(8.0);
  for (const Yld2004* f : {&y, &iso})
    for (const auto& p : pts) {
      double n[6], m[6];
      f->gradient(p.data(), n);
      numeric_gradient(*f, p.data(), m);
      for (int i = 0; i < 6; ++i)
        BOOST_TEST(std::abs(n[i] - m[i]) <= 1e-6, "component " << i << ": " << n[i] << " vs " << m[i]);
    }
  // r(theta) from numerical differentiation of sigma_bar under unit tension along theta.
  for (double t = 0; t <= M_PI / 2 + 1e-12; t += M_PI / 12) {
    const double c = std::cos(t), s = std::sin(t);
    const double u[6] = {c * c, s * s, 0, c * s, 0, 0};
    double m[6];
    numeric_gradient(y, u, m);
    const double eww = m[0] * s * s + m[1] * c * c - 2 * m[3] * c * s;
    BOOST_TEST(std::abs(y.r_value(t) - eww / m[2]) <= 1e-6, "t " << t);
  }
}

BOOST_AUTO_TEST_CASE(return_map_von_mises_equals_radial_return) {
  const auto curve = HardeningCurve::swift(498.8, 0.0089, 0.285);
  const Yld2004Plasticity y(E, NU, RHO, curve, KinematicHardening{}, Yld2004::isotropic(2.0));
  const J2Isotropic j(E, NU, RHO, curve);
  V6 sy{}, sj{};
  auto sty = fresh(y), stj = fresh(j);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int k = 0; k < 300; ++k) {
    double d[6];
    for (double& v : d) v = 2e-4 * U(rng);
    d[0] += 3e-4;  // a drift so that the path stays plastic
    y.update(d, sy.data(), sty.data());
    j.update(d, sj.data(), stj.data());
    const double q = von_mises(sj.data());
    for (int i = 0; i < 6; ++i) BOOST_TEST(std::abs(sy[i] - sj[i]) <= 1e-6 * q, "step " << k << " component " << i);
    BOOST_TEST(std::abs(sty[0] - stj[0]) <= 1e-6 * std::max(stj[0], 1e-3));
  }
  BOOST_TEST(stj[0] > 0.05);
}

BOOST_AUTO_TEST_CASE(return_map_anisotropic_uniaxial_and_equibiaxial_points) {
  const Yld2004 yf = aniso();
  const Yld2004Plasticity m(E, NU, RHO, HardeningCurve({0.0}, {100.0}), KinematicHardening{}, yf);
  for (double t = 0; t <= M_PI / 2 + 1e-12; t += M_PI / 12) {
    SheetAxes a;  // global x at angle t to RD
    a.rd[0] = std::cos(t), a.rd[1] = -std::sin(t);
    a.td[0] = std::sin(t), a.td[1] = std::cos(t);
    V6 s{};
    auto st = fresh(m, a);
    double ep0 = 0, e11 = 0, e22 = 0, e33 = 0;
    for (int i = 0; i < 30; ++i) {
      const V6 d = mixed_step(m, 2e-4, s, st, false);
      if (i >= 20) {  // plastic: the elastic part of the increments is zero (perfectly plastic, stress constant)
        e11 += d[0], e22 += d[1], e33 += d[2];
      } else {
        ep0 = st[0];
      }
    }
    BOOST_TEST(ep0 > 0.0);
    BOOST_TEST(std::abs(s[0] - 100.0 * yf.uniaxial_ratio(t)) <= 1e-6 * s[0], "t " << t);
    BOOST_TEST(std::abs(e22 / e33 - yf.r_value(t)) <= 1e-4, "t " << t << ": " << e22 / e33 << " vs " << yf.r_value(t));
  }
  V6 s{};
  auto st = fresh(m);
  double e11 = 0, e22 = 0;
  for (int i = 0; i < 30; ++i) {
    const V6 d = mixed_step(m, 2e-4, s, st, true);
    if (i >= 20) e11 += d[0], e22 += d[1];
    double xi[6] = {s[0], s[1], s[2], s[3], s[4], s[5]};
    if (st[0] > 0) BOOST_TEST(std::abs(yf.equivalent(xi) - 100.0) <= 1e-6 * 100.0);
  }
  BOOST_TEST(std::abs(s[0] - 100.0 * yf.biaxial_ratio()) <= 1e-6 * s[0]);
  // mixed control makes sigma_yy = sigma_xx by its strain d[1]; the plastic strain ratio is rb
  BOOST_TEST(std::abs(e22 / e11 - yf.biaxial_r()) <= 1e-4);
}

BOOST_AUTO_TEST_CASE(set_up_check_refuses_bad_sets) {
  Yld2004 y = Yld2004::isotropic(1.5);
  BOOST_CHECK_THROW(y.validate(), std::invalid_argument);
  y = Yld2004::isotropic(8);
  y.c1[3] = NAN;
  BOOST_CHECK_THROW(y.validate(), std::invalid_argument);
  y = Yld2004::isotropic(8);
  for (int i = 0; i < 6; ++i) y.c1[i] = y.c2[i] = 0.0;  // blind to every normal deviator: not closed
  BOOST_CHECK_THROW(y.validate(), std::invalid_argument);
  BOOST_CHECK_THROW(Yld2004Plasticity(E, NU, RHO, HardeningCurve({0.0}, {100.0}), KinematicHardening{}, y),
                    std::invalid_argument);
  aniso().validate();  // a convex, closed set passes
}

// Event counts are the instance's own (Material::event_counts; a run writes them to summary.csv): along a
// strain path, plastic_updates equals the number of updates in which eps_p grew (the trial point lay outside
// the surface), split and fallback stay 0 for von Mises (one radial return converges), and a second instance
// that made no update counts nothing.
BOOST_AUTO_TEST_CASE(event_counts_are_per_instance) {
  const auto curve = HardeningCurve::swift(498.8, 0.0089, 0.285);
  const Yld2004Plasticity y(E, NU, RHO, curve, KinematicHardening{}, Yld2004::isotropic(2.0));
  const Yld2004Plasticity other(E, NU, RHO, curve, KinematicHardening{}, Yld2004::isotropic(2.0));
  V6 s{};
  auto st = fresh(y);
  long grew = 0;
  for (int k = 0; k < 40; ++k) {
    const double d[6] = {k % 10 < 7 ? 4e-4 : -4e-4, 0, 0, 0, 0, 0};  // loading, then unloading elastically
    const double ep = st[0];
    y.update(d, s.data(), st.data());
    if (st[0] > ep) ++grew;
  }
  const auto n = y.event_counts();
  BOOST_TEST(n.size() == 3u);
  BOOST_TEST(n[0].first == "plastic_updates");
  BOOST_TEST(n[0].second == grew);
  BOOST_TEST(grew > 5);
  BOOST_TEST(grew < 40);
  BOOST_TEST(n[1].second == 0);
  BOOST_TEST(n[2].second == 0);
  for (const auto& [name, v] : other.event_counts()) BOOST_TEST(v == 0, name);
}
