// Node-to-rigid-surface penalty contact with friction (member of fe::Solver).
//
// Penalty stiffness.  Each slave node gets k = alpha K A / L, with K the bulk
// modulus, A the node's current tributary area on the contact face set and L
// the size of the underlying element normal to the face (V/A_face, at the
// start).  With this choice the contact pressure p = k d / A = alpha K d / L is
// set by the node's own area, which is what the thesis's Sec. 3.3.1 found
// decisive: a stiffness based on the *slave* area gives a uniform pressure
// under a uniform load, edges included, whatever the element sizes.  The
// penetration this costs is d/L = p/(alpha K): 10 MPa at alpha = 0.1 on
// aluminium (K = 69 GPa) is 0.15 % of the element size.
//
// Pressure.  p = normal force / tributary area, the area being a quarter of
// each adjacent face's current area.
//
// Damping.  The normal force is F_n = max(0, k d - c v_n) with c = 2 zeta
// sqrt(k m) (zeta: `damping`, fraction of critical; m: the node's mass) and
// v_n the normal velocity relative to the tool.  Without it, friction couples
// the tangential and normal motion of the penalty springs and an undamped
// strip drawn over a pin chatters at high frequency (seen in the capstan
// verification: velocities oscillating by 25 % of the drawing speed and a
// spurious hourglass energy); production codes damp contact for the same
// reason (LS-DYNA's VDC, 10-20 % of critical in sheet forming).  The damping
// force is part of the contact force, so its work is in the energy balance.
//
// Friction.  A tangential penalty spring (stiffness k) gives the trial force
// f_t = f_t,old - k v_t dt (v_t: tangential velocity relative to the tool);
// the friction law returns the limit (mu_1, mu_2) on the texture axes, and a
// trial force outside the ellipse (f_1/mu_1)^2 + (f_2/mu_2)^2 <= F_n^2 is
// scaled back onto it (radial return; for mu_1 = mu_2 this is the classical
// Coulomb return mapping).  The texture axis is the pair's fixed global axis,
// or the node's corotational axis (contact/texture.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "fe/solver.hpp"

