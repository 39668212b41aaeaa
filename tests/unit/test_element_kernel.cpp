// The element kernel on vector lanes (fe/element_kernel.hpp, core/lanes.hpp).
// Answers:
//  - Bit-identity: on 11 distorted, spinning, plastically loaded elements, three
//    cycles of the kernel four elements side by side (baseline and, where the
//    CPU has it, AVX2; eight and four on AVX-512) give exactly the bits of one
//    element at a time: corner
//    forces, stresses, material states, hourglass forces and ratios, energy
//    increments and stable time steps; for J2 isotropic and for Hill'48 with a
//    Chaboche back stress (whose state holds back stresses and axes that turn
//    with the spin).  Every per-element record (stresses, states, hourglass
//    forces, ratio, energies, steps) passes through the lanes' record
//    transposes (core/lane_records.hpp: 1, 2, 6 and 12 values per element), so a
//    misplaced value there fails this comparison.
//  - J2 on the lanes (material/lanes/j2_lanes.hpp): a block mixing elastic points,
//    points below the initial yield stress, plastic points and points whose
//    increment crosses several curve points gives the scalar bits.
//  - Combined hardening on the lanes (material/lanes/combined_lanes.hpp): for von Mises
//    and Hill'48 with isotropic, split and two-term Chaboche hardening, a block
//    mixing elastic and plastic points, loaded for three cycles and then
//    reversed for three (Bauschinger re-yielding the other way), gives the
//    scalar bits after both phases (every output, as above).
//  - An inverted element (here no. 5, of a block of four) is reported, and the
//    other elements of its block come out as if computed one by one.
//  - Closed form: a rigid translation of an unstressed element gives zero
//    stress, zero corner forces and zero energy increments.
#define BOOST_TEST_MODULE element_kernel
#include <boost/test/unit_test.hpp>
#include <array>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "element_arrays.hpp"
#include "fe/element_view.hpp"
#include "material/hardening_curve.hpp"
#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/sheet_frame.hpp"

using namespace drawbend;
using namespace drawbend::fe;

namespace {
/// Independent elements (8 own nodes each) with their solver-like arrays.
struct Block : testing::ElementArrays {
  int ne;
  material::J2Isotropic j2{70000, 0.33, 2.7e-9, material::HardeningCurve({0, 0.1, 1}, {100, 200, 300})};
  material::CombinedPlasticity hill{70000,
                                    0.33,
                                    2.7e-9,
                                    material::HardeningCurve({0, 0.1, 1}, {100, 200, 300}),
                                    material::KinematicHardening{{{5000.0, 40.0}}, 0.0},
                                    material::Hill48::from_r_values(0.65, 0.65, 0.72)};
  // Curve points close together: one increment crosses several of them.
  material::J2Isotropic j2_fine{70000, 0.33, 2.7e-9,
                                material::HardeningCurve({0, 0.001, 0.002, 0.004, 0.1, 1}, {100, 120, 130, 150, 200, 300})};
  const material::Material& mat;

