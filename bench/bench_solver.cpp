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
// build/bench/results.csv (--out; --help lists the options).  `--bar-material NAME` times only the 1,600-element
// bar on one thread with another material (bar_material(): the lane versions
// of the material models are compared on it).
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
#include "core/options.hpp"
#include "fe/element_view.hpp"
#include "fe/solver.hpp"
#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"

using namespace drawbend;

namespace {

/// The bar's material (--bar-material): J2 isotropic (the default, the
/// reference figures), or CombinedPlasticity on the same curve and elastic
/// constants: "split" (beta = 0.3), "chaboche" (one Armstrong-Frederick term,
/// C = 5000 MPa, gamma = 40), "hill48" (Hill'48 from r = 0.65 / 0.65 / 0.72,
/// isotropic hardening) or "hill48_chaboche" (both).  Empty for an unknown name.
std::shared_ptr<const material::Material> bar_material(const std::string& name) {
  const double E = 70000.0, nu = 0.33, rho = 2.7e-9;
  const material::HardeningCurve curve({0.0, 1.0}, {100.0, 600.0});
  const material::Hill48 hill = material::Hill48::from_r_values(0.65, 0.65, 0.72);
  material::KinematicHardening split, chab, none;
  split.beta = 0.3;
  chab.chaboche = {{5000.0, 40.0}};
  if (name == "j2") return std::make_shared<material::J2Isotropic>(E, nu, rho, curve);
  if (name == "split") return std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve, split);
  if (name == "chaboche") return std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve, chab);
  if (name == "hill48") return std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve, none, hill);
  if (name == "hill48_chaboche") return std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve, chab, hill);
  return nullptr;
}

fe::Model bar(int nx, int ny, int nz, std::shared_ptr<const material::Material> mat = nullptr) {
  fe::Model m;
  const double h = 1.0;  // 1 mm elements
  m.mesh = fe::structured_block(fe::uniform_lines(0, nx * h, nx), fe::uniform_lines(0, ny * h, ny),
                                fe::uniform_lines(0, nz * h, nz));
  m.material = mat ? std::move(mat) : bar_material("j2");
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
  // 1. Options (--help lists them; an unknown option is an error, exit 2).
  std::string out = "build/bench/results.csv", bar_mat;
  bool quick = false, friction_only = false, material_only = false, solver_only = false;
  Options opt("bench_solver", "make bench: the explicit solver's cost per element-cycle (ns), the material updates, "
                              "the friction laws and the quick draw-bend deck on 1 and 2 threads");
  opt.add(out, "out", "results CSV (its folder also gets friction_cost.csv and the deck's scratch runs)");
  opt.add_flag(quick, "quick", "shorter runs, no 64,000-element bar and no deck timing");
  opt.add_flag(friction_only, "friction", "only the friction-law cost");
  opt.add_flag(material_only, "materials", "only the material updates");
  opt.add_flag(solver_only, "solver", "only the element-cycle costs (and the deck unless --quick)");
  opt.add(bar_mat, "bar-material",
          "only the 1,600-element bar on 1 thread with this material: j2, split, chaboche, hill48 or hill48_chaboche");
  try {
    if (!opt.parse(argc, argv)) return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "bench_solver: " << e.what() << "\n";
    return 2;
  }
  if (out.empty()) out = "results.csv";
  const std::filesystem::path dir = std::filesystem::path(out).has_parent_path() ? std::filesystem::path(out).parent_path() : ".";
  try {  // before any timing: a bad folder fails now, not after minutes
    std::filesystem::create_directories(dir);
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "bench_solver: --out " << out << ": " << e.what() << "\n";
    return 2;
  }
  struct Case {
    std::string name;
    fe::Model model;
  };
  std::vector<Case> cases = {{"bar_1600", bar(40, 8, 5)}, {"bar_8000", bar(100, 16, 5)}, {"drawbend_4800", strip_on_pin()}};
  if (!quick) cases.push_back({"bar_64000", bar(200, 40, 8)});
  if (!bar_mat.empty()) {
    auto m = bar_material(bar_mat);
    if (!m) {
      std::cerr << "bench_solver: --bar-material '" << bar_mat
                << "' is not j2, split, chaboche, hill48 or hill48_chaboche\n";
      return 2;
    }
    cases = {{"bar_1600_" + bar_mat, bar(40, 8, 5, std::move(m))}};
  }
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
      if (threads > maxt || (threads > 1 && !bar_mat.empty())) continue;
      omp_set_num_threads(threads);
      const double t_short = seconds(c.model, base), t_long = seconds(c.model, base + extra);
      const double ns = (t_long - t_short) / (static_cast<double>(extra) * ne) * 1e9;
      std::cout << c.name << ": " << ne << " elements, " << threads << " thread(s): " << fmt(ns, 4)
                << " ns per element-cycle\n";
      w.row({c.name, std::to_string(ne), std::to_string(threads), fmt(ns, 5)});
    }
  }
  bool deck_ok = true;
  if (!bar_mat.empty()) {
    w.save(out);
    std::cout << "written " << out << "\n";
    return 0;
  }
  if (!friction_only && !material_only && !quick)
    deck_ok = bench_deck((dir / "scratch").string(), w);
  if (solver_only) {
    w.save(out);
    std::cout << "written " << out << "\n";
    return deck_ok ? 0 : 1;
  }
  if (!friction_only) bench_material(w, quick);
  if (!material_only) bench_friction(std::string(DRAWBEND_DATA_DIR) + "/cases/block_surface.toml",
                 (dir / "friction_cost.csv").string(), w, quick);
  w.save(out);
  std::cout << "written " << out << "\n";
  return deck_ok ? 0 : 1;
}
