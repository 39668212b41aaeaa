// The rigid analytic tool surfaces (contact/surface.hpp): penetration depth,
// outward normal and closest point, in closed form.  Units: mm.
//  - Plane z = 0 with normal +z: a point at height h has depth -h, normal
//    +z and foot (x, y, 0); outside the annulus r_min..r_max it is not in
//    contact.
//  - Cylinder of radius R = 6.35 along y (a pin): a point at radius rho in
//    the x-z plane has depth R - rho, normal its radial unit vector and foot
//    R times that vector; outside z_min..z_max it is not in contact.
//  - Torus about z, R = 10, tube r = 5: the point at (R + 3.6, 0, 4.8) lies
//    at distance 6 from the tube centre (3-4-5 triangle, scaled by 1.2):
//    depth -1, normal (0.6, 0, 0.8), foot (10 + 3, 0, 4), tube angle
//    atan2(4.8, 3.6) = 0.9273 rad; with a_max = 0.9 it is not in contact.
//  - Beyond the search distance no surface reports contact.
//  - The torus rejects a point far outside the tube before hypot and atan2
//    (surface.cpp): on a grid of points around the tube, with gaps close to
//    the search distance, every answer (contact or not, depth, normal, foot)
//    is bitwise that of the definition (hypot, tube angle, gap), written out
//    here.
#define BOOST_TEST_MODULE contact_surface
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstring>

#include "contact/surface.hpp"

using namespace drawbend;
using contact::Surface;

namespace {
constexpr double kTol = 1e-12;  // closed forms in mm, evaluated in double: round-off only

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

/// The torus by its definition, in the order of the definition (the code
/// under test tests the gap before the angle, and far points before hypot).
bool torus_by_definition(const Surface& s, const Vec3& x, double search, double& depth, Vec3& n, Vec3& foot) {
  const Vec3 d = {x[0] - s.origin[0], x[1] - s.origin[1], x[2] - s.origin[2]};
  const double za = contact::dot(d, s.axis);
  const Vec3 radial = {-za * s.axis[0] + d[0], -za * s.axis[1] + d[1], -za * s.axis[2] + d[2]};
  const double rr = std::sqrt(contact::dot(radial, radial));
  if (rr == 0.0) return false;
  const Vec3 er = {radial[0] / rr, radial[1] / rr, radial[2] / rr};
  const double dr = rr - s.R;
  const double dist = std::hypot(dr, za);
  if (dist == 0.0) return false;
  const double angle = std::atan2(za, dr);
  if (angle < s.a_min || angle > s.a_max) return false;
  const double g = dist - s.r;
  if (g > search || g < -search) return false;
  depth = -g;
  const double c = dr / dist, sn = za / dist;
  n = {c * er[0] + sn * s.axis[0], c * er[1] + sn * s.axis[1], c * er[2] + sn * s.axis[2]};
  const Vec3 centre = {s.R * er[0] + s.origin[0], s.R * er[1] + s.origin[1], s.R * er[2] + s.origin[2]};
  foot = {s.r * n[0] + centre[0], s.r * n[1] + centre[1], s.r * n[2] + centre[2]};
  return true;
}
}  // namespace

BOOST_AUTO_TEST_CASE(plane_closed_form) {
  Surface s;  // z = 0, normal +z
  s.r_min = 1.0;
  s.r_max = 20.0;
  double depth = 0;
  Vec3 n{}, foot{};
  BOOST_TEST(contact::penetration(s, {0, 0, 0}, {3.0, 4.0, -0.25}, 1.0, depth, n, foot));
  BOOST_TEST(depth == 0.25, boost::test_tools::tolerance(kTol));
  BOOST_TEST(n[2] == 1.0);
  BOOST_TEST(foot[0] == 3.0, boost::test_tools::tolerance(kTol));
  BOOST_TEST(foot[1] == 4.0, boost::test_tools::tolerance(kTol));
  BOOST_TEST(std::abs(foot[2]) < kTol);
  BOOST_TEST(!contact::penetration(s, {0, 0, 0}, {0.5, 0.0, -0.25}, 1.0, depth, n, foot));   // in the hole
  BOOST_TEST(!contact::penetration(s, {0, 0, 0}, {3.0, 4.0, 1.5}, 1.0, depth, n, foot));     // beyond search
}