  /// `other`: a material of the caller's instead of j2, hill or j2_fine.
  /// `row`: the elements share nodes in one row, numbered as a structured
  /// block (fe/mesh.cpp): element e + l has node n + l at each corner, the
  /// kernels' one-load gather.
  Block(int n, unsigned seed, bool anisotropic = false, bool fine = false, const material::Material* other = nullptr,
        bool row = false)
      : ne(n),
        mat(other ? *other
                  : anisotropic ? static_cast<const material::Material&>(hill)
                                : fine ? static_cast<const material::Material&>(j2_fine) : j2) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const double base[8][3] = {{0, 0, 0},  {2, 0, 0},  {2, 1, 0},  {0, 1, 0},
                               {0, 0, .5}, {2, 0, .5}, {2, 1, .5}, {0, 1, .5}};
    if (row) {
      const int nx = n + 1;
      auto id = [&](int i, int j, int k) { return i + nx * (j + 2 * k); };
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < nx; ++i) {
            x.push_back(2.0 * i + 0.1 * u(rng));
            y.push_back(j + 0.1 * u(rng));
            z.push_back(0.5 * k + 0.05 * u(rng));
            vx.push_back(500 * u(rng) + 150 * k);  // shear and spin: Jaumann terms matter
            vy.push_back(500 * u(rng));
            vz.push_back(500 * u(rng) - 150 * i);
          }
      for (int e = 0; e < n; ++e)
        hex.push_back({id(e, 0, 0), id(e + 1, 0, 0), id(e + 1, 1, 0), id(e, 1, 0), id(e, 0, 1), id(e + 1, 0, 1),
                       id(e + 1, 1, 1), id(e, 1, 1)});
    }
    for (int e = 0; e < n && !row; ++e) {
      std::array<int, 8> c;
      for (int a = 0; a < 8; ++a) {
        c[a] = 8 * e + a;
        x.push_back(base[a][0] + 0.1 * u(rng) + 3 * e);
        y.push_back(base[a][1] + 0.1 * u(rng));
        z.push_back(base[a][2] + 0.05 * u(rng));
        vx.push_back(500 * u(rng) + 300 * base[a][2]);  // shear and spin: Jaumann terms matter
        vy.push_back(500 * u(rng));
        vz.push_back(500 * u(rng) - 300 * base[a][0]);
      }
      hex.push_back(c);
    }
    sig.resize(12 * n);
    for (double& s : sig) s = 60 * u(rng);
    const int ns = mat.state_size();
    state.assign(static_cast<std::size_t>(2 * n * ns), 0.0);
    const material::SheetAxes axes = material::sheet_axes({0.8660254, 0.5, 0.0}, {0.0, 0.0, 1.0});
    for (int k = 0; k < 2 * n; ++k) {
      mat.init_state(&state[static_cast<std::size_t>(k) * ns], axes);
      state[static_cast<std::size_t>(k) * ns] = 0.05 * (1 + u(rng));  // eps_p
    }
    hgq.resize(6 * n);
    for (double& q : hgq) q = 0.1 * u(rng);
    ratio.assign(n, 1.0);
    corner.assign(8 * kCornerStride * n, 0.0);
    ie.assign(n, 0.0);
    hg.assign(n, 0.0);
    dt.assign(n, 0.0);
    mf.assign(n, 10.0);  // sqrt of a mass factor of 100
  }
  ElementView view() { return view_of(mat, 1e-4); }
};

std::vector<double> run(ElementRangeFn f, int width, int cycles, int* inverted = nullptr, bool invert5 = false,
                        bool anisotropic = false) {
  Block b(11, 7, anisotropic);
  if (invert5)  // bottom and top faces swapped: a mirrored, negative-volume element
    for (int a = 0; a < 4; ++a) std::swap(b.hex[5][a], b.hex[5][a + 4]);
  const ElementView v = b.view();
  for (int c = 0; c < cycles; ++c) {
    const int r = f(v, 0, b.ne, width);
    if (inverted) *inverted = r;
  }
  return b.outputs();
}

/// J2 on the lanes with every branch of the radial return in one block: 37
/// elements (blocks of 8 and 4 and single ones), some barely moving (elastic,
/// some below the initial yield stress), some loaded hard (plastic, crossing
/// several points of j2_fine's curve in one increment), some starting exactly
/// on a curve point.  `fresh`: the state before, for the coverage checks.
std::vector<double> run_mixed(ElementRangeFn f, int width, std::vector<double>* fresh = nullptr) {
  Block b(37, 11, false, true);
  for (int e = 0; e < b.ne; ++e) {
    const double scale = e % 3 == 0 ? 0.01 : e % 3 == 1 ? 8.0 : 1.0;
    for (int a = 0; a < 8; ++a) b.vx[8 * e + a] *= scale, b.vy[8 * e + a] *= scale, b.vz[8 * e + a] *= scale;
    if (e % 3 == 0)
      for (int k = 0; k < 12; ++k) b.sig[12 * e + k] *= 0.2;  // well inside the initial yield surface
    if (e % 5 == 0) b.state[2 * e] = b.state[2 * e + 1] = 0.002;  // on a curve point
    if (e % 7 == 0) b.state[2 * e] = 0.0;                          // virgin
  }
  if (fresh) *fresh = b.state;
  const ElementView v = b.view();
  for (int c = 0; c < 3; ++c) f(v, 0, b.ne, width);
  return b.outputs();
}

