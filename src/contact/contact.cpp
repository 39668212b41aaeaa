// Node-to-rigid-surface penalty contact with friction: one pair over one
// interval, over a ContactView (contact/contact.hpp).
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
#include "contact/contact.hpp"

#include <algorithm>
#include <cmath>

namespace drawbend::contact {

double face_area(const double* x, const double* y, const double* z, const std::array<int, 4>& f) {
  const double d1[3] = {x[f[2]] - x[f[0]], y[f[2]] - y[f[0]], z[f[2]] - z[f[0]]};
  const double d2[3] = {x[f[3]] - x[f[1]], y[f[3]] - y[f[1]], z[f[3]] - z[f[1]]};
  const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

SlotFaces slot_faces(const int* face_slot, int num_faces, int num_slots) {
  SlotFaces sf;
  sf.start.assign(num_slots + 1, 0);
  for (int c = 0; c < 4 * num_faces; ++c) ++sf.start[face_slot[c] + 1];
  for (int k = 0; k < num_slots; ++k) sf.start[k + 1] += sf.start[k];
  sf.face.resize(sf.start.back());
  std::vector<int> fill(sf.start.begin(), sf.start.end() - 1);
  for (int f = 0; f < num_faces; ++f)  // ascending faces, so each slot's list is ascending
    for (int q = 0; q < 4; ++q) sf.face[fill[face_slot[4 * f + q]]++] = f;
  return sf;
}

namespace {

/// The deepest surface of the tool at node position x (-1: none within reach).
int closest_surface(const ContactView& v, const Vec3& x, double L, double& best, Vec3& n, Vec3& foot) {
  int surf = -1;
  best = 0;
  for (int s = 0; s < v.num_surfaces; ++s) {
    double d;
    Vec3 ns, fs;
    if (penetration(v.surfaces[s], v.tool_offset, x, 2.0 * L, d, ns, fs) && d > best) {
      best = d;
      n = ns;
      foot = fs;
      surf = s;
    }
  }
  return surf;
}

/// Friction: the trial tangential force of node k (old force turned into the
/// tangent plane, minus k_n v_t dt) returned onto the law's ellipse.  Adds the
/// stored tangential energy and the dissipation.
Vec3 friction_force(const ContactView& v, int k, const ContactNode& c, const Vec3& n, const Vec3& vtan, double kn,
                    double Fn, double dt) {
  // Old tangential force, brought into the current tangent plane (magnitude kept).
  Vec3 fo = c.ft;
  const double mag = std::sqrt(dot(fo, fo));
  const double fn_ = dot(fo, n);
  fo = {fo[0] - fn_ * n[0], fo[1] - fn_ * n[1], fo[2] - fn_ * n[2]};
  const double m2 = std::sqrt(dot(fo, fo));
  if (m2 > 0) for (double& x : fo) x *= mag / m2;
  Vec3 ft = {fo[0] - kn * vtan[0] * dt, fo[1] - kn * vtan[1] * dt, fo[2] - kn * vtan[2] * dt};
  // Texture axes in the tangent plane.
  const Vec3 ax = v.texture ? texture_axis(v.texture[k], v.x, v.y, v.z) : v.rolling_direction;
  const double an = dot(ax, n);
  Vec3 e1{ax[0] - an * n[0], ax[1] - an * n[1], ax[2] - an * n[2]};
  double e1n = std::sqrt(dot(e1, e1));
  if (!(e1n > 1e-12)) {
    // RD along the normal (a fixed RD meets a wall square to it, e.g. a cup
    // wall on the RD symmetry plane): the texture has no direction in the
    // tangent plane.  Take the global axis least aligned with n instead; an
    // isotropic law does not see the choice.  (Before, e1 = e2 = 0 here made
    // the limit phi = 0, and the node's friction was never limited: it stuck.)
    const double a0 = std::abs(n[0]), a1 = std::abs(n[1]), a2 = std::abs(n[2]);
    const int a = a0 <= a1 && a0 <= a2 ? 0 : (a1 <= a2 ? 1 : 2);
    e1 = {0, 0, 0};
    e1[a] = 1;
    const double gn = n[a];
    for (int d = 0; d < 3; ++d) e1[d] -= gn * n[d];
    e1n = std::sqrt(dot(e1, e1));
  }
  for (double& x : e1) x /= e1n;
  const Vec3 e2{n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
  friction::ContactState st;
  st.pressure = c.pressure;
  st.slip_speed = c.slip_speed;
  if (c.slip_speed > 0) st.slip_dir = {vtan[0] / c.slip_speed, vtan[1] / c.slip_speed, vtan[2] / c.slip_speed};
  st.normal = n;
  st.e1 = e1;
  st.state = v.state_size ? &v.friction_state[static_cast<std::size_t>(k) * v.state_size] : nullptr;
  const friction::Limit lim = v.law->limit(st);
  const double f1 = dot(ft, e1), f2 = dot(ft, e2);
  double phi;
  if (lim.mu1 > 0 && lim.mu2 > 0) phi = std::sqrt(f1 * f1 / (lim.mu1 * lim.mu1) + f2 * f2 / (lim.mu2 * lim.mu2));
  else phi = (f1 != 0 || f2 != 0) ? INFINITY : 0;
  if (phi > Fn) {
    const double s = std::isfinite(phi) ? Fn / phi : 0.0;
    for (double& x : ft) x *= s;
  } else {
    v.nodes[k].status = 1;  // stick: node_forces set 2 (slip) before the call
  }
  v.dissipated[k] = -dot(ft, vtan) * dt;
  v.stored[k] = 0.5 * dot(ft, ft) / kn;
  return ft;
}

/// One slave node: depth, normal force with damping, friction, force on the sheet.
void node_forces(const ContactView& v, int k, double dt) {
  ContactNode& c = v.nodes[k];
  const int i = c.node;
  const double L = v.stiffness_len[k];
  double best;
  Vec3 n{0, 0, 0}, foot{0, 0, 0};
  const int surf = closest_surface(v, {v.x[i], v.y[i], v.z[i]}, L, best, n, foot);
  Vec3& F = v.force[k];
  if (surf < 0) {
    // Out of contact: the node's state reset (area and accumulated slip kept).  A node already
    // reset is left as it is: only the contact branch below, and a
    // checkpoint's copy of a reset state, make its surface >= 0 or its other
    // fields non-zero, so the bits are the same.
    if (c.surface >= 0) {
      const double slip = c.slip;  // the accumulated slip outlives the contact
      c = ContactNode{i, c.area};
      c.slip = slip;
    }
    F = {0, 0, 0};
    return;
  }
  const double kn = v.penalty * v.bulk_modulus * c.area / L;
  const Vec3 vt = v.tool_velocity;
  const Vec3 vr{v.vx[i] - vt[0], v.vy[i] - vt[1], v.vz[i] - vt[2]};
  const double vn = dot(vr, n);
  const double Fn = std::max(0.0, kn * best - v.damping * 2.0 * std::sqrt(kn * v.mass[i]) * vn);
  c.depth = best;
  c.normal = n;
  c.foot = foot;
  c.surface = surf;
  c.normal_force = Fn;
  c.pressure = c.area > 0 ? Fn / c.area : 0;
  // Tangential relative velocity.
  const Vec3 vtan{vr[0] - vn * n[0], vr[1] - vn * n[1], vr[2] - vn * n[2]};
  c.slip_speed = std::sqrt(dot(vtan, vtan));
  c.slip += c.slip_speed * dt;
  c.status = 2;  // slip, unless friction_force finds the node sticking
  const Vec3 ft = v.law ? friction_force(v, k, c, n, vtan, kn, Fn, dt) : Vec3{0, 0, 0};
  c.ft = ft;
  v.stored[k] += 0.5 * kn * best * best;
  F = {Fn * n[0] + ft[0], Fn * n[1] + ft[1], Fn * n[2] + ft[2]};
}

}  // namespace

int pair_forces(const ContactView& v, double dt, double penetration_limit, const PairTotals& totals) {
  const int nn = v.num_nodes;
#pragma omp parallel if (v.parallel)
  {
    // The faces' areas on the current configuration, then per node its
    // tributary area (a quarter of each of its faces, in ascending face order,
    // SlotFaces), its energies (summed below in a fixed order) and forces.
#pragma omp for schedule(static)
    for (int f = 0; f < v.num_faces; ++f) v.face_area[f] = face_area(v.x, v.y, v.z, v.faces[f]);
#pragma omp for schedule(static)
    for (int k = 0; k < nn; ++k) {
      double area = 0;
      for (int j = v.slot_face_start[k]; j < v.slot_face_start[k + 1]; ++j) area += 0.25 * v.face_area[v.slot_face[j]];
      v.nodes[k].area = area;
      v.stored[k] = 0;
      v.dissipated[k] = 0;
      node_forces(v, k, dt);
    }
  }
  int deep = -1;
  for (int k = 0; k < nn; ++k) {
    *totals.friction += v.dissipated[k];
    *totals.stored += v.stored[k];
    if (deep < 0 && v.nodes[k].depth > penetration_limit * v.stiffness_len[k]) deep = k;
  }
  // Force on the tool: the opposite of the sum on the sheet (fixed order).
  for (int k = 0; k < nn; ++k)
    for (int j = 0; j < 3; ++j) (*totals.tool_force)[j] -= v.force[k][j];
  return deep;
}

}  // namespace drawbend::contact
