// make bench: cost of the explicit solver per element-cycle.
//
// Problem (as the reference figures of the issue): a structured bar of
// hexahedra, J2 with linear hardening (E = 70 GPa, nu = 0.33, rho = 2.7e-9
// t/mm^3, yield 100 MPa, hardening modulus 500 MPa), one end fixed, the other
// pulled axially at 20 m/s with the other directions held; plus a draw-bend-
// sized model with contact (strip over a pin, about 4,000 elements).
// Cost = (wall(long run) - wall(short run)) / (extra cycles x elements), which
// removes set-up time; each wall time is the shortest of kRepeats runs (one
// with --quick), as interference only adds time, the 1- and 2-thread runs
// taking turns.  Then the quick draw-bend deck's wall time on 1 and 2
// threads, which must not be slower on 2 (bench_deck.cpp; not with --quick).
// The CPU model and the element kernel head the output; each case's
// per-phase split on 1 and 2 threads follows its timings (bench_phases.cpp);
// on 2 threads also the share of cycles whose element loop forked and the
// host's capacity for two threads that share nothing (bench_host.cpp); and a
// Markdown table with the issue-22 goals, each ok or FAIL, closes the solver
// part (bench_summary.cpp).  The models: bench_models.hpp.  Results go to
// build/bench/results.csv (--out; --help lists the options).
// Then, if CalculiX's ccx is on PATH, the same bar in its explicit solver on
// the same simulated window, as a ratio (bench_calculix.cpp; optional).
// `--bar-material NAME` times only the 1,600-element bar on one thread with
// another material (the lane versions of the material models are compared on it);
// `--case NAME` times only that case, on 1 and 2 threads, with its phases.
#include <omp.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "bench_calculix.hpp"
#include "bench_deck.hpp"
#include "bench_friction.hpp"
#include "bench_host.hpp"
#include "bench_material.hpp"
#include "bench_models.hpp"
#include "bench_phases.hpp"
#include "bench_summary.hpp"
#include "core/csv.hpp"
#include "core/options.hpp"
#include "fe/element_view.hpp"
#include "fe/solver.hpp"

using namespace drawbend;

constexpr int kRepeats = 3;  // runs per timing, the shortest kept

