// The draw-bend builder's deck (sim/drawbend_case.hpp) with the inlet sliding
// in the bend step (bend_inlet_slides) does not harden the strip before the
// test (issue 51, docs/issue51-large-pin.md).
//
// Case: the 42 mm pin (the largest R/t of the thesis, where a pre-strain
// matters most), the quick mesh (1 mm along, 4 through), a narrow strip (half
// width 0.5 mm, 1 across: plane stress, so the layered beam applies without a
// transverse factor), 74.8 N on the full 1 mm strip: 71.9 MPa, the 1900 N of
// the 25.4 mm strip's Sec. 5.7.1 cases; 50 mm/s at mass scaling 40000; the
// RD Swift curve (data/materials/aa5754_o_rd.csv, initial yield 92.1 MPa since
// issue 51 put Table 5.1's 99.71 MPa at eps_p = 0.002; 99.7 MPa before).
// Frictionless pin.  One run, about 13 s of one core.
//
// 1. inlet_leg_elastic: the strip upstream of the pin carries F_X / A = 71.9
//    MPa < 92.1 MPa, so it stays elastic until it reaches the bend (on the
//    curve of issue 51 the sections read 0.01-0.07 % at 8 mm before the tangent,
//    still under the tolerance; on the old curve, below 0.03 %).
//    Answer: plastic strain 0 at x = -5, -20, -35, -50 mm (reference x; the
//    wrap holds x = 0 to 33.8 mm after step 1), read 8 mm of slide before
//    each section reaches the entry tangent (x = -5 at the start of the
//    draw).  The first version read 3 mm before and failed (0.21 % at x = -5,
//    0.10 % at -50): the strip there is already bending, which starts 4-5 mm
//    ahead of the tangent (about sqrt(R t) = 4.7 mm); 6-10 mm before, every
//    section is below 0.03 %.  Tolerance 0.1 % plastic strain
//    (absolute): the clamped bend step of old left 1.2-1.6 %, a strip left
//    slack by a free, tensionless bend 1.3-4.3 % (the snatch when it pulls
//    taut); 0.1 % of pre-strain raises the flow stress at the 42 mm pin's
//    2.4 % bending strain by under 1 %.
// 2. bending_force: F_B = F_Y - F_X (full strip, mean over the last third of
//    the draw) against the layered beam bent to the pin and unbent under the
//    same tension (analysis::bend_unbend, plane stress, the same curve): 1.886
//    N (1.98 N on the curve before issue 51).  Tolerance 5 % (relative): the element's own bend-unbend cycle is
//    within 0.5 % of the beam (plastic_bending.bend_unbend_work), and F_B's
//    eighths along the draw scatter by about +-4 % on this mesh; the clamped
//    deck's pre-stretch gave +24 %.
// 3. plane_strain_bending_force: the same deck with the strip's free edge held
//    across the width (plane_strain_width: plane strain, the width condition
//    of plane-strain beam theory and of 2-D plane-strain codes) against
//    analysis::bend_unbend in plane strain (c = 2/sqrt(3), modulus E / (1 -
//    nu^2)), the same curve and tension: 62.65 N / 25.4 = 2.467 N on the 1 mm
//    strip.  Tolerance 5 % (relative), the reason of case 2, written before
//    the run: the full-width strip on the quick mesh with its edge held gave
//    66.08 N (+1.35 %), with it free 63.47 N (-2.7 %), so the shortfall of
//    the chapters' free strip below plane-strain beam theory on this pin is
//    the width condition, not the solver; a pin this large keeps the beam's
//    small-strain idealisations small (stretch 0.9 % in the bend; on the
//    12.7 mm pin, 1.8 %, the converged plane-strain FE lies 5.6 % below the
//    fixed-thickness beam and within 0.7 % of one whose section thins: case
//    4, docs/issue51-large-pin.md).  The narrow strip's two cases differ
//    only by the edge condition, so together they show that F_B moves from
//    plane stress to plane strain with it by the beam's factor (1.29).
// 4. small_pin_thinning: the 12.7 mm pin (the smallest R/t, 6.1), plane strain
//    (edge held), 0.5 mm along, 4 through, at 59.06 N on the 1 mm strip (56.8
//    MPa: the 1500 N of the 25.4 mm strip, Table 5.13) and at 20 N; two runs,
//    about 6 s of one core each.  There the chapters' FE lies 4-5 % below
//    the small-strain beam, because the strip thins as it stretches over the
//    pin and the beam's section does not (BendCase::thinning; issue 51,
//    docs/issue51-large-pin.md).  Reference: analysis::bend_unbend, plane
//    strain, with thinning.  (a) F_B at 59.06 N within 3 % of it; (b) the
//    ratio F_B(59.06 N) / F_B(20 N) within 2 % of the beam's.  Tolerances
//    written before these two runs (the same decks through `drawbend
//    drawbend-deck` had been run on 1 and 0.25 mm, not on 0.5 mm at 20 N):
//    the thinning beam lies 5.2 % below the fixed-thickness one at 59.06 N
//    and its ratio 3.5 % below, so 3 and 2 % tell the two apart; F_B at
//    59.06 N moved by 1.9 % over the mesh study (1 to 0.25 mm along, 4 to 16
//    through) and the thinning beam leaves out the tension's rise along the
//    wrap (-1.8 % in a beam re-analysis).  A solver that reached the
//    fixed-thickness beam here would have lost the strip's change of
//    thickness.
#define BOOST_TEST_MODULE drawbend_prestretch
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "analysis/bending_work.hpp"
#include "core/csv.hpp"
#include "io/case_spec.hpp"
#include "io/deck.hpp"
#include "io/run_case.hpp"
#include "material/hardening_curve.hpp"
#include "sim/drawbend_case.hpp"

