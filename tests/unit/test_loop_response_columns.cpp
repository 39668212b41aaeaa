// Columns computed from the measured forces (src/loop/response_columns.hpp).
// Known answers, on a made-up set: 3 pins x 4 fixed-pin tests x 10 rows,
// back tension 1500-2400 N, outlet force by the rope formula (mu 0.1) plus a
// bending force, noise sd 3 N (a fixed pseudo-random sequence), and
//  - mu_lab = ln(F_out / F_back) / (pi / 2), 4 decimals: computed from the
//    forces, flagged (variance left about 1e-6 of the 1e-3 allowed);
//  - fric_N = F_out - F_back, 1 decimal: flagged;
//  - humidity: unrelated to the forces: not flagged;
//  - film: a physical variable acting on the outlet force with an effect of
//    5 noise sd: it can be read back from F_out to 1 / (1 + 25) of its
//    variance at best, far above 1e-3: not flagged;
//  - bt_kN = F_back / 1000: the back tension alone determines it (not the
//    response): not flagged;
//  - lot: one value per test (never varies within a test): not flagged;
//  - note: text: not flagged.
#define BOOST_TEST_MODULE loop_response_columns
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "loop/measured.hpp"
#include "loop/response_columns.hpp"

using namespace drawbend::loop;

namespace {

// A fixed sequence of uniform numbers in (0, 1) (the same on every platform).
struct Lcg {
  unsigned long long s = 12345;
  double u() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (static_cast<double>(s >> 11) + 0.5) / 9007199254740992.0;
  }
  double n() { return std::sqrt(-2 * std::log(u())) * std::cos(6.283185307179586 * u()); }
};

std::string made_up_set() {
  std::ostringstream o;
  o << "test_id,pin_diameter_mm,pin,direction_deg,speed_mm_s,lubricant,back_tension_N,outlet_force_N,"
       "mu_lab,fric_N,humidity,film,bt_kN,lot,note\n";
  Lcg r;
  const double pins[3] = {12.7, 25.4, 42}, bend[3] = {400, 150, 90};
  for (int p = 0; p < 3; ++p)
    for (int t = 0; t < 4; ++t)
      for (int j = 0; j < 10; ++j) {
        const double fb = 1500 + 100 * ((j * 7 + t) % 10), film = r.u(), hum = 40 + 20 * r.u();
        const double fo = fb * std::exp(0.1 * 1.5707963267948966) + bend[p] + 5 * 3 * (film - 0.5) / 0.2887 + 3 * r.n();
        char line[512];
        std::snprintf(line, sizeof line, "T%d-%d,%g,fixed,0,10,oil,%.1f,%.4f,%.4f,%.1f,%.2f,%.4f,%.4f,L%d,row %d\n", p,
                      t, pins[p], fb, fo, std::log(fo / fb) / 1.5707963267948966, fo - fb, hum, film, fb / 1000,
                      t % 2, j);
        o << line;
      }
  return o.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(columns_computed_from_the_forces) {
  const Dataset d = parse_measured(made_up_set(), "made_up.csv");
  BOOST_TEST(d.rows.size() == 120u);
  const auto rc = response_columns(d);
  BOOST_TEST_REQUIRE(rc.size() == 2u);
  BOOST_TEST(rc[0].name == "mu_lab");
  BOOST_TEST(rc[1].name == "fric_N");
  for (const auto& c : rc) BOOST_TEST(c.fraction < kResponseFraction);
}
