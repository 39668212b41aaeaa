// The element loop of the explicit solver (member of fe::Solver): the
// hexahedron with two integration points through the thickness.
//
// Why two points.  A one-point element crossed by the neutral axis of a bent,
// plastic strip sees almost no strain at its centre, stays elastic, and its
// stabilisation then carries a large spurious bending moment; under back
// tension the neutral axis moves into the elements.  With two points at
// zeta = +-1/sqrt(3) through the thickness (zeta: the element's third natural
// axis, normal to the sheet in the generated meshes) each half of the element
// yields on its own.
//
// Assumed strain.  At the points, L_+- = L_mean +- (1/sqrt 3) L_C with
//   L_mean = sum_a v_a (x) B_a          (Flanagan-Belytschko uniform gradient)
//   L_C    = sum_a v_a (x) C_a,  C_a = R (gamma_zx,a / 8h_x, gamma_yz,a / 8h_y, 0),
// built from the hourglass vectors gamma (orthogonal to linear fields, so the
// patch test still holds) of the two modes that are linear in zeta.  For a
// rectangular element this is exact 1x1x2 Gauss integration of bending, free
// of transverse shear locking.  The thickness strain of a trilinear element
// cannot vary linearly through it, so its zeta-linear part is assumed:
//   (L_C)_zz = -c ((L_C)_xx + (L_C)_yy),  c = nu/(1-nu) elastic (plane stress
// through the thickness), 1 plastic (isochoric), blended by the tangent ratio;
// without it plastic incompressibility would lock the element in bending.
// The nodal forces follow from the internal power (V/2) sum_+- sigma : L.
//
// Stabilisation.  The two modes linear in zeta now have stiffness from the
// integration points; the remaining hourglass modes (xi*eta, xi*eta*zeta) keep
// the physical corotational stiffness of hex8.hpp with the elastic moduli.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fe/hex8.hpp"
#include "fe/solver.hpp"

