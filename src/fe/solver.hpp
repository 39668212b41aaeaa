#pragma once
// The explicit solver: central differences with lumped mass.
//
// One cycle (time t_n -> t_n+1), LULESH-style:
//   1. element loop (OpenMP): gather nodes -> uniform gradient, Jaumann rate,
//      material update, hourglass -> per-element corner forces;
//   2. node loop (OpenMP): sum the corners of each node in a fixed order, add
//      loads and contact forces -> accelerations;
//   3. velocities at t_n+1/2 (with dynamic-relaxation damping in damped steps),
//      boundary conditions (their reactions are recorded), positions at t_n+1.
// Forces are summed in a fixed order, so the result does not depend on the
// thread count.  Units: mm, N, MPa, s, t/mm^3.
#include <functional>
#include <string>
#include <vector>

#include "contact/contact.hpp"
#include "fe/guards.hpp"
#include "fe/model.hpp"
#include "fe/mesh.hpp"
#include "fe/parallel_policy.hpp"  // whether a loop forks: parallel::worth_forking
#include "fe/fork_governor.hpp"
#include "fe/phase_times.hpp"
#include "fe/step_phases.hpp"
#include "fe/work_shares.hpp"

namespace drawbend::fe {


struct Energies {
  double kinetic = 0, internal = 0, hourglass = 0;
  double external_work = 0;  ///< work of loads, boundary reactions and tools on the sheet
  double friction = 0;       ///< frictional dissipation (part of the tools' work)
  double contact_stored = 0; ///< penalty spring energy now stored (part of the tools' work)
  double damping = 0;        ///< energy removed by dynamic-relaxation damping
  double initial_kinetic = 0;  ///< kinetic energy of the initial velocities (set_velocity)
  /// |KE + IE + HG + damping - W - KE0| relative to the largest energy flow (W,
  /// KE + IE + HG, KE0, friction or damping), where W is the work done on the
  /// sheet by loads, boundary reactions and contact forces and KE0 the initial
  /// kinetic energy.
  double balance_error() const;
};

/// Per contact node, the state the contact maps report (contact/contact.hpp).
using ContactNode = contact::ContactNode;

struct Progress {
  int step_index;
  const Step* step;
  double time, step_time, dt;
  long cycle;
};

class Solver {
 public:
  explicit Solver(Model& model);

  /// Run all steps.  on_cycle is called every cycle (cheap checks); outputs
  /// are the caller's business through the accessors.
  void run(const std::function<void(const Progress&)>& on_cycle = {});
  /// Run one step of the model (index into model.steps).
  void run_step(int index, const std::function<void(const Progress&)>& on_cycle = {});

  /// Initial conditions (before run): nodal velocity [mm/s], element stress [MPa].
  void set_velocity(int node, const Vec3& v);
  void set_stress(int element, const double s[6]);

