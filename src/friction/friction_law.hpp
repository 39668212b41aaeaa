#pragma once
// The friction-law interface of the contact algorithm.
//
// At every contacting node and step the contact code asks the law for the
// friction coefficients given the local contact state: pressure, sliding
// speed, sliding direction and the sheet's texture axes.  The law returns the
// semi-axes (mu_1, mu_2) of an elliptical stick/slip limit in the tangent
// plane, along the texture axes e_1 (rolling direction) and e_2 (transverse);
// an isotropic law returns mu_1 = mu_2.  Stick/slip is a return mapping of
// the trial tangential force onto that limit, done by the contact code.
// Laws may keep per-node state (e.g. the Stribeck law's interval-averaged
// speed, Sec. 3.3.2) in `state`, state_size() doubles per contact node.
// Units: pressure MPa, speed mm/s.
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/vec3.hpp"

namespace drawbend::friction {

using drawbend::Vec3;

struct ContactState {
  double pressure = 0;    ///< normal force / tributary area [MPa]
  double slip_speed = 0;  ///< magnitude of the tangential relative velocity [mm/s]
  Vec3 slip_dir{0, 0, 0}; ///< unit tangential slip direction (zero when sticking)
  Vec3 normal{0, 0, 1};   ///< outward tool normal
  Vec3 e1{1, 0, 0};       ///< texture axis 1 (RD) projected onto the tangent plane, unit
  double* state = nullptr;
};

struct Limit {
  double mu1 = 0, mu2 = 0;  ///< friction coefficients along e1 and e2
};

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;
  virtual Limit limit(const ContactState& s) const = 0;
  virtual int state_size() const { return 0; }
  virtual std::string describe() const = 0;
  /// Named event counts summed over the per-node states of one contact pair
  /// (`state`: state_size() doubles per node), e.g. evaluations clamped to the
  /// law's input domain; reported once at the end of a run.  Empty: none.
  virtual std::vector<std::pair<std::string, double>> counters(const std::vector<double>& /*state*/) const {
    return {};
  }
};

/// Coulomb friction, mu constant (>= 0).
class Coulomb final : public FrictionLaw {
 public:
  explicit Coulomb(double mu) : mu_(mu) {
    if (!(mu >= 0.0)) throw std::invalid_argument("Coulomb friction: mu must be >= 0");
  }
  Limit limit(const ContactState&) const override { return {mu_, mu_}; }
  std::string describe() const override { return "coulomb mu=" + std::to_string(mu_); }
  double mu() const { return mu_; }

 private:
  double mu_;
};

}  // namespace drawbend::friction
