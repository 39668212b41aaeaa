#include "material/yld2004.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/csv.hpp"
#include "material/principal_values.hpp"
#include "material/yield_points.hpp"

namespace drawbend::material {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kCoincide = 1e-5;  // eigenvalues closer than this (relative) use the derivative

// t^e for t >= 0; integer exponents by squaring, not pow (a = 8 takes t^7 = (t t^2)(t^2 t^2): four products).
inline double pw(double t, double e, bool integral) {
  if (integral && e >= 0) {
    double r = 1.0, b = t;
    for (int k = static_cast<int>(e); k > 0; k >>= 1) {
      if (k & 1) r *= b;
      if (k > 1) b *= b;
    }
    return r;
  }
  if (t == 0.0) return e > 0 ? 0.0 : (e == 0 ? 1.0 : 0.0);
  return std::pow(t, e);
}

// The transformed deviator X = C s (Voigt, tensor shears), Barlat's form.
void transform_dev(const std::array<double, 9>& c, const double s[6], double X[6]) {
  X[0] = -(c[0] * s[1] + c[1] * s[2]);
  X[1] = -(c[2] * s[0] + c[3] * s[2]);
  X[2] = -(c[4] * s[0] + c[5] * s[1]);
  X[3] = c[8] * s[3];  // xy: c66
  X[4] = c[6] * s[4];  // yz: c44
  X[5] = c[7] * s[5];  // zx: c55
}
// d Phi / d s (normal components, and tensor shears) from G = d Phi / d X: the transpose of transform_dev.
void transform_back(const std::array<double, 9>& c, const double G[6], double m[6]) {
  m[0] += -(c[2] * G[1] + c[4] * G[2]);
  m[1] += -(c[0] * G[0] + c[5] * G[2]);
  m[2] += -(c[1] * G[0] + c[3] * G[1]);
  m[3] += c[8] * G[3];
  m[4] += c[6] * G[4];
  m[5] += c[7] * G[5];
}

struct Exponent {
  double a;
  bool integral;
  // g(x) = a sum_k sgn(x - y_k) |x - y_k|^(a-1) (d/dx of sum_k |x - y_k|^a) is formed from evaluate()'s
  // powers (gradient() below); its first two derivatives, at the midpoints of coincident roots:
  double g1(double x, const double y[3]) const {
    double r = 0;
    for (int k = 0; k < 3; ++k) r += pw(std::abs(x - y[k]), a - 2, integral);
    return a * (a - 1) * r;
  }
  double g2(double x, const double y[3]) const {
    if (a == 2.0) return 0.0;
    double r = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = x - y[k];
      if (d == 0.0) continue;  // a in (2, 3): |d|^(a-3) unbounded at 0; a >= 3: 0 there
      const double p = pw(std::abs(d), a - 3, integral && a >= 3);
      r += d < 0 ? -p : p;
    }
    return a * (a - 1) * (a - 2) * r;
  }
};

// G = sum_i g(x_i) P_i of the symmetric X (eigenvalues x, descending) by divided differences; f = g(x_i).
void spectral_gradient(const Exponent& E, const double X[6], const double x[3], const double y[3], const double f[3],
                       double tol, double G[6]) {
  const double f1 = f[0], f2 = f[1], f3 = f[2];
  const double d12 = x[0] - x[1] > tol ? (f1 - f2) / (x[0] - x[1]) : E.g1(0.5 * (x[0] + x[1]), y);
  const double d23 = x[1] - x[2] > tol ? (f2 - f3) / (x[1] - x[2]) : E.g1(0.5 * (x[1] + x[2]), y);
  const double d123 = x[0] - x[2] > tol ? (d12 - d23) / (x[0] - x[2]) : 0.5 * E.g2(x[1], y);
  // A = X - x1 I, B = X - x2 I (commuting); G = f1 I + d12 A + d123 A B.
  const double A[3][3] = {{X[0] - x[0], X[3], X[5]}, {X[3], X[1] - x[0], X[4]}, {X[5], X[4], X[2] - x[0]}};
  const double B[3][3] = {{X[0] - x[1], X[3], X[5]}, {X[3], X[1] - x[1], X[4]}, {X[5], X[4], X[2] - x[1]}};
  constexpr int I[6] = {0, 1, 2, 0, 1, 2}, J[6] = {0, 1, 2, 1, 2, 0};
  for (int n = 0; n < 6; ++n) {
    const int i = I[n], j = J[n];
    const double ab = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
    G[n] = (i == j ? f1 : 0.0) + d12 * A[i][j] + d123 * ab;
  }
}

