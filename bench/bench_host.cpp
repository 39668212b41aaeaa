// make bench: the host's capacity for two threads (bench_host.hpp).
#include "bench_host.hpp"

#include <omp.h>

#include <algorithm>
#include <exception>
#include <thread>

#include "bench_models.hpp"

using namespace drawbend;

double two_core_capacity(const fe::Model& m, long cycles, int repeats) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  double alone = 1e300, pair = 1e300;
  for (int k = 0; k < repeats; ++k) {
    alone = std::min(alone, seconds(m, cycles));
    // Each run times itself after its set-up, as the run alone does; the pair
    // took as long as the slower of the two.
    double t[2] = {0, 0};
    std::exception_ptr fault[2];
    auto one = [&](int i) {
      try {
        omp_set_num_threads(1);  // a new thread starts from the OpenMP defaults
        t[i] = seconds(m, cycles);
      } catch (...) {
        fault[i] = std::current_exception();  // rethrown below: never std::terminate
      }
    };
    std::thread a(one, 0), b(one, 1);
    a.join();
    b.join();
    for (const auto& f : fault)
      if (f) {
        omp_set_num_threads(before);
        std::rethrow_exception(f);
      }
    pair = std::min(pair, std::max(t[0], t[1]));
  }
  omp_set_num_threads(before);
  return 2 * alone / pair;
}