  // State (structure of arrays).
  const Model& model() const { return m_; }
  double time() const { return t_; }
  double dt() const { return dt_; }
  long cycles() const { return cycle_; }
  /// Cycles whose element loop ran on threads (make bench: how much of a run
  /// the fork model and governor let fork; fe/fork_governor.hpp).
  long forked_cycles() const { return forked_cycles_; }
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::vector<double>& z() const { return z_; }
  const std::vector<double>& vx() const { return vx_; }
  const std::vector<double>& vy() const { return vy_; }
  const std::vector<double>& vz() const { return vz_; }
  const std::vector<double>& mass() const { return mass_; }
  /// Element stress (mean of the two integration points), 6 per element (Voigt) [MPa].
  std::vector<double> stress() const;
  const std::vector<double>& material_state() const { return state_; }
  double plastic_strain(int e) const;  ///< mean of the two integration points
  const Energies& energies() const { return en_; }
  /// Hourglass state per element: 6 generalised forces of the xi*eta and
  /// xi*eta*zeta modes (local components) and the relaxed tangent ratio; for
  /// diagnostics and tests.
  const std::vector<double>& hourglass_forces() const { return hgq_; }
  const std::vector<double>& hourglass_ratio() const { return hg_ratio_; }
  /// Hourglass work of each element in the last cycle [mJ] (sums to the
  /// cycle's increment of energies().hourglass); for diagnostics.
  const std::vector<double>& hourglass_increments() const { return hg_inc_; }
  double added_mass() const { return added_mass_; }   ///< mass added by scaling [t]
  double physical_mass() const { return phys_mass_; }
  /// Reaction force [N] of the boundary conditions on node set `set` in the
  /// last cycle (sum over the set; x, y, z).
  Vec3 reaction(const std::string& set) const;
  /// Reaction force [N] at one node in the last cycle.
  Vec3 node_reaction(int node) const { return {rx_[node], ry_[node], rz_[node]}; }
  /// Sum of the loads applied on `set` in the last cycle [N].
  Vec3 applied(const std::string& set) const;
  /// Contact force of the sheet on tool `tool` in the last cycle [N] (x, y, z).
  Vec3 tool_force(const std::string& tool) const;
  Vec3 tool_offset(const std::string& tool) const;  ///< displacement of a tool [mm]
  const std::vector<ContactNode>& contact_nodes(int pair) const { return contact_[pair]; }
  int num_contact_pairs() const { return static_cast<int>(contact_.size()); }
  /// Friction-law state of a contact pair (state_size() doubles per contact node).
  const std::vector<double>& friction_state(int pair) const { return friction_state_[pair]; }
  double stable_dt() const;  ///< current critical step times the safety factor [s]
  double max_penetration() const;

  /// Accumulate the wall time of each phase of the cycle into `t` (make
  /// bench's per-phase split; nullptr, the default: not timed).  `t` must
  /// outlive the runs; timing changes no result.
  void time_phases(PhaseTimes* t) { phases_ = t; }

  /// Guards set to "warn" report here (default: kept in warnings()).
  void set_warning_handler(std::function<void(const std::string&)> h) { on_warning_ = std::move(h); }
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// Checkpoint/restart (fe/checkpoint.cpp): the complete state at the end of
  /// a cycle, so that a restarted run continues bit for bit.  load_state
  /// expects a solver built from the same model; run() then continues from
  /// the saved step and step time.
  void save_state(std::string& out) const;
  void load_state(const std::string& in, const std::string& source);

 private:
  // The phases of a cycle that touch the solver's own state (run_step).
  void begin_step(int index);                 ///< resolve the step's names (plan_), reset per-step state
  NodeView node_view();
  void check_force_driven_tools() const;      ///< throws std::invalid_argument: a tool too light for dt
  void check_damping(const Step& step) const; ///< throws std::invalid_argument: damping x dt >= 2
  void guard_time_step();                     ///< non-finite or collapsed time step
  void guard_tool_travel(double dt) const;    ///< a tool moved past the smallest element in one cycle
  void element_forces();                      ///< the element loop: corner forces into their slots
  contact::ContactView contact_view(std::size_t pair, bool friction, const NodeView& nodes);
  void guard_penetration(std::size_t pair, int slot);  ///< the penetration guard for one slave node
  /// contact::pair_forces per pair, added into ext; the penetration guard.
  void contact_phase(double dt, bool friction, const NodeView& nodes, NodeField ext);
  [[noreturn]] void fault_nonfinite_velocity(int node) const;
  /// Adds the interval's energies and the elements' (one pass over the
  /// elements, which also finds their smallest stable step); non-finite guard.
  void account_energies(const EnergyIncrement& inc);
  void advance_time(double dt);               ///< t, cycle and the next stable step (account_energies')
  void compute_dt();
  /// Throws NumericalFault naming the element if the step is zero or not finite.
  void check_dt() const;
  /// A guard fired: throw NumericalFault (action "error") or warn once per step.
  void guard_fired(const Guard& g, int id, const std::string& what);
  /// The element with a non-finite stress or corner force (-1: none), for messages.
  int nonfinite_element() const;
  void check_step_energies(const Step& step);