// x^(1/a): square roots for a = 2, 4, 8 (the usual exponents), else pow.
inline double root_a(double x, double a) {
  if (a == 8.0) return std::sqrt(std::sqrt(std::sqrt(x)));
  if (a == 4.0) return std::sqrt(std::sqrt(x));
  if (a == 2.0) return std::sqrt(x);
  return std::pow(x, 1.0 / a);
}

// The scaled deviator's transforms, their principal values and Phi (of s / scale); d_ij = x_i - y_j and
// q_ij = |d_ij|^(a-1), shared by Phi (sum q_ij |d_ij|) and the gradient (g's terms +-q_ij).
struct Eval {
  double scale = 0, X1[6], X2[6], x[3], y[3], d[3][3], q[3][3], phi = 0;
  bool integral = false;
};
bool evaluate(const Yld2004& Y, const double sig[6], Eval& e) {
  const double mean = (sig[0] + sig[1] + sig[2]) / 3.0;
  double s[6] = {sig[0] - mean, sig[1] - mean, sig[2] - mean, sig[3], sig[4], sig[5]};
  for (double v : s) e.scale = std::max(e.scale, std::abs(v));
  if (!(e.scale > 0)) return false;
  const double inv = 1.0 / e.scale;
  for (double& v : s) v *= inv;
  transform_dev(Y.c1, s, e.X1);
  transform_dev(Y.c2, s, e.X2);
  sym_eigenvalues(e.X1, e.x);
  sym_eigenvalues(e.X2, e.y);
  e.integral = Y.a == std::floor(Y.a) && Y.a <= 64;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double d = e.x[i] - e.y[j], t = std::abs(d);
      e.d[i][j] = d;
      e.q[i][j] = pw(t, Y.a - 1, e.integral);
      e.phi += e.q[i][j] * t;
    }
  return true;
}
}  // namespace

void sym_eigenvalues(const double v[6], double lam[3]) { lanes::DRAWBEND_ISA::principal_values(v, lam); }

Yld2004 Yld2004::isotropic(double a) {
  Yld2004 y;
  y.a = a;
  return y;
}

Yld2004 Yld2004::normalised() const {
  const double s[6] = {1, 0, 0, 0, 0, 0};
  const double k = equivalent(s);
  if (!(k > 0) || !std::isfinite(k))
    throw std::invalid_argument("Yld2004-18p: uniaxial tension along RD gives sigma_bar = " + fmt_shortest(k) +
                                ": no yield surface");
  Yld2004 y = *this;
  for (int i = 0; i < 9; ++i) y.c1[i] /= k, y.c2[i] /= k;
  return y;
}

double Yld2004::gradient(const double sig[6], double n[6]) const {
  for (int i = 0; i < 6; ++i) n[i] = 0.0;
  Eval e;
  if (!evaluate(*this, sig, e) || !(e.phi > 0)) return 0.0;
  const double sbar_hat = root_a(0.25 * e.phi, a);
  const Exponent E{a, e.integral};
  const double tol =
      kCoincide * std::max({std::abs(e.x[0]), std::abs(e.x[2]), std::abs(e.y[0]), std::abs(e.y[2]), 1e-300});
  // g(x_i) against y and g(y_j) against x (y_j - x_i = -d_ij), in the order of the sums over k.
  double fx[3], fy[3];
  for (int i = 0; i < 3; ++i) {
    double rx = 0, ry = 0;
    for (int k = 0; k < 3; ++k) {
      rx += e.d[i][k] < 0 ? -e.q[i][k] : e.q[i][k];
      ry += e.d[k][i] > 0 ? -e.q[k][i] : e.q[k][i];
    }
    fx[i] = a * rx, fy[i] = a * ry;
  }
  double G1[6], G2[6], m[6] = {0, 0, 0, 0, 0, 0};
  spectral_gradient(E, e.X1, e.x, e.y, fx, tol, G1);  // d Phi / d X'
  spectral_gradient(E, e.X2, e.y, e.x, fy, tol, G2);  // d Phi / d X'' (the same form with the roles swapped)
  transform_back(c1, G1, m);
  transform_back(c2, G2, m);
  const double mm = (m[0] + m[1] + m[2]) / 3.0;
  const double f = sbar_hat / (a * e.phi);  // d sigma_bar / d Phi, of the scaled stress
  n[0] = f * (m[0] - mm), n[1] = f * (m[1] - mm), n[2] = f * (m[2] - mm);
  n[3] = f * m[3], n[4] = f * m[4], n[5] = f * m[5];
  return e.scale * sbar_hat;
}

