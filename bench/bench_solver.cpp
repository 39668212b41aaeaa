// make bench: cost of the explicit solver per element-cycle.
//
// Problem (as the reference figures of the issue): a structured bar of
// hexahedra, J2 with linear hardening (E = 70 GPa, nu = 0.33, rho = 2.7e-9
// t/mm^3, yield 100 MPa, hardening modulus 500 MPa), one end fixed, the other
// pulled axially at 20 m/s with the other directions held; plus a draw-bend-
// sized model with contact (strip over a pin, about 4,000 elements).
// Cost = (wall(long run) - wall(short run)) / (extra cycles x elements), which
// removes set-up time.  Then the quick draw-bend deck's wall time on 1 and 2
// threads, which must not be slower on 2 (bench_deck.cpp; not with --quick).
// The CPU model and the element kernel head the output.  Results go to
// build/bench/results.csv.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "bench_deck.hpp"
#include "bench_friction.hpp"
#include "bench_material.hpp"
#include "core/csv.hpp"
#include "fe/element_view.hpp"
#include "fe/solver.hpp"
#include "material/j2_isotropic.hpp"

using namespace drawbend;

namespace {

fe::Model bar(int nx, int ny, int nz) {
  fe::Model m;
  const double h = 1.0;  // 1 mm elements
  m.mesh = fe::structured_block(fe::uniform_lines(0, nx * h, nx), fe::uniform_lines(0, ny * h, ny),
                                fe::uniform_lines(0, nz * h, nz));
  m.material = std::make_shared<material::J2Isotropic>(70000.0, 0.33, 2.7e-9,
                                                       material::HardeningCurve({0.0, 1.0}, {100.0, 600.0}));
  fe::Step s;
  s.duration = 1.0;  // long; runs are cut by cycle count
  s.fixed = {{"xmin", {true, true, true}}, {"xmax", {false, true, true}}};
  s.velocities.push_back({"xmax", {1, 0, 0}, fe::History::constant(20000.0)});
  m.steps.push_back(s);
  return m;
}

fe::Model strip_on_pin() {
  fe::Model m;
  // 1.04 mm thick, 12.7 mm half-width strip over a 12.7 mm pin: 100 x 8 x 4 = 3,200 elements in the
  // refined zone plus 2 x 25 x 8 x 4 coarse = 4,800 in all.
  m.mesh = fe::structured_block(fe::piecewise_lines({-40, -12.5, 12.5, 40}, {25, 100, 25}), fe::uniform_lines(0, 12.7, 8),
                                fe::uniform_lines(0, 1.04, 4));
  m.material = std::make_shared<material::J2Isotropic>(70000.0, 0.33, 2.7e-9,
                                                       material::HardeningCurve({0.0, 1.0}, {100.0, 600.0}));
  contact::Surface c;
  c.kind = contact::Surface::Kind::cylinder;
  c.origin = {0, 0, -6.35};
  c.axis = {0, 1, 0};
  c.R = 6.35;
  m.add_rigid_contact("pin", c, "zmin", std::make_shared<friction::Coulomb>(0.1));
  fe::Step s;
  s.duration = 1.0;
  s.fixed = {{"ymin", {false, true, false}}};
  s.forces.push_back({"xmin", {-1, 0, 0}, fe::History::constant(750.0)});
  s.velocities.push_back({"xmax", {1, 0, 0}, fe::History::constant(50.0)});
  m.steps.push_back(s);
  m.mass_scaling = 100;
  return m;
}

double seconds(fe::Model m, long cycles) {
  fe::Solver s(m);
  const auto t0 = std::chrono::steady_clock::now();
  bool stop = false;
  try {
    s.run_step(0, [&](const fe::Progress& p) {
      if (p.cycle >= cycles && !stop) {
        stop = true;
        throw std::runtime_error("done");
      }
    });
  } catch (const std::runtime_error&) {
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "build/bench/results.csv";
  auto flag = [&](const std::string& f) {
    for (int i = 2; i < argc; ++i)
      if (f == argv[i]) return true;
    return false;
  };
  const bool quick = flag("--quick");
  const bool friction_only = flag("--friction");  // only the friction-law cost
  const bool material_only = flag("--materials");  // only the material updates
  const bool solver_only = flag("--solver");       // only the element-cycle costs (and the deck unless --quick)
  struct Case {
    std::string name;
    fe::Model model;
  };
  std::vector<Case> cases = {{"bar_1600", bar(40, 8, 5)}, {"bar_8000", bar(100, 16, 5)}, {"drawbend_4800", strip_on_pin()}};
  if (!quick) cases.push_back({"bar_64000", bar(200, 40, 8)});
  CsvWriter w({"case", "elements", "threads", "ns_per_element_cycle"});
  const char* isa = "";
  int width = 4;
  fe::element_kernel(&isa, &width);
  const std::string cpu = cpu_model();
  w.comment(std::string("explicit solver cost; element kernel: ") + isa + " (" + std::to_string(width) +
            " elements side by side); CPU: " + cpu + " (" + std::to_string(omp_get_num_procs()) + " processors)");
  std::cout << "CPU: " << cpu << " (" << omp_get_num_procs() << " processors)\nelement kernel: " << isa << " ("
            << width << " elements side by side)\n";
  const int maxt = omp_get_num_procs();
  if (friction_only || material_only) cases.clear();
  for (auto& c : cases) {
    const long ne = c.model.mesh.num_elements();
    const long base = std::max(20L, 2000000L / ne), extra = std::max(50L, (quick ? 4000000L : 20000000L) / ne);
    for (int threads : {1, 2}) {
      if (threads > maxt) continue;
      omp_set_num_threads(threads);
      const double t_short = seconds(c.model, base), t_long = seconds(c.model, base + extra);
      const double ns = (t_long - t_short) / (static_cast<double>(extra) * ne) * 1e9;
      std::cout << c.name << ": " << ne << " elements, " << threads << " thread(s): " << fmt(ns, 4)
                << " ns per element-cycle\n";
      w.row({c.name, std::to_string(ne), std::to_string(threads), fmt(ns, 5)});
    }
  }
  std::filesystem::create_directories(std::filesystem::path(out).parent_path());
  bool deck_ok = true;
  if (!friction_only && !material_only && !quick)
    deck_ok = bench_deck((std::filesystem::path(out).parent_path() / "scratch").string(), w);
  if (solver_only) {
    w.save(out);
    std::cout << "written " << out << "\n";
    return deck_ok ? 0 : 1;
  }
  if (!friction_only) bench_material(w, quick);
  if (!material_only) bench_friction(std::string(DRAWBEND_DATA_DIR) + "/cases/block_surface.toml",
                 (std::filesystem::path(out).parent_path() / "friction_cost.csv").string(), w, quick);
  w.save(out);
  std::cout << "written " << out << "\n";
  return deck_ok ? 0 : 1;
}