  Model& m_;
  NodeCorners nc_;
  std::vector<double> x_, y_, z_, vx_, vy_, vz_, mass_;  // nodes
  std::vector<double> inv_mass_;                         // 1 / mass_, set with it
  std::vector<double> sig_, state_, hgq_, corner_, elem_mass_factor_, dt_elem_, ie_inc_, hg_inc_;  // elements
  std::vector<double> elem_sqrt_mass_factor_;  // sqrt of elem_mass_factor_, set with it (the element loop's time step)
  std::vector<int> corner_slot_;  // per element corner (8e + a): its slot in corner_, node-major (nc_ order)
  bool elements_forked_ = false;  // this cycle's element loop ran on threads (parallel::worth_forking)
  ForkGovernor governor_;         // whether forking pays on this machine now (measured)
  bool fork_allowed_ = true;      // this cycle: governor_'s answer (always true unless parallel::Mode::model)
  // The element loop's blocks: a share per thread, stolen at the end (fe/work_shares.hpp).
  parallel::WorkShares element_shares_;
  double dt_elem_min_ = 0;        // this cycle's smallest element step (account_energies)
  std::vector<Vec3> tool_offset_, tool_vel_, tool_force_;
  std::vector<std::vector<ContactNode>> contact_;
  std::vector<std::vector<double>> contact_stiffness_len_;  // per pair, per node: adjacent element size V/A [mm]
  std::vector<std::vector<double>> friction_state_;
  std::vector<std::vector<contact::TextureRef>> texture_ref_;  // per pair (corotational with friction only), per node
  std::vector<std::vector<Vec3>> contact_force_;  // per pair, per contact node, force on sheet
  // Contact pairs resolved at set-up: tool index, face list, and per face corner the slot of its node.
  std::vector<int> pair_tool_;
  std::vector<const std::vector<Quad>*> pair_faces_;
  std::vector<std::vector<int>> face_slot_;
  std::vector<contact::SlotFaces> slot_faces_;  // per pair: each slot's faces (the area pass per node)
  std::vector<double> face_area_scratch_;       // contact: per face of the largest pair, its area
  StepPlan plan_;         // the current step's names resolved (begin_step)
  int plan_step_ = -1;    // the step plan_ belongs to
  std::vector<Vec3> reactions_, applied_;  // last cycle: per reaction slot of plan_, per load of the step
  std::vector<double> ex_, ey_, ez_, v0x_, v0y_, v0z_;  // per node: external force, velocity before the update
  std::vector<int> ext_nodes_;  // the step's load-set and contact nodes: where apply_loads resets ext
  std::vector<double> energy_scratch_[2];  // contact: per node of the largest pair, stored and dissipated energy
  std::vector<double> rx_, ry_, rz_;  // per-node reactions of the last cycle
  std::vector<double> elem_partial_, node_partial_;  // per chunk of kSumChunk: element (ie, hg, dt) and node energy sums
  std::vector<Vec3> slide_offset_;    // per rotation BC of the current step: slid distance [mm]
  std::vector<double> hg_ratio_;      // per element, relaxed tangent ratio (stabilisation, thickness strain)
  Energies en_;
  double last_dt_ = 0;  // length of the interval that produced the current velocities
  double t_ = 0, dt_ = 0, dt0_ = 0, added_mass_ = 0, phys_mass_ = 0, wave_speed_ = 0;
  double min_length_ = 0;  ///< the smallest element's stable length in the initial mesh [mm] (guard_tool_travel)
  long cycle_ = 0;
  long forked_cycles_ = 0;  // forked_cycles()
  // Where the run is: step index, time into it, its start time (restart point).
  int step_index_ = 0;
  double step_time_ = 0, step_t_start_ = 0;
  PhaseTimes* phases_ = nullptr;  // time_phases
  std::function<void(const std::string&)> on_warning_;
  std::vector<std::string> warnings_;
  static constexpr int kGuardIds = 8;
  bool warned_[kGuardIds] = {};
};

}  // namespace drawbend::fe
