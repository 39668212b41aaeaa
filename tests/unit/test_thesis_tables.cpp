// Properties of the typed-in thesis tables (data/thesis/) that hold by the
// printed inputs alone.  They were once Chapter 3 "checks", but they test the
// data files, not the thesis's results, so they belong here: a test fails if
// a file is mistyped or edited, never because of our solver.
//  - Table 3.2's five strip-draw cases span both Stribeck transitions
//    (Sec. 3.3.3): min L < L_BL and max L > L_EHL, with L by Eq. (3.1) and
//    Table 3.1's parameters.
//  - On the Table 3.1 curve mu rises as the speed falls (Sec. 3.3.2): at
//    10 MPa, mu(1 mm/s) > mu(10 mm/s), since Eq. (3.2) falls with L = v eta/(p Ra).
//  - Tables 3.1 and 3.3 differ only in mu_BL (0.1 against 0.131, Sec. 3.5.1).
//  - The ESAFORM 2021 cup's Hill'48 variants (data/benchmarks/esaform2021.csv,
//    chapter v1-earing-benchmark) use the published tests of
//    data/materials/aa6016_t4_esaform2021.csv: r0/r45/r90 and s45/s90/sb equal.
#define BOOST_TEST_MODULE thesis_tables
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <map>
#include <string>

#include "analysis/stribeck.hpp"
#include "core/csv.hpp"
#include "study/thesis_data.hpp"

using namespace drawbend;
using namespace drawbend::analysis;

static const std::string kThesis = std::string(DRAWBEND_DATA_DIR) + "/thesis/";

BOOST_AUTO_TEST_CASE(table_3_2_spans_both_transitions) {
  const StribeckParams s31 = study::load_stribeck(kThesis + "table_3_1.csv");
  const CsvTable t32 = read_csv(kThesis + "table_3_2.csv");
  double lmin = 1e300, lmax = 0;
  for (const auto& r : t32.rows) {
    const double L = lubricant_number(t32.number(r, "velocity_mm_s"), t32.number(r, "pressure_MPa"), s31);
    lmin = std::min(lmin, L);
    lmax = std::max(lmax, L);
  }
  BOOST_TEST(t32.rows.size() == 5u);
  BOOST_TEST(lmin < s31.L_BL);
  BOOST_TEST(lmax > s31.L_EHL);
}

BOOST_AUTO_TEST_CASE(table_3_1_mu_rises_as_speed_falls) {
  const StribeckParams s31 = study::load_stribeck(kThesis + "table_3_1.csv");
  BOOST_TEST(stribeck_mu(1.0, 10.0, s31) > stribeck_mu(10.0, 10.0, s31));
}

BOOST_AUTO_TEST_CASE(tables_3_1_and_3_3_differ_only_in_mu_bl) {
  const StribeckParams a = study::load_stribeck(kThesis + "table_3_1.csv");
  const StribeckParams b = study::load_stribeck(kThesis + "table_3_3.csv");
  BOOST_TEST(a.mu_EHL == b.mu_EHL);
  BOOST_TEST(a.L_BL == b.L_BL);
  BOOST_TEST(a.L_EHL == b.L_EHL);
  BOOST_TEST(a.Ra_um == b.Ra_um);
  BOOST_TEST(a.eta_Pa_s == b.eta_Pa_s);
  BOOST_TEST(a.mu_BL == 0.1);
  BOOST_TEST(b.mu_BL == 0.131);
}

BOOST_AUTO_TEST_CASE(esaform2021_variants_are_the_published_tests) {
  const std::string data = std::string(DRAWBEND_DATA_DIR) + "/";
  const CsvTable mt = read_csv(data + "materials/aa6016_t4_esaform2021.csv");
  std::map<std::string, double> pub;  // "r0", "s45", "sb", ...
  for (const auto& row : mt.rows) {
    const std::string test = mt.text(row, "test"), ang = mt.text(row, "angle_deg");
    if (test == "uniaxial") pub["s" + ang] = mt.number(row, "stress_ratio"), pub["r" + ang] = mt.number(row, "r_value");
    if (test == "balanced_biaxial") pub["sb"] = mt.number(row, "stress_ratio");
  }
  const CsvTable vt = read_csv(data + "benchmarks/esaform2021.csv");
  int seen = 0;
  for (const auto& row : vt.rows) {
    const std::string id = vt.text(row, "variant");
    const char* keys_r[] = {"r0", "r45", "r90"};
    const char* keys_s[] = {"s45", "s90", "sb"};
    if (id == "hill48_r")
      for (const char* k : keys_r) {
        BOOST_TEST(vt.number(row, k) == pub.at(k));
        ++seen;
      }
    if (id == "hill48_s")
      for (const char* k : keys_s) {
        BOOST_TEST(vt.number(row, k) == pub.at(k));
        ++seen;
      }
  }
  BOOST_TEST(seen == 6);
}
