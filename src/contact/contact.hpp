#pragma once
// Node-to-rigid-surface penalty contact with friction, as a module of its own
// (library drawbend_contact, with src/friction/).  The solver hands it one
// contact pair at a time as a ContactView: plain pointers into the solver's
// nodal arrays and into the pair's own state, like fe::ElementView for the
// element loop.  The pair's names (face set, tool) were resolved to index
// arrays at set-up; nothing here allocates.  The physics (penalty stiffness,
// pressure, damping, friction return) is described in contact/contact.cpp.
// Units: mm, N, MPa, s, t.
#include <array>
#include <vector>

#include "contact/surface.hpp"
#include "contact/texture.hpp"
#include "friction/friction_law.hpp"

namespace drawbend::contact {

/// Per contact node, the state the contact maps report.
struct ContactNode {
  int node = -1;
  double area = 0;          ///< tributary area [mm^2]
  double normal_force = 0;  ///< [N]
  double pressure = 0;      ///< [MPa]
  double depth = 0;         ///< penetration [mm]
  Vec3 normal{0, 0, 0}, ft{0, 0, 0};  ///< tool normal; tangential force on the sheet [N]
  double slip_speed = 0;    ///< [mm/s]
  int surface = -1;         ///< index of the tool surface in contact (-1: none)
  Vec3 foot{0, 0, 0};       ///< closest point on the tool [mm]
  /// Slip accumulated over the run [mm]: the sum of slip_speed x dt over every
  /// cycle the node was in contact (kept when it leaves contact, so a node that
  /// slid over the pin and left still shows how far it slid).
  double slip = 0;
  /// Friction status of the last cycle: 0 no contact, 1 stick (the trial
  /// tangential force inside the law's limit), 2 slip (returned onto the limit,
  /// or a frictionless pair).
  int status = 0;
};

/// One contact pair for one cycle.
struct ContactView {
  // The sheet's nodes (solver arrays, indexed by node id).
  const double *x = nullptr, *y = nullptr, *z = nullptr;     ///< positions [mm]
  const double *vx = nullptr, *vy = nullptr, *vz = nullptr;  ///< velocities [mm/s]
  const double* mass = nullptr;                              ///< lumped masses [t]
  // The pair's slave side, resolved at set-up.
  const std::array<int, 4>* faces = nullptr;  ///< the face set
  int num_faces = 0;
  const int* slot_face_start = nullptr;       ///< per slot + 1: where its faces start in slot_face (SlotFaces)
  const int* slot_face = nullptr;             ///< the faces of each slot, ascending
  double* face_area = nullptr;                ///< per face: scratch, its current area [mm^2]
  ContactNode* nodes = nullptr;               ///< unique slave nodes, sorted by node id
  int num_nodes = 0;
  const double* stiffness_len = nullptr;      ///< per slot: element size normal to the face [mm]
  std::array<double, 3>* force = nullptr;     ///< per slot: contact force on the sheet [N] (out)
  double* stored = nullptr;                   ///< per slot: scratch, stored penalty energy [mJ]
  double* dissipated = nullptr;               ///< per slot: scratch, friction dissipation [mJ]
  // The tool.
  const Surface* surfaces = nullptr;
  int num_surfaces = 0;
  Vec3 tool_offset{0, 0, 0}, tool_velocity{0, 0, 0};  ///< [mm], [mm/s]
  // Contact law.
  double penalty = 0;        ///< alpha in k = alpha K A / L
  double damping = 0;        ///< fraction of critical
  double bulk_modulus = 0;   ///< K [MPa]
  const friction::FrictionLaw* law = nullptr;  ///< nullptr: frictionless (this step or this pair)
  double* friction_state = nullptr;            ///< law->state_size() per slot
  int state_size = 0;
  const TextureRef* texture = nullptr;         ///< per slot: corotational texture; nullptr: fixed axis
  Vec3 rolling_direction{1, 0, 0};             ///< the fixed texture axis
  bool parallel = false;                       ///< run the node loop on threads (results do not depend on it)
};

/// What one pair did in one cycle, summed in a fixed order (deterministic).
struct PairTotals {
  double* friction = nullptr;   ///< += frictional dissipation [mJ]
  double* stored = nullptr;     ///< += stored penalty energy [mJ]
  Vec3* tool_force = nullptr;   ///< -= the forces on the sheet: the force on the tool [N]
};

/// Each slot's faces in ascending order (compressed rows: slot k's are
/// face[start[k]] .. face[start[k+1]-1]), built once from a pair's face_slot
/// (4 per face: the slot of each corner).
/// A node's tributary area is then summed by the node itself, face by face in
/// the order a pass over the faces would add them: the same bits, on any
/// number of threads.
struct SlotFaces {
  std::vector<int> start, face;
};
SlotFaces slot_faces(const int* face_slot, int num_faces, int num_slots);

/// Area of a (possibly warped) quadrilateral face: half the cross product of its diagonals [mm^2].
double face_area(const double* x, const double* y, const double* z, const std::array<int, 4>& f);

/// Contact and friction forces of one pair over an interval dt: the nodes'
/// areas, depths, pressures, tangential forces and contact forces.  Returns
/// the first slot deeper than `penetration_limit` x its element size (-1: none),
/// for the solver's penetration guard.
int pair_forces(const ContactView& v, double dt, double penetration_limit, const PairTotals& totals);

}  // namespace drawbend::contact
