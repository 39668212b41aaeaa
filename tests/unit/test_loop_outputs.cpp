// The loop's decisions, noise floor, bending choices, group factors and the
// friction-model export (src/loop), on cases with known answers.
//  - sequential_decision (Clopper-Pearson at 1e-3 against thr = 0.0025):
//    0 exceedances in 3000 permutations: upper bound 1 - 0.001^(1/3000) =
//    0.0023 < thr -> significant; 0 in 100: upper 0.067 -> undecided; 50 in
//    100: lower bound far above thr -> not significant.
//  - Noise floor: rows exactly on a line per test -> sigma = 0, flagged exact;
//    null synthetic data with noise sd 5 N (45 tests x 2 dof after the
//    within-test polynomial of 6 terms on 8 rows): estimate within 30 % (4
//    standard errors of an estimated sd, 1/sqrt(2 x 90) = 7.5 %).
//  - No rotating-pin rows: make_design throws InputError unless a bending
//    source is chosen; with swift, F_B = Swift Eq. 2.1 (analysis::swift_bending_force)
//    and the label says "NO rotating-pin rows".
//  - A hidden coil (batch) factor of +20 % on coil C: the loop adds a group
//    factor for 'coil' with one parameter per level but the first, and the C
//    level's factor is the largest, within 3 SE of its true value relative to
//    the reference coil.
//  - Export: a curved nine-node surface written to friction_model.toml and
//    read back; the Abaqus table (bilinear interpolation) and the Radioss
//    polynomial, parsed from the written text, evaluate to within 1.05x the
//    stated error (+1e-6 print rounding) of the law at 200 points.
#define BOOST_TEST_MODULE loop_outputs
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "analysis/rope.hpp"
#include "core/csv.hpp"
#include "loop/candidates.hpp"
#include "loop/export.hpp"
#include "loop/loop.hpp"
#include "loop/noise.hpp"
#include "loop/synth.hpp"

using namespace drawbend;
using namespace drawbend::loop;

BOOST_AUTO_TEST_CASE(sequential_decisions) {
  BOOST_TEST(sequential_decision(0, 3000, 0.0025) == 1);
  BOOST_TEST(sequential_decision(0, 100, 0.0025) == 0);
  BOOST_TEST(sequential_decision(50, 100, 0.0025) == -1);
}

static Dataset synth(const std::string& effect, double noise, int seed) {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  SynthOptions o;
  o.effect = effect;
  o.noise_N = noise;
  o.seed = seed;
  SynthTruth t;
  return synthesize(o, maps, t);
}

BOOST_AUTO_TEST_CASE(noise_floor) {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  const Dataset exact = synth("none", 0, 3);
  BOOST_TEST(replicate_noise(make_design(exact, maps)).exact);
  const Dataset d = synth("none", 5, 3);
  const NoiseFloor n = replicate_noise(make_design(d, maps));
  BOOST_TEST(!n.exact);
  BOOST_TEST(n.tests == 45);
  BOOST_TEST(n.dof == 90);
  BOOST_TEST(std::abs(n.sigma_N / 5 - 1) < 0.3);
}

BOOST_AUTO_TEST_CASE(no_rotating_rows) {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  Dataset d = synth("none", 5, 4);
  std::vector<Sample> fixed;
  for (const auto& s : d.rows)
    if (!s.rotating) fixed.push_back(s);
  d.rows = fixed;
  BOOST_CHECK_THROW(make_design(d, maps), InputError);
  const Design des = make_design(d, maps, 0.4, BendingSource::swift);
  BOOST_TEST(des.missing_rotating);
  BOOST_TEST(des.bending_label.find("NO rotating-pin rows") != std::string::npos);
  const double sw = analysis::swift_bending_force(99.71, 1.04, 25.4, 12.7 / 2, M_PI / 2, analysis::ForceBasis::full_strip);
  BOOST_TEST(des.bend_fallback[0] == sw, boost::test_tools::tolerance(1e-12));
  const Fit f = fit_model(des, ModelSpec{});
  for (size_t i = 0; i < des.rows.size(); ++i) BOOST_TEST(std::isfinite(predict(des, f, static_cast<int>(i))));
}

