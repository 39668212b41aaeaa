// The phases of one explicit cycle over plain views (fe/step_phases.hpp).
// The arithmetic is the time loop's, operation for operation: results are
// bit-identical to the loop they were cut from.
#include "fe/step_phases.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fe/element_view.hpp"


namespace drawbend::fe {

int tool_index(const Model& m, const std::string& name) {
  for (std::size_t i = 0; i < m.tools.size(); ++i)
    if (m.tools[i].name == name) return static_cast<int>(i);
  throw std::invalid_argument("no tool named '" + name + "'");
}

StepPlan plan_step(const Model& m, const Step& step, const std::vector<double>& mass) {
  const Mesh& mesh = m.mesh;
  StepPlan plan;
  for (const auto& t : m.tools) plan.drive.push_back(t.drive);
  for (const auto& [name, d] : step.tool_drive) plan.drive[tool_index(m, name)] = d;
  // Per-node load weights (mass-proportional) for each force load.
  for (const auto& fl : step.forces) {
    StepPlan::Load load;
    load.nodes = &mesh.node_set(fl.set);
    double mt = 0;
    for (int i : *load.nodes) mt += mass[i];
    for (int i : *load.nodes) load.weight.push_back(mass[i] / mt);
    plan.loads.push_back(std::move(load));
  }
  auto constrain = [&](const std::string& set) {
    StepPlan::Constrained c;
    c.nodes = &mesh.node_set(set);
    const auto it = std::find(plan.reaction_names.begin(), plan.reaction_names.end(), set);
    c.first = it == plan.reaction_names.end();
    c.slot = static_cast<int>(it - plan.reaction_names.begin());
    if (c.first) plan.reaction_names.push_back(set);
    return c;
  };
  // The order in which the constraints are enforced (enforce_constraints).
  for (const auto& b : step.rotations) plan.rotations.push_back(constrain(b.set));
  for (const auto& b : step.affine) plan.affine.push_back(constrain(b.set));
  for (const auto& b : step.velocities) plan.velocities.push_back(constrain(b.set));
  for (const auto& b : step.fixed) plan.fixed.push_back(constrain(b.set));
  return plan;
}

void apply_loads(const Model& m, const Step& step, const StepPlan& plan, double ts, const NodeView& v, NodeField ext,
                 Vec3* applied, const std::vector<int>& reset) {
  const bool gravity = m.gravity != Vec3{0, 0, 0};
  if (gravity) {
    std::fill(ext.x, ext.x + v.n, 0.0);
    std::fill(ext.y, ext.y + v.n, 0.0);
    std::fill(ext.z, ext.z + v.n, 0.0);
  } else {
    for (int i : reset) ext.x[i] = ext.y[i] = ext.z[i] = 0.0;
  }
  for (std::size_t l = 0; l < step.forces.size(); ++l) {
    const auto& fl = step.forces[l];
    const auto& set = *plan.loads[l].nodes;
    const auto& w = plan.loads[l].weight;
    const double F = fl.magnitude(ts);
    for (std::size_t k = 0; k < set.size(); ++k) {
      const int i = set[k];
      ext.x[i] += F * w[k] * fl.direction[0];
      ext.y[i] += F * w[k] * fl.direction[1];
      ext.z[i] += F * w[k] * fl.direction[2];
    }
    applied[l] = {F * fl.direction[0], F * fl.direction[1], F * fl.direction[2]};
  }
  if (gravity)
    for (int i = 0; i < v.n; ++i) {
      ext.x[i] += v.mass[i] * m.gravity[0];
      ext.y[i] += v.mass[i] * m.gravity[1];
      ext.z[i] += v.mass[i] * m.gravity[2];
    }
}

int sum_and_integrate(const int* start, const double* corner, const NodeView& v, NodeField ext, double a1, double a2,
                      NodeField v0, bool parallel) {
  int bad = v.n;
#pragma omp parallel for schedule(static) reduction(min : bad) if (parallel)
  for (int i = 0; i < v.n; ++i) {
    double fx = 0, fy = 0, fz = 0;
    for (int k = start[i]; k < start[i + 1]; ++k) {
      fx += corner[kCornerStride * k];
      fy += corner[kCornerStride * k + 1];
      fz += corner[kCornerStride * k + 2];
    }
    // In locals: the arrays may alias as far as the compiler knows, and it
    // would otherwise read each velocity back after storing it.
    const double ux = v.vx[i], uy = v.vy[i], uz = v.vz[i];
    v0.x[i] = ux;
    v0.y[i] = uy;
    v0.z[i] = uz;
    const double im = v.inv_mass[i];
    const double nx = a1 * ux + a2 * (fx + ext.x[i]) * im;
    const double ny = a1 * uy + a2 * (fy + ext.y[i]) * im;
    const double nz = a1 * uz + a2 * (fz + ext.z[i]) * im;
    v.vx[i] = nx;
    v.vy[i] = ny;
    v.vz[i] = nz;
    if (!(std::isfinite(nx) && std::isfinite(ny) && std::isfinite(nz))) bad = std::min(bad, i);
  }
  return bad < v.n ? bad : -1;
}

namespace {
/// Enforce one constraint on its nodes: set_velocity(i) sets the velocity; the
/// reaction is the force that did it, m dv / dt.
template <class SetVelocity>
void enforce(const StepPlan::Constrained& c, double dt, const NodeView& v, NodeField r, Vec3* reactions,
             SetVelocity&& set_velocity) {
  Vec3 R{0, 0, 0};
  for (int i : *c.nodes) {
    const double bx = v.vx[i], by = v.vy[i], bz = v.vz[i];
    set_velocity(i);
    const double f[3] = {v.mass[i] * (v.vx[i] - bx) / dt, v.mass[i] * (v.vy[i] - by) / dt,
                         v.mass[i] * (v.vz[i] - bz) / dt};
    r.x[i] += f[0];
    r.y[i] += f[1];
    r.z[i] += f[2];
    R[0] += f[0];
    R[1] += f[1];
    R[2] += f[2];
  }
  if (c.first) reactions[c.slot] = R;
  else
    for (int k = 0; k < 3; ++k) reactions[c.slot][k] += R[k];
}
}  // namespace

void enforce_constraints(const Step& step, const StepPlan& plan, double th, double dt, const NodeView& v,
                         Vec3* slide_offset, NodeField r, Vec3* reactions) {
  // r is zero away from the plan's constrained nodes (the solver zeroes it at
  // each step's start), so only theirs are reset: not every node every cycle.
  for (const auto* group : {&plan.rotations, &plan.affine, &plan.velocities, &plan.fixed})
    for (const StepPlan::Constrained& c : *group)
      for (int i : *c.nodes) r.x[i] = r.y[i] = r.z[i] = 0.0;
  for (std::size_t b = 0; b < step.rotations.size(); ++b) {
    const auto& rb = step.rotations[b];
    // Exact rigid rotation over the interval: x_new = c + Rot(omega dt) (x - c),
    // v = (x_new - x)/dt, which keeps all distances (Rodrigues' formula).
    const double angle = rb.omega(th) * dt, cs = std::cos(angle), sn = std::sin(angle);
    const auto& k = rb.axis;
    // Free rigid sliding along rb.slide: the mass-weighted mean of the
    // unconstrained velocities (momentum conserving, no net reaction).
    double us = 0;
    if (rb.slide != Vec3{0, 0, 0}) {
      double mv = 0, ms = 0;
      for (int i : *plan.rotations[b].nodes) {
        mv += v.mass[i] * (v.vx[i] * rb.slide[0] + v.vy[i] * rb.slide[1] + v.vz[i] * rb.slide[2]);
        ms += v.mass[i];
      }
      us = mv / ms;
    }
    const Vec3 c{rb.centre[0] + slide_offset[b][0], rb.centre[1] + slide_offset[b][1],
                 rb.centre[2] + slide_offset[b][2]};
    for (int j = 0; j < 3; ++j) slide_offset[b][j] += dt * us * rb.slide[j];
    enforce(plan.rotations[b], dt, v, r, reactions, [&](int i) {
      const double d[3] = {v.x[i] - c[0], v.y[i] - c[1], v.z[i] - c[2]};
      const double kd = k[0] * d[0] + k[1] * d[1] + k[2] * d[2];
      const double kxd[3] = {k[1] * d[2] - k[2] * d[1], k[2] * d[0] - k[0] * d[2], k[0] * d[1] - k[1] * d[0]};
      double p[3];
      for (int j = 0; j < 3; ++j) p[j] = d[j] * cs + kxd[j] * sn + k[j] * kd * (1 - cs);
      v.vx[i] = (p[0] - d[0]) / dt + us * rb.slide[0];
      v.vy[i] = (p[1] - d[1]) / dt + us * rb.slide[1];
      v.vz[i] = (p[2] - d[2]) / dt + us * rb.slide[2];
    });
  }
  for (std::size_t b = 0; b < step.affine.size(); ++b) {
    const auto& ab = step.affine[b];
    const double sc = ab.scale(th);
    enforce(plan.affine[b], dt, v, r, reactions, [&](int i) {
      const double d[3] = {v.X[i] - ab.centre[0], v.Y[i] - ab.centre[1], v.Z[i] - ab.centre[2]};
      v.vx[i] = sc * (ab.G[0][0] * d[0] + ab.G[0][1] * d[1] + ab.G[0][2] * d[2]);
      v.vy[i] = sc * (ab.G[1][0] * d[0] + ab.G[1][1] * d[1] + ab.G[1][2] * d[2]);
      v.vz[i] = sc * (ab.G[2][0] * d[0] + ab.G[2][1] * d[1] + ab.G[2][2] * d[2]);
    });
  }
  for (std::size_t b = 0; b < step.velocities.size(); ++b) {
    const auto& vb = step.velocities[b];
    const double sp = vb.speed(th);
    const auto& d = vb.direction;
    enforce(plan.velocities[b], dt, v, r, reactions, [&](int i) {
      const double along = v.vx[i] * d[0] + v.vy[i] * d[1] + v.vz[i] * d[2];
      v.vx[i] += (sp - along) * d[0];
      v.vy[i] += (sp - along) * d[1];
      v.vz[i] += (sp - along) * d[2];
    });
  }
  for (std::size_t b = 0; b < step.fixed.size(); ++b) {
    const auto& fb = step.fixed[b];
    enforce(plan.fixed[b], dt, v, r, reactions, [&](int i) {
      if (fb.dof[0]) v.vx[i] = 0;
      if (fb.dof[1]) v.vy[i] = 0;
      if (fb.dof[2]) v.vz[i] = 0;
    });
  }
}

EnergyIncrement energies_and_move(const NodeView& v, NodeField ext, NodeField r, NodeField v0, double dt, double c,
                                  double* partial, bool parallel) {
  // The damping force -c m v_mid,free (v_free: before the boundary conditions,
  // v_free = v - r dt/m) does work -c m v_mid,free . v_mid dt; on a fixed
  // node v_mid = 0 and the reaction takes the damping force, so it removes
  // no energy there.
  const int nchunk = (v.n + kSumChunk - 1) / kSumChunk;
#pragma omp parallel for schedule(static) if (parallel)
  for (int ch = 0; ch < nchunk; ++ch) {
    double work = 0, kinetic = 0, damping = 0;
    const int end = std::min(v.n, (ch + 1) * kSumChunk);
    for (int i = ch * kSumChunk; i < end; ++i) {
      const double mx = 0.5 * (v.vx[i] + v0.x[i]), my = 0.5 * (v.vy[i] + v0.y[i]), mz = 0.5 * (v.vz[i] + v0.z[i]);
      work += ((ext.x[i] + r.x[i]) * mx + (ext.y[i] + r.y[i]) * my + (ext.z[i] + r.z[i]) * mz) * dt;
      kinetic += 0.5 * v.mass[i] * (v.vx[i] * v.vx[i] + v.vy[i] * v.vy[i] + v.vz[i] * v.vz[i]);
      if (c > 0) {
        const double h = 0.5 * dt / v.mass[i];
        damping += c * v.mass[i] * ((mx - h * r.x[i]) * mx + (my - h * r.y[i]) * my + (mz - h * r.z[i]) * mz) * dt;
      }
      v.x[i] += dt * v.vx[i];
      v.y[i] += dt * v.vy[i];
      v.z[i] += dt * v.vz[i];
    }
    partial[3 * ch] = work;
    partial[3 * ch + 1] = kinetic;
    partial[3 * ch + 2] = damping;
  }
  EnergyIncrement e;
  for (int ch = 0; ch < nchunk; ++ch) {
    e.work += partial[3 * ch];
    e.kinetic += partial[3 * ch + 1];
    e.damping += partial[3 * ch + 2];
  }
  return e;
}

void move_tools(const Model& m, const StepPlan& plan, double th, double ts, double dt, double a1, double a2,
                const Vec3* tool_force, Vec3* tool_vel, Vec3* tool_offset) {
  for (std::size_t k = 0; k < m.tools.size(); ++k) {
    const Tool& tool = m.tools[k];
    const auto& d = tool.direction;
    if (plan.drive[k] == Tool::Drive::velocity) {
      const double sp = tool.speed(th);
      tool_vel[k] = {sp * d[0], sp * d[1], sp * d[2]};
    } else if (plan.drive[k] == Tool::Drive::force) {
      // Rigid body along `direction`: m a = F(t) + (force of the sheet on the tool) . d;
      // the sheet pushes back against the motion, so that term is negative in contact.
      const double Fs = tool_force[k][0] * d[0] + tool_force[k][1] * d[1] + tool_force[k][2] * d[2];
      const double a = (tool.force(ts) + Fs) / tool.mass;
      const double along = tool_vel[k][0] * d[0] + tool_vel[k][1] * d[1] + tool_vel[k][2] * d[2];
      double vnew = (along * a1 + a * a2);
      // A stop at `tool.stop` along d: the tool rests there (no further motion along d) while pushed onto it.
      const double at = tool_offset[k][0] * d[0] + tool_offset[k][1] * d[1] + tool_offset[k][2] * d[2];
      if (at + dt * vnew > tool.stop) vnew = std::max(0.0, tool.stop - at) / dt;
      tool_vel[k] = {vnew * d[0], vnew * d[1], vnew * d[2]};
    } else {
      tool_vel[k] = {0, 0, 0};
    }
    for (int j = 0; j < 3; ++j) tool_offset[k][j] += dt * tool_vel[k][j];
  }
}

}  // namespace drawbend::fe