BOOST_AUTO_TEST_CASE(cylinder_closed_form) {
  Surface s;
  s.kind = Surface::Kind::cylinder;
  s.axis = {0, 1, 0};
  s.R = 6.35;
  s.z_min = -10.0;
  s.z_max = 10.0;
  double depth = 0;
  Vec3 n{}, foot{};
  const double rho = 6.30, c = 0.6, sn = 0.8;  // the point at radius rho along (0.6, 0, 0.8)
  BOOST_TEST(contact::penetration(s, {0, 0, 0}, {rho * c, 2.0, rho * sn}, 1.0, depth, n, foot));
  BOOST_TEST(depth == 6.35 - rho, boost::test_tools::tolerance(kTol));
  BOOST_TEST(n[0] == c, boost::test_tools::tolerance(kTol));
  BOOST_TEST(std::abs(n[1]) < kTol);
  BOOST_TEST(n[2] == sn, boost::test_tools::tolerance(kTol));
  BOOST_TEST(foot[0] == 6.35 * c, boost::test_tools::tolerance(kTol));
  BOOST_TEST(foot[1] == 2.0, boost::test_tools::tolerance(kTol));
  BOOST_TEST(foot[2] == 6.35 * sn, boost::test_tools::tolerance(kTol));
  BOOST_TEST(!contact::penetration(s, {0, 0, 0}, {rho * c, 12.0, rho * sn}, 1.0, depth, n, foot));  // past z_max
  BOOST_TEST(!contact::penetration(s, {0, 0, 0}, {9.0, 0.0, 0.0}, 1.0, depth, n, foot));  // gap 2.65 > search
}

BOOST_AUTO_TEST_CASE(torus_closed_form) {
  Surface s;
  s.kind = Surface::Kind::torus;
  s.R = 10.0;
  s.r = 5.0;
  double depth = 0;
  Vec3 n{}, foot{};
  const Vec3 x = {10.0 + 3.6, 0.0, 4.8};  // 6 mm from the tube centre
  BOOST_TEST(contact::penetration(s, {0, 0, 0}, x, 2.0, depth, n, foot));
  BOOST_TEST(depth == -1.0, boost::test_tools::tolerance(kTol));
  BOOST_TEST(n[0] == 0.6, boost::test_tools::tolerance(kTol));
  BOOST_TEST(std::abs(n[1]) < kTol);
  BOOST_TEST(n[2] == 0.8, boost::test_tools::tolerance(kTol));
  BOOST_TEST(foot[0] == 13.0, boost::test_tools::tolerance(kTol));
  BOOST_TEST(foot[2] == 4.0, boost::test_tools::tolerance(kTol));
  BOOST_TEST(!contact::penetration(s, {0, 0, 0}, x, 0.5, depth, n, foot));  // gap 1 > search 0.5
  s.a_max = 0.9;                                                           // the point's angle is 0.9273 rad
  BOOST_TEST(!contact::penetration(s, {0, 0, 0}, x, 2.0, depth, n, foot));
}

BOOST_AUTO_TEST_CASE(torus_early_rejection_changes_no_answer) {
  Surface s;
  s.kind = Surface::Kind::torus;
  s.origin = {0.3, -0.2, 1.0};
  s.axis = {0.0, 0.6, 0.8};
  s.R = 10.0;
  s.r = 5.0;
  s.a_min = -1.2;
  s.a_max = 2.5;
  // Points in a meridional plane around the tube, gaps from -2 to +3 mm, and
  // gaps within 1e-13 mm of the search distance (the boundary the early test
  // must respect).
  const Vec3 e1 = {1.0, 0.0, 0.0};  // normal to the axis
  const double search = 0.75;
  int contacts = 0, points = 0;
  for (int i = 0; i < 181; ++i) {
    const double t = -3.2 + 6.4 * i / 180.0;  // tube angle
    for (int j = 0; j < 41; ++j) {
      for (int k = -2; k <= 2; ++k) {
        if (j < 40 && k != 0) continue;  // the boundary row (j = 40) at five gaps, the others once
        const double gap = j < 40 ? -2.0 + 5.0 * j / 39.0 : search + 1e-13 * k;
        const double rho = s.R + (s.r + gap) * std::cos(t), z = (s.r + gap) * std::sin(t);
        const Vec3 x = {s.origin[0] + rho * e1[0] + z * s.axis[0], s.origin[1] + rho * e1[1] + z * s.axis[1],
                        s.origin[2] + rho * e1[2] + z * s.axis[2]};
        double d0 = 0, d1 = 0;
        Vec3 n0{}, n1{}, f0{}, f1{};
        const bool hit = contact::penetration(s, {0, 0, 0}, x, search, d0, n0, f0);
        const bool ref = torus_by_definition(s, x, search, d1, n1, f1);
        ++points;
        BOOST_TEST_REQUIRE(hit == ref, "point " << points << " (angle " << t << ", gap " << gap << ")");
        if (!hit) continue;
        ++contacts;
        bool bits = same_bits(d0, d1);
        for (int c = 0; c < 3; ++c) bits = bits && same_bits(n0[c], n1[c]) && same_bits(f0[c], f1[c]);
        BOOST_TEST_REQUIRE(bits, "point " << points);
      }
    }
  }
  // The grid has both answers in it, so the comparison means something.
  BOOST_TEST(contacts > 1000);
  BOOST_TEST(points - contacts > 1000);
}
