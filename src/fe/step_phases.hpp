#pragma once
// The phases of one explicit cycle (fe/solver_loop.cpp, Solver::run_step,
// reads them in this order: time-step guard; forces (element loop, into corner
// slots); loads at t_n; contact and friction; nodal sums and velocities at
// t_n+1/2; constraints; energies and positions at t_n+1 (with their guards);
// tools; time; output, the caller's) as functions over plain
// views of the solver's structure-of-arrays state, and the step plan: the
// step's node-set and tool names resolved to index arrays once, when the step
// starts.  Nothing here allocates; the plan and the scratch arrays are sized
// at set-up.  Units: mm, N, MPa, s, t/mm^3.
#include <string>
#include <vector>

#include "fe/model.hpp"
#include "fe/node_view.hpp"

namespace drawbend::fe {


/// A step's names resolved once, at its start.
struct StepPlan {
  /// A constraint on a node set; its reaction goes to a slot of `reaction_names`
  /// (sets named twice share one slot: the first constraint writes it, later ones add).
  struct Constrained {
    const std::vector<int>* nodes = nullptr;
    int slot = 0;
    bool first = true;
  };
  struct Load {
    const std::vector<int>* nodes = nullptr;
    std::vector<double> weight;  ///< mass-proportional share of each node
  };
  std::vector<Load> loads;                      ///< one per step.forces
  std::vector<Constrained> rotations, affine, velocities, fixed;  ///< one per BC of the step, same order
  std::vector<std::string> reaction_names;      ///< unique set names, first appearance first
  std::vector<Tool::Drive> drive;               ///< per tool: its drive in this step
};

/// Names -> index arrays for `step` (throws std::invalid_argument on an unknown name).
StepPlan plan_step(const Model& m, const Step& step, const std::vector<double>& mass);
/// The tool of that name (throws std::invalid_argument).
int tool_index(const Model& m, const std::string& name);

/// Loads: ext = the step's force loads at step time `ts` plus gravity; applied[l] = the total of load l.
/// `reset`: the nodes whose ext the last cycle may have set (the step's load
/// sets and the contact nodes); without gravity only they are zeroed first,
/// so ext must be zero at every other node (zero it when the step starts).
void apply_loads(const Model& m, const Step& step, const StepPlan& plan, double ts, const NodeView& v, NodeField ext,
                 Vec3* applied, const std::vector<int>& reset);

/// The node pass, one per node: f = the node's corner forces summed in their
/// fixed order (`corner`, node-major: kCornerStride doubles per slot, node i's slots
/// start[i] .. start[i+1]-1, ascending element and corner), then v0 = v;
/// v = a1 v + a2 (f + ext) / m.  Over threads when `parallel` (each node is
/// its own, so the results do not depend on it).  Returns the lowest node with
/// a non-finite velocity (-1: none).
int sum_and_integrate(const int* start, const double* corner, const NodeView& v, NodeField ext, double a1, double a2,
                      NodeField v0, bool parallel);

/// Constraints at mid-interval step time `th`: rotations (with free sliding,
/// `slide_offset` per rotation), affine fields, velocities, fixed dofs, in that
/// order; r = the per-node reactions, reactions = their sums per slot.  r must
/// be zero at every node outside the plan's constraints (zero it when the
/// step starts): only the constrained nodes' entries are reset here.
void enforce_constraints(const Step& step, const StepPlan& plan, double th, double dt, const NodeView& v,
                         Vec3* slide_offset, NodeField r, Vec3* reactions);

/// Work of loads and reactions over the interval, kinetic energy, damping loss.
struct EnergyIncrement {
  double work = 0, kinetic = 0, damping = 0;
};
/// The fixed chunk of the solver's reductions: a total over nodes or
/// elements is summed in order inside each chunk of kSumChunk items, then
/// over the chunks in order, so its bits depend on neither the thread count
/// nor the schedule (issue 22).
inline constexpr int kSumChunk = 256;

/// The interval's energies, summed in fixed chunks (kSumChunk), and in the
/// same pass the positions at t_n+1, x += dt v; on the threads when `parallel`.
/// `partial`: room for 3 values per chunk.
EnergyIncrement energies_and_move(const NodeView& v, NodeField ext, NodeField r, NodeField v0, double dt, double c,
                                  double* partial, bool parallel);

/// Rigid tools: velocity-driven tools at their speed at `th`, force-driven
/// tools as rigid masses (force at step time `ts`, the sheet's reaction
/// `tool_force`, damping factors a1, a2), then offsets.
void move_tools(const Model& m, const StepPlan& plan, double th, double ts, double dt, double a1, double a2,
                const Vec3* tool_force, Vec3* tool_vel, Vec3* tool_offset);

}  // namespace drawbend::fe
