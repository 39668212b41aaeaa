#pragma once
// Constitutive models for the explicit solver: the interface every material
// implements, and the isotropic elastic constants they share.
//
// Conventions (all materials):
//  - Voigt order for stress and strain: xx, yy, zz, xy, yz, zx.
//  - Strain increments use ENGINEERING shear (gamma_xy = 2 eps_xy); stresses
//    and back stresses are tensor components (sigma_xy).
//  - Units: MPa, t/mm^3, mm/s (see README.md "Units").
//
// The contract with the element (fe/element_kernel.hpp), as it is:
//  - Set-up: init_state(state, axes) once per integration point, with the
//    sheet axes there (RD, TD, ND in global components, from the deck's one
//    rolling direction projected into the element's sheet plane:
//    material/sheet_frame.hpp).  A material that carries directions (Hill'48)
//    stores them in its state; the default ignores them.
//  - Each cycle: the element rotates the stress with the point's spin
//    (material/objectivity.hpp, the Jaumann increment) and calls
//    update(deps, spin, sigma, state) with the small-strain increment.  The
//    material must rotate every other tensor- or vector-valued history it
//    keeps (back stresses, anisotropy axes) with the same spin and the same
//    functions, so that all of them turn together with the sheet.
//  - update() must not allocate and must be deterministic (no state outside
//    `state`), so that results do not depend on thread count or kernel.
//
// Extending: a new model derives from Material with its own state layout
// (state_size() doubles per point) and follows the rules above; the element
// code does not change.  A model with a lane twin of its update (the element
// kernel's vector lanes, material/lanes/: J2Isotropic, CombinedPlasticity) says so
// through bind_lanes() (material/lane_binding.hpp); the others run point by point.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "material/objectivity.hpp"