BOOST_AUTO_TEST_CASE(batch_group_factor) {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  const Dataset d = synth("batch", 5, 5);
  const LoopResult r = run_loop(make_design(d, maps), LoopOptions{});
  BOOST_TEST_REQUIRE(!r.steps.empty());
  BOOST_TEST(r.steps[0].variable == "coil");
  BOOST_TEST(r.steps[0].effect == "group_factor");
  BOOST_TEST_REQUIRE(r.steps[0].params.size() == 2u);  // three coils, one reference
  // True factors relative to the reference level (the first coil seen).
  const std::string ref = d.rows[0].extra[d.extra_index("coil")];
  for (const auto& p : r.steps[0].params) {
    const bool c = p.name.find("= C]") != std::string::npos;
    const double truth = ref == "C" ? (c ? 0 : 1 / 1.2 - 1) : (c ? 0.2 : 0.0);
    BOOST_TEST(std::abs(p.value - truth) < 3 * p.se + 1e-3, p.name << " " << p.value << " +- " << p.se);
  }
}

BOOST_AUTO_TEST_CASE(export_evaluates_back) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "drawbend_test_export";
  fs::create_directories(dir);
  std::ofstream(dir / "nodes.csv") << "node,mu_RD,mu_TD\n1,0.10,0.08\n2,0.09,0.075\n3,0.07,0.07\n4,0.12,0.09\n5,"
                                      "0.10,0.08\n6,0.085,0.072\n7,0.15,0.10\n8,0.12,0.09\n9,0.09,0.075\n";
  std::ofstream(dir / "fm.toml") << "[friction]\nlaw = \"surface\"\nnodes = \"nodes.csv\"\np_min = 2\np_max = 40\n"
                                    "v_min = 6.35\nv_max = 101.6\ninterval = 100\n";
  const ExportModel m = read_friction_model((dir / "fm.toml").string());
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> up(2, 40), uv(6.35, 101.6);
  // Abaqus: lines mu1, mu2, slip rate, pressure.
  const ExportResult ab = export_abaqus(m);
  std::vector<double> P, V, M1, M2;
  std::istringstream in(ab.text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '*') continue;
    double a, b, v, p;
    char c;
    std::istringstream l(line);
    l >> a >> c >> b >> c >> v >> c >> p;
    M1.push_back(a), M2.push_back(b), V.push_back(v), P.push_back(p);
  }
  BOOST_TEST_REQUIRE(M1.size() == 121u);
  const int nv = 11;
  auto interp = [&](const std::vector<double>& mu, double p, double v) {
    int i = 0, j = 0;
    while (i < 9 && p > P[(i + 1) * nv]) ++i;
    while (j < 9 && v > V[j + 1]) ++j;
    const double a = (p - P[i * nv]) / (P[(i + 1) * nv] - P[i * nv]), b = (v - V[j]) / (V[j + 1] - V[j]);
    return (1 - a) * ((1 - b) * mu[i * nv + j] + b * mu[i * nv + j + 1]) +
           a * ((1 - b) * mu[(i + 1) * nv + j] + b * mu[(i + 1) * nv + j + 1]);
  };
  for (int k = 0; k < 200; ++k) {
    const double p = up(rng), v = uv(rng);
    BOOST_TEST(std::abs(interp(M1, p, v) - m.rd(p, v)) <= 1.05 * ab.max_error + 1e-6);
    BOOST_TEST(std::abs(interp(M2, p, v) - m.td(p, v)) <= 1.05 * ab.max_error + 1e-6);
  }
  // OpenRadioss: the last two coefficient blocks (RD, TD) of the /FRICTION card.
  const ExportResult ra = export_openradioss(m);
  std::vector<std::vector<double>> rows;
  std::istringstream rin(ra.text);
  while (std::getline(rin, line)) {
    if (line.empty() || line[0] == '#' || line[0] == '/' || line.find("drawbend") != std::string::npos) continue;
    std::istringstream l(line);
    std::vector<double> x;
    for (int k = 0; k * 10 < static_cast<int>(line.size()); ++k) x.push_back(std::stod(line.substr(10 * k, 10)));
    rows.push_back(x);
  }
  BOOST_TEST_REQUIRE(rows.size() == 8u);  // Ifric line, default block (2), part line, RD (2), TD (2)
  for (int dir = 0; dir < 2; ++dir) {
    const auto& c = rows[4 + 2 * dir];
    const auto& f = rows[5 + 2 * dir];
    const std::vector<double> k = {f[1], c[0], c[1], c[2], c[3], c[4]};
    for (int n = 0; n < 200; ++n) {
      const double p = up(rng), v = uv(rng);
      const double law = dir == 0 ? m.rd(p, v) : m.td(p, v);
      BOOST_TEST(std::abs(radioss_mu(k, p, v) - law) <= 1.05 * ra.max_error + 1e-6);
    }
  }
  fs::remove_all(dir);
}
