#include "contact/surface.hpp"

#include <cmath>
#include <sstream>
#include <tuple>
#include <stdexcept>

namespace drawbend::contact {

namespace {
inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 axpy(double s, const Vec3& a, const Vec3& b) { return {s * a[0] + b[0], s * a[1] + b[1], s * a[2] + b[2]}; }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
}  // namespace

void Surface::validate(const std::string& where) const {
  if (std::abs(norm(axis) - 1.0) > 1e-9) throw std::invalid_argument(where + ": axis/normal must be a unit vector");
  if (kind == Kind::cylinder && !(R > 0)) throw std::invalid_argument(where + ": cylinder radius must be > 0 mm");
  if (kind == Kind::torus && (!(r > 0) || !(R >= 0)))
    throw std::invalid_argument(where + ": torus radii must satisfy r > 0 and R >= 0 mm");
  // Which bounds are empty, with their values (said only "empty bounds" before 2026-12-05).
  for (const auto& [lo, hi, name] : {std::tuple{r_min, r_max, "r"}, std::tuple{z_min, z_max, "z"}, std::tuple{a_min, a_max, "angle"}})
    if (!(hi > lo)) {
      std::ostringstream m;
      m << where << ": empty bounds: expected " << name << "_min < " << name << "_max, found " << name << "_min = " << lo
        << " and " << name << "_max = " << hi;
      throw std::invalid_argument(m.str());
    }
}

bool penetration(const Surface& s, const Vec3& offset, const Vec3& x, double search, double& depth, Vec3& n,
                 Vec3& foot) {
  const Vec3 o = {s.origin[0] + offset[0], s.origin[1] + offset[1], s.origin[2] + offset[2]};
  const Vec3 d = sub(x, o);
  switch (s.kind) {
    case Surface::Kind::plane: {
      const double g = dot(d, s.axis);
      if (g > search || g < -search) return false;
      const Vec3 inplane = axpy(-g, s.axis, d);
      const double rr = norm(inplane);
      if (rr < s.r_min || rr > s.r_max) return false;
      depth = -g;
      n = s.axis;
      foot = axpy(-g, s.axis, x);
      return true;
    }
    case Surface::Kind::cylinder: {
      const double za = dot(d, s.axis);
      if (za < s.z_min || za > s.z_max) return false;
      const Vec3 radial = axpy(-za, s.axis, d);
      const double rr = norm(radial);
      if (rr == 0.0) return false;
      const double g = s.inside ? s.R - rr : rr - s.R;  // distance on the free side
      if (g > search || g < -search) return false;
      const Vec3 er = {radial[0] / rr, radial[1] / rr, radial[2] / rr};  // (only past the test: most nodes are far)
      depth = -g;
      n = s.inside ? Vec3{-er[0], -er[1], -er[2]} : er;
      foot = axpy(s.R, er, axpy(za, s.axis, o));
      return true;
    }
    case Surface::Kind::torus: {
      const double za = dot(d, s.axis);
      const Vec3 radial = axpy(-za, s.axis, d);
      const double rr = norm(radial);
      if (rr == 0.0) return false;
      const double dr = rr - s.R;  // in the meridional plane: (dr, za) from the tube centre
      // Far outside the tube: dist >= |dr| and >= |za| (hypot rounds faithfully), so
      // then g = dist - r > search too; the same answer without hypot and atan2.
      if (std::abs(dr) - s.r > search || std::abs(za) - s.r > search) return false;
      const double dist = std::hypot(dr, za);
      if (dist == 0.0) return false;
      const double g = dist - s.r;
      if (g > search || g < -search) return false;  // before the angle: the answer does not depend on the order
      const double angle = std::atan2(za, dr);
      if (angle < s.a_min || angle > s.a_max) return false;
      const Vec3 er = {radial[0] / rr, radial[1] / rr, radial[2] / rr};
      depth = -g;
      const double c = dr / dist, sn = za / dist;
      n = {c * er[0] + sn * s.axis[0], c * er[1] + sn * s.axis[1], c * er[2] + sn * s.axis[2]};
      const Vec3 centre = axpy(s.R, er, o);
      foot = axpy(s.r, n, centre);
      return true;
    }
  }
  return false;
}

}  // namespace drawbend::contact
