// make bench, friction part: the run-time cost of the mu(p, v) surface law with
// its elliptical limit against Coulomb friction on the block-sliding problem of
// Chapter 6 (data/cases/block_surface.toml: 64 elements, 25 contact nodes, all
// sliding).  The thesis reports +3.8 % for its block (Sec. 7.1.2); the goal
// here is < 1 %.
// Method: press (untimed), then time a fixed number of cycles of steady
// sliding; the laws alternate, 7 repetitions each, and the minimum time of
// each law is kept (the least disturbed run on a shared machine).  On a busy
// shared machine that whole-run ratio is noisy (a few %), so the law's own
// cost is also timed in isolation: ns per limit() call over 10^7 calls with
// varying (p, v), times the contact nodes per cycle, over the Coulomb cycle
// time, gives the implied overhead.  Written to build/bench/friction_cost.csv
// and as rows of build/bench/results.csv.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>

#include "bench_friction.hpp"

#include "bench_deck.hpp"  // cpu_model
#include "fe/solver.hpp"
#include "io/deck.hpp"

using namespace drawbend;

namespace {

double slide_seconds(const fe::Model& model, long cycles) {
  fe::Model m = model;
  m.steps.at(1).duration = 1.0;  // long: the run is cut by cycle count
  fe::Solver s(m);
  s.run_step(0);
  const long c0 = s.cycles();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    s.run_step(1, [&](const fe::Progress& p) {
      if (p.cycle - c0 >= cycles) throw std::runtime_error("done");
    });
  } catch (const std::runtime_error&) {
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// ns per limit() call, minimum of 5 repetitions of n calls (per-node state of 1,000 nodes).
double ns_per_call(const friction::FrictionLaw& law, long n) {
  std::vector<double> state(1000 * std::max(1, law.state_size()), 0.0);
  double best = 1e30, sink = 0;
  for (int rep = 0; rep < 5; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    friction::ContactState st;
    for (long k = 0; k < n; ++k) {
      st.pressure = 5.0 + 0.001 * static_cast<double>(k % 70000);
      st.slip_speed = 10.0 + 0.0001 * static_cast<double>(k % 900000);
      st.state = state.data() + (k % 1000) * law.state_size();
      const auto l = law.limit(st);
      sink += l.mu1 - l.mu2;
    }
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / n * 1e9);
  }
  if (sink == 12345.678) std::cout << "";  // keep the loop
  return best;
}

}  // namespace

void bench_friction(const std::string& deck_path, const std::string& out_csv, CsvWriter& results, bool quick) {
  omp_set_num_threads(1);
  const io::Deck deck = io::read_deck(deck_path);
  struct Law {
    std::string name;
    fe::Model model;
    double best = 1e30;
  };
  std::vector<Law> laws(3, {"", deck.model});
  laws[0].name = "coulomb";
  laws[0].model.contacts[0].friction = std::make_shared<friction::Coulomb>(0.043);
  laws[1].name = "surface_fixed";
  laws[2].name = "surface_corotational";
  laws[2].model.contacts[0].texture = fe::ContactPair::Texture::corotational;
  const long cycles = quick ? 5000 : 40000;
  const int reps = quick ? 3 : 7;
  for (int r = 0; r < reps; ++r)
    for (auto& l : laws) l.best = std::min(l.best, slide_seconds(l.model, cycles));
  const long ne = deck.model.mesh.num_elements();
  // The law alone.
  const long calls = quick ? 1000000 : 10000000;
  const double c_coulomb = ns_per_call(*laws[0].model.contacts[0].friction, calls);
  const double c_surface = ns_per_call(*laws[1].model.contacts[0].friction, calls);
  std::size_t nodes = 0;  // contact nodes of the block's face set
  {
    std::vector<int> ids;
    for (const auto& f : deck.model.mesh.face_set(deck.model.contacts[0].faces)) ids.insert(ids.end(), f.begin(), f.end());
    std::sort(ids.begin(), ids.end());
    nodes = static_cast<std::size_t>(std::unique(ids.begin(), ids.end()) - ids.begin());
  }
  const double implied = (c_surface - c_coulomb) * nodes / (laws[0].best / cycles * 1e9);
  std::cout << "limit() call: Coulomb " << fmt(c_coulomb, 3) << " ns, surface " << fmt(c_surface, 3) << " ns; x "
            << nodes << " contact nodes = " << fmt(100 * implied, 3) << " % of a Coulomb cycle\n";
  const std::string cpu = cpu_model();
  CsvWriter w({"case", "law", "elements", "cycles", "seconds_min", "ns_per_cycle", "ratio_to_coulomb", "ns_per_limit_call",
               "implied_overhead_pct", "cpu"});
  w.comment("friction-law cost on " + deck_path + ", 1 thread, min of " + std::to_string(reps) + " alternating runs");
  for (const auto& l : laws) {
    const double ns = l.best / cycles * 1e9, ratio = l.best / laws[0].best;
    std::cout << "block " << l.name << ": " << fmt(ns, 4) << " ns per cycle, ratio to Coulomb " << fmt(ratio, 5)
              << " (" << cpu << ")\n";
    const bool surf = l.name == "surface_fixed";  // the law alone (the corotational axis is contact-side work)
    w.row({"block_surface", l.name, std::to_string(ne), std::to_string(cycles), fmt(l.best, 6), fmt(ns, 6),
           fmt(ratio, 6), fmt(l.name == "coulomb" ? c_coulomb : c_surface, 4), surf ? fmt(100 * implied, 4) : "", cpu});
    results.row({"block_" + l.name, std::to_string(ne), "1", fmt(ns / ne, 5)});
  }
  w.save(out_csv);
}
