// The draw-bend builder's deck (sim/drawbend_case.hpp) with the inlet sliding
// in the bend step (bend_inlet_slides) does not harden the strip before the
// test (issue 51, docs/issue51-large-pin.md).
//
// Case: the 42 mm pin (the largest R/t of the thesis, where a pre-strain
// matters most), the quick mesh (1 mm along, 4 through), a narrow strip (half
// width 0.5 mm, 1 across: plane stress, so the layered beam applies without a
// transverse factor), 74.8 N on the full 1 mm strip: 71.9 MPa, the 1900 N of
// the 25.4 mm strip's Sec. 5.7.1 cases; 50 mm/s at mass scaling 40000; the
// RD Swift curve (data/materials/aa5754_o_rd.csv, initial yield 99.7 MPa).
// Frictionless pin.  One run, about 13 s of one core.
//
// 1. inlet_leg_elastic: the strip upstream of the pin carries F_X / A = 71.9
//    MPa < 99.7 MPa, so it stays elastic until it reaches the bend.
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
//    same tension (analysis::bend_unbend, plane stress, the same curve): 1.98
//    N.  Tolerance 5 % (relative): the element's own bend-unbend cycle is
//    within 0.5 % of the beam (plastic_bending.bend_unbend_work), and F_B's
//    eighths along the draw scatter by about +-4 % on this mesh; the clamped
//    deck's pre-stretch gave +24 %.
#define BOOST_TEST_MODULE drawbend_prestretch
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "analysis/bending_work.hpp"
#include "core/csv.hpp"
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

const Run& the_run() {
  static const Run run = [] {
    Run r;
    sim::DrawBendSpec& s = r.spec;
    s.name = "prestretch";
    s.pin_diameter = 42.0;
    s.width = 0.5;
    s.across = 1;
    s.through = 4;
    s.element_length = 1.0;
    s.back_tension = 37.4;  // half model: 74.8 N on the full 1 mm strip
    s.speed = 50.0;
    s.mass_scaling = 40000.0;
    s.snapshots = 1;
    s.bend_inlet_slides = true;  // the fix (not yet the chapters' default)
    s.hardening = std::string(DRAWBEND_DATA_DIR) + "/materials/aa5754_o_rd.csv";
    std::string text = sim::deck_text(s);
    // The plastic strain of the element at mid-thickness (outer half) along the inlet leg.
    std::ostringstream probes;
    for (double x : kProbes)
      probes << "  { name = \"" << probe_name(x) << "\", kind = \"strain\", point = [" << x << ", 0.25, "
             << s.pin_diameter / 2 + 0.625 * s.thickness << "], component = 1 },\n";
    const std::string head = "history = [\n";
    const std::size_t at = text.find(head);
    BOOST_REQUIRE(at != std::string::npos);
    text.insert(at + head.size(), probes.str());
    const fs::path dir = fs::temp_directory_path() / "drawbend_verify_prestretch";
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
  }();
  return run;
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
  std::vector<double> fb;
  for (const auto& row : r.history.rows)
    if (r.history.text(row, "step") == "draw")
      fb.push_back(r.history.number(row, "F_Y_full_strip_N") - r.history.number(row, "F_X_full_strip_N"));
  BOOST_REQUIRE(fb.size() > 30);
  double sum = 0;
  const std::size_t from = 2 * fb.size() / 3;
  for (std::size_t i = from; i < fb.size(); ++i) sum += fb[i];
  const double fe_fb = sum / static_cast<double>(fb.size() - from);
  const material::HardeningCurve curve = material::HardeningCurve::load(r.spec.hardening);
  analysis::BendMaterial bm;
  bm.constraint = 1.0;  // plane stress: the narrow strip's sides are free
  bm.flow = [curve](double p) { return curve.stress(p); };
  bm.dflow = [curve](double p) { return curve.slope(p); };
  const double beam =
      analysis::bend_unbend({r.spec.pin_diameter, r.spec.thickness, 2 * r.spec.width, 2 * r.spec.back_tension, 200, 400}, bm)
          .bending_force_N;
  BOOST_TEST_MESSAGE("F_B " << fe_fb << " N (last third of the draw), beam theory " << beam << " N, error "
                            << 100 * (fe_fb - beam) / beam << " %");
  BOOST_TEST(std::abs(fe_fb - beam) / beam < 0.05);
}
