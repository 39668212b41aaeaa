#include "friction/stribeck_law.hpp"

#include <stdexcept>

namespace drawbend::friction {

Stribeck::Stribeck(const analysis::StribeckParams& p, int interval) : p_(p), interval_(interval) {
  p_.validate("Stribeck friction law");
  if (interval < 1) throw std::invalid_argument("Stribeck friction law: update interval must be >= 1 cycle");
}

Limit Stribeck::limit(const ContactState& s) const {
  auto mu_at = [&](double v) {
    if (!(s.pressure > 0)) return p_.mu_EHL;  // no load: L -> infinity
    return analysis::stribeck_mu(analysis::lubricant_number(v, s.pressure, p_), p_);
  };
  double* st = s.state;  // [0] current mu (0: not yet set), [1] speed sum, [2] count
  st[1] += s.slip_speed;
  st[2] += 1.0;
  if (st[0] == 0.0 || st[2] >= interval_) {
    st[0] = mu_at(st[1] / st[2]);
    if (st[2] >= interval_) {
      st[1] = 0.0;
      st[2] = 0.0;
    }
  }
  return {st[0], st[0]};
}

std::string Stribeck::describe() const {
  return "stribeck mu_BL=" + std::to_string(p_.mu_BL) + " mu_EHL=" + std::to_string(p_.mu_EHL) +
         " interval=" + std::to_string(interval_);
}

}  // namespace drawbend::friction