/// The combined-hardening models on the lanes (material/lanes/combined_lanes.hpp), each
/// on j2_fine's curve: von Mises with the split form, with two Chaboche terms
/// and with isotropic hardening only (no spin: nothing to turn), and Hill'48
/// with isotropic hardening, the split form and two Chaboche terms.
std::vector<std::pair<std::string, std::unique_ptr<material::CombinedPlasticity>>> combined_models() {
  const material::HardeningCurve curve({0, 0.001, 0.002, 0.004, 0.1, 1}, {100, 120, 130, 150, 200, 300});
  const material::Hill48 hill = material::Hill48::from_r_values(0.65, 0.65, 0.72);
  material::KinematicHardening split, chab, none;
  split.beta = 0.3;
  chab.chaboche = {{6000.0, 60.0}, {800.0, 5.0}};
  std::vector<std::pair<std::string, std::unique_ptr<material::CombinedPlasticity>>> m;
  auto add = [&](const char* name, const material::KinematicHardening& k, const material::Hill48& h) {
    m.emplace_back(name, std::make_unique<material::CombinedPlasticity>(70000, 0.33, 2.7e-9, curve, k, h));
  };
  add("von Mises, split", split, material::Hill48::von_mises());
  add("von Mises, Chaboche x2", chab, material::Hill48::von_mises());
  add("von Mises, isotropic", none, material::Hill48::von_mises());
  add("Hill'48, isotropic", none, hill);
  add("Hill'48, split", split, hill);
  add("Hill'48, Chaboche x2", chab, hill);
  return m;
}

/// A combined model with every branch in one block and a reversal: 37
/// elements loaded as in run_mixed() for three cycles (after a first one with
/// dtp = 0, as the solver's), then with every velocity reversed for three more.  Returns the outputs after the third
/// cycle followed by those after the sixth; `fresh`: the state before.
std::vector<double> run_reversal(ElementRangeFn f, int width, const material::Material& m,
                                 std::vector<double>* fresh = nullptr) {
  Block b(37, 13, false, false, &m);
  const int ns = m.state_size();
  for (int e = 0; e < b.ne; ++e) {
    const double scale = e % 3 == 0 ? 0.01 : e % 3 == 1 ? 8.0 : 1.0;
    for (int a = 0; a < 8; ++a) b.vx[8 * e + a] *= scale, b.vy[8 * e + a] *= scale, b.vz[8 * e + a] *= scale;
    if (e % 3 == 0)
      for (int k = 0; k < 12; ++k) b.sig[12 * e + k] *= 0.2;  // well inside the initial yield surface
    for (int gp = 0; gp < 2; ++gp) {
      double& ep = b.state[static_cast<std::size_t>(2 * e + gp) * ns];
      if (e % 5 == 0) ep = 0.002;  // on a curve point
      if (e % 7 == 0) ep = 0.0;    // virgin
    }
  }
  if (fresh) *fresh = b.state;
  const ElementView v = b.view();
  ElementView first = v;  // the solver's first cycle: no interval yet, so no strain and no turn
  first.dtp = 0.0;
  f(first, 0, b.ne, width);
  for (int c = 0; c < 3; ++c) f(v, 0, b.ne, width);
  std::vector<double> out = b.outputs();
  for (auto* a : {&b.vx, &b.vy, &b.vz})
    for (double& x : *a) x = -x;
  for (int c = 0; c < 3; ++c) f(v, 0, b.ne, width);
  const std::vector<double> second = b.outputs();
  out.insert(out.end(), second.begin(), second.end());
  return out;
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(double)) != 0) return false;
  return true;
}
}  // namespace