namespace drawbend::fe {

namespace {
constexpr double kRelax = 0.01;         // tangent ratio relaxes over ~100 cycles (no chatter)
constexpr double kZg = 0.57735026918962576;  // 1/sqrt(3)

inline void inverse3(const double M[3][3], double Mi[3][3]) {
  const double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                     M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  const double id = 1.0 / det;
  Mi[0][0] = (M[1][1] * M[2][2] - M[1][2] * M[2][1]) * id;
  Mi[0][1] = (M[0][2] * M[2][1] - M[0][1] * M[2][2]) * id;
  Mi[0][2] = (M[0][1] * M[1][2] - M[0][2] * M[1][1]) * id;
  Mi[1][0] = (M[1][2] * M[2][0] - M[1][0] * M[2][2]) * id;
  Mi[1][1] = (M[0][0] * M[2][2] - M[0][2] * M[2][0]) * id;
  Mi[1][2] = (M[0][2] * M[1][0] - M[0][0] * M[1][2]) * id;
  Mi[2][0] = (M[1][0] * M[2][1] - M[1][1] * M[2][0]) * id;
  Mi[2][1] = (M[0][1] * M[2][0] - M[0][0] * M[2][1]) * id;
  Mi[2][2] = (M[0][0] * M[1][1] - M[0][1] * M[1][0]) * id;
}

/// Jaumann rotation and material update of one integration point; returns the
/// stress power increment per unit volume (midpoint rule).
inline double update_point(const material::Material& mat, const double L[3][3], double dt, double* s, double* st) {
  const double w01 = 0.5 * (L[0][1] - L[1][0]), w12 = 0.5 * (L[1][2] - L[2][1]), w20 = 0.5 * (L[2][0] - L[0][2]);
  const double S[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  const double W[3][3] = {{0, w01, -w20}, {-w01, 0, w12}, {w20, -w12, 0}};
  double WS[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) WS[i][j] = W[i][0] * S[0][j] + W[i][1] * S[1][j] + W[i][2] * S[2][j];
  // W S - S W = WS + (WS)^T since W is skew and S symmetric.
  s[0] += dt * 2 * WS[0][0];
  s[1] += dt * 2 * WS[1][1];
  s[2] += dt * 2 * WS[2][2];
  s[3] += dt * (WS[0][1] + WS[1][0]);
  s[4] += dt * (WS[1][2] + WS[2][1]);
  s[5] += dt * (WS[2][0] + WS[0][2]);
  const double deps[6] = {L[0][0] * dt, L[1][1] * dt, L[2][2] * dt, (L[0][1] + L[1][0]) * dt, (L[1][2] + L[2][1]) * dt,
                          (L[2][0] + L[0][2]) * dt};
  double before[6];
  for (int k = 0; k < 6; ++k) before[k] = s[k];
  mat.update(deps, s, st);
  double w = 0;
  for (int k = 0; k < 6; ++k) w += 0.5 * (before[k] + s[k]) * deps[k];
  return w;
}
}  // namespace

void Solver::element_forces() {
  const Mesh& mesh = m_.mesh;
  const int ne = mesh.num_elements();
  const material::Material& mat = *m_.material;
  const int ns = mat.state_size();
  const double E0 = mat.youngs_modulus(), G0 = mat.shear_modulus(), hg = m_.hourglass;
  const double c_elastic = mat.poisson_ratio() / (1.0 - mat.poisson_ratio());
  // The velocities v_n-1/2 act over the previous interval [t_n-1, t_n]: strain,
  // spin and hourglass increments use its length (zero before the first cycle).
  const double dtp = last_dt_;
  int inverted = -1;
#pragma omp parallel for schedule(static) if (ne >= kParallelMin)
  for (int e = 0; e < ne; ++e) {
    // Gather.
    double x[8], y[8], z[8], v[8][3];
    for (int a = 0; a < 8; ++a) {
      const int i = mesh.hex[e][a];
      x[a] = x_[i];
      y[a] = y_[i];
      z[a] = z_[i];
      v[a][0] = vx_[i];
      v[a][1] = vy_[i];
      v[a][2] = vz_[i];
    }
    HexGeometry g;
    if (!hex_geometry(x, y, z, g)) {
#pragma omp critical
      inverted = inverted < 0 ? e : std::min(inverted, e);
      continue;
    }
    const double V = g.volume;
    const double(*R)[3] = g.R;
    // Hourglass vectors gamma_alpha,a = h_alpha,a - (h_alpha . x) . B_a.
    double gam[4][8];
    for (int al = 0; al < 4; ++al) {
      double hx = 0, hy = 0, hz = 0;
      for (int b = 0; b < 8; ++b) {
        hx += kHg[al][b] * x[b];
        hy += kHg[al][b] * y[b];
        hz += kHg[al][b] * z[b];
      }
      for (int a = 0; a < 8; ++a) gam[al][a] = kHg[al][a] - (hx * g.B[0][a] + hy * g.B[1][a] + hz * g.B[2][a]);
    }
    // Local velocities, mean and thickness-linear velocity gradients.
    double vl[8][3], Ln[3][3] = {{0}}, LCl[3][3] = {{0}}, cx[8], cy[8];
    for (int a = 0; a < 8; ++a) {
      for (int i = 0; i < 3; ++i) vl[a][i] = R[0][i] * v[a][0] + R[1][i] * v[a][1] + R[2][i] * v[a][2];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Ln[i][j] += v[a][i] * g.B[j][a];
      cx[a] = gam[1][a] / (8.0 * g.h[0]);  // zeta*xi mode: d/dx of the zeta-linear part
      cy[a] = gam[0][a] / (8.0 * g.h[1]);  // eta*zeta mode: d/dy
      for (int i = 0; i < 3; ++i) {
        LCl[i][0] += vl[a][i] * cx[a];
        LCl[i][1] += vl[a][i] * cy[a];
      }
    }
    const double rbar = hg_ratio_[e];
    const double c = rbar * c_elastic + (1.0 - rbar);
    LCl[2][2] = -c * (LCl[0][0] + LCl[1][1]);
    double LC[3][3];  // R LCl R^T
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double sacc = 0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) sacc += R[i][k] * LCl[k][l] * R[j][l];
        LC[i][j] = sacc;
      }
    // Mid-interval geometry: L_mid = L (I - dt/2 L_mean)^-1 (exact for rigid rotation).
    double M[3][3], Mi[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[i][j] = (i == j ? 1.0 : 0.0) - 0.5 * dtp * Ln[i][j];
    inverse3(M, Mi);
    // The two integration points.
    double* sp = &sig_[12 * e];
    double* sm = sp + 6;
    double* stp = ns ? &state_[static_cast<std::size_t>(e) * 2 * ns] : nullptr;
    double* stm = ns ? stp + ns : nullptr;
    double ie = 0;
    for (int gp = 0; gp < 2; ++gp) {
      const double zeta = gp == 0 ? kZg : -kZg;
      double Lg[3][3], Lmid[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Lg[i][j] = Ln[i][j] + zeta * LC[i][j];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Lmid[i][j] = Lg[i][0] * Mi[0][j] + Lg[i][1] * Mi[1][j] + Lg[i][2] * Mi[2][j];
      ie += update_point(mat, Lmid, dtp, gp == 0 ? sp : sm, gp == 0 ? stp : stm);
    }
    ie_inc_[e] = 0.5 * V * ie;
    // Internal forces: mean part (V/2)(sig+ + sig-) . B_a ...
    double smean[6], f[8][3];
    for (int k = 0; k < 6; ++k) smean[k] = 0.5 * (sp[k] + sm[k]);
    for (int a = 0; a < 8; ++a) {
      const double b0 = g.B[0][a], b1 = g.B[1][a], b2 = g.B[2][a];
      f[a][0] = V * (smean[0] * b0 + smean[3] * b1 + smean[5] * b2);
      f[a][1] = V * (smean[3] * b0 + smean[1] * b1 + smean[4] * b2);
      f[a][2] = V * (smean[5] * b0 + smean[4] * b1 + smean[2] * b2);
    }
    // ... plus the thickness-linear part (V/2) Dl : LCl(v), Dl = R^T (sig+ - sig-)/sqrt3 R.
    const double dg[3][3] = {{kZg * (sp[0] - sm[0]), kZg * (sp[3] - sm[3]), kZg * (sp[5] - sm[5])},
                             {kZg * (sp[3] - sm[3]), kZg * (sp[1] - sm[1]), kZg * (sp[4] - sm[4])},
                             {kZg * (sp[5] - sm[5]), kZg * (sp[4] - sm[4]), kZg * (sp[2] - sm[2])}};
    double Dl[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double sacc = 0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) sacc += R[k][i] * dg[k][l] * R[l][j];
        Dl[i][j] = sacc;
      }
    // Remaining hourglass modes (xi*eta, xi*eta*zeta), corotational, physical stiffness.
    const double ratio = 0.5 * (mat.tangent_ratio(sp, stp) + mat.tangent_ratio(sm, stm));
    const double rnew = rbar + kRelax * (ratio - rbar);
    hg_ratio_[e] = rnew;
    // The remaining modes keep the elastic modulus: bending is carried by the
    // integration points, and a stiffness that follows yielding would pump
    // energy into these modes as material streams through a bend (elastic ->
    // plastic -> elastic), which a draw-bend strip does.
    const double Er = E0;
    const double ih2[3] = {1.0 / (g.h[0] * g.h[0]), 1.0 / (g.h[1] * g.h[1]), 1.0 / (g.h[2] * g.h[2])};
    double q[2][3] = {{0}};
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) {
        q[0][i] += vl[a][i] * gam[2][a];
        q[1][i] += vl[a][i] * gam[3][a];
      }
    double* Q = &hgq_[6 * e];  // [mode xi*eta: 3][mode xi*eta*zeta: 3]
    for (int i = 0; i < 3; ++i) {
      const double K2 = i < 2 ? Er * V * ih2[i] / 3.0 : G0 * V * (ih2[0] + ih2[1]) / 3.0;
      const double K3 = Er * V * ih2[i] / 9.0;
      Q[i] += dtp * hg * K2 / 64.0 * q[0][i];
      Q[3 + i] += dtp * hg * K3 / 64.0 * q[1][i];
    }
    double ehg = 0;
    double* cbuf = &corner_[24 * e];
    for (int a = 0; a < 8; ++a) {
      const double fc[3] = {0.5 * V * (Dl[0][0] * cx[a] + Dl[0][1] * cy[a] - c * Dl[2][2] * cx[a]),
                            0.5 * V * (Dl[1][0] * cx[a] + Dl[1][1] * cy[a] - c * Dl[2][2] * cy[a]),
                            0.5 * V * (Dl[2][0] * cx[a] + Dl[2][1] * cy[a])};
      double fh[3];
      for (int i = 0; i < 3; ++i) fh[i] = Q[i] * gam[2][a] + Q[3 + i] * gam[3][a];
      double fg[3], hgg[3];
      for (int i = 0; i < 3; ++i) {
        fg[i] = R[i][0] * fc[0] + R[i][1] * fc[1] + R[i][2] * fc[2];
        hgg[i] = R[i][0] * fh[0] + R[i][1] * fh[1] + R[i][2] * fh[2];
      }
      ehg += (hgg[0] * v[a][0] + hgg[1] * v[a][1] + hgg[2] * v[a][2]) * dtp;
      for (int i = 0; i < 3; ++i) cbuf[3 * a + i] = -(f[a][i] + fg[i] + hgg[i]);
    }
    hg_inc_[e] = ehg;
    dt_elem_[e] = hex_stable_length(g) / wave_speed_ * std::sqrt(elem_mass_factor_[e]);
  }
  if (inverted >= 0) {
    std::ostringstream os;
    os << "element " << inverted << " inverted (non-positive volume or Jacobian) at t = " << t_ << " s (cycle "
       << cycle_ << "), nodes";
    for (int a = 0; a < 8; ++a) os << " " << mesh.hex[inverted][a];
    os << ": it was crushed or turned inside out (loads too fast or too large, or a time step too large)";
    throw NumericalFault(os.str());
  }
  // Nodal sums in a fixed order (the corners are sorted by element and corner).
  const int n = mesh.num_nodes();
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (int i = 0; i < n; ++i) {
    double sx = 0, sy = 0, sz = 0;
    for (int k = nc_.start[i]; k < nc_.start[i + 1]; ++k) {
      const double* cc = &corner_[3 * nc_.corner[k]];
      sx += cc[0];
      sy += cc[1];
      sz += cc[2];
    }
    fx_[i] = sx;
    fy_[i] = sy;
    fz_[i] = sz;
  }
}

}  // namespace drawbend::fe