int main(int argc, char** argv) {
  // 1. Options (--help lists them; an unknown option is an error, exit 2).
  std::string out = "build/bench/results.csv", bar_mat, only;
  bool quick = false, friction_only = false, material_only = false, solver_only = false, calculix_only = false;
  Options opt("bench_solver", "make bench: the explicit solver's cost per element-cycle (ns), the material updates, "
                              "the friction laws and the quick draw-bend deck on 1 and 2 threads");
  opt.add(out, "out", "results CSV (its folder also gets friction_cost.csv and the deck's scratch runs)");
  opt.add_flag(quick, "quick", "shorter runs, no 64,000-element bar and no deck timing");
  opt.add_flag(friction_only, "friction", "only the friction-law cost");
  opt.add_flag(material_only, "materials", "only the material updates");
  opt.add_flag(solver_only, "solver", "only the element-cycle costs (and the deck unless --quick)");
  opt.add_flag(calculix_only, "calculix", "only CalculiX (ccx) and ours on the same bar, if ccx is installed");
  opt.add(only, "case", "only this case of the element-cycle costs: bar_1600, bar_8000, drawbend_4800 or bar_64000");
  opt.add(bar_mat, "bar-material",
          "only the 1,600-element bar on 1 thread with this material: j2, split, chaboche, hill48, hill48_chaboche or yld2004, or one of them with _scalar appended (no lanes)");
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
  if (!quick || only == "bar_64000") cases.push_back({"bar_64000", bar(200, 40, 8)});
  if (!only.empty()) {
    std::erase_if(cases, [&](const Case& c) { return c.name != only; });
    if (cases.empty()) {
      std::cerr << "bench_solver: --case '" << only << "' is not bar_1600, bar_8000, drawbend_4800 or bar_64000\n";
      return 2;
    }
  }
  if (!bar_mat.empty()) {
    auto m = bar_material(bar_mat);
    if (!m) {
      std::cerr << "bench_solver: --bar-material '" << bar_mat
                << "' is not j2, split, chaboche, hill48, hill48_chaboche or yld2004 (with _scalar or without)\n";
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
  if (friction_only || material_only || calculix_only) cases.clear();
  std::vector<CaseResult> results;
  for (auto& c : cases) {
    const long ne = c.model.mesh.num_elements();
    const long base = std::max(20L, 2000000L / ne), extra = std::max(50L, (quick ? 4000000L : 20000000L) / ne);
    CaseResult r;
    r.name = c.name;
    r.elements = ne;
    // The shortest of kRepeats runs each: interference from the rest of the
    // machine (another guest on the host, a daemon) only ever adds time, and
    // it falls mostly on the 2-thread runs, which need both cores at once.
    // The thread counts take turns, repeat by repeat, so that the 1- and
    // 2-thread figures come from the same minute: the host's speed drifts
    // (2026-11-29, Zen 4: bar 1,600 on one thread 86 ns timed, then its
    // per-phase run a minute later 117).
    const int nthreads = bar_mat.empty() ? std::min(2, maxt) : 1;
    double t_short[2] = {1e300, 1e300}, t_long[2] = {1e300, 1e300};
    double forked = 0;  // share of the kept 2-thread long run's cycles
    for (int k = 0; k < (quick ? 1 : kRepeats); ++k)
      for (int threads = 1; threads <= nthreads; ++threads) {
        omp_set_num_threads(threads);
        t_short[threads - 1] = std::min(t_short[threads - 1], seconds(c.model, base));
        double share = 0;
        const double t = seconds(c.model, base + extra, nullptr, &share);
        if (t < t_long[threads - 1]) {
          t_long[threads - 1] = t;
          if (threads > 1) forked = share;
        }
      }
    for (int threads = 1; threads <= nthreads; ++threads) {
      const double ns = (t_long[threads - 1] - t_short[threads - 1]) / (static_cast<double>(extra) * ne) * 1e9;
      std::cout << c.name << ": " << ne << " elements, " << threads << " thread(s): " << fmt(ns, 4)
                << " ns per element-cycle";
      if (threads > 1) std::cout << " (element loop forked in " << fmt(100 * forked, 3) << " % of the cycles)";
      std::cout << "\n";
      w.row({c.name, std::to_string(ne), std::to_string(threads), fmt(ns, 5)});
      (threads == 1 ? r.ns1 : r.ns2) = ns;
    }
    if (nthreads > 1) {
      // What the host gave two threads that share nothing, just now
      // (bench_host.hpp): a reference for the 2-thread figure above.
      r.forked = forked;
      r.capacity = two_core_capacity(c.model, std::max(20L, extra / 2), quick ? 1 : kRepeats);
      std::cout << c.name << ": two 1-thread runs at once did " << fmt(r.capacity, 3)
                << "x the work of one (the host's capacity for 2 threads now)\n";
    }
    if (bar_mat.empty()) {
      r.split = bench_phases(c.name, c.model, extra, w);
      if (maxt >= 2) bench_phases(c.name, c.model, extra, w, 2);  // which phase keeps 2 threads from 2x
    }
    results.push_back(r);
  }
  omp_set_num_threads(1);  // what follows runs on one thread unless it sets its own
  bool deck_ok = true;
  if (!bar_mat.empty() || !only.empty()) {
    w.save(out);
    std::cout << "written " << out << "\n";
    return 0;
  }
  if (!friction_only && !material_only && !calculix_only && !quick)
    deck_ok = bench_deck((dir / "scratch").string(), w);
  std::vector<PeerResult> peers;
  if (!friction_only && !material_only) peers = bench_calculix((dir / "scratch").string(), w, quick);
  if (!results.empty()) print_summary(cpu, isa, width, results);
  if (!friction_only && !material_only) print_calculix_summary(peers, !find_ccx().empty());
  if (solver_only || calculix_only) {
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