BOOST_AUTO_TEST_CASE(lanes_give_the_bits_of_one_element_at_a_time) {
  const auto one = run(&baseline::element_range, 1, 3);
  // The load is plastic: some material state moved.
  Block fresh(11, 7);
  bool yielded = false;
  // The outputs are sig (12 per element), then the material states.
  for (std::size_t i = 0; i < fresh.state.size(); ++i) yielded = yielded || one[12 * 11 + i] != fresh.state[i];
  BOOST_TEST(yielded);
  BOOST_TEST(bitwise_equal(one, run(&baseline::element_range, 4, 3)));
#ifdef DRAWBEND_HAVE_AVX2_KERNEL
  if (avx2_kernel_available()) {
    BOOST_TEST(bitwise_equal(one, run(&avx2::element_range, 4, 3)));
    BOOST_TEST(bitwise_equal(one, run(&avx2::element_range, 1, 3)));
  } else {
    BOOST_TEST_MESSAGE("this CPU has no AVX2: only the baseline kernel checked");
  }
#endif
#ifdef DRAWBEND_HAVE_AVX512_KERNEL
  if (avx512_kernel_available()) {
    BOOST_TEST(bitwise_equal(one, run(&avx512::element_range, 8, 3)));
    BOOST_TEST(bitwise_equal(one, run(&avx512::element_range, 4, 3)));
    BOOST_TEST(bitwise_equal(one, run(&avx512::element_range, 1, 3)));
  } else {
    BOOST_TEST_MESSAGE("this CPU has no AVX-512F: the avx512 kernel not checked");
  }
#endif
}

/// Elements sharing nodes in a row, as a structured block numbers them: the
/// kernels gather each corner's W nodes with one load where they run on with
/// the lanes (elements 0-7, 8-15 of 21), and one by one where they do not
/// (element 11's corners renumbered, turned about its normal: the same
/// element, so block 8-15 takes the per-lane gather).  Answer: the bits of
/// the scalar kernel, every output, after three cycles.
BOOST_AUTO_TEST_CASE(lanes_gather_rows_of_shared_nodes_with_the_bits_of_one_element_at_a_time) {
  auto rows = [](ElementRangeFn f, int width, bool turned) {
    Block b(21, 5, false, false, nullptr, true);
    if (turned) {
      const std::array<int, 8> h = b.hex[11];
      b.hex[11] = {h[1], h[2], h[3], h[0], h[5], h[6], h[7], h[4]};
    }
    const ElementView v = b.view();
    for (int c = 0; c < 3; ++c) BOOST_TEST(f(v, 0, b.ne, width) == -1);
    return b.outputs();
  };
  for (const bool turned : {false, true}) {
    const auto one = rows(&baseline::element_range, 1, turned);
    BOOST_TEST(bitwise_equal(one, rows(&baseline::element_range, 4, turned)));
#ifdef DRAWBEND_HAVE_AVX2_KERNEL
    if (avx2_kernel_available()) BOOST_TEST(bitwise_equal(one, rows(&avx2::element_range, 4, turned)));
#endif
#ifdef DRAWBEND_HAVE_AVX512_KERNEL
    if (avx512_kernel_available()) {
      BOOST_TEST(bitwise_equal(one, rows(&avx512::element_range, 8, turned)));
      BOOST_TEST(bitwise_equal(one, rows(&avx512::element_range, 4, turned)));
    }
#endif
  }
}