namespace drawbend::material {

// Voigt component indices.
inline constexpr int XX = 0, YY = 1, ZZ = 2, XY = 3, YZ = 4, ZX = 5;

/// The sheet's axes at an integration point: unit, orthonormal, right-handed,
/// global components.  Default: RD = x, TD = y, ND = z.
struct LaneBinding;  // material/lane_binding.hpp

struct SheetAxes {
  double rd[3] = {1, 0, 0}, td[3] = {0, 1, 0}, nd[3] = {0, 0, 1};
};

class Material {
 public:
  virtual ~Material() = default;
  /// Number of history variables per integration point (J2 isotropic: 1 = equivalent plastic strain).
  virtual int state_size() const = 0;
  /// Initial (virgin) state at a point whose sheet axes are `axes`; the default sets all
  /// state_size() doubles to zero.
  virtual void init_state(double* state, const SheetAxes& axes) const;
  void init_state(double* state) const { init_state(state, SheetAxes{}); }
  /// Update the Cauchy stress (already rotated by the caller with `spin`) for the strain
  /// increment deps (engineering shear); rotate the state's own tensors and axes with `spin`
  /// first.  state points to state_size() doubles.  Must not allocate.
  virtual void update(const double deps[6], const Spin& spin, double sigma[6], double* state) const = 0;
  /// The same without rotation (a point that does not spin: material-level tests and drivers).
  void update(const double deps[6], double sigma[6], double* state) const { update(deps, Spin{}, sigma, state); }
  /// Update `count` integration points stored contiguously: deps and sigma hold 6*count doubles,
  /// state holds state_size()*count doubles.  Same result as calling update() on each point; models
  /// override it (as `final` classes) so that a block of elements costs one virtual call, not one per point.
  /// (No spin: for points that do not rotate.)
  virtual void update_many(std::size_t count, const double* deps, double* sigma, double* state) const;
  virtual double density() const = 0;         // t/mm^3
  virtual double youngs_modulus() const = 0;  // MPa
  virtual double poisson_ratio() const = 0;
  double bulk_modulus() const;   // E/(3(1-2nu))
  double shear_modulus() const;  // E/(2(1+nu))
  /// Dilatational wave speed sqrt((K + 4G/3)/rho) in mm/s, for the critical time step.
  double wave_speed() const;
  /// Current tangent stiffness relative to the elastic one, in [0, 1], for stiffness-proportional
  /// numerics such as hourglass control.  sigma and state are the values AFTER update().  Elastic
  /// response (and the default): 1.  J2 on the yield surface: the uniaxial elastoplastic ratio
  /// E_t/E = H/(E + H), H the hardening modulus; 0 for perfect plasticity (callers may want a floor).
  /// (Defined out of line in material.cpp: the element kernel is compiled per
  /// instruction set, and an inline body would be emitted in the AVX-512 object
  /// too, where the linker may pick that copy for every caller.)
  virtual double tangent_ratio(const double* sigma, const double* state) const;
  /// Whether update() needs the spin (its state holds tensors or axes to rotate); the element
  /// passes a zero spin otherwise, which saves the work on the isotropic models' hot path.
  virtual bool uses_spin() const { return false; }
  /// Whether the state carries the sheet axes (anisotropic models): the solver then builds
  /// them for init_state() and refuses a rolling direction normal to the sheet.
  virtual bool directional() const { return false; }
  /// Equivalent plastic strain of a state vector (0 for elastic materials), for output.
  virtual double plastic_strain(const double* /*state*/) const { return 0.0; }
  /// Whether the state holds back stresses (kinematic hardening), for output.
  virtual bool has_back_stress() const { return false; }
  /// Sum of the back stresses of a state (global axes, Voigt, tensor shears) [MPa], for
  /// output; zero for a model without kinematic hardening (the default, in material.cpp).
  virtual void back_stress(const double* state, double alpha[6]) const;
  /// A directional model's current sheet axes at a point (global, unit: they turn with the
  /// material), for output; false (and rd, nd untouched) for an isotropic model (the default).
  virtual bool sheet_axes(const double* /*state*/, double /*rd*/[3], double /*nd*/[3]) const { return false; }
  /// One-line description with the constants, for output-file headers (default: the elastic constants).
  virtual std::string describe() const;
  /// The lane twin of update(), where the model has one: sets its flag and
  /// constants in `b` (material/lane_binding.hpp), which the element kernel
  /// reads instead of asking for the model's type.  Default: none (the update
  /// runs point by point).  Out of line, as tangent_ratio.
  virtual void bind_lanes(LaneBinding& b) const;
  /// Events of this instance's updates since it was built, by name (e.g. Yld2004-18p's plastic updates,
  /// those that needed sub-increments and those that fell back to the radial scaling): the health of the
  /// update over a run, written by the run to its summary.csv (io/run_case.cpp, rows material_<name>).
  /// Counted whatever the thread, they change no result; for a deterministic run they are deterministic.
  /// Default: none.  Out of line, as tangent_ratio.
  virtual std::vector<std::pair<std::string, long>> event_counts() const;
};

/// Isotropic linear elastic constants and the derived moduli.  The constructor
/// validates E > 0, -1 < nu < 0.5, rho > 0 (throws std::invalid_argument).
struct IsotropicElasticity {
  IsotropicElasticity(double youngs_modulus, double poisson_ratio, double density);
  double E, nu, rho;
  double G;       ///< shear modulus E/(2(1+nu))
  double K;       ///< bulk modulus E/(3(1-2nu))
  double lambda;  ///< Lame's first parameter K - 2G/3

  /// sigma += C : deps (engineering shear in deps).
  void add_elastic(const double deps[6], double sigma[6]) const noexcept {
    const double lt = lambda * (deps[XX] + deps[YY] + deps[ZZ]);
    const double g2 = 2.0 * G;
    sigma[XX] += lt + g2 * deps[XX];
    sigma[YY] += lt + g2 * deps[YY];
    sigma[ZZ] += lt + g2 * deps[ZZ];
    sigma[XY] += G * deps[XY];
    sigma[YZ] += G * deps[YZ];
    sigma[ZX] += G * deps[ZX];
  }
};

/// Von Mises equivalent stress of a Voigt stress (tensor shear components).
double von_mises(const double sigma[6]) noexcept;

/// The hourglass tangent ratio of a point at f = (equivalent stress)/(yield stress)
/// whose plastic tangent ratio is `plastic` (H/(E + H)): 1 below 0.90, `plastic`
/// above 0.98, linear between.  A point flowing plastically unloads by round-off
/// now and then, and an on/off switch would flip the stabilisation every cycle.
inline double yield_proximity_ratio(double f, double plastic) noexcept {
  if (f <= 0.90) return 1.0;
  if (f >= 0.98) return plastic;
  return 1.0 + (plastic - 1.0) * (f - 0.90) / 0.08;
}

}  // namespace drawbend::material