namespace drawbend::fe {

namespace {
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
}  // namespace

void Solver::contact_forces(double dt, bool friction_on) {
  const Mesh& mesh = m_.mesh;
  const double K = m_.material->bulk_modulus();
  for (auto& f : tool_force_) f = {0, 0, 0};
  en_.contact_stored = 0;
  for (std::size_t p = 0; p < contact_.size(); ++p) {
    const ContactPair& cp = m_.contacts[p];
    int tool = -1;
    for (std::size_t k = 0; k < m_.tools.size(); ++k)
      if (m_.tools[k].name == cp.tool) tool = static_cast<int>(k);
    const Tool& T = m_.tools[tool];
    auto& nodes = contact_[p];
    // Tributary areas on the current configuration (sequential: fixed order).
    for (auto& c : nodes) c.area = 0;
    for (const auto& f : mesh.face_set(cp.faces)) {
      const double A = quad_area(x_, y_, z_, f);
      for (int q = 0; q < 4; ++q) {
        auto it = std::lower_bound(nodes.begin(), nodes.end(), f[q],
                                   [](const ContactNode& c, int v) { return c.node < v; });
        it->area += 0.25 * A;
      }
    }
    const friction::FrictionLaw* law = friction_on ? cp.friction.get() : nullptr;
    if (texture_ref_.size() <= p) texture_ref_.resize(contact_.size());
    const bool corot = law && cp.texture == ContactPair::Texture::corotational;
    if (corot && texture_ref_[p].empty()) {
      std::vector<int> ids;
      for (const auto& c : nodes) ids.push_back(c.node);
      texture_ref_[p] = contact::texture_refs(mesh, cp.faces, ids, m_.rolling_direction);
    }
    const int ss = cp.friction ? cp.friction->state_size() : 0;
    const Vec3 off = tool_offset_[tool], vt = tool_vel_[tool];
    const int nn = static_cast<int>(nodes.size());
    // Per-node energies, summed afterwards in a fixed order (deterministic).
    std::vector<double>& stored = energy_scratch_[0];
    std::vector<double>& diss = energy_scratch_[1];
    stored.assign(nn, 0.0);
    diss.assign(nn, 0.0);
#pragma omp parallel for schedule(static) if (parallel::worth_forking(nn, parallel::kContactNodeNs))
    for (int k = 0; k < nn; ++k) {
      ContactNode& c = nodes[k];
      const int i = c.node;
      const double L = contact_stiffness_len_[p][k];
      const Vec3 x{x_[i], y_[i], z_[i]};
      double best = 0;
      Vec3 n{0, 0, 0}, foot{0, 0, 0};
      int surf = -1;
      for (std::size_t s = 0; s < T.surfaces.size(); ++s) {
        double d;
        Vec3 nn_, ff;
        if (contact::penetration(T.surfaces[s], off, x, 2.0 * L, d, nn_, ff) && d > best) {
          best = d;
          n = nn_;
          foot = ff;
          surf = static_cast<int>(s);
        }
      }
      Vec3& F = contact_force_[p][k];
      if (surf < 0) {
        c = ContactNode{i, c.area};
        F = {0, 0, 0};
        continue;
      }
      const double kn = cp.penalty * K * c.area / L;
      const Vec3 vr{vx_[i] - vt[0], vy_[i] - vt[1], vz_[i] - vt[2]};
      const double vn = dot(vr, n);
      const double Fn = std::max(0.0, kn * best - cp.damping * 2.0 * std::sqrt(kn * mass_[i]) * vn);
      c.depth = best;
      c.normal = n;
      c.foot = foot;
      c.surface = surf;
      c.normal_force = Fn;
      c.pressure = c.area > 0 ? Fn / c.area : 0;
      // Tangential relative velocity.
      const Vec3 vtan{vr[0] - vn * n[0], vr[1] - vn * n[1], vr[2] - vn * n[2]};
      c.slip_speed = std::sqrt(dot(vtan, vtan));
      Vec3 ft{0, 0, 0};
      if (law) {
        // Old tangential force, brought into the current tangent plane (magnitude kept).
        Vec3 fo = c.ft;
        const double mag = std::sqrt(dot(fo, fo));
        const double fn_ = dot(fo, n);
        fo = {fo[0] - fn_ * n[0], fo[1] - fn_ * n[1], fo[2] - fn_ * n[2]};
        const double m2 = std::sqrt(dot(fo, fo));
        if (m2 > 0) for (double& v : fo) v *= mag / m2;
        ft = {fo[0] - kn * vtan[0] * dt, fo[1] - kn * vtan[1] * dt, fo[2] - kn * vtan[2] * dt};
        // Texture axes in the tangent plane.
        const Vec3 ax = corot ? contact::texture_axis(texture_ref_[p][k], x_, y_, z_) : m_.rolling_direction;
        const double an = dot(ax, n);
        Vec3 e1{ax[0] - an * n[0], ax[1] - an * n[1], ax[2] - an * n[2]};
        const double e1n = std::sqrt(dot(e1, e1));
        if (e1n > 1e-12) for (double& v : e1) v /= e1n;
        const Vec3 e2{n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
        friction::ContactState st;
        st.pressure = c.pressure;
        st.slip_speed = c.slip_speed;
        if (c.slip_speed > 0) st.slip_dir = {vtan[0] / c.slip_speed, vtan[1] / c.slip_speed, vtan[2] / c.slip_speed};
        st.normal = n;
        st.e1 = e1;
        st.state = ss ? &friction_state_[p][static_cast<std::size_t>(k) * ss] : nullptr;
        const friction::Limit lim = law->limit(st);
        const double f1 = dot(ft, e1), f2 = dot(ft, e2);
        double phi;
        if (lim.mu1 > 0 && lim.mu2 > 0) phi = std::sqrt(f1 * f1 / (lim.mu1 * lim.mu1) + f2 * f2 / (lim.mu2 * lim.mu2));
        else phi = (f1 != 0 || f2 != 0) ? INFINITY : 0;
        if (phi > Fn) {
          const double s = std::isfinite(phi) ? Fn / phi : 0.0;
          for (double& v : ft) v *= s;
        }
        diss[k] = -dot(ft, vtan) * dt;
        stored[k] = 0.5 * dot(ft, ft) / kn;
      }
      c.ft = ft;
      stored[k] += 0.5 * kn * best * best;
      F = {Fn * n[0] + ft[0], Fn * n[1] + ft[1], Fn * n[2] + ft[2]};
    }
    const Guard& pen = m_.guards.penetration;
    for (int k = 0; k < nn; ++k) {
      en_.friction += diss[k];
      en_.contact_stored += stored[k];
      if (nodes[k].depth > pen.limit * contact_stiffness_len_[p][k]) {
        std::ostringstream os;
        os << "contact penetration " << nodes[k].depth << " mm at node " << nodes[k].node << " (faces '" << cp.faces
           << "' on tool '" << cp.tool << "') is " << nodes[k].depth / contact_stiffness_len_[p][k]
           << " x the element size " << contact_stiffness_len_[p][k] << " mm normal to the face at t = " << t_
           << " s (cycle " << cycle_ << "), above [guards] penetration = " << pen.limit << " (raise the contact penalty)";
        guard_fired(pen, 4, os.str());
      }
    }
    // Force on the tool: the opposite of the sum on the sheet (fixed order).
    for (const auto& F : contact_force_[p])
      for (int j = 0; j < 3; ++j) tool_force_[tool][j] -= F[j];
  }
}

}  // namespace drawbend::fe
