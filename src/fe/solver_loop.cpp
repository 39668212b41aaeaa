// The time loop of the explicit solver: loads, contact, velocity update with
// dynamic-relaxation damping, boundary conditions and their reactions, energy
// bookkeeping, tool motion.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fe/solver.hpp"

namespace drawbend::fe {

namespace {
int tool_index(const Model& m, const std::string& name) {
  for (std::size_t i = 0; i < m.tools.size(); ++i)
    if (m.tools[i].name == name) return static_cast<int>(i);
  throw std::invalid_argument("no tool named '" + name + "'");
}
}  // namespace

void Solver::run(const std::function<void(const Progress&)>& on_cycle) {
  for (int s = step_index_; s < static_cast<int>(m_.steps.size()); ++s) run_step(s, on_cycle);
}

void Solver::run_step(int index, const std::function<void(const Progress&)>& on_cycle) {
  const Step& step = m_.steps.at(index);
  const Mesh& mesh = m_.mesh;
  const int n = mesh.num_nodes();
  // Tool drives for this step.
  std::vector<Tool::Drive> drive;
  for (const auto& t : m_.tools) drive.push_back(t.drive);
  for (const auto& [name, d] : step.tool_drive) drive[tool_index(m_, name)] = d;
  // A force-driven tool is a rigid mass on its contact springs; explicit
  // integration is stable only if omega dt <= 2 (with the element safety factor).
  for (std::size_t k = 0; k < m_.tools.size(); ++k)
    if (drive[k] == Tool::Drive::force) {
      double stiffness = 0;
      for (std::size_t p = 0; p < m_.contacts.size(); ++p) {
        if (m_.contacts[p].tool != m_.tools[k].name) continue;
        std::vector<double> area(contact_[p].size(), 0.0);
        for (const auto& f : mesh.face_set(m_.contacts[p].faces))
          for (int q = 0; q < 4; ++q) {
            const auto it = std::lower_bound(contact_[p].begin(), contact_[p].end(), f[q],
                                             [](const ContactNode& c, int v) { return c.node < v; });
            area[it - contact_[p].begin()] += 0.25 * quad_area(x_, y_, z_, f);
          }
        for (std::size_t i = 0; i < area.size(); ++i)
          stiffness += m_.contacts[p].penalty * m_.material->bulk_modulus() * area[i] / contact_stiffness_len_[p][i];
      }
      const double limit = 2.0 * m_.dt_safety;
      if (stiffness > 0 && std::sqrt(stiffness / m_.tools[k].mass) * dt_ > limit) {
        std::ostringstream os;
        os << "tool '" << m_.tools[k].name << "': mass " << m_.tools[k].mass << " t is too small for a stable time step "
           << dt_ << " s on its contact stiffness " << stiffness << " N/mm; it needs at least "
           << stiffness * (dt_ / limit) * (dt_ / limit) << " t";
        throw std::invalid_argument(os.str());
      }
    }
  // Per-node load weights (mass-proportional) for each force load.
  std::vector<std::vector<double>> load_w;
  for (const auto& fl : step.forces) {
    const auto& set = mesh.node_set(fl.set);
    double mt = 0;
    for (int i : set) mt += mass_[i];
    std::vector<double> w;
    for (int i : set) w.push_back(mass_[i] / mt);
    load_w.push_back(std::move(w));
  }
  std::vector<double> v0x(n), v0y(n), v0z(n), ex(n), ey(n), ez(n);
  // A step starts afresh, or continues from a checkpoint (load_state) where it was.
  const bool resume = index == step_index_ && step_time_ > 0;
  if (!resume) {
    slide_offset_.assign(step.rotations.size(), Vec3{0, 0, 0});
    step_t_start_ = t_;
    step_time_ = 0;
    for (bool& w : warned_) w = false;
  }
  step_index_ = index;
  if (cycle_ == 0) {
    double ke0 = 0;
    for (int i = 0; i < n; ++i) ke0 += 0.5 * mass_[i] * (vx_[i] * vx_[i] + vy_[i] * vy_[i] + vz_[i] * vz_[i]);
    en_.initial_kinetic = ke0;
  }
  rx_.assign(n, 0.0);
  ry_.assign(n, 0.0);
  rz_.assign(n, 0.0);
  std::vector<double>& rx = rx_;
  std::vector<double>& ry = ry_;
  std::vector<double>& rz = rz_;
  const double t_start = step_t_start_;
  double& step_time = step_time_;
  while (step_time < step.duration * (1 - 1e-12)) {
    const double dt = std::min(dt_, step.duration - step_time);
    if (step.duration - step_time < 1e-3 * dt0_) break;  // only round-off left in this step
    check_dt();  // zero or non-finite: a fault whatever the collapse guard says
    if (dt_ < m_.guards.dt_collapse.limit * dt0_) {
      std::ostringstream os;
      os << "time step collapsed to " << dt_ << " s = " << dt_ / dt0_ << " x the initial " << dt0_
         << " s at t = " << t_ << " s (cycle " << cycle_ << "), below [guards] dt_collapse = "
         << m_.guards.dt_collapse.limit << "; the smallest element is being crushed (check loads and contact)";
      guard_fired(m_.guards.dt_collapse, 0, os.str());
    }
    // 1-2. Internal forces (element loop + fixed-order nodal sums).
    element_forces();
    // External loads at t_n.
    std::fill(ex.begin(), ex.end(), 0.0);
    std::fill(ey.begin(), ey.end(), 0.0);
    std::fill(ez.begin(), ez.end(), 0.0);
    applied_.clear();
    for (std::size_t l = 0; l < step.forces.size(); ++l) {
      const auto& fl = step.forces[l];
      const auto& set = mesh.node_set(fl.set);
      const double F = fl.magnitude(t_ - t_start);
      for (std::size_t k = 0; k < set.size(); ++k) {
        const int i = set[k];
        ex[i] += F * load_w[l][k] * fl.direction[0];
        ey[i] += F * load_w[l][k] * fl.direction[1];
        ez[i] += F * load_w[l][k] * fl.direction[2];
      }
      applied_.push_back({fl.set, {F * fl.direction[0], F * fl.direction[1], F * fl.direction[2]}});
    }
    if (m_.gravity != Vec3{0, 0, 0})
      for (int i = 0; i < n; ++i) {
        ex[i] += mass_[i] * m_.gravity[0];
        ey[i] += mass_[i] * m_.gravity[1];
        ez[i] += mass_[i] * m_.gravity[2];
      }
    // Contact forces (added to ex, ey, ez through contact_force_).
    contact_forces(dt, step.friction);
    for (std::size_t p = 0; p < contact_.size(); ++p)
      for (std::size_t k = 0; k < contact_[p].size(); ++k) {
        const int i = contact_[p][k].node;
        ex[i] += contact_force_[p][k][0];
        ey[i] += contact_force_[p][k][1];
        ez[i] += contact_force_[p][k][2];
      }
    // 3. Velocities at t_n+1/2, with damping in dynamic-relaxation steps.
    const double c = step.damping;
    const double a1 = (1 - 0.5 * c * dt) / (1 + 0.5 * c * dt), a2 = dt / (1 + 0.5 * c * dt);
    for (int i = 0; i < n; ++i) {
      v0x[i] = vx_[i];
      v0y[i] = vy_[i];
      v0z[i] = vz_[i];
      const double im = 1.0 / mass_[i];
      vx_[i] = a1 * vx_[i] + a2 * (fx_[i] + ex[i]) * im;
      vy_[i] = a1 * vy_[i] + a2 * (fy_[i] + ey[i]) * im;
      vz_[i] = a1 * vz_[i] + a2 * (fz_[i] + ez[i]) * im;
      if (!(std::isfinite(vx_[i]) && std::isfinite(vy_[i]) && std::isfinite(vz_[i]))) {
        std::ostringstream os;
        os << "non-finite velocity (NaN or Inf) at node " << i << " at t = " << t_ << " s (cycle " << cycle_ << ")";
        if (const int e = nonfinite_element(); e >= 0) os << "; element " << e << " has a non-finite stress or force";
        os << ": the solution diverged (time step too large for a stiffness: penalty, hourglass, tool mass?)";
        throw NumericalFault(os.str());
      }
    }
    // Boundary conditions; a reaction is the force that enforces them.
    std::fill(rx.begin(), rx.end(), 0.0);
    std::fill(ry.begin(), ry.end(), 0.0);
    std::fill(rz.begin(), rz.end(), 0.0);
    reactions_.clear();
    const double th = t_ - t_start + 0.5 * dt;  // mid-interval step time
    auto enforce = [&](const std::string& set_name, auto&& set_velocity) {
      Vec3 R{0, 0, 0};
      for (int i : mesh.node_set(set_name)) {
        const double bx = vx_[i], by = vy_[i], bz = vz_[i];
        set_velocity(i);
        const double f[3] = {mass_[i] * (vx_[i] - bx) / dt, mass_[i] * (vy_[i] - by) / dt,
                             mass_[i] * (vz_[i] - bz) / dt};
        rx[i] += f[0];
        ry[i] += f[1];
        rz[i] += f[2];
        R[0] += f[0];
        R[1] += f[1];
        R[2] += f[2];
      }
      bool merged = false;
      for (auto& [name, r] : reactions_)
        if (name == set_name) {
          for (int k = 0; k < 3; ++k) r[k] += R[k];
          merged = true;
        }
      if (!merged) reactions_.push_back({set_name, R});
    };
    for (std::size_t r = 0; r < step.rotations.size(); ++r) {
      const auto& rb = step.rotations[r];
      // Exact rigid rotation over the interval: x_new = c + Rot(omega dt) (x - c),
      // v = (x_new - x)/dt, which keeps all distances (Rodrigues' formula).
      const double th_ = rb.omega(th) * dt, cs = std::cos(th_), sn = std::sin(th_);
      const auto& k = rb.axis;
      // Free rigid sliding along rb.slide: the mass-weighted mean of the
      // unconstrained velocities (momentum conserving, no net reaction).
      double us = 0;
      if (rb.slide != Vec3{0, 0, 0}) {
        double mv = 0, ms = 0;
        for (int i : mesh.node_set(rb.set)) {
          mv += mass_[i] * (vx_[i] * rb.slide[0] + vy_[i] * rb.slide[1] + vz_[i] * rb.slide[2]);
          ms += mass_[i];
        }
        us = mv / ms;
      }
      const Vec3 c{rb.centre[0] + slide_offset_[r][0], rb.centre[1] + slide_offset_[r][1],
                   rb.centre[2] + slide_offset_[r][2]};
      for (int j = 0; j < 3; ++j) slide_offset_[r][j] += dt * us * rb.slide[j];
      enforce(rb.set, [&](int i) {
        const double d[3] = {x_[i] - c[0], y_[i] - c[1], z_[i] - c[2]};
        const double kd = k[0] * d[0] + k[1] * d[1] + k[2] * d[2];
        const double kxd[3] = {k[1] * d[2] - k[2] * d[1], k[2] * d[0] - k[0] * d[2], k[0] * d[1] - k[1] * d[0]};
        double r[3];
        for (int j = 0; j < 3; ++j) r[j] = d[j] * cs + kxd[j] * sn + k[j] * kd * (1 - cs);
        vx_[i] = (r[0] - d[0]) / dt + us * rb.slide[0];
        vy_[i] = (r[1] - d[1]) / dt + us * rb.slide[1];
        vz_[i] = (r[2] - d[2]) / dt + us * rb.slide[2];
      });
    }
    for (const auto& ab : step.affine) {
      const double sc = ab.scale(th);
      enforce(ab.set, [&](int i) {
        const double d[3] = {mesh.x[i] - ab.centre[0], mesh.y[i] - ab.centre[1], mesh.z[i] - ab.centre[2]};
        vx_[i] = sc * (ab.G[0][0] * d[0] + ab.G[0][1] * d[1] + ab.G[0][2] * d[2]);
        vy_[i] = sc * (ab.G[1][0] * d[0] + ab.G[1][1] * d[1] + ab.G[1][2] * d[2]);
        vz_[i] = sc * (ab.G[2][0] * d[0] + ab.G[2][1] * d[1] + ab.G[2][2] * d[2]);
      });
    }
    for (const auto& vb : step.velocities) {
      const double sp = vb.speed(th);
      const auto& d = vb.direction;
      enforce(vb.set, [&](int i) {
        const double along = vx_[i] * d[0] + vy_[i] * d[1] + vz_[i] * d[2];
        vx_[i] += (sp - along) * d[0];
        vy_[i] += (sp - along) * d[1];
        vz_[i] += (sp - along) * d[2];
      });
    }
    for (const auto& fb : step.fixed)
      enforce(fb.set, [&](int i) {
        if (fb.dof[0]) vx_[i] = 0;
        if (fb.dof[1]) vy_[i] = 0;
        if (fb.dof[2]) vz_[i] = 0;
      });
    // Work of loads, contact and reactions over the interval, kinetic energy.
    // The damping force -c m v_mid,free (v_free: before the boundary conditions,
    // v_free = v - r dt/m) does work -c m v_mid,free . v_mid dt; on a fixed
    // node v_mid = 0 and the reaction takes the damping force, so it removes
    // no energy there.
    double work = 0, ke = 0, damp = 0;
    for (int i = 0; i < n; ++i) {
      const double mx = 0.5 * (vx_[i] + v0x[i]), my = 0.5 * (vy_[i] + v0y[i]), mz = 0.5 * (vz_[i] + v0z[i]);
      work += ((ex[i] + rx[i]) * mx + (ey[i] + ry[i]) * my + (ez[i] + rz[i]) * mz) * dt;
      ke += 0.5 * mass_[i] * (vx_[i] * vx_[i] + vy_[i] * vy_[i] + vz_[i] * vz_[i]);
      if (c > 0) {
        const double h = 0.5 * dt / mass_[i];
        damp += c * mass_[i] * ((mx - h * rx[i]) * mx + (my - h * ry[i]) * my + (mz - h * rz[i]) * mz) * dt;
      }
    }
    en_.damping += damp;
    en_.external_work += work;
    en_.kinetic = ke;
    double ie = 0, eh = 0;
    for (int e = 0; e < mesh.num_elements(); ++e) {
      ie += ie_inc_[e];
      eh += hg_inc_[e];
    }
    if (!std::isfinite(ie + eh)) {
      std::ostringstream os;
      os << "non-finite internal or hourglass energy at t = " << t_ << " s (cycle " << cycle_ << ")";
      if (const int e = nonfinite_element(); e >= 0) os << " in element " << e;
      throw NumericalFault(os.str() + ": the solution diverged");
    }
    en_.internal += ie;
    en_.hourglass += eh;
    // Positions at t_n+1.
#pragma omp parallel for schedule(static) if (parallel::worth_forking(n, parallel::kNodeUpdateNs))
    for (int i = 0; i < n; ++i) {
      x_[i] += dt * vx_[i];
      y_[i] += dt * vy_[i];
      z_[i] += dt * vz_[i];
    }
    // Tools.
    for (std::size_t k = 0; k < m_.tools.size(); ++k) {
      const Tool& tool = m_.tools[k];
      const auto& d = tool.direction;
      if (drive[k] == Tool::Drive::velocity) {
        const double sp = tool.speed(th);
        tool_vel_[k] = {sp * d[0], sp * d[1], sp * d[2]};
      } else if (drive[k] == Tool::Drive::force) {
        // Rigid body along `direction`: m a = F(t) + (force of the sheet on the tool) . d;
        // the sheet pushes back against the motion, so that term is negative in contact.
        const double Fs = tool_force_[k][0] * d[0] + tool_force_[k][1] * d[1] + tool_force_[k][2] * d[2];
        const double a = (tool.force(t_ - t_start) + Fs) / tool.mass;
        const double along = tool_vel_[k][0] * d[0] + tool_vel_[k][1] * d[1] + tool_vel_[k][2] * d[2];
        const double vnew = (along * a1 + a * a2);
        tool_vel_[k] = {vnew * d[0], vnew * d[1], vnew * d[2]};
      } else {
        tool_vel_[k] = {0, 0, 0};
      }
      for (int j = 0; j < 3; ++j) tool_offset_[k][j] += dt * tool_vel_[k][j];
    }
    t_ += dt;
    last_dt_ = dt;
    step_time += dt;
    ++cycle_;
    double dtmin = 1e30;
    for (double d : dt_elem_) dtmin = std::min(dtmin, d);
    dt_ = m_.dt_safety * dtmin;
    if (on_cycle) on_cycle({index, &step, t_, step_time, dt, cycle_});
  }
  check_step_energies(step);
  step_index_ = index + 1;
  step_time_ = 0;
}

void Solver::guard_fired(const Guard& g, int id, const std::string& what) {
  if (g.error)
    throw NumericalFault(what + " (to continue anyway, set the guard's action to \"warn\" in [guards])");
  if (warned_[id]) return;
  warned_[id] = true;
  const std::string w = what + " (guard set to warn; once per step)";
  warnings_.push_back(w);
  if (on_warning_) on_warning_(w);
}

int Solver::nonfinite_element() const {
  const int ne = m_.mesh.num_elements();
  for (int e = 0; e < ne; ++e) {
    for (int k = 0; k < 12; ++k)
      if (!std::isfinite(sig_[12 * e + k])) return e;
    for (int k = 0; k < 24; ++k)
      if (!std::isfinite(corner_[24 * e + k])) return e;
  }
  return -1;
}

void Solver::check_step_energies(const Step& step) {
  const Guards& g = m_.guards;
  const Energies& e = en_;
  // Ratios to the internal energy are meaningless while nothing has deformed:
  // they are checked only when the energy in question is a visible part of the
  // largest energy flow.
  const double flow = std::max({std::abs(e.external_work), e.kinetic + e.internal + e.hourglass, std::abs(e.friction),
                                std::abs(e.damping)});
  auto at = [&] {
    std::ostringstream os;
    os << " at the end of step '" << step.name << "' (t = " << t_ << " s, cycle " << cycle_ << ")";
    return os.str();
  };
  if (e.hourglass > g.hourglass_ratio.limit * e.internal && e.hourglass > 1e-6 * flow) {
    std::ostringstream os;
    os << "hourglass energy " << e.hourglass << " mJ is " << e.hourglass / std::max(e.internal, 1e-300)
       << " x the internal energy " << e.internal << " mJ" << at() << ", above [guards] hourglass_ratio = "
       << g.hourglass_ratio.limit << " (refine the mesh, avoid point loads)";
    guard_fired(g.hourglass_ratio, 1, os.str());
  }
  if (step.quasi_static && e.kinetic > g.kinetic_ratio.limit * e.internal && e.kinetic > 1e-6 * flow) {
    std::ostringstream os;
    os << "kinetic energy " << e.kinetic << " mJ is " << e.kinetic / std::max(e.internal, 1e-300)
       << " x the internal energy " << e.internal << " mJ" << at() << " of a quasi-static step, above [guards] kinetic_ratio = "
       << g.kinetic_ratio.limit << " (slower loading, less mass scaling, or damping)";
    guard_fired(g.kinetic_ratio, 2, os.str());
  }
  if (e.balance_error() > g.energy_balance.limit) {
    std::ostringstream os;
    os << "energy balance error " << e.balance_error() << at() << " (kinetic " << e.kinetic << ", internal "
       << e.internal << ", hourglass " << e.hourglass << ", damping " << e.damping << ", external work "
       << e.external_work << " mJ), above [guards] energy_balance = " << g.energy_balance.limit;
    guard_fired(g.energy_balance, 3, os.str());
  }
}

Vec3 Solver::reaction(const std::string& set) const {
  for (const auto& [name, r] : reactions_)
    if (name == set) return r;
  return {0, 0, 0};
}

Vec3 Solver::applied(const std::string& set) const {
  Vec3 s{0, 0, 0};
  for (const auto& [name, f] : applied_)
    if (name == set)
      for (int k = 0; k < 3; ++k) s[k] += f[k];
  return s;
}

Vec3 Solver::tool_force(const std::string& tool) const { return tool_force_[tool_index(m_, tool)]; }
Vec3 Solver::tool_offset(const std::string& tool) const { return tool_offset_[tool_index(m_, tool)]; }

double Solver::max_penetration() const {
  double d = 0;
  for (const auto& pair : contact_)
    for (const auto& c : pair) d = std::max(d, c.depth);
  return d;
}

}  // namespace drawbend::fe
