// make bench: the host's capacity for two threads (bench_host.hpp).
#include "bench_host.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "bench_models.hpp"

using namespace drawbend;

double two_core_capacity(const fe::Model& m, long cycles, int repeats) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  double alone = 1e300, pair = 1e300;
  for (int k = 0; k < repeats; ++k) {
    alone = std::min(alone, seconds(m, cycles));
    const auto t0 = std::chrono::steady_clock::now();
    auto one = [&] {
      omp_set_num_threads(1);  // a new thread starts from the OpenMP defaults
      seconds(m, cycles);
    };
    std::thread a(one), b(one);
    a.join();
    b.join();
    pair = std::min(pair, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  omp_set_num_threads(before);
  return 2 * alone / pair;
}
