// The element loop's driver (member of fe::Solver): the element kernel over
// all elements, four or eight side by side, into node-major corner slots that
// the node pass (fe/step_phases.hpp: sum_and_integrate) sums in a fixed order.
// The element itself is described in fe/element_kernel.hpp.
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "fe/element_view.hpp"
#include "fe/solver.hpp"
#include "material/lane_binding.hpp"

namespace drawbend::fe {

bool avx2_kernel_available() {
#if defined(DRAWBEND_HAVE_AVX2_KERNEL) && (defined(__x86_64__) || defined(__i386__))
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

void bind_lanes(ElementView& v) {
  material::LaneBinding b;  // the material says which lane twin it has (Material::bind_lanes)
  v.mat->bind_lanes(b);
  v.j2_lanes = b.j2;
  if (b.j2) v.j2 = b.j2_params;
  v.combined_lanes = b.combined;
  if (b.combined) v.combined = b.combined_params;
  v.yld2004_lanes = b.yld2004;
  if (b.yld2004) v.yld2004 = b.yld2004_params;
}

bool avx512_kernel_available() {
#if defined(DRAWBEND_HAVE_AVX512_KERNEL) && (defined(__x86_64__) || defined(__i386__))
  return __builtin_cpu_supports("avx512f");
#else
  return false;
#endif
}

ElementRangeFn element_kernel(const char** name, int* width) {
  const char* env = std::getenv("DRAWBEND_ISA");
  const std::string want = env ? env : "";
  if (!want.empty() && want != "baseline" && want != "avx2" && want != "avx512")
    std::cerr << "warning: DRAWBEND_ISA='" << want << "' is not 'baseline', 'avx2' or 'avx512'; ignored\n";
  if (width) *width = 4;
#ifdef DRAWBEND_HAVE_AVX512_KERNEL
  if (want != "baseline" && want != "avx2" && avx512_kernel_available()) {
    if (name) *name = "avx512";
    if (width) *width = 8;
    return &avx512::element_range;
  }
#endif
  if (want == "avx512")
    std::cerr << "warning: DRAWBEND_ISA=avx512, but this build or this CPU has no AVX-512 kernel; trying avx2\n";
#ifdef DRAWBEND_HAVE_AVX2_KERNEL
  if (want != "baseline" && avx2_kernel_available()) {
    if (name) *name = "avx2";
    return &avx2::element_range;
  }
#endif
  if (want == "avx2")
    std::cerr << "warning: DRAWBEND_ISA=avx2, but this build or this CPU has no AVX2 kernel; using the baseline\n";
  if (name) *name = "baseline";
  return &baseline::element_range;
}

void Solver::element_forces() {
  const Mesh& mesh = m_.mesh;
  const int ne = mesh.num_elements();
  const material::Material& mat = *m_.material;
  ElementView ev;
  ev.hex = mesh.hex.data();
  ev.nodes = node_view();
  ev.sig = sig_.data();
  ev.state = state_.data();
  ev.hgq = hgq_.data();
  ev.hg_ratio = hg_ratio_.data();
  ev.corner = corner_.data();
  ev.corner_slot = corner_slot_.data();
  ev.ie_inc = ie_inc_.data();
  ev.hg_inc = hg_inc_.data();
  ev.dt_elem = dt_elem_.data();
  ev.sqrt_mass_factor = elem_sqrt_mass_factor_.data();
  ev.mat = &mat;
  bind_lanes(ev);
  ev.ns = mat.state_size();
  ev.spin = mat.uses_spin();
  ev.E0 = mat.youngs_modulus();
  ev.G0 = mat.shear_modulus();
  ev.hourglass = m_.hourglass;
  ev.c_elastic = mat.poisson_ratio() / (1.0 - mat.poisson_ratio());
  // The velocities v_n-1/2 act over the previous interval [t_n-1, t_n]: strain,
  // spin and hourglass increments use its length (zero before the first cycle).
  ev.dtp = last_dt_;
  ev.wave_speed = wave_speed_;
  struct Chosen {
    ElementRangeFn fn = nullptr;
    int width = 4;
  };
  static const Chosen chosen = [] {
    Chosen c;
    c.fn = element_kernel(nullptr, &c.width);
    return c;
  }();
  const ElementRangeFn kernel = chosen.fn;
  const int kBlock = chosen.width;
  // Blocks of four (eight: avx512) elements: every element's result is
  // independent of the block it falls in and of the thread that runs it.
  const int nb = (ne + kBlock - 1) / kBlock;
  int inverted = -1;
  elements_forked_ = fork_allowed_ && parallel::worth_forking(ne, parallel::kElementNs);
  // The material's ticks (make bench's split) on one thread only: forked, the
  // threads' atomic adds to one counter would bounce its cache line between
  // the cores every block (bar 8,000, 2 threads, 2026-11-29: the per-phase
  // run's element loop took 55 ns per element-cycle with them, 38.5-40.8 without),
  // and bench_phases reports a forked element loop whole anyway.
  ev.material_ticks = phases_ && !elements_forked_ ? &phases_->material_ticks : nullptr;
  // Then, in the same parallel region, the elements' energy increments and
  // smallest time step per chunk of kSumChunk elements, in order
  // (account_energies sums the chunks in order): bits independent of threads.
  const int nchunk = (ne + kSumChunk - 1) / kSumChunk;
  double* partial = elem_partial_.data();
  // The blocks in static shares, one per thread, stolen at the end
  // (fe/work_shares.hpp): the same bits whoever runs a block.
  element_shares_.reset(nb, elements_forked_ ? parallel::threads() : 1);
#pragma omp parallel if (elements_forked_)
  {
    element_shares_.run(parallel::thread_num(), [&](int b0, int b1) {
      const int r = kernel(ev, kBlock * b0, std::min(ne, kBlock * b1), kBlock);
      if (r >= 0) {
#pragma omp critical
        inverted = inverted < 0 ? r : std::min(inverted, r);
      }
    });
#pragma omp barrier
#pragma omp for schedule(static)
    for (int ch = 0; ch < nchunk; ++ch) {
      double ie = 0, eh = 0, dtmin = 1e30;
      const int end = std::min(ne, (ch + 1) * kSumChunk);
      for (int e = ch * kSumChunk; e < end; ++e) {
        ie += ie_inc_[e];
        eh += hg_inc_[e];
        dtmin = std::min(dtmin, dt_elem_[e]);
      }
      partial[3 * ch] = ie;
      partial[3 * ch + 1] = eh;
      partial[3 * ch + 2] = dtmin;
    }
  }
  if (inverted >= 0) {
    std::ostringstream os;
    os << "element " << inverted << " inverted (non-positive volume or Jacobian) at t = " << t_ << " s (cycle "
       << cycle_ << "), nodes";
    for (int a = 0; a < 8; ++a) os << " " << mesh.hex[inverted][a];
    os << ": it was crushed or turned inside out (loads too fast or too large, or a time step too large)";
    throw NumericalFault(os.str());
  }
}

}  // namespace drawbend::fe