BOOST_AUTO_TEST_CASE(lanes_give_the_bits_of_one_element_at_a_time_hill48_chaboche) {
  const auto one = run(&baseline::element_range, 1, 3, nullptr, false, true);
  Block fresh(11, 7, true);
  bool yielded = false;
  for (std::size_t i = 0; i < fresh.state.size(); ++i) yielded = yielded || one[12 * 11 + i] != fresh.state[i];
  BOOST_TEST(yielded);
  BOOST_TEST(bitwise_equal(one, run(&baseline::element_range, 4, 3, nullptr, false, true)));
#ifdef DRAWBEND_HAVE_AVX2_KERNEL
  if (avx2_kernel_available()) {
    BOOST_TEST(bitwise_equal(one, run(&avx2::element_range, 4, 3, nullptr, false, true)));
    BOOST_TEST(bitwise_equal(one, run(&avx2::element_range, 1, 3, nullptr, false, true)));
  }
#endif
#ifdef DRAWBEND_HAVE_AVX512_KERNEL
  if (avx512_kernel_available()) {
    BOOST_TEST(bitwise_equal(one, run(&avx512::element_range, 8, 3, nullptr, false, true)));
    BOOST_TEST(bitwise_equal(one, run(&avx512::element_range, 4, 3, nullptr, false, true)));
  }
#endif
}

BOOST_AUTO_TEST_CASE(j2_on_lanes_every_branch_gives_the_scalar_bits) {
  std::vector<double> fresh;
  const auto one = run_mixed(&baseline::element_range, 1, &fresh);
  // Coverage: some points stayed elastic, some yielded, some crossed two or more curve points.
  const int ne = 37;
  int elastic = 0, plastic = 0, crossed = 0;
  const std::vector<double> pts = {0, 0.001, 0.002, 0.004, 0.1, 1};
  auto segment = [&](double ep) {
    int k = 0;
    while (k + 1 < static_cast<int>(pts.size()) && ep >= pts[k + 1]) ++k;
    return k;
  };
  for (int i = 0; i < 2 * ne; ++i) {
    const double before = fresh[i], after = one[12 * ne + i];
    if (after == before) ++elastic;
    else ++plastic;
    if (segment(after) >= segment(before) + 2) ++crossed;
  }
  BOOST_TEST_MESSAGE("points: " << elastic << " elastic, " << plastic << " plastic, " << crossed << " crossed 2+ curve points");
  BOOST_TEST(elastic > 0);
  BOOST_TEST(plastic > 0);
  BOOST_TEST(crossed > 0);
  BOOST_TEST(bitwise_equal(one, run_mixed(&baseline::element_range, 4)));
#ifdef DRAWBEND_HAVE_AVX2_KERNEL
  if (avx2_kernel_available()) BOOST_TEST(bitwise_equal(one, run_mixed(&avx2::element_range, 4)));
#endif
#ifdef DRAWBEND_HAVE_AVX512_KERNEL
  if (avx512_kernel_available()) {
    BOOST_TEST(bitwise_equal(one, run_mixed(&avx512::element_range, 8)));
    BOOST_TEST(bitwise_equal(one, run_mixed(&avx512::element_range, 4)));
  } else {
    BOOST_TEST_MESSAGE("this CPU has no AVX-512F: the avx512 kernel not checked");
  }
#endif
}

