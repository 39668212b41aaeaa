#pragma once
// A complete explicit analysis: mesh, material, rigid tools, contact pairs,
// and a sequence of steps with their boundary conditions and loads.
// Units: mm, N, MPa, s, t/mm^3 (so that N = t mm/s^2).
#include <array>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "contact/surface.hpp"
#include "core/vec3.hpp"
#include "fe/guards.hpp"
#include "fe/history.hpp"
#include "fe/mesh.hpp"
#include "friction/friction_law.hpp"
#include "material/material.hpp"

namespace drawbend::fe {

using drawbend::Vec3;  // core/vec3.hpp

/// Fixed degrees of freedom (also symmetry planes: fix the normal component).
struct FixedBC {
  std::string set;
  std::array<bool, 3> dof{true, true, true};
};

/// Prescribed velocity of a node set along a unit direction [mm/s].
struct VelocityBC {
  std::string set;
  Vec3 direction{1, 0, 0};
  History speed;
};

/// Rigid rotation of a node set about an axis through `centre` [rad/s]:
/// v = omega(t) axis x (x - centre).  The thesis's step 1 (circular motion).
struct RotationBC {
  std::string set;
  Vec3 centre{0, 0, 0};
  Vec3 axis{0, 0, 1};
  History omega;
  /// Optional unit direction along which the set (and the centre) slides freely
  /// as a rigid body, with no net reaction: pure bending of a strip whose other
  /// end is a symmetry plane.  Zero vector: no sliding.
  Vec3 slide{0, 0, 0};
};

/// A velocity field linear in the reference coordinates X:
/// v = scale(t) G (X - centre) [mm/s]; G in 1/s.  Patch tests, homogeneous deformation.
struct AffineBC {
  std::string set;
  std::array<std::array<double, 3>, 3> G{};
  Vec3 centre{0, 0, 0};
  History scale = History::constant(1.0);
};

/// A total force [N] along a unit direction, spread over a node set in
/// proportion to the nodal masses (back tension).
struct ForceLoad {
  std::string set;
  Vec3 direction{1, 0, 0};
  History magnitude;
};

/// A rigid tool: analytic surfaces moving together.
struct Tool {
  enum class Drive { fixed, velocity, force };
  std::string name;
  std::vector<contact::Surface> surfaces;
  Drive drive = Drive::fixed;
  Vec3 direction{0, 0, 1};  ///< direction of motion (velocity or force drive)
  History speed;            ///< velocity drive [mm/s]
  History force;            ///< force drive: applied force along direction [N]
  double mass = 0;          ///< force drive: rigid-body mass [t]
  /// force drive: the largest offset along `direction` [mm] (a stop, as a blank holder pressed onto spacers:
  /// the force holds the tool there until the sheet pushes it back with more); +inf: none.
  double stop = std::numeric_limits<double>::infinity();
};

/// Node-to-rigid-surface penalty contact between a face set and a tool.
struct ContactPair {
  std::string faces;  ///< face set of the sheet (slave side)
  std::string tool;
  double penalty = 0.1;  ///< penalty factor alpha: k = alpha K A / L (see contact.cpp)
  double damping = 0.2;  ///< normal contact damping, fraction of critical 2 sqrt(k m) (see contact.cpp)
  std::shared_ptr<friction::FrictionLaw> friction;  ///< nullptr: frictionless
  /// fixed: RD = the model's rolling direction projected on the tool (thesis Sec. 6.4); corotational:
  /// RD follows the polar rotation of the sheet face at each node (contact/texture.hpp).
  enum class Texture { fixed, corotational };
  Texture texture = Texture::fixed;
};

struct Step {
  std::string name = "step";
  double duration = 1.0;        ///< [s]
  double damping = 0.0;         ///< dynamic relaxation: velocity damping rate [1/s] (0 = none)
  std::string damping_where;    ///< "file:line: key" of damping in a deck, for messages (empty: set in code)
  bool friction = true;         ///< false: contact is frictionless during this step
  bool quasi_static = false;    ///< the kinetic-energy guard applies (fe/guards.hpp)
  std::vector<FixedBC> fixed;
  std::vector<VelocityBC> velocities;
  std::vector<RotationBC> rotations;
  std::vector<AffineBC> affine;
  std::vector<ForceLoad> forces;
  std::vector<std::pair<std::string, Tool::Drive>> tool_drive;  ///< override a tool's drive for this step
};

struct Model {
  std::string name = "case";
  Mesh mesh;
  std::shared_ptr<const material::Material> material;
  /// The sheet frame: the rolling direction RD (global, need not be unit), stated once.  The
  /// friction texture of every contact pair and the material axes of an anisotropic material
  /// both start from it, projected into the sheet's plane (material/sheet_frame.hpp).
  Vec3 rolling_direction{1, 0, 0};
  std::vector<Tool> tools;
  std::vector<ContactPair> contacts;
  std::vector<Step> steps;
  // Numerical settings.
  double dt_safety = 0.8;      ///< fraction of the critical time step
  double mass_scaling = 1.0;   ///< uniform density factor (>= 1)
  double target_dt = 0.0;      ///< > 0: scale element masses so that each element's stable step >= target [s]
  double hourglass = 1.0;      ///< factor on the physical hourglass stiffness
  Vec3 gravity{0, 0, 0};       ///< [mm/s^2]
  Guards guards;               ///< numerical fault detection (fe/guards.hpp)

  void validate() const;  ///< throws std::invalid_argument naming what is wrong

  /// A fixed rigid tool with one surface, in contact with face set `faces`
  /// (frictionless when `friction` is null).  Returns the contact pair.
  ContactPair& add_rigid_contact(const std::string& tool, const contact::Surface& surface, const std::string& faces,
                                 std::shared_ptr<friction::FrictionLaw> friction = nullptr);
};

}  // namespace drawbend::fe
