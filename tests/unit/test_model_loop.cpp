// The model-level loop's inputs (src/modelloop/model_loop.hpp), without FE runs.
// Closed-form answers:
//  - a measured CSV with 2 good rows reads as 2 points (full strip values kept);
//  - a row with a non-number and a row with a negative force are both named
//    by file:line in one InputError;
//  - spec_for_point halves the back tension (1500 N full strip -> 750 N half)
//    and sets the pin (25.4 mm);
//  - "split:0.3/0.6" is two members whose material is j2_combined with
//    beta = 0.3 and 0.6; "ms:2500" sets mass scaling 2500; "across:4" sets 4;
//    unknown names, beta 1.5 and across 2.5 are input errors;
//  - candidates compose: Voce on top of split beta 0.3 keeps the back stress
//    and replaces only the flow curve; Hill'48 on top of it keeps the back
//    stress and the (tabulated) flow curve and sets the published r-values
//    0.65 / 0.65 / 0.72 (data/materials/aa5754_o_hill48_hou2020.toml);
//  - "offset" on top of split beta 0.3 keeps the back stress and sets a Swift
//    curve K (e0 + eps_p)^n through Table 5.1's RD row with the 0.2 % offset
//    yield stress at eps_p = 0.002: sigma(0.002) = 99.71 MPa, n = 0.32, and
//    an initial yield stress below 99.71 MPa;
//  - "chaboche:30" on top of split beta 0.3 replaces the kinematic part by one
//    term C = 300 * 30 = 9000 MPa, gamma = 300, and carves R = sigma - X out
//    of the tabulated RD curve: R non-decreasing, R + X = sigma at eps_p = 0.5
//    (the envelope cuts only at small strain), R(0) <= sigma(0) - 0;
//  - Voce (and offset) on top of a back stress "chaboche:30@100" carve the new
//    curve too: the model's hardening becomes an inline table R with
//    R + 30 (1 - exp(-100 eps_p)) = Voce(eps_p) = 100.4 + 183.6 (1 - exp(-14.09
//    eps_p)) at the curve's last point (eps_p >= 0.5), no voce key, and the back stress kept
//    (C = 3000 MPa, gamma = 100); without the carving every flow stress would
//    rise by up to X_sat; on a linear term (gamma 0) it is an InputError;
//  - a loop whose points all lie on the fit pin has nothing held out: an
//    input error before any run;
//  - the leave-one-pin-out split needs 3 distinct pins (one to fit, one to
//    choose, one left out): points on 2 pins are an input error before any
//    run, and the candidate list is never asked for.
#define BOOST_TEST_MODULE model_loop
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <toml++/toml.h>

#include "core/csv.hpp"
#include "material/hardening_curve.hpp"
#include "modelloop/model_loop.hpp"
#include "sim/material_choice.hpp"

using namespace drawbend;

namespace {
std::string write_tmp(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p.string();
}
}  // namespace

BOOST_AUTO_TEST_CASE(reads_points) {
  const auto p = write_tmp("ml_good.csv", "# c\npin_diameter_mm,back_tension_N,bending_force_N\n12.7,1500,303.1\n42,1900,47.7\n");
  const auto pts = modelloop::read_fb_points(p);
  BOOST_REQUIRE_EQUAL(pts.size(), 2u);
  BOOST_TEST(pts[1].pin_mm == 42.0);
  BOOST_TEST(pts[0].bending_N == 303.1);
}

