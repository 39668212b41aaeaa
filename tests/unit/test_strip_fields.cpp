// Reading a draw-bend snapshot back (src/sim/strip_fields).  Two separate
// 2 x 2 x 1 mm hexahedra (reference y 0 to 2, z from R to R + 1 with the pin
// radius R = 6.35 mm, t = 1 mm), written with io::write_vtu, E = 70000 MPa,
// nu = 0.3.  Closed-form answers:
//  - element A, upstream (reference x -3 to -1), stretched by 1.1 along x
//    about its centroid, sigma_xx = 100, sigma_yy = 20 MPa, plastic strain
//    0.05: position s = -2 mm (x upstream), extent 2.2 mm, depth 0.5,
//    eps_L = ln 1.1, eps_pL = ln 1.1 - (100 - 0.3 * 20) / 70000;
//  - element B (reference x 10 to 12) carried rigidly onto the pin with its
//    centroid at 45 deg on the mid-surface radius Rm = R + 0.5: s = Rm pi/4,
//    extent 2 Rm atan(1/Rm) (its end faces sit at 45 deg -+ atan(1/Rm)),
//    eps_L = 0; a stress of 50 MPa along its tangent t = (cos 45, 0, -sin 45)
//    gives sigma_L = 50 and eps_pL = -50/70000;
//  - the node plane nearest 40 deg is B's upstream face (x0 = 10, its inside
//    centre node at 45 - atan(1/R) = 36.05 deg); its inside nodes lie
//    sqrt(R^2 + 1) - R from the pin surface, its outside ones
//    sqrt((R + 1)^2 + 1) - R;
//  - the last snapshot of a folder holding fields_0 and fields_3 is fields_3.
#define BOOST_TEST_MODULE strip_fields
#include <boost/test/unit_test.hpp>
#include <array>
#include <cmath>
#include <filesystem>
#include <vector>

#include "io/vtu.hpp"
#include "sim/strip_fields.hpp"

using namespace drawbend;
namespace fs = std::filesystem;
namespace tt = boost::test_tools;

namespace {

const double R = 6.35, E = 70000, nu = 0.3;

struct Case {
  std::vector<double> x, y, z, disp, stress, ep;
  std::vector<int> hex;
};

/// A hexahedron from reference corners and a map reference -> current.
template <class F>
void add_hex(Case& c, double xa, double xb, F current) {
  const int base = static_cast<int>(c.x.size());
  for (double zz : {R, R + 1.0})
    for (auto [xx, yy] : std::array<std::pair<double, double>, 4>{{{xa, 0.0}, {xb, 0.0}, {xb, 2.0}, {xa, 2.0}}}) {
      const std::array<double, 3> p = current(xx, yy, zz);
      c.x.push_back(p[0]), c.y.push_back(p[1]), c.z.push_back(p[2]);
      c.disp.insert(c.disp.end(), {p[0] - xx, p[1] - yy, p[2] - zz});
    }
  for (int a = 0; a < 8; ++a) c.hex.push_back(base + a);
}

std::string write_case(const fs::path& dir, const std::string& name) {
  Case c;
  add_hex(c, -3, -1, [](double x, double y, double z) { return std::array<double, 3>{-2 + 1.1 * (x + 2), y, z}; });
  const double th = M_PI / 4;
  add_hex(c, 10, 12, [&](double x, double y, double z) {
    const double u = x - 11;  // along the tangent from the centroid
    return std::array<double, 3>{z * std::sin(th) + u * std::cos(th), y, z * std::cos(th) - u * std::sin(th)};
  });
  c.stress = {100, 20, 0, 0, 0, 0, 25, 0, 25, 0, 0, -25};  // B: 50 t (x) t
  c.ep = {0.05, 0.0};
  io::VtuMesh m{c.x.size(), c.x.data(), c.y.data(), c.z.data(), 2, c.hex.data()};
  fs::create_directories(dir);
  const std::string path = (dir / name).string();
  io::write_vtu(path, m, {{"displacement_mm", 3, c.disp.data()}},
                {{"stress_MPa", 6, c.stress.data()}, {"plastic_strain", 1, c.ep.data()}}, 0.25);
  return path;
}

sim::DrawBendSpec spec() {
  sim::DrawBendSpec s;
  s.pin_diameter = 2 * R;
  s.thickness = 1.0;
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(elements_in_strip_coordinates) {
  const fs::path dir = fs::temp_directory_path() / "drawbend_test_strip_fields";
  const auto f = sim::read_fields_vtu(write_case(dir, "fields_0.vtu"));
  BOOST_TEST(f.time == 0.25);
  BOOST_TEST(f.x.size() == 16u);
  BOOST_TEST(f.x0[1][0] == -1.0, tt::tolerance(1e-12));  // reference = current - displacement
  const auto els = sim::strip_elements(f, spec(), E, nu);
  BOOST_REQUIRE(els.size() == 2u);
  const auto& a = els[0].s < 0 ? els[0] : els[1];
  const auto& b = els[0].s < 0 ? els[1] : els[0];
  BOOST_TEST(a.s == -2.0, tt::tolerance(1e-12));
  BOOST_TEST(a.ds == 2.2, tt::tolerance(1e-12));
  BOOST_TEST(a.depth == 0.5, tt::tolerance(1e-12));
  BOOST_TEST(a.y0 == 1.0, tt::tolerance(1e-12));
  BOOST_TEST(a.sigma_L == 100.0, tt::tolerance(1e-12));
  BOOST_TEST(a.eps_L == std::log(1.1), tt::tolerance(1e-12));
  BOOST_TEST(a.eps_pL == std::log(1.1) - 94.0 / 70000.0, tt::tolerance(1e-12));
  BOOST_TEST(a.eps_p == 0.05);
  const double Rm = R + 0.5;
  BOOST_TEST(b.s == Rm * M_PI / 4, tt::tolerance(1e-12));
  BOOST_TEST(b.ds == 2 * Rm * std::atan(1 / Rm), tt::tolerance(1e-12));
  BOOST_TEST(std::abs(b.eps_L) < 1e-12);
  BOOST_TEST(b.sigma_L == 50.0, tt::tolerance(1e-12));
  BOOST_TEST(b.eps_pL == -50.0 / 70000.0, tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(section_and_last_snapshot) {
  const fs::path dir = fs::temp_directory_path() / "drawbend_test_strip_fields_last";
  fs::remove_all(dir);
  write_case(dir, "fields_0.vtu");
  write_case(dir, "fields_3.vtu");
  BOOST_TEST(fs::path(sim::last_fields_vtu(dir.string())).filename() == "fields_3.vtu");
  const auto f = sim::read_fields_vtu(sim::last_fields_vtu(dir.string()));
  const auto sec = sim::section_at(f, spec(), 40.0);
  BOOST_TEST(sec.x0 == 10.0, tt::tolerance(1e-12));
  BOOST_TEST(sec.angle_deg == 45.0 - std::atan(1 / R) * 180 / M_PI, tt::tolerance(1e-9));
  BOOST_REQUIRE(sec.nodes.size() == 4u);
  for (const auto& q : sec.nodes) {
    const double want = q.z0 < R + 0.5 ? std::sqrt(R * R + 1) - R : std::sqrt((R + 1) * (R + 1) + 1) - R;
    BOOST_TEST(q.h == want, tt::tolerance(1e-9));
    BOOST_TEST(q.y == q.y0, tt::tolerance(1e-12));
  }
  BOOST_CHECK_THROW(sim::last_fields_vtu((dir / "none").string()), std::exception);
  fs::remove_all(dir);
}
