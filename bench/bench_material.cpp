// The material update alone: 4,096 integration points driven through a
// cyclic strain path (uniaxial-like increments of 2e-4, reversed every 50
// steps, so every point yields in both directions) with a small spin, timed
// per point update on one thread.  J2 isotropic is the element loop's model
// today; the others are CombinedPlasticity (material/combined_plasticity.hpp):
// the split form, two Chaboche terms, Hill'48 alone and Hill'48 with Chaboche;
// and Yld2004-18p (material/yld2004_plasticity.hpp) with the set fitted to the
// ESAFORM 2021 AA6016-T4 tests (Chapter v1), a = 8, alone and with two
// Chaboche terms.  These are the scalar updates, one point at a time; the
// element kernel runs each of these models on its vector lanes
// (material/lanes/), which `--bar-material` times in the element loop.
// Material constants: AA5754-O-like (E = 70 GPa, nu = 0.33, yield 100 MPa).
// Timed on the thread's CPU clock (the update is serial: time the thread
// spends descheduled on a shared machine is not the model's), the shortest of
// 3 rounds in which the models take turns, so that they share the minute's
// host speed; then Yld2004-18p's and Hill'48's costs as ratios (issue 54 aims
// at Yld2004-18p <= 3 x Hill'48).  Two paths: the cyclic one above, and
// rows `<model>_explicit_step`, plastic points on an explicit run's small
// increments (an iterative return converges in fewer iterations there).
#include "bench_material.hpp"
#include "bench_models.hpp"

#include <time.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <vector>

#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/yld2004_plasticity.hpp"

using namespace drawbend;

namespace {
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The cyclic path: increments of 2e-4 (about 0.2 of the initial yield strain), reversed every 50 steps.
// explicit_step: each point first strained into plastic flow along the same direction (10 untimed increments
// of 2e-4), then timed on increments of 2e-6, as a plastic point of an explicit run sees them (the cup's
// 50 mm in 150,000 cycles: about 1e-5 per cycle at most), without reversal.
double ns_per_update(const material::Material& m, int points, int steps, bool explicit_step) {
  const int ns = m.state_size();
  std::vector<double> sig(6 * points, 0.0), st(static_cast<std::size_t>(ns) * points, 0.0);
  for (int p = 0; p < points; ++p) m.init_state(&st[static_cast<std::size_t>(p) * ns]);
  const auto step = [&](int k, double size) {
    const double s = (explicit_step || (k / 50) % 2 == 0) ? 1.0 : -1.0;
    for (int p = 0; p < points; ++p) {
      const double f = 1.0 + 0.001 * (p % 17);  // points differ a little
      const double q = size / 2e-4;
      const double d[6] = {size * s * f, -1e-4 * q * s * f, -1e-4 * q * s * f, 3e-5 * q * s, 0.0, 1e-5 * q * s};
      const material::Spin w{10.0 * f, 0.0, -5.0, 1e-5 * q};
      m.update(d, w, &sig[6 * p], &st[static_cast<std::size_t>(p) * ns]);
    }
  };
  if (explicit_step)
    for (int k = 0; k < 10; ++k) step(k, 2e-4);
  const double t0 = thread_seconds();
  for (int k = 0; k < steps; ++k) step(k, explicit_step ? 2e-6 : 2e-4);
  const double sec = thread_seconds() - t0;
  return sec / (static_cast<double>(points) * steps) * 1e9;
}
}  // namespace

void bench_material(CsvWriter& w, bool quick) {
  const double E = 70000, nu = 0.33, rho = 2.7e-9;
  auto curve = [] { return material::HardeningCurve::voce(100.0, 180.0, 14.0); };
  const auto hill = material::Hill48::from_r_values(0.65, 0.65, 0.72);
  const material::Yld2004 yld = bench_yld2004_set();  // bench_models.hpp
  material::KinematicHardening split, chab, none;
  split.beta = 0.3;
  chab.chaboche = {{6000.0, 60.0}, {800.0, 5.0}};
  struct M {
    std::string name;
    std::shared_ptr<const material::Material> m;
  };
  const std::vector<M> models = {
      {"j2_isotropic", std::make_shared<material::J2Isotropic>(E, nu, rho, curve())},
      {"j2_combined_split", std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve(), split)},
      {"j2_combined_chaboche2", std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve(), chab)},
      {"hill48_isotropic", std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve(), none, hill)},
      {"hill48_chaboche2", std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve(), chab, hill)},
      {"yld2004_isotropic", std::make_shared<material::Yld2004Plasticity>(E, nu, rho, curve(), none, yld)},
      {"yld2004_chaboche2", std::make_shared<material::Yld2004Plasticity>(E, nu, rho, curve(), chab, yld)}};
  const int points = 4096, steps = quick ? 100 : 400, rounds = 3;
  for (const bool explicit_step : {false, true}) {
    const std::string path = explicit_step ? "_explicit_step" : "";
    std::vector<double> best(models.size(), 1e300);
    for (int k = 0; k < rounds; ++k)
      for (std::size_t i = 0; i < models.size(); ++i)
        best[i] = std::min(best[i], ns_per_update(*models[i].m, points, steps, explicit_step));
    double of[3] = {0, 0, 0};  // j2_isotropic, hill48_isotropic, yld2004_isotropic
    for (std::size_t i = 0; i < models.size(); ++i) {
      const auto& name = models[i].name;
      std::cout << "material " << name << path << ": " << fmt(best[i], 4)
                << " ns per integration-point update (1 thread, CPU time, shortest of " << rounds << ")\n";
      w.row({"material_" + name + path, std::to_string(points), "1", fmt(best[i], 5)});
      if (name == "j2_isotropic") of[0] = best[i];
      if (name == "hill48_isotropic") of[1] = best[i];
      if (name == "yld2004_isotropic") of[2] = best[i];
    }
    std::cout << "material" << path << " yld2004_isotropic / hill48_isotropic: " << fmt(of[2] / of[1], 3)
              << " (issue 54's aim: at most 3); / j2_isotropic: " << fmt(of[2] / of[0], 3) << "\n";
  }
}
