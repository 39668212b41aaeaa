#include "fe/strip.hpp"

#include <cmath>
#include <stdexcept>

namespace drawbend::fe {

double wrap_length(const StripSpec& s) { return (s.pin_radius + 0.5 * s.thickness) * s.wrap; }

Mesh wrapped_strip(const StripSpec& s) {
  if (!(s.pin_radius > 0 && s.thickness > 0 && s.width > 0 && s.element_length > 0 && s.inlet_length >= 0 &&
        s.outlet_length >= 0 && s.across >= 1 && s.through >= 1))
    throw std::invalid_argument("wrapped_strip: lengths must be > 0 and element counts >= 1");
  if (!(s.wrap > 0 && s.wrap < M_PI)) throw std::invalid_argument("wrapped_strip: wrap angle must lie in (0, 180) deg");
  const double arc = wrap_length(s);
  auto count = [&](double len) { return std::max(1, static_cast<int>(std::lround(len / s.element_length))); };
  std::vector<double> bp{-s.inlet_length, 0.0, arc, arc + s.outlet_length};
  std::vector<int> counts{count(s.inlet_length), count(arc), count(s.outlet_length)};
  if (s.inlet_length == 0) {
    bp.erase(bp.begin());
    counts.erase(counts.begin());
  }
  if (s.outlet_length == 0) {
    bp.pop_back();
    counts.pop_back();
  }
  Mesh m = structured_block(piecewise_lines(bp, counts), uniform_lines(0, s.width, s.across),
                            uniform_lines(0, s.thickness, s.through));
  const double Rm = s.pin_radius + 0.5 * s.thickness;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const double sp = m.x[i], zeta = m.z[i], r = s.pin_radius + zeta;
    double x, z;
    if (sp <= 0) {  // inlet leg, along +x at the top of the pin
      x = sp;
      z = r;
    } else if (sp <= arc) {  // wrapped: angle from the top, clockwise about +y
      const double phi = sp / Rm;
      x = r * std::sin(phi);
      z = r * std::cos(phi);
    } else {  // outlet leg along the tangent at the end of the wrap
      const double d = sp - arc;
      x = r * std::sin(s.wrap) + d * std::cos(s.wrap);
      z = r * std::cos(s.wrap) - d * std::sin(s.wrap);
    }
    m.x[i] = x;
    m.z[i] = z;
  }
  return m;
}

}  // namespace drawbend::fe
