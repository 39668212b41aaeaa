// The time loop of the explicit solver, one cycle as named phases (their
// bodies: fe/step_phases.cpp; the element loop: fe/element_forces.cpp; contact
// and friction: the contact module, contact/contact.hpp), the step's set-up, and the guards.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fe/contact_springs.hpp"
#include "fe/element_view.hpp"
#include "fe/solver.hpp"

namespace drawbend::fe {

namespace {
/// Adds the wall time since the previous lap to one phase of a PhaseTimes
/// (Solver::time_phases); does nothing when there is none.
class Laps {
 public:
  explicit Laps(PhaseTimes* t) : t_(t) {
    if (t_) last_ = clock::now();
  }
  void operator()(double PhaseTimes::*phase) {
    if (!t_) return;
    const auto now = clock::now();
    t_->*phase += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  using clock = std::chrono::steady_clock;
  PhaseTimes* t_;
  clock::time_point last_;
};
}  // namespace

void Solver::run(const std::function<void(const Progress&)>& on_cycle) {
  for (int s = step_index_; s < static_cast<int>(m_.steps.size()); ++s) run_step(s, on_cycle);
}

void Solver::run_step(int index, const std::function<void(const Progress&)>& on_cycle) {
  const Step& step = m_.steps.at(index);
  begin_step(index);
  const NodeView nodes = node_view();
  const NodeField ext{ex_.data(), ey_.data(), ez_.data()}, reaction{rx_.data(), ry_.data(), rz_.data()};
  const NodeField v_old{v0x_.data(), v0y_.data(), v0z_.data()};
  const double t_start = step_t_start_;
  Laps lap(phases_);
  // Forking measured against not forking (fe/fork_governor.hpp), where the model decides.
  // A cycle is timed without the caller's callback (its output would weigh on one window).
  const bool govern = parallel::mode().load() == parallel::Mode::model && parallel::threads() > 1;
  auto cycle_start = std::chrono::steady_clock::now();
  while (step_time_ < step.duration * (1 - 1e-12)) {
    fork_allowed_ = !govern || governor_.allowed();
    const double dt = std::min(dt_, step.duration - step_time_);
    if (step.duration - step_time_ < 1e-3 * dt0_) break;  // only round-off left in this step
    guard_time_step();
    const double ts = t_ - t_start, th = ts + 0.5 * dt;  // step time at t_n and mid-interval
    // Damped central differences: v+ = a1 v- + a2 F / m (dynamic relaxation when step.damping > 0).
    const double c = step.damping;
    const double a1 = (1 - 0.5 * c * dt) / (1 + 0.5 * c * dt), a2 = dt / (1 + 0.5 * c * dt);

    lap(&PhaseTimes::other);
    element_forces();                                              // forces: element loop, into corner slots
    forked_cycles_ += elements_forked_;
    lap(&PhaseTimes::kernel);
    apply_loads(m_, step, plan_, ts, nodes, ext, applied_.data(), ext_nodes_);  // loads at t_n (and gravity)
    lap(&PhaseTimes::nodes);
    contact_phase(dt, step.friction, nodes, ext);                   // contact and friction, into ext
    lap(&PhaseTimes::contact);
    // Nodal sums (fixed order) and velocities at t_n+1/2, one pass over the nodes.
    const bool fork = fork_allowed_ && parallel::worth_forking(nodes.n, parallel::kNodePassNs, elements_forked_);
    if (const int i = sum_and_integrate(nc_.start.data(), corner_.data(), nodes, ext, a1, a2, v_old, fork); i >= 0)
      fault_nonfinite_velocity(i);
    enforce_constraints(step, plan_, th, dt, nodes, slide_offset_.data(), reaction, reactions_.data());
    const EnergyIncrement inc = energies_and_move(nodes, ext, reaction, v_old, dt, c, node_partial_.data(), fork);  // and x at t_n+1
    account_energies(inc);                                                          // guards: non-finite energy
    lap(&PhaseTimes::nodes);
    move_tools(m_, plan_, th, ts, dt, a1, a2, tool_force_.data(), tool_vel_.data(), tool_offset_.data());
    guard_tool_travel(dt);
    lap(&PhaseTimes::other);
    advance_time(dt);
    lap(&PhaseTimes::nodes);
    if (phases_) ++phases_->cycles;
    if (govern)
      governor_.after_cycle(std::chrono::duration<double>(std::chrono::steady_clock::now() - cycle_start).count());
    if (on_cycle) on_cycle({index, &step, t_, step_time_, dt, cycle_});  // output: the caller's
    if (govern) cycle_start = std::chrono::steady_clock::now();
  }
  check_step_energies(step);
  step_index_ = index + 1;
  step_time_ = 0;
}

void Solver::begin_step(int index) {
  const Step& step = m_.steps.at(index);
  const int n = m_.mesh.num_nodes();
  plan_ = plan_step(m_, step, mass_);
  plan_step_ = index;
  reactions_.assign(plan_.reaction_names.size(), Vec3{0, 0, 0});
  applied_.assign(step.forces.size(), Vec3{0, 0, 0});
  check_force_driven_tools();
  check_damping(step);
  // A step starts afresh, or continues from a checkpoint (load_state) where it was.
  const bool resume = index == step_index_ && step_time_ > 0;
  if (!resume && step.duration < 1e-3 * dt0_) {
    // run_step treats what is left of a step below 1e-3 of the initial time
    // step as round-off: such a step simulates nothing (duration = 1e-300
    // ran to exit 0 without a word, 2026-11-29).
    std::ostringstream os;
    os << "step '" << step.name << "' lasts " << step.duration << " s, less than 1e-3 of the time step " << dt0_
       << " s: nothing is simulated in it (a duration in ms or us instead of s?)";
    warnings_.push_back(os.str());
    if (on_warning_) on_warning_(os.str());
  }
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
  // External forces: zero, and the nodes where loads and contact set them,
  // which apply_loads resets each cycle instead of every node.
  ex_.assign(n, 0.0);
  ey_.assign(n, 0.0);
  ez_.assign(n, 0.0);
  ext_nodes_.clear();
  for (const auto& load : plan_.loads) ext_nodes_.insert(ext_nodes_.end(), load.nodes->begin(), load.nodes->end());
  for (const auto& pair : contact_)
    for (const auto& c : pair) ext_nodes_.push_back(c.node);
  std::sort(ext_nodes_.begin(), ext_nodes_.end());
  ext_nodes_.erase(std::unique(ext_nodes_.begin(), ext_nodes_.end()), ext_nodes_.end());
}

NodeView Solver::node_view() {
  NodeView v;
  v.n = m_.mesh.num_nodes();
  v.x = x_.data();
  v.y = y_.data();
  v.z = z_.data();
  v.vx = vx_.data();
  v.vy = vy_.data();
  v.vz = vz_.data();
  v.mass = mass_.data();
  v.inv_mass = inv_mass_.data();
  v.X = m_.mesh.x.data();
  v.Y = m_.mesh.y.data();
  v.Z = m_.mesh.z.data();
  return v;
}

void Solver::check_damping(const Step& step) const {
  // The damped central difference v+ = a1 v- + a2 F/m has a1 = (1 - c dt/2) /
  // (1 + c dt/2): at c dt >= 2 it is zero or negative, so every cycle stops
  // or reverses every velocity, and the run ends without deforming (damping =
  // 1e300 on a strip deck ran to exit 0 with a strip that never moved,
  // 2026-11-29).  Damping for dynamic relaxation is near twice the lowest
  // eigenfrequency, orders of magnitude below 2/dt (the shipped decks: c dt
  // about 1e-4), and the step only shrinks, so checking at the step's start suffices.
  if (step.damping * dt_ >= 2.0) {
    std::ostringstream os;
    if (step.damping_where.empty()) os << "step '" << step.name << "': damping = ";
    else os << step.damping_where << ": ";  // the deck's line (the solver finds the time step, the deck reader cannot)
    os << step.damping << " 1/s with the stable time step " << dt_
       << " s gives c dt = " << step.damping * dt_ << ", at or above 2, where the damped central difference stops "
       << "or reverses every velocity each cycle; use damping below " << 2.0 / dt_ << " 1/s (dynamic relaxation "
       << "damps near twice the lowest eigenfrequency)";
    throw std::invalid_argument(os.str());
  }
}

void Solver::check_force_driven_tools() const {
  // A force-driven tool is a rigid mass on its contact springs; explicit
  // integration is stable only if omega dt <= 2 (with the element safety factor).
  for (std::size_t k = 0; k < m_.tools.size(); ++k)
    if (plan_.drive[k] == Tool::Drive::force) {
      double stiffness = 0;  // on the current coordinates (fe/contact_springs.hpp)
      for (std::size_t p = 0; p < m_.contacts.size(); ++p) {
        if (pair_tool_[p] != static_cast<int>(k)) continue;
        const ContactSprings springs{{}, face_slot_[p], contact_stiffness_len_[p]};
        stiffness += spring_stiffness(springs, *pair_faces_[p], x_, y_, z_, m_.contacts[p].penalty,
                                      m_.material->bulk_modulus());
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
}

contact::ContactView Solver::contact_view(std::size_t p, bool friction_on, const NodeView& n) {
  const ContactPair& cp = m_.contacts[p];
  const int tool = pair_tool_[p];
  const Tool& T = m_.tools[tool];
  contact::ContactView v;
  v.x = n.x, v.y = n.y, v.z = n.z;
  v.vx = n.vx, v.vy = n.vy, v.vz = n.vz;
  v.mass = n.mass;
  v.faces = pair_faces_[p]->data();
  v.num_faces = static_cast<int>(pair_faces_[p]->size());
  v.slot_face_start = slot_faces_[p].start.data();
  v.slot_face = slot_faces_[p].face.data();
  v.face_area = face_area_scratch_.data();
  v.nodes = contact_[p].data();
  v.num_nodes = static_cast<int>(contact_[p].size());
  v.stiffness_len = contact_stiffness_len_[p].data();
  v.force = contact_force_[p].data();
  v.stored = energy_scratch_[0].data();
  v.dissipated = energy_scratch_[1].data();
  v.surfaces = T.surfaces.data();
  v.num_surfaces = static_cast<int>(T.surfaces.size());
  v.tool_offset = tool_offset_[tool];
  v.tool_velocity = tool_vel_[tool];
  v.penalty = cp.penalty;
  v.damping = cp.damping;
  v.bulk_modulus = m_.material->bulk_modulus();
  v.law = friction_on ? cp.friction.get() : nullptr;
  v.state_size = cp.friction ? cp.friction->state_size() : 0;
  v.friction_state = friction_state_[p].data();
  v.texture = v.law && cp.texture == ContactPair::Texture::corotational ? texture_ref_[p].data() : nullptr;
  v.rolling_direction = m_.rolling_direction;
  v.parallel = fork_allowed_ && parallel::worth_forking(v.num_nodes, parallel::kContactNodeNs, elements_forked_);
  return v;
}

void Solver::guard_penetration(std::size_t p, int k) {
  const ContactPair& cp = m_.contacts[p];
  const Guard& pen = m_.guards.penetration;
  const ContactNode& c = contact_[p][k];
  const double L = contact_stiffness_len_[p][k];
  std::ostringstream os;
  os << "contact penetration " << c.depth << " mm at node " << c.node << " (faces '" << cp.faces << "' on tool '"
     << cp.tool << "') is " << c.depth / L << " x the element size " << L << " mm normal to the face at t = " << t_
     << " s (cycle " << cycle_ << "), above [guards] penetration = " << pen.limit << " (raise the contact penalty)";
  guard_fired(pen, 4, os.str());
}

void Solver::contact_phase(double dt, bool friction, const NodeView& nodes, NodeField ext) {
  for (auto& f : tool_force_) f = {0, 0, 0};
  en_.contact_stored = 0;
  for (std::size_t p = 0; p < contact_.size(); ++p) {
    const contact::PairTotals totals{&en_.friction, &en_.contact_stored, &tool_force_[pair_tool_[p]]};
    const contact::ContactView v = contact_view(p, friction, nodes);
    if (const int k = contact::pair_forces(v, dt, m_.guards.penetration.limit, totals); k >= 0) guard_penetration(p, k);
  }
  for (std::size_t p = 0; p < contact_.size(); ++p)
    for (std::size_t k = 0; k < contact_[p].size(); ++k) {
      const int i = contact_[p][k].node;
      ext.x[i] += contact_force_[p][k][0];
      ext.y[i] += contact_force_[p][k][1];
      ext.z[i] += contact_force_[p][k][2];
    }
}

void Solver::guard_tool_travel(double dt) const {
  // A tool that moves past a whole element in one cycle has left the contact
  // behind: a node it passes through is never found inside it, so the run
  // would go on as if the tool were not there (a die driven by 1e20 N flew
  // off and `drawbend run` ended with exit 0, 2026-11-29).  Even a physical
  // tool that fast outruns the (mass-scaled) wave speed, which is what the
  // stable step is made of, so no sound deck comes near this limit.
  for (std::size_t k = 0; k < m_.tools.size(); ++k) {
    const Vec3& v = tool_vel_[k];
    const double travel = dt * std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(travel <= min_length_)) {
      std::ostringstream os;
      os << "tool '" << m_.tools[k].name << "' moved " << travel << " mm in one cycle at t = " << t_ << " s (cycle "
         << cycle_ << "), more than the smallest element (" << min_length_
         << " mm): the contact cannot follow it (a tool load or speed far beyond what the model can carry)";
      throw NumericalFault(os.str());
    }
  }
}

void Solver::guard_time_step() {
  check_dt();  // zero or non-finite: a fault whatever the collapse guard says
  if (dt_ < m_.guards.dt_collapse.limit * dt0_) {
    std::ostringstream os;
    os << "time step collapsed to " << dt_ << " s = " << dt_ / dt0_ << " x the initial " << dt0_
       << " s at t = " << t_ << " s (cycle " << cycle_ << "), below [guards] dt_collapse = "
       << m_.guards.dt_collapse.limit << "; the smallest element is being crushed (check loads and contact)";
    guard_fired(m_.guards.dt_collapse, 0, os.str());
  }
}

void Solver::fault_nonfinite_velocity(int node) const {
  std::ostringstream os;
  os << "non-finite velocity (NaN or Inf) at node " << node << " at t = " << t_ << " s (cycle " << cycle_ << ")";
  if (const int e = nonfinite_element(); e >= 0) os << "; element " << e << " has a non-finite stress or force";
  os << ": the solution diverged (a load far beyond what the sheet can carry, or a time step too large for a "
        "stiffness: penalty, hourglass, tool mass?)";
  throw NumericalFault(os.str());
}

void Solver::account_energies(const EnergyIncrement& inc) {
  en_.damping += inc.damping;
  en_.external_work += inc.work;
  en_.kinetic = inc.kinetic;
  double ie = 0, eh = 0, dtmin = 1e30;  // the element loop's chunk sums (element_forces), in order
  for (std::size_t ch = 0; ch < elem_partial_.size(); ch += 3) {
    ie += elem_partial_[ch];
    eh += elem_partial_[ch + 1];
    dtmin = std::min(dtmin, elem_partial_[ch + 2]);
  }
  dt_elem_min_ = dtmin;
  if (!std::isfinite(ie + eh)) {
    std::ostringstream os;
    os << "non-finite internal or hourglass energy at t = " << t_ << " s (cycle " << cycle_ << ")";
    if (const int e = nonfinite_element(); e >= 0) os << " in element " << e;
    throw NumericalFault(os.str() + ": the solution diverged");
  }
  en_.internal += ie;
  en_.hourglass += eh;
}

void Solver::advance_time(double dt) {
  t_ += dt;
  last_dt_ = dt;
  step_time_ += dt;
  ++cycle_;
  dt_ = m_.dt_safety * dt_elem_min_;
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
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k)
        if (!std::isfinite(corner_[kCornerStride * static_cast<std::size_t>(corner_slot_[8 * e + a]) + k])) return e;
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
  for (std::size_t k = 0; k < plan_.reaction_names.size(); ++k)
    if (plan_.reaction_names[k] == set) return reactions_[k];
  return {0, 0, 0};
}

Vec3 Solver::applied(const std::string& set) const {
  Vec3 s{0, 0, 0};
  if (plan_step_ < 0) return s;
  const auto& forces = m_.steps[plan_step_].forces;
  for (std::size_t l = 0; l < forces.size(); ++l)
    if (forces[l].set == set)
      for (int k = 0; k < 3; ++k) s[k] += applied_[l][k];
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