double Yld2004::equivalent(const double sig[6]) const {
  Eval e;
  if (!evaluate(*this, sig, e)) return 0.0;
  return e.scale * root_a(0.25 * e.phi, a);
}

void Yld2004::validate() const {
  if (!std::isfinite(a) || !(a >= 2.0))
    throw std::invalid_argument("Yld2004-18p: the exponent a must be finite and >= 2 (8 for FCC), found " +
                                fmt_shortest(a));
  for (int i = 0; i < 9; ++i)
    if (!std::isfinite(c1[i]) || !std::isfinite(c2[i]))
      throw std::invalid_argument("Yld2004-18p: coefficient " + std::to_string(i + 1) + " of c1 or c2 is not finite");
  // 13 planes of unit deviator directions (Voigt, tensor shears; a shear of 1/sqrt(2) is a unit tensor).
  const double r6 = 1.0 / std::sqrt(6.0), r2 = 1.0 / std::sqrt(2.0);
  const double N1[6] = {2 * r6, -r6, -r6, 0, 0, 0}, N2[6] = {0, r2, -r2, 0, 0, 0};
  const double S[3][6] = {{0, 0, 0, r2, 0, 0}, {0, 0, 0, 0, r2, 0}, {0, 0, 0, 0, 0, r2}};
  const double U1[6] = {1, 0, 0, 0, 0, 0}, U2[6] = {0, 1, 0, 0, 0, 0};
  std::vector<std::pair<const double*, const double*>> planes = {{N1, N2}, {U1, U2}, {U1, S[0]}, {U2, S[0]}};
  for (int k = 0; k < 3; ++k) {
    planes.push_back({N1, S[k]});
    planes.push_back({N2, S[k]});
    planes.push_back({S[k], S[(k + 1) % 3]});
  }
  const char* names[] = {"the pi-plane", "the (s11, s22) plane", "the (s11, s12) plane", "the (s22, s12) plane"};
  constexpr int kN = 180;
  for (std::size_t p = 0; p < planes.size(); ++p) {
    const std::string where = p < 4 ? names[p] : "a normal-shear or shear-shear plane of the deviators";
    double px[kN], py[kN];
    for (int k = 0; k < kN; ++k) {
      const double t = 2.0 * kPi * k / kN, c = std::cos(t), s = std::sin(t);
      double d[6];
      for (int i = 0; i < 6; ++i) d[i] = c * planes[p].first[i] + s * planes[p].second[i];
      const double e = equivalent(d);
      if (!(e > 1e-12) || !std::isfinite(e))
        throw std::invalid_argument("Yld2004-18p: the yield surface is not closed (sigma_bar = " + fmt_shortest(e) +
                                    " on a unit stress direction in " + where + ")");
      px[k] = c / e, py[k] = s / e;
    }
    for (int k = 0; k < kN; ++k) {
      const int a0 = (k + kN - 1) % kN, a2 = (k + 1) % kN;
      const double ux = px[k] - px[a0], uy = py[k] - py[a0], vx = px[a2] - px[k], vy = py[a2] - py[k];
      const double turn = ux * vy - uy * vx;
      if (turn < -1e-9 * std::hypot(ux, uy) * std::hypot(vx, vy))
        throw std::invalid_argument("Yld2004-18p: the yield surface is not convex in " + where + " (at " +
                                    fmt_shortest(360.0 * k / kN) + " deg of the plane)");
    }
  }
}

double Yld2004::uniaxial_ratio(double t) const { return points::uniaxial_ratio(*this, t); }
double Yld2004::r_value(double t) const { return points::r_value(*this, t); }
double Yld2004::biaxial_ratio() const { return points::biaxial_ratio(*this); }
double Yld2004::biaxial_r() const { return points::biaxial_r(*this); }
double Yld2004::plane_strain_ratio(double t) const { return points::plane_strain_ratio(*this, t); }

std::string Yld2004::describe() const {
  std::string c = "Yld2004-18p a = " + fmt_shortest(a) + ", c1 = [";
  for (int i = 0; i < 9; ++i) c += (i ? ", " : "") + fmt(c1[i], 4);
  c += "], c2 = [";
  for (int i = 0; i < 9; ++i) c += (i ? ", " : "") + fmt(c2[i], 4);
  const double q = kPi / 4;
  return c + "] (r0/r45/r90 = " + fmt(r_value(0.0)) + "/" + fmt(r_value(q)) + "/" + fmt(r_value(2 * q)) +
         ", s45/s90/sb = " + fmt(uniaxial_ratio(q)) + "/" + fmt(uniaxial_ratio(2 * q)) + "/" + fmt(biaxial_ratio()) +
         ")";
}

}  // namespace drawbend::material