BOOST_AUTO_TEST_CASE(bad_rows_named) {
  const auto p = write_tmp("ml_bad.csv", "pin_diameter_mm,back_tension_N,bending_force_N\n12.7,abc,303\n25.4,1800,-1\n");
  try {
    modelloop::read_fb_points(p);
    BOOST_FAIL("no error");
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("ml_bad.csv:2") != std::string::npos);
    BOOST_TEST(m.find("ml_bad.csv:3") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(spec_and_candidates) {
  sim::DrawBendSpec base;
  const auto s = modelloop::spec_for_point(base, {25.4, 1500, 100, ""});
  BOOST_TEST(s.back_tension == 750.0);
  BOOST_TEST(s.pin_diameter == 25.4);
  const auto c = modelloop::named_candidate("split:0.3/0.6", "/data");
  BOOST_REQUIRE_EQUAL(c.members.size(), 2u);
  sim::DrawBendSpec t = base;
  c.members[1].apply(t);
  {  // the typed material the member wrote: j2_combined, beta 0.6, the spec's own flow curve
    const io::MaterialSpec m = sim::material_choice(t.material, "own.csv");
    BOOST_TEST((m.type == io::MaterialType::j2_combined));
    BOOST_TEST(std::get<io::KinematicSplit>(m.kinematic.value()).beta == 0.6);
    BOOST_TEST(std::get<io::CurveFile>(m.curve.value()).path == "own.csv");
  }
  t = base;
  modelloop::named_candidate("ms:2500", "/data").members[0].apply(t);
  BOOST_TEST(t.mass_scaling == 2500.0);
  modelloop::named_candidate("across:4", "/data").members[0].apply(t);
  BOOST_TEST(t.across == 4);
  BOOST_CHECK_THROW(modelloop::named_candidate("chaboche", "/data"), InputError);
  BOOST_CHECK_THROW(modelloop::named_candidate("split:1.5", "/data"), InputError);
  BOOST_CHECK_THROW(modelloop::named_candidate("split:0.3/x", "/data"), InputError);
  BOOST_CHECK_THROW(modelloop::named_candidate("across:2.5", "/data"), InputError);
}

BOOST_AUTO_TEST_CASE(candidates_compose) {
  sim::DrawBendSpec t;
  t.hardening = std::string(DRAWBEND_DATA_DIR) + "/materials/aa5754_o_rd.csv";
  modelloop::named_candidate("split:0.3", DRAWBEND_DATA_DIR).members[0].apply(t);
  sim::DrawBendSpec v = t, h = t;
  modelloop::named_candidate("voce", DRAWBEND_DATA_DIR).members[0].apply(v);
  modelloop::named_candidate("hill48", DRAWBEND_DATA_DIR).members[0].apply(h);
  auto table = [](const std::string& m) {
    const std::string doc = "m = " + m;
    return toml::table(*toml::parse(std::string_view(doc))["m"].as_table());
  };
  const toml::table mv = table(v.material), mh = table(h.material);
  BOOST_TEST(mv["type"].value_or(std::string()) == "j2_combined");
  BOOST_TEST(mv["kinematic"]["beta"].value_or(0.0) == 0.3);
  BOOST_TEST(mv["voce"]["sigma0"].value_or(0.0) == 100.4);
  BOOST_TEST(mh["type"].value_or(std::string()) == "hill48");
  BOOST_TEST(mh["kinematic"]["beta"].value_or(0.0) == 0.3);
  BOOST_TEST(mh["hill48"]["r0"].value_or(0.0) == 0.65);
  BOOST_TEST(mh["hill48"]["r90"].value_or(0.0) == 0.72);
  BOOST_TEST(!mh.contains("voce"));  // the flow curve stays the tabulated one
  BOOST_TEST(sim::deck_text(h).find("aa5754_o_rd.csv") != std::string::npos);

  sim::DrawBendSpec o = t;
  modelloop::named_candidate("offset", DRAWBEND_DATA_DIR).members[0].apply(o);
  const toml::table mo = table(o.material);
  BOOST_TEST(mo["kinematic"]["beta"].value_or(0.0) == 0.3);
  const double K = mo["swift"]["K"].value_or(0.0), e0 = mo["swift"]["e0"].value_or(0.0), n = mo["swift"]["n"].value_or(0.0);
  BOOST_TEST(n == 0.32);
  BOOST_TEST(K * std::pow(e0 + 0.002, n) == 99.71, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(K * std::pow(e0, n) < 99.71);

  sim::DrawBendSpec ch = t;
  modelloop::named_candidate("chaboche:30", DRAWBEND_DATA_DIR).members[0].apply(ch);
  const toml::table mc = table(ch.material);
  BOOST_TEST(mc["type"].value_or(std::string()) == "j2_combined");
  BOOST_TEST(!mc["kinematic"].as_table()->contains("beta"));  // replaces split's back stress
  // chaboche:X1/X2@G1/G2: every (X, G) pair is a member, G outer.
  const modelloop::ModelCandidate grid = modelloop::named_candidate("chaboche:60/90@30/120", DRAWBEND_DATA_DIR);
  BOOST_TEST(grid.members.size() == 4u);
  BOOST_TEST(grid.members[1].label == "Chaboche X_sat 90 MPa, gamma 30");
  sim::DrawBendSpec g = t;
  grid.members[3].apply(g);
  const toml::table mg = table(g.material);
  BOOST_TEST((*mg["kinematic"]["gamma"].as_array())[0].value_or(0.0) == 120.0);
  BOOST_TEST((*mg["kinematic"]["C"].as_array())[0].value_or(0.0) == 90.0 * 120.0);
  BOOST_CHECK_THROW(modelloop::named_candidate("chaboche:60@0", DRAWBEND_DATA_DIR), InputError);
  BOOST_CHECK_THROW(modelloop::named_candidate("chaboche:60@x", DRAWBEND_DATA_DIR), InputError);
  BOOST_TEST((*mc["kinematic"]["C"].as_array())[0].value_or(0.0) == 9000.0);
  BOOST_TEST((*mc["kinematic"]["gamma"].as_array())[0].value_or(0.0) == 300.0);
  std::vector<double> ex, R;
  for (const auto& v : *mc["hardening"]["plastic_strain"].as_array()) ex.push_back(v.value_or(0.0));
  for (const auto& v : *mc["hardening"]["true_stress_MPa"].as_array()) R.push_back(v.value_or(0.0));
  BOOST_REQUIRE(ex.size() == R.size());
  for (std::size_t i = 1; i < R.size(); ++i) BOOST_TEST(R[i] >= R[i - 1]);
  const auto base = material::HardeningCurve::load(t.hardening);
  for (std::size_t i = 0; i < ex.size(); ++i)
    if (std::abs(ex[i] - 0.5) < 1e-12)
      BOOST_TEST(R[i] + 30 * (1 - std::exp(-300 * ex[i])) == base.stress(ex[i]), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(R.front() <= base.stress(0.0));
  BOOST_CHECK_THROW(modelloop::named_candidate("chaboche:0", DRAWBEND_DATA_DIR), InputError);
  sim::DrawBendSpec bad = t;  // an inline curve without its arrays: an input error, not a crash
  bad.material = "{ type = \"j2\", hardening = { plastic_strain = [0.0, 0.1] } }";
  BOOST_CHECK_THROW(modelloop::named_candidate("chaboche:30", DRAWBEND_DATA_DIR).members[0].apply(bad), InputError);

  // Voce / offset on a back stress: the new curve is carved by it.
  sim::DrawBendSpec af = t;
  modelloop::named_candidate("chaboche:30@100", DRAWBEND_DATA_DIR).members[0].apply(af);
  for (const char* kind : {"voce", "offset"}) {
    sim::DrawBendSpec w = af;
    modelloop::named_candidate(kind, DRAWBEND_DATA_DIR).members[0].apply(w);
    const toml::table mw = table(w.material);
    BOOST_TEST(!mw.contains("voce"));
    BOOST_TEST(!mw.contains("swift"));
    BOOST_TEST((*mw["kinematic"]["C"].as_array())[0].value_or(0.0) == 3000.0);
    BOOST_TEST((*mw["kinematic"]["gamma"].as_array())[0].value_or(0.0) == 100.0);
    std::vector<double> wx, wr;
    for (const auto& v : *mw["hardening"]["plastic_strain"].as_array()) wx.push_back(v.value_or(0.0));
    for (const auto& v : *mw["hardening"]["true_stress_MPa"].as_array()) wr.push_back(v.value_or(0.0));
    BOOST_REQUIRE(wx.size() == wr.size());
    BOOST_REQUIRE(wx.size() > 2);
    BOOST_TEST(wx.back() >= 0.5);
    const std::size_t i = wx.size() - 1;  // large strain: the envelope does not cut there
    const double monotonic = std::string(kind) == "voce" ? 100.4 + 183.6 * (1 - std::exp(-14.09 * wx[i]))
                                                         : K * std::pow(e0 + wx[i], n);
    BOOST_TEST(wr[i] + 30 * (1 - std::exp(-100 * wx[i])) == monotonic, boost::test_tools::tolerance(1e-9));
  }
  // A linear kinematic term (gamma 0, valid in a deck) has no X_sat: Voce on it is an input error.
  sim::DrawBendSpec lin = t;
  lin.material = "{ type = \"j2_combined\", kinematic = { C = [500.0], gamma = [0.0] } }";
  BOOST_CHECK_EXCEPTION(modelloop::named_candidate("voce", DRAWBEND_DATA_DIR).members[0].apply(lin), InputError,
                        [](const InputError& e) { return std::string(e.what()).find("linear kinematic") != std::string::npos; });
}

BOOST_AUTO_TEST_CASE(nothing_held_out) {
  modelloop::ModelLoopConfig cfg;
  cfg.fit_pin = 12.7;
  cfg.run_root = (std::filesystem::temp_directory_path() / "ml_none").string();
  BOOST_CHECK_THROW(modelloop::run_model_loop(sim::DrawBendSpec{}, {{12.7, 1500, 303, ""}}, {}, cfg), InputError);
}

BOOST_AUTO_TEST_CASE(blind_split_needs_three_pins) {
  modelloop::ModelLoopConfig cfg;
  cfg.fit_pin = 12.7;
  cfg.run_root = (std::filesystem::temp_directory_path() / "ml_blind").string();
  int asked = 0;
  const modelloop::CandidatesFor none = [&](double) {
    ++asked;
    return std::vector<modelloop::ModelCandidate>{};
  };
  BOOST_CHECK_EXCEPTION(
      modelloop::run_model_loop_blind(sim::DrawBendSpec{}, {{12.7, 1500, 303, ""}, {25.4, 1800, 107, ""}}, none, cfg),
      InputError, [](const InputError& e) { return std::string(e.what()).find("at least 3 pins") != std::string::npos; });
  BOOST_TEST(asked == 0);
}