using namespace drawbend;
namespace fs = std::filesystem;

namespace {

const double kProbes[] = {-5.0, -20.0, -35.0, -50.0};
/// Read each section this far before it reaches the entry tangent [mm] (x = -5
/// at the start of the draw): the strip starts to bend plastically ahead of
/// the tangent, over about sqrt(R t) = 4.7 mm on this pin.
constexpr double kAhead = 8.0;

std::string probe_name(double x) { return "pe_inlet_" + std::to_string(static_cast<int>(-x)); }

struct Run {
  sim::DrawBendSpec spec;
  CsvTable history;
};

/// The narrow strip's deck: pin [mm], F_X on the full 1 mm strip [N], element length along [mm]; probes:
/// the inlet leg's strain probes (kProbes, read by inlet_leg_elastic on the 42 mm pin only: on the
/// 12.7 mm pin's shorter mesh the point at -50 mm lies 16.5 mm outside the sheet, which the deck reader
/// refuses since 2026-12-05; before, it read the nearest edge element's strain under the probe's name).
Run make_run(const std::string& name, bool plane_strain, double pin = 42.0, double fx_full = 74.8, double el = 1.0,
             bool probes = true) {
  {
    Run r;
    sim::DrawBendSpec& s = r.spec;
    s.name = name;
    s.plane_strain_width = plane_strain;
    s.pin_diameter = pin;
    s.width = 0.5;
    s.across = 1;
    s.through = 4;
    s.element_length = el;
    s.back_tension = fx_full / 2;  // half model (74.8 N: 37.4 N)
    s.speed = 50.0;
    s.mass_scaling = 40000.0;
    s.snapshots = 1;
    s.bend_inlet_slides = true;  // the fix (the default since issue 51; set here so the test keeps guarding it)
    s.hardening = std::string(DRAWBEND_DATA_DIR) + "/materials/aa5754_o_rd.csv";
    io::CaseSpec c = sim::drawbend_case(s);
    // The plastic strain of the element at mid-thickness (outer half) along the inlet leg.
    toml::array* history = c.output["history"].as_array();
    BOOST_REQUIRE(history);
    for (double x : kProbes) {
      if (!probes) break;
      toml::table probe{{"name", probe_name(x)}, {"kind", "strain"},
                        {"point", toml::array{x, 0.25, s.pin_diameter / 2 + 0.625 * s.thickness}}, {"component", 1}};
      probe.is_inline(true);
      history->push_back(std::move(probe));
    }
    const std::string text = io::to_toml(c);
    const fs::path dir = fs::temp_directory_path() / ("drawbend_verify_" + s.name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    io::Deck deck = io::parse_deck(text, (dir / "deck.toml").string());
    io::RunOptions ro;
    ro.out_dir = dir.string();
    ro.quiet = true;
    std::ostringstream log;
    io::run_case(deck, ro, log);
    r.history = read_csv((dir / "history.csv").string());
    return r;
  }
}

const Run& the_run() {
  static const Run run = make_run("prestretch", false);
  return run;
}

const Run& plane_strain_run() {
  static const Run run = make_run("prestretch_plane_strain", true);
  return run;
}

/// Case 4's runs: the 12.7 mm pin, plane strain, 0.5 mm along, at 59.06 N and 20 N.
const Run& small_pin_run(bool high) {
  static const Run hi = make_run("thinning_12p7_59", true, 12.7, 59.06, 0.5, false);
  static const Run lo = make_run("thinning_12p7_20", true, 12.7, 20.0, 0.5, false);
  return high ? hi : lo;
}

/// F_B = F_Y - F_X [N], mean over the last third of the draw.
double fe_bending_force(const Run& r) {
  std::vector<double> fb;
  for (const auto& row : r.history.rows)
    if (r.history.text(row, "step") == "draw")
      fb.push_back(r.history.number(row, "F_Y_full_strip_N") - r.history.number(row, "F_X_full_strip_N"));
  if (fb.size() <= 30) return NAN;
  double sum = 0;
  const std::size_t from = 2 * fb.size() / 3;
  for (std::size_t i = from; i < fb.size(); ++i) sum += fb[i];
  return sum / static_cast<double>(fb.size() - from);
}

/// analysis::bend_unbend on the run's curve and tension with constraint c [N];
/// thinning: the section thins with the strip's stretch (BendCase::thinning).
double beam_bending_force(const Run& r, double c, bool thinning = false) {
  const material::HardeningCurve curve = material::HardeningCurve::load(r.spec.hardening);
  analysis::BendMaterial bm;
  bm.constraint = c;
  bm.flow = [curve](double p) { return curve.stress(p); };
  bm.dflow = [curve](double p) { return curve.slope(p); };
  analysis::BendCase bc{r.spec.pin_diameter, r.spec.thickness, 2 * r.spec.width, 2 * r.spec.back_tension, 200, 400};
  bc.thinning = thinning;
  return analysis::bend_unbend(bc, bm).bending_force_N;
}

}  // namespace

BOOST_AUTO_TEST_CASE(inlet_leg_elastic) {
  const Run& r = the_run();
  const CsvTable& h = r.history;
  double x0 = NAN;
  for (double x : kProbes) {
    double pe = NAN;
    for (const auto& row : h.rows) {
      if (h.text(row, "step") != "draw") continue;
      const double inlet = h.number(row, "inlet_x_mm");
      if (std::isnan(x0)) x0 = inlet;
      pe = h.number(row, probe_name(x));
      if (inlet - x0 >= -x - kAhead) break;  // the strip moves to +x
    }
    BOOST_TEST_MESSAGE("inlet leg at x = " << x << " mm: plastic strain " << pe << " before it bends");
    BOOST_TEST(std::isfinite(pe));
    BOOST_TEST(std::abs(pe) < 1e-3);
  }
}

BOOST_AUTO_TEST_CASE(bending_force) {
  const Run& r = the_run();
  const double fe_fb = fe_bending_force(r);
  const double beam = beam_bending_force(r, 1.0);  // plane stress: the narrow strip's sides are free
  BOOST_TEST_MESSAGE("F_B " << fe_fb << " N (last third of the draw), beam theory " << beam << " N, error "
                            << 100 * (fe_fb - beam) / beam << " %");
  BOOST_TEST(std::abs(fe_fb - beam) / beam < 0.05);
}

BOOST_AUTO_TEST_CASE(plane_strain_bending_force) {
  const Run& r = plane_strain_run();
  const double fe_fb = fe_bending_force(r);
  const double beam = beam_bending_force(r, analysis::BendMaterial{}.constraint);  // plane strain, E / (1 - nu^2)
  BOOST_TEST_MESSAGE("plane-strain width: F_B " << fe_fb << " N (last third of the draw), beam theory (plane strain) "
                                                << beam << " N, error " << 100 * (fe_fb - beam) / beam << " %");
  BOOST_TEST(std::abs(fe_fb - beam) / beam < 0.05);
}

BOOST_AUTO_TEST_CASE(small_pin_thinning) {
  const double c = analysis::BendMaterial{}.constraint;  // plane strain, E / (1 - nu^2)
  double fe[2], thin[2], plain[2];
  for (int k = 0; k < 2; ++k) {
    const Run& r = small_pin_run(k == 0);
    fe[k] = fe_bending_force(r);
    thin[k] = beam_bending_force(r, c, true);
    plain[k] = beam_bending_force(r, c, false);
    BOOST_TEST_MESSAGE("12.7 mm pin, plane strain, F_X " << 2 * r.spec.back_tension << " N: F_B " << fe[k]
                                                         << " N, beam with thinning " << thin[k] << " N ("
                                                         << 100 * (fe[k] / thin[k] - 1) << " %), thickness fixed "
                                                         << plain[k] << " N (" << 100 * (fe[k] / plain[k] - 1) << " %)");
  }
  // (a) the level at the chapters' stress, against the beam that thins
  BOOST_TEST(std::abs(fe[0] - thin[0]) / thin[0] < 0.03);
  // (b) how much the tension takes off, against the beam that thins
  const double r_fe = fe[0] / fe[1], r_thin = thin[0] / thin[1], r_plain = plain[0] / plain[1];
  BOOST_TEST_MESSAGE("F_B(59.06 N) / F_B(20 N): FE " << r_fe << ", beam with thinning " << r_thin << ", thickness fixed "
                                                      << r_plain);
  BOOST_TEST(std::abs(r_fe - r_thin) / r_thin < 0.02);
}
