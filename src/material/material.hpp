#pragma once
// Constitutive models for the explicit solver: the interface every material
// implements, and the isotropic elastic constants they share.
//
// Conventions (all materials):
//  - Voigt order for stress and strain: xx, yy, zz, xy, yz, zx.
//  - Strain increments use ENGINEERING shear (gamma_xy = 2 eps_xy); stresses
//    are tensor components (sigma_xy).
//  - Units: MPa, t/mm^3, mm/s (see README.md "Units").
//  - The caller rotates the stress to the current configuration before
//    update() (objective stress rate); the material sees a small-strain
//    increment only.
//
// Extending: a new model (kinematic hardening with a backstress in the state,
// Hill'48 with its own yield function, ...) is a new class deriving from
// Material with its own state layout.  Element code only calls state_size(),
// init_state() and update()/update_many(), so it does not change.
#include <cstddef>
#include <string>

namespace drawbend::material {

// Voigt component indices.
inline constexpr int XX = 0, YY = 1, ZZ = 2, XY = 3, YZ = 4, ZX = 5;

class Material {
 public:
  virtual ~Material() = default;
  /// Number of history variables per integration point (J2 isotropic: 1 = equivalent plastic strain).
  virtual int state_size() const = 0;
  /// Initial (virgin) state; the default sets all state_size() doubles to zero.
  virtual void init_state(double* state) const;
  /// Update the Cauchy stress (already rotated to the current configuration by the caller) for the strain
  /// increment deps (engineering shear). state points to state_size() doubles. Must not allocate.
  virtual void update(const double deps[6], double sigma[6], double* state) const = 0;
  /// Update `count` integration points stored contiguously: deps and sigma hold 6*count doubles,
  /// state holds state_size()*count doubles.  Same result as calling update() on each point; models
  /// override it (as `final` classes) so that a block of elements costs one virtual call, not one per point.
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
  virtual double tangent_ratio(const double* /*sigma*/, const double* /*state*/) const { return 1.0; }
  /// Equivalent plastic strain of a state vector (0 for elastic materials), for output.
  virtual double plastic_strain(const double* /*state*/) const { return 0.0; }
  /// One-line description with the constants, for output-file headers (default: the elastic constants).
  virtual std::string describe() const;
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

}  // namespace drawbend::material
