// The deck's material types and the sheet frame (io/material_spec.cpp, io/deck.cpp).
// Expected: valid j2_combined, hill48 and yld2004 decks build a CombinedPlasticity with the given
// constants (Hill'48 returns r0/r45/r90; Voce at eps_p = 0 is sigma0); [sheet]
// rolling_direction sets the model's RD (normalised); every non-physical value
// (r <= 0, Yld2004 a < 2, c1/c2 not 9 numbers or not closed, gamma < 0, C < 0, beta outside [0, 1], 4 terms, a typo, both r-values and
// stress ratios, a rolling direction stated twice) is an input error naming
// file:line: key.  An inline hardening table { plastic_strain, true_stress_MPa }
// reads like a CSV table; unequal lengths, a falling stress and a wrong key are input errors.
#define BOOST_TEST_MODULE deck_material
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "core/csv.hpp"
#include "io/deck.hpp"
#include "material/combined_plasticity.hpp"
#include "material/yld2004_plasticity.hpp"

using namespace drawbend;

namespace {
std::string deck(const std::string& material, const std::string& extra = "") {
  return "[mesh]\nx = { from = 0.0, to = 1.0, n = 1 }\ny = { from = 0.0, to = 1.0, n = 1 }\n"
         "z = { from = 0.0, to = 1.0, n = 1 }\n" +
         extra + "[material]\nE = 70000.0\nnu = 0.33\ndensity = 2.7e-9\n" + material +
         "\n[[step]]\nduration = 1e-4\n";
}
std::string error_of(const std::string& text) {
  try {
    io::parse_deck(text, "case.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

BOOST_AUTO_TEST_CASE(valid_combined_and_hill48) {
  const auto d = io::parse_deck(
      deck("type = \"j2_combined\"\nvoce = { sigma0 = 100.0, Q = 150.0, b = 12.0 }\nkinematic = { beta = 0.4 }"),
      "case.toml");
  const auto* m = dynamic_cast<const material::CombinedPlasticity*>(d.model.material.get());
  BOOST_TEST_REQUIRE(m != nullptr);
  BOOST_TEST(m->kinematic().beta == 0.4);
  BOOST_TEST(!m->directional());
  BOOST_TEST(std::abs(m->isotropic_stress(0.0) - 100.0) < 1e-12);
  const auto h = io::parse_deck(deck("type = \"hill48\"\nyield = 120.0\nhill48 = { r0 = 0.65, r45 = 0.65, r90 = 0.72 }\n"
                                     "kinematic = { C = [5000.0, 500.0], gamma = [50.0, 2.0] }",
                                     "[sheet]\nrolling_direction = [3.0, 4.0, 0.0]\n"),
                                "case.toml");
  const auto* mh = dynamic_cast<const material::CombinedPlasticity*>(h.model.material.get());
  BOOST_TEST_REQUIRE(mh != nullptr);
  BOOST_TEST(mh->directional());
  BOOST_TEST(std::abs(mh->yield().r_value(0.0) - 0.65) < 1e-12);
  BOOST_TEST(std::abs(mh->yield().r_value(M_PI / 4) - 0.65) < 1e-12);
  BOOST_TEST(std::abs(mh->yield().r_value(M_PI / 2) - 0.72) < 1e-12);
  BOOST_TEST(mh->kinematic().chaboche.size() == 2u);
  BOOST_TEST(std::abs(h.model.rolling_direction[0] - 0.6) < 1e-15);
  BOOST_TEST(std::abs(h.model.rolling_direction[1] - 0.8) < 1e-15);
}

// An inline flow curve reads as the same table from a file: 100 MPa at 0 and
// 150 MPa at 0.1 give 125 MPa at eps_p = 0.05 (linear between points).
BOOST_AUTO_TEST_CASE(inline_hardening_table) {
  const auto d = io::parse_deck(
      deck("type = \"j2_combined\"\nhardening = { plastic_strain = [0.0, 0.1], true_stress_MPa = [100.0, 150.0] }\n"
           "kinematic = { C = [3000.0], gamma = [300.0] }"),
      "case.toml");
  const auto* m = dynamic_cast<const material::CombinedPlasticity*>(d.model.material.get());
  BOOST_TEST_REQUIRE(m != nullptr);
  BOOST_TEST(std::abs(m->isotropic_stress(0.05) - 125.0) < 1e-12);
}

BOOST_AUTO_TEST_CASE(bad_values_name_file_line_key) {
  struct Bad {
    std::string material, extra, expect;
  };
  const Bad bad[] = {
      {"type = \"hill48\"\nyield = 100.0\nhill48 = { r0 = 0.0, r45 = 1.0, r90 = 1.0 }", "", "case.toml:11: material.hill48.r0"},
      {"type = \"hill48\"\nyield = 100.0\nhill48 = { r0 = 1.0, r45 = -1.0, r90 = 1.0 }", "", "material.hill48.r45"},
      {"type = \"hill48\"\nyield = 100.0\nhill48 = { r0 = 1.0, r45 = 1.0, r90 = 1.0, s90 = 1.0 }", "",
       "case.toml:11: material.hill48"},
      {"type = \"j2_combined\"\nyield = 100.0\nkinematic = { beta = 1.5 }", "", "case.toml:11: material.kinematic.beta"},
      {"type = \"j2_combined\"\nyield = 100.0\nkinematic = { beta = -0.1 }", "", "material.kinematic.beta"},
      {"type = \"j2_combined\"\nyield = 100.0\nkinematic = { C = [1000.0], gamma = [-2.0] }", "",
       "case.toml:11: material.kinematic.gamma"},
      {"type = \"j2_combined\"\nyield = 100.0\nkinematic = { C = [-1000.0], gamma = [2.0] }", "", "material.kinematic.C"},
      {"type = \"j2_combined\"\nyield = 100.0\nkinematic = { C = [1.0, 1.0, 1.0, 1.0], gamma = [1.0, 1.0, 1.0, 1.0] }", "",
       "material.kinematic.C"},
      {"type = \"j2_combined\"\nyield = 100.0\nkinematc = { beta = 0.5 }", "", "kinematc"},
      {"type = \"j2_combined\"\nyield = 100.0", "", "missing required table [kinematic]"},
      {"type = \"j2\"\nyield = 100.0\nkinematic = { beta = 0.5 }", "", "kinematic"},
      {"type = \"hill\"\nyield = 100.0", "", "material.type"},
      {"type = \"j2\"\nvoce = { sigma0 = 100.0, Q = -5.0, b = 10.0 }", "", "material.voce.Q"},
      {"type = \"j2\"\nyield = 100.0\nvoce = { sigma0 = 100.0, Q = 5.0, b = 10.0 }", "", "exactly one flow curve"},
      {"type = \"j2\"\nyield = 100.0", "[sheet]\nrolling_direction = [0.0, 0.0, 0.0]\n", "sheet.rolling_direction"},
      {"type = \"j2\"\nhardening = { plastic_strain = [0.0, 0.1], true_stress_MPa = [100.0] }", "",
       "case.toml:10: material.hardening"},
      {"type = \"j2\"\nhardening = { plastic_strain = [0.0, 0.1], true_stress_MPa = [100.0, 90.0] }", "",
       "must not decrease"},
      {"type = \"j2\"\nhardening = { plastic_strain = [0.0, 0.1], stress = [100.0, 90.0] }", "", "material.hardening"},
      {"type = \"yld2004\"\nyield = 100.0\nyld2004 = { a = 1.5, c1 = [1,1,1,1,1,1,1,1,1], c2 = [1,1,1,1,1,1,1,1,1] }", "",
       "case.toml:11: material.yld2004.a"},
      {"type = \"yld2004\"\nyield = 100.0\nyld2004 = { a = 8, c1 = [1,1,1,1,1,1,1,1], c2 = [1,1,1,1,1,1,1,1,1] }", "",
       "case.toml:11: material.yld2004.c1"},
      {"type = \"yld2004\"\nyield = 100.0\nyld2004 = { a = 8, c1 = [1,1,1,1,1,1,1,1,1], c2 = [1,1,1,1,\"x\",1,1,1,1] }", "",
       "case.toml:11: material.yld2004.c2"},
      {"type = \"yld2004\"\nyield = 100.0\nyld2004 = { a = 8, c1 = [0,0,0,0,0,0,1,1,1], c2 = [0,0,0,0,0,0,1,1,1] }", "",
       "case.toml:11: material.yld2004"},
      {"type = \"yld2004\"\nyield = 100.0\nyld2004 = { a = 8, c1 = [1,1,1,1,1,1,1,1,1], c2 = [1,1,1,1,1,1,1,1,1], b = 2 }",
       "", "material.yld2004"},
      {"type = \"yld2004\"\nyield = 100.0", "", "yld2004"},
  };
  for (const Bad& b : bad) {
    const std::string e = error_of(deck(b.material, b.extra));
    BOOST_TEST(e.find(b.expect) != std::string::npos, "deck material:\n" << b.material << "\nmessage: " << e);
  }
}

// yld2004 = { a, c1, c2 } builds a Yld2004Plasticity, normalised to RD (isotropic coefficients 2: scaled by 1/2).
BOOST_AUTO_TEST_CASE(valid_yld2004) {
  const auto d = io::parse_deck(deck("type = \"yld2004\"\nyield = 100.0\nkinematic = { beta = 0.3 }\n"
                                     "yld2004 = { a = 8, c1 = [2,2,2,2,2,2,2,2,2], c2 = [2,2,2,2,2,2,2,2,2] }"),
                                "case.toml");
  const auto* m = dynamic_cast<const material::Yld2004Plasticity*>(d.model.material.get());
  BOOST_TEST_REQUIRE(m != nullptr);
  BOOST_TEST(m->directional());
  BOOST_TEST(std::abs(m->scaled_by() - 2.0) < 1e-12);
  BOOST_TEST(std::abs(m->yield().c1[0] - 1.0) < 1e-12);
  BOOST_TEST(std::abs(m->yield().r_value(M_PI / 4) - 1.0) < 1e-9);
}

BOOST_AUTO_TEST_CASE(rolling_direction_is_stated_once) {
  const std::string tools =
      "[[tool]]\nname = \"floor\"\ndrive = \"fixed\"\n[[tool.surface]]\nkind = \"plane\"\norigin = [0.0, 0.0, 0.0]\n"
      "normal = [0.0, 0.0, 1.0]\n";
  const std::string text = deck("type = \"j2\"\nyield = 100.0", "[sheet]\nrolling_direction = [1.0, 0.0, 0.0]\n") + tools +
                           "[[contact]]\nfaces = \"zmin\"\ntool = \"floor\"\ntexture_axis = [0.0, 1.0, 0.0]\n";
  BOOST_TEST(error_of(text).find("contact.texture_axis") != std::string::npos);
  // Without [sheet], the contact's texture_axis is the rolling direction (older decks).
  const auto d = io::parse_deck(deck("type = \"j2\"\nyield = 100.0") + tools +
                                    "[[contact]]\nfaces = \"zmin\"\ntool = \"floor\"\ntexture_axis = [0.0, 2.0, 0.0]\n",
                                "case.toml");
  BOOST_TEST(d.model.rolling_direction[1] == 1.0);
}
