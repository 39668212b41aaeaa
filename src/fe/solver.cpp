#include "fe/solver.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "fe/hex8.hpp"

namespace drawbend::fe {

namespace {
constexpr double kTangentFloor = 0.01;
constexpr double kRelax = 0.01;
}  // namespace

double Energies::balance_error() const {
  // The contact work on the sheet is part of external_work; friction and the
  // stored penalty energy are diagnostics of how that work splits.
  const double lhs = kinetic + internal + hourglass + damping;
  const double scale = std::max({std::abs(external_work), std::abs(kinetic) + std::abs(internal) + std::abs(hourglass), 1e-30});
  return std::abs(lhs - external_work) / scale;
}

Solver::Solver(Model& model) : m_(model) {
  m_.validate();
  const Mesh& mesh = m_.mesh;
  const int n = mesh.num_nodes(), ne = mesh.num_elements();
  nc_ = NodeCorners::build(mesh);
  x_ = mesh.x;
  y_ = mesh.y;
  z_ = mesh.z;
  for (auto* v : {&vx_, &vy_, &vz_, &fx_, &fy_, &fz_, &mass_}) v->assign(n, 0.0);
  const auto& mat = *m_.material;
  sig_.assign(6 * ne, 0.0);
  state_.assign(static_cast<std::size_t>(ne) * mat.state_size(), 0.0);
  for (int e = 0; e < ne && mat.state_size() > 0; ++e) mat.init_state(&state_[static_cast<std::size_t>(e) * mat.state_size()]);
  hgq_.assign(12 * ne, 0.0);
  hg_modulus_.assign(3 * ne, mat.youngs_modulus());
  corner_.assign(24 * ne, 0.0);
  ie_inc_.assign(ne, 0.0);
  hg_inc_.assign(ne, 0.0);
  dt_elem_.assign(ne, 0.0);
  elem_mass_factor_.assign(ne, m_.mass_scaling);
  wave_speed_ = mat.wave_speed();
  // Lumped masses with mass scaling (uniform factor, then per element up to the target step).
  for (int e = 0; e < ne; ++e) {
    double ex[8], ey[8], ez[8];
    for (int a = 0; a < 8; ++a) {
      ex[a] = x_[mesh.hex[e][a]];
      ey[a] = y_[mesh.hex[e][a]];
      ez[a] = z_[mesh.hex[e][a]];
    }
    const double V = hex_volume(ex, ey, ez);
    const double dt_e = hex_characteristic_length(ex, ey, ez, V) / wave_speed_ * std::sqrt(elem_mass_factor_[e]);
    if (m_.target_dt > 0 && m_.dt_safety * dt_e < m_.target_dt)
      elem_mass_factor_[e] *= std::pow(m_.target_dt / (m_.dt_safety * dt_e), 2);
    const double me = mat.density() * V;
    phys_mass_ += me;
    added_mass_ += me * (elem_mass_factor_[e] - 1.0);
    for (int a = 0; a < 8; ++a) mass_[mesh.hex[e][a]] += me * elem_mass_factor_[e] / 8.0;
  }
  // Contact pairs: unique slave nodes, tributary faces, penalty length scale.
  for (const auto& cp : m_.contacts) {
    const auto& faces = mesh.face_set(cp.faces);
    std::vector<int> nodes;
    for (const auto& f : faces) nodes.insert(nodes.end(), f.begin(), f.end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    std::vector<ContactNode> cn(nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) cn[k].node = nodes[k];
    // Element size normal to the face: V / A of the element owning each face.
    std::vector<double> len(nodes.size(), 1e30);
    for (const auto& f : faces) {
      int owner = -1;
      for (int c = nc_.start[f[0]]; c < nc_.start[f[0] + 1] && owner < 0; ++c) {
        const int e = nc_.corner[c] / 8;
        int hits = 0;
        for (int a = 0; a < 8; ++a)
          for (int q = 0; q < 4; ++q) hits += mesh.hex[e][a] == f[q];
        if (hits == 4) owner = e;
      }
      if (owner < 0) throw std::invalid_argument("contact: face set '" + cp.faces + "' has a face on no element");
      double ex[8], ey[8], ez[8];
      for (int a = 0; a < 8; ++a) {
        ex[a] = x_[mesh.hex[owner][a]];
        ey[a] = y_[mesh.hex[owner][a]];
        ez[a] = z_[mesh.hex[owner][a]];
      }
      const double V = hex_volume(ex, ey, ez);
      const double d1[3] = {x_[f[2]] - x_[f[0]], y_[f[2]] - y_[f[0]], z_[f[2]] - z_[f[0]]};
      const double d2[3] = {x_[f[3]] - x_[f[1]], y_[f[3]] - y_[f[1]], z_[f[3]] - z_[f[1]]};
      const double A = 0.5 * std::sqrt(std::pow(d1[1] * d2[2] - d1[2] * d2[1], 2) +
                                       std::pow(d1[2] * d2[0] - d1[0] * d2[2], 2) +
                                       std::pow(d1[0] * d2[1] - d1[1] * d2[0], 2));
      for (int q = 0; q < 4; ++q) {
        const auto k = std::lower_bound(nodes.begin(), nodes.end(), f[q]) - nodes.begin();
        len[k] = std::min(len[k], V / A);
      }
    }
    contact_.push_back(std::move(cn));
    contact_stiffness_len_.push_back(std::move(len));
    contact_force_.emplace_back(nodes.size(), Vec3{0, 0, 0});
    const int ss = cp.friction ? cp.friction->state_size() : 0;
    friction_state_.emplace_back(nodes.size() * ss, 0.0);
  }
  tool_offset_.assign(m_.tools.size(), Vec3{0, 0, 0});
  tool_vel_.assign(m_.tools.size(), Vec3{0, 0, 0});
  tool_force_.assign(m_.tools.size(), Vec3{0, 0, 0});
  compute_dt();
  dt0_ = dt_;
}

void Solver::set_velocity(int node, const Vec3& v) {
  vx_.at(node) = v[0];
  vy_.at(node) = v[1];
  vz_.at(node) = v[2];
}

void Solver::set_stress(int element, const double s[6]) {
  for (int k = 0; k < 6; ++k) sig_.at(6 * element + k) = s[k];
}

double Solver::plastic_strain(int e) const {
  return m_.material->plastic_strain(state_.data() + static_cast<std::size_t>(e) * m_.material->state_size());
}

void Solver::compute_dt() {
  const Mesh& mesh = m_.mesh;
  double dtmin = 1e30;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    double ex[8], ey[8], ez[8];
    for (int a = 0; a < 8; ++a) {
      ex[a] = x_[mesh.hex[e][a]];
      ey[a] = y_[mesh.hex[e][a]];
      ez[a] = z_[mesh.hex[e][a]];
    }
    const double V = hex_volume(ex, ey, ez);
    dt_elem_[e] = hex_characteristic_length(ex, ey, ez, V) / wave_speed_ * std::sqrt(elem_mass_factor_[e]);
    dtmin = std::min(dtmin, dt_elem_[e]);
  }
  dt_ = m_.dt_safety * dtmin;
}

double Solver::stable_dt() const { return dt_; }

void Solver::element_forces() {
  // The velocities v_n-1/2 act over the previous interval [t_n-1, t_n]: the
  // strain, spin and hourglass increments use its length (zero before the
  // first cycle, so initial velocities do not pre-strain the mesh).
  const double dt_prev = last_dt_;
  const Mesh& mesh = m_.mesh;
  const int ne = mesh.num_elements();
  const material::Material& mat = *m_.material;
  const int ns = mat.state_size();
  const double E0 = mat.youngs_modulus(), G0 = mat.shear_modulus(), hg = m_.hourglass;
  int inverted = -1;
#pragma omp parallel for schedule(static)
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
    // Velocity gradient on the current geometry, L_n = sum_a v_a (x) B_a, then
    // brought to the mid-interval geometry x_n-1/2 = x_n - dt/2 v:
    //   L_mid = L_n (I - dt/2 L_n)^-1,
    // exact for homogeneous increments.  For a rigid rotation R it gives the
    // Cayley transform (R - I)(R + I)^-1 / dt, which is skew: no spurious strain.
    double Ln[3][3] = {{0}};
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Ln[i][j] += v[a][i] * g.B[j][a];
    double M[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[i][j] = (i == j ? 1.0 : 0.0) - 0.5 * dt_prev * Ln[i][j];
    const double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                       M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    const double id = 1.0 / det;
    const double Mi[3][3] = {{(M[1][1] * M[2][2] - M[1][2] * M[2][1]) * id, (M[0][2] * M[2][1] - M[0][1] * M[2][2]) * id,
                              (M[0][1] * M[1][2] - M[0][2] * M[1][1]) * id},
                             {(M[1][2] * M[2][0] - M[1][0] * M[2][2]) * id, (M[0][0] * M[2][2] - M[0][2] * M[2][0]) * id,
                              (M[0][2] * M[1][0] - M[0][0] * M[1][2]) * id},
                             {(M[1][0] * M[2][1] - M[1][1] * M[2][0]) * id, (M[0][1] * M[2][0] - M[0][0] * M[2][1]) * id,
                              (M[0][0] * M[1][1] - M[0][1] * M[1][0]) * id}};
    double L[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) L[i][j] = Ln[i][0] * Mi[0][j] + Ln[i][1] * Mi[1][j] + Ln[i][2] * Mi[2][j];
    // Jaumann rotation of the stress: sigma += dt (W sigma - sigma W).
    double* s = &sig_[6 * e];
    const double w01 = 0.5 * (L[0][1] - L[1][0]), w12 = 0.5 * (L[1][2] - L[2][1]), w20 = 0.5 * (L[2][0] - L[0][2]);
    const double S[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
    const double W[3][3] = {{0, w01, -w20}, {-w01, 0, w12}, {w20, -w12, 0}};
    double WS[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) WS[i][j] = W[i][0] * S[0][j] + W[i][1] * S[1][j] + W[i][2] * S[2][j];
    // W S - S W = WS + (WS)^T since W is skew and S symmetric.
    s[0] += dt_prev * 2 * WS[0][0];
    s[1] += dt_prev * 2 * WS[1][1];
    s[2] += dt_prev * 2 * WS[2][2];
    s[3] += dt_prev * (WS[0][1] + WS[1][0]);
    s[4] += dt_prev * (WS[1][2] + WS[2][1]);
    s[5] += dt_prev * (WS[2][0] + WS[0][2]);
    // Material update with the strain increment (engineering shear).
    const double deps[6] = {L[0][0] * dt_prev, L[1][1] * dt_prev, L[2][2] * dt_prev, (L[0][1] + L[1][0]) * dt_prev,
                            (L[1][2] + L[2][1]) * dt_prev, (L[2][0] + L[0][2]) * dt_prev};
    double before[6];
    for (int k = 0; k < 6; ++k) before[k] = s[k];
    double* st = ns ? &state_[static_cast<std::size_t>(e) * ns] : nullptr;
    mat.update(deps, s, st);
    double w = 0;
    for (int k = 0; k < 6; ++k) w += 0.5 * (before[k] + s[k]) * deps[k];
    ie_inc_[e] = w * V;
    // Internal force of node a: V sigma B_a.
    double f[8][3];
    for (int a = 0; a < 8; ++a) {
      const double b0 = g.B[0][a], b1 = g.B[1][a], b2 = g.B[2][a];
      f[a][0] = V * (s[0] * b0 + s[3] * b1 + s[5] * b2);
      f[a][1] = V * (s[3] * b0 + s[1] * b1 + s[4] * b2);
      f[a][2] = V * (s[5] * b0 + s[4] * b1 + s[2] * b2);
    }
    // Hourglass: gamma_alpha,a = h_alpha,a - (h_alpha . x) . B_a (orthogonal to linear fields).
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
    // Hourglass rates in the corotational frame: q_i,alpha = sum_a (R^T v_a)_i gamma_alpha,a.
    double q[4][3] = {{0}};
    for (int a = 0; a < 8; ++a) {
      const double vl[3] = {g.R[0][0] * v[a][0] + g.R[1][0] * v[a][1] + g.R[2][0] * v[a][2],
                            g.R[0][1] * v[a][0] + g.R[1][1] * v[a][1] + g.R[2][1] * v[a][2],
                            g.R[0][2] * v[a][0] + g.R[1][2] * v[a][1] + g.R[2][2] * v[a][2]};
      for (int al = 0; al < 4; ++al)
        for (int i = 0; i < 3; ++i) q[al][i] += vl[i] * gam[al][a];
    }
    // Physical mode stiffnesses (see hex8.hpp), scaled by the material tangent.
    // Floor: a perfectly plastic layer keeps 1 % of the elastic stabilisation so
    // that hourglass modes stay controlled (costs < 2 % of the plastic moment).
    // Plastic flow softens each normal-strain (bending, warping) mode by the J2
    // tangent projected on that mode's normal strain e_i (x) e_i:
    //   r_i = 1 - (1 - ratio) (3/2) n_ii^2,  n = s/|s| the unit flow direction,
    // where ratio = H/(E+H) is the uniaxial tangent ratio.  Uniaxial flow along
    // x gives r_x = ratio and r_y = r_z = 1 - 3/4 (1 - ratio): the thickness and
    // width modes stay stiff, as J2 plasticity has them.  Pure-shear modes keep
    // the elastic shear modulus.  The floor keeps perfectly plastic modes controlled.
    // The moduli relax towards their targets over ~1/kRelax cycles: an element
    // hovering at the yield surface would otherwise flip between elastic and
    // plastic every cycle, and a chattering incremental spring pumps energy
    // into the hourglass modes.
    const double ratio = mat.tangent_ratio(s, st);
    double Ei[3] = {E0, E0, E0};
    if (ratio < 1.0) {
      const double p = (s[0] + s[1] + s[2]) / 3.0;
      const double dev[3][3] = {{s[0] - p, s[3], s[5]}, {s[3], s[1] - p, s[4]}, {s[5], s[4], s[2] - p}};
      double nrm = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) nrm += dev[i][j] * dev[i][j];
      nrm = std::sqrt(nrm);
      for (int i = 0; i < 3 && nrm > 0; ++i) {
        double nii = 0;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) nii += g.R[a][i] * dev[a][b] * g.R[b][i];
        nii /= nrm;
        Ei[i] = E0 * std::max(1.0 - (1.0 - ratio) * 1.5 * nii * nii, kTangentFloor);
      }
    }
    double* er = &hg_modulus_[3 * e];
    for (int i = 0; i < 3; ++i) {
      er[i] += kRelax * (Ei[i] - er[i]);
      Ei[i] = er[i];
    }
    const double G = G0;
    const double ih2[3] = {1.0 / (g.h[0] * g.h[0]), 1.0 / (g.h[1] * g.h[1]), 1.0 / (g.h[2] * g.h[2])};
    static constexpr int kModeCoords[3][2] = {{1, 2}, {2, 0}, {0, 1}};
    double* Q = &hgq_[12 * e];
    for (int al = 0; al < 4; ++al)
      for (int i = 0; i < 3; ++i) {
        double K;
        if (al == 3) K = Ei[i] * V * ih2[i] / 9.0;
        else if (kModeCoords[al][0] == i || kModeCoords[al][1] == i) K = Ei[i] * V * ih2[i] / 3.0;
        else K = G * V * (ih2[kModeCoords[al][0]] + ih2[kModeCoords[al][1]]) / 3.0;
        Q[3 * al + i] += dt_prev * hg * K / 64.0 * q[al][i];
      }
    double ehg = 0;
    double* c = &corner_[24 * e];
    for (int a = 0; a < 8; ++a) {
      double fl[3] = {0, 0, 0};
      for (int al = 0; al < 4; ++al)
        for (int i = 0; i < 3; ++i) fl[i] += Q[3 * al + i] * gam[al][a];
      const double fh[3] = {g.R[0][0] * fl[0] + g.R[0][1] * fl[1] + g.R[0][2] * fl[2],
                            g.R[1][0] * fl[0] + g.R[1][1] * fl[1] + g.R[1][2] * fl[2],
                            g.R[2][0] * fl[0] + g.R[2][1] * fl[1] + g.R[2][2] * fl[2]};
      ehg += (fh[0] * v[a][0] + fh[1] * v[a][1] + fh[2] * v[a][2]) * dt_prev;
      c[3 * a + 0] = -(f[a][0] + fh[0]);
      c[3 * a + 1] = -(f[a][1] + fh[1]);
      c[3 * a + 2] = -(f[a][2] + fh[2]);
    }
    hg_inc_[e] = ehg;
    // Characteristic length 2 min(h) (= V / largest face area for a parallelepiped).
    dt_elem_[e] = 2.0 * std::min({g.h[0], g.h[1], g.h[2]}) / wave_speed_ * std::sqrt(elem_mass_factor_[e]);
  }
  if (inverted >= 0) {
    std::ostringstream os;
    os << "element " << inverted << " inverted (non-positive volume) at t = " << t_ << " s";
    throw std::runtime_error(os.str());
  }
  // Nodal sums in a fixed order (the corners are sorted by element and corner).
  const int n = mesh.num_nodes();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    double sx = 0, sy = 0, sz = 0;
    for (int k = nc_.start[i]; k < nc_.start[i + 1]; ++k) {
      const double* c = &corner_[3 * nc_.corner[k]];
      sx += c[0];
      sy += c[1];
      sz += c[2];
    }
    fx_[i] = sx;
    fy_[i] = sy;
    fz_[i] = sz;
  }
}

}  // namespace drawbend::fe
