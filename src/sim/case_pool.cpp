#include "sim/case_pool.hpp"

#include "sim/executor.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <mutex>
#include <numeric>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace drawbend::sim {

namespace {
int hardware_threads() {
#ifdef _OPENMP
  return std::max(1, omp_get_num_procs());
#else
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
#endif
}
std::atomic<int> g_case_threads{0};  // set_case_threads(); 0: the hardware threads
int pool_threads() {
  const int n = g_case_threads.load();
  return n > 0 ? n : hardware_threads();
}
}  // namespace

void set_case_threads(int n) { g_case_threads.store(std::max(0, n)); }

int default_case_jobs() {
  if (const char* e = std::getenv("DRAWBEND_JOBS")) {
    const int j = std::atoi(e);
    if (j >= 1) return j;
    std::cerr << "warning: DRAWBEND_JOBS='" << e << "' is not a positive integer; using the hardware threads\n";
  }
  return pool_threads();
}

void run_cases(std::size_t n, const std::function<void(std::size_t)>& f, const std::vector<double>& cost, int jobs) {
  if (n == 0) return;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (cost.size() == n)
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  const int budget = g_case_threads.load();
  const int cap = budget > 0 ? std::min(jobs, budget) : jobs;
  const int nw = static_cast<int>(std::min<std::size_t>(n, static_cast<std::size_t>(std::max(1, cap))));
  const int threads_each = std::max(1, (budget > 0 ? budget : hardware_threads()) / nw);
  std::vector<std::exception_ptr> err(n);
  std::atomic<std::size_t> next{0};
  auto worker = [&]() {
#ifdef _OPENMP
    omp_set_num_threads(threads_each);  // this thread's teams only
#endif
    for (std::size_t k; (k = next.fetch_add(1)) < n;) {
      const std::size_t i = order[k];
      try {
        f(i);
      } catch (...) {
        err[i] = std::current_exception();
      }
    }
  };
  if (nw == 1) {  // on the calling thread: its OpenMP setting restored after
#ifdef _OPENMP
    const int before = omp_get_max_threads();
#endif
    worker();
#ifdef _OPENMP
    omp_set_num_threads(before);
#endif
  } else {
    std::vector<std::thread> pool;
    for (int w = 0; w < nw; ++w) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
  }
  for (const auto& e : err)
    if (e) std::rethrow_exception(e);
}

std::vector<DrawBendResult> run_drawbend_all(const std::vector<CaseJob>& jobs, bool reuse,
                                             const std::vector<std::string>& runs_from) {
  std::vector<DrawBendResult> out(jobs.size());
  std::vector<double> cost;  // ~ elements x cycles ~ (wrap / h) x across x through x (slide / speed) / sqrt(ms)
  for (const auto& j : jobs) {
    const DrawBendSpec& s = j.spec;
    cost.push_back(wrap_length(s) / s.element_length * s.across * s.through * draw_length(s) / s.speed /
                   std::sqrt(s.mass_scaling));
  }
  std::mutex io;
  // Progress: cases done of all, and the time left, estimated from the wall
  // time so far and the share of the estimated cost still to run.
  double cost_all = std::accumulate(cost.begin(), cost.end(), 0.0);
  double cost_done = 0;
  std::size_t n_done = 0;
  const auto start = std::chrono::steady_clock::now();
  run_cases(jobs.size(), [&](std::size_t i) {
    const auto t0 = std::chrono::steady_clock::now();
    {
      std::lock_guard<std::mutex> lock(io);
      std::cout << "  FE: " << jobs[i].spec.name << " (pin " << jobs[i].spec.pin_diameter << " mm) started\n" << std::flush;
    }
    out[i] = run_drawbend(jobs[i].spec, jobs[i].dir, reuse, true, runs_from);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::lock_guard<std::mutex> lock(io);
    ++n_done;
    if (out[i].dir != jobs[i].dir)
      cost_all -= cost[i];  // read, not run: no part of the time the rest will take
    else
      cost_done += cost[i];
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "  FE: " << jobs[i].spec.name << " (pin " << jobs[i].spec.pin_diameter << " mm) ";
    if (out[i].dir != jobs[i].dir)
      std::cout << "read from " << out[i].dir << ", the same deck run before";
    else
      std::cout << "done in " << static_cast<int>(s + 0.5) << " s";
    std::cout << " (" << n_done << "/" << jobs.size() << " cases";
    if (n_done < jobs.size() && cost_done > 0)
      std::cout << ", about " << static_cast<int>(elapsed * (cost_all - cost_done) / cost_done + 0.5) << " s left";
    std::cout << ")\n" << std::flush;
  }, cost, executor_jobs(executor(), default_case_jobs()));
  return out;
}

}  // namespace drawbend::sim