BOOST_AUTO_TEST_CASE(combined_on_lanes_every_branch_and_reversal_give_the_scalar_bits) {
  const int ne = 37;
  for (const auto& named : combined_models()) {
    const auto& name = named.first;
    const auto& m = named.second;  // not a structured binding: clang 14 cannot capture one in a lambda
    BOOST_TEST_CONTEXT(name) {
      std::vector<double> fresh;
      const auto one = run_reversal(&baseline::element_range, 1, *m, &fresh);
      // Coverage, from the scalar run: points elastic and plastic in the first
      // three cycles, blocks of four mixing both, and points that flowed in the
      // first three cycles and again, the other way, after the reversal
      // (relative stresses sigma - alpha with a negative scalar product).
      const int ns = m->state_size();
      const std::size_t half = one.size() / 2, st0 = 12 * ne;
      auto relative = [&](std::size_t at, int i, double xi[6]) {
        double alpha[6];
        m->back_stress(&one[at + st0 + static_cast<std::size_t>(i) * ns], alpha);
        for (int c = 0; c < 6; ++c) xi[c] = one[at + 6 * i + c] - alpha[c];
      };
      int elastic = 0, plastic = 0, reversed = 0, mixed_blocks = 0;
      std::vector<bool> flowed(2 * ne);
      for (int i = 0; i < 2 * ne; ++i) {
        const double ep0 = fresh[static_cast<std::size_t>(i) * ns], ep1 = one[st0 + static_cast<std::size_t>(i) * ns],
                     ep2 = one[half + st0 + static_cast<std::size_t>(i) * ns];
        flowed[i] = ep1 != ep0;
        (flowed[i] ? plastic : elastic) += 1;
        double x1[6], x2[6], dot = 0;
        relative(0, i, x1);
        relative(half, i, x2);
        for (int c = 0; c < 6; ++c) dot += x1[c] * x2[c] * (c < 3 ? 1.0 : 2.0);
        if (flowed[i] && ep2 != ep1 && dot < 0) ++reversed;
      }
      for (int e0 = 0; e0 + 4 <= ne; e0 += 4) {
        bool any_elastic = false, any_plastic = false;
        for (int i = 2 * e0; i < 2 * (e0 + 4); ++i) (flowed[i] ? any_plastic : any_elastic) = true;
        mixed_blocks += any_elastic && any_plastic;
      }
      BOOST_TEST_MESSAGE(name << ": " << elastic << " elastic, " << plastic << " plastic, " << reversed
                              << " reversed, " << mixed_blocks << " mixed blocks of 4");
      BOOST_TEST(elastic > 0);
      BOOST_TEST(plastic > 0);
      BOOST_TEST(reversed > 0);
      BOOST_TEST(mixed_blocks > 0);
      BOOST_TEST(bitwise_equal(one, run_reversal(&baseline::element_range, 4, *m)));
#ifdef DRAWBEND_HAVE_AVX2_KERNEL
      if (avx2_kernel_available()) {
        BOOST_TEST(bitwise_equal(one, run_reversal(&avx2::element_range, 4, *m)));
        BOOST_TEST(bitwise_equal(one, run_reversal(&avx2::element_range, 1, *m)));
      }
#endif
#ifdef DRAWBEND_HAVE_AVX512_KERNEL
      if (avx512_kernel_available()) {
        BOOST_TEST(bitwise_equal(one, run_reversal(&avx512::element_range, 8, *m)));
        BOOST_TEST(bitwise_equal(one, run_reversal(&avx512::element_range, 4, *m)));
      } else {
        BOOST_TEST_MESSAGE("this CPU has no AVX-512F: the avx512 kernel not checked");
      }
#endif
    }
  }
}

BOOST_AUTO_TEST_CASE(inverted_element_reported_and_block_neighbours_unchanged) {
  int r1 = -2, r4 = -2;
  const auto one = run(&baseline::element_range, 1, 1, &r1, true);
  int width = 4;
  const ElementRangeFn widest = element_kernel(nullptr, &width);
  const auto four = run(widest, 4, 1, &r4, true);
  BOOST_TEST(r1 == 5);
  BOOST_TEST(r4 == 5);
  BOOST_TEST(bitwise_equal(one, four));
  int r8 = -2;  // the widest kernel's own width (8 on AVX-512): element 5 is in the first block
  BOOST_TEST(bitwise_equal(one, run(widest, width, 1, &r8, true)));
  BOOST_TEST(r8 == 5);
}

BOOST_AUTO_TEST_CASE(rigid_translation_is_stress_free) {
  Block b(4, 3);
  for (std::size_t i = 0; i < b.vx.size(); ++i) b.vx[i] = 120.0, b.vy[i] = -40.0, b.vz[i] = 75.0;
  std::fill(b.sig.begin(), b.sig.end(), 0.0);
  std::fill(b.hgq.begin(), b.hgq.end(), 0.0);
  const ElementView v = b.view();
  BOOST_TEST(element_kernel()(v, 0, b.ne, 4) == -1);
  for (double s : b.sig) BOOST_TEST(std::abs(s) < 1e-9);      // abs_zero: round-off of O(100 mm/s x 1e-4 s / 1 mm x E)
  for (double f : b.corner) BOOST_TEST(std::abs(f) < 1e-9);
  for (double e : b.ie) BOOST_TEST(std::abs(e) < 1e-12);
}
