// Yld2004-18p plasticity on the element kernel's lanes (material/lanes/
// yld2004_lanes.hpp, yld2004_function_lanes.hpp) against its scalar update
// (material/yld2004_plasticity.cpp), which the kernel runs one element at a
// time (width 1).
// Answers (exact: the lanes must give the scalar bits, nothing less):
//  - For the set fitted to the ESAFORM 2021 tests (a = 8) and for the
//    isotropic set (all coefficients 1, a = 8), each with isotropic hardening,
//    the split form and two Chaboche terms: 40 cubes, each strained
//    homogeneously along one path in the sheet axes (x = RD, z = ND) -
//    equibiaxial, plane strain along RD and along TD, pure shear in the sheet
//    plane, uniaxial along RD - or along a random velocity field with spin,
//    at rates from well inside the yield surface to increments of several
//    times the yield strain, blocks of four and eight mixing the paths, for
//    four cycles and then four with every velocity reversed.  Where the CPU
//    has them, the AVX2 kernel (four side by side) and the AVX-512 kernel
//    (eight and four) give the bits of one element at a time in every output (stresses, states, hourglass forces and
//    ratios, corner forces, energy increments, stable steps) after both
//    phases, and the same return counts (plastic, split, fallback updates);
//    so does the baseline kernel four side by side, which runs this model
//    point by point (fe/element_kernel.hpp says why).
//  - Coverage, from the scalar run: elastic and plastic points in both
//    phases; with the isotropic set, equibiaxial points whose transformed
//    deviator has two principal values closer than the yield function's 1e-5
//    (the divided differences' midpoint branch); returns that the lanes hand
//    back to the scalar update (split into sub-increments) where the rates
//    are largest.
#define BOOST_TEST_MODULE yld2004_lanes
#include <boost/test/unit_test.hpp>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "element_arrays.hpp"
#include "fe/element_view.hpp"
#include "material/hardening_curve.hpp"
#include "material/sheet_frame.hpp"
#include "material/yld2004.hpp"
#include "material/yld2004_plasticity.hpp"

using namespace drawbend;
using namespace drawbend::fe;

namespace {
constexpr int kNe = 40, kPaths = 6;

/// 40 cubes of 1 mm with their own nodes; element e follows path e % 6 at rate scale(e).
struct Cubes : testing::ElementArrays {
  const material::Material& mat;

  static double scale(int e) {
    const double s[5] = {0.02, 1.0, 4.0, 0.3, 40.0};  // 0.02: elastic; 40: increments of several yield strains
    return s[(e / kPaths) % 5];
  }
  explicit Cubes(const material::Material& m) : mat(m) {
    std::mt19937 rng(54);
    std::uniform_real_distribution<double> u(-1, 1);
    const double corner_xyz[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (int e = 0; e < kNe; ++e) {
      // The velocity gradient L (1/s) of the path; v = L x at each node.
      const double r = 20.0 * scale(e);
      double L[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      switch (e % kPaths) {
        case 0: L[0][0] = r, L[1][1] = r, L[2][2] = -2 * r; break;  // equibiaxial
        case 1: L[0][0] = r, L[2][2] = -r; break;                    // plane strain along RD
        case 2: L[1][1] = r, L[2][2] = -r; break;                    // plane strain along TD
        case 3: L[0][1] = r, L[1][0] = r; break;                     // pure shear in the sheet plane
        case 4: L[0][0] = r, L[1][1] = -0.5 * r, L[2][2] = -0.5 * r; break;  // uniaxial along RD
        default:
          for (auto& row : L)
            for (double& v : row) v = r * u(rng);  // random, with spin
      }
      std::array<int, 8> c;
      for (int a = 0; a < 8; ++a) {
        c[a] = 8 * e + a;
        const double p[3] = {corner_xyz[a][0] + 2.0 * e, corner_xyz[a][1], corner_xyz[a][2]};
        const double q[3] = {corner_xyz[a][0], corner_xyz[a][1], corner_xyz[a][2]};  // relative to the cube
        x.push_back(p[0]), y.push_back(p[1]), z.push_back(p[2]);
        vx.push_back(L[0][0] * q[0] + L[0][1] * q[1] + L[0][2] * q[2]);
        vy.push_back(L[1][0] * q[0] + L[1][1] * q[1] + L[1][2] * q[2]);
        vz.push_back(L[2][0] * q[0] + L[2][1] * q[1] + L[2][2] * q[2]);
      }
      hex.push_back(c);
    }
    sig.assign(12 * kNe, 0.0);
    const int ns = mat.state_size();
    state.assign(static_cast<std::size_t>(2 * kNe * ns), 0.0);
    const material::SheetAxes axes = material::sheet_axes({1.0, 0.0, 0.0}, {0.0, 0.0, 1.0});
    for (int k = 0; k < 2 * kNe; ++k) {
      mat.init_state(&state[static_cast<std::size_t>(k) * ns], axes);
      if (k % 3 == 1) state[static_cast<std::size_t>(k) * ns] = 0.05;  // some points prestrained
    }
    hgq.assign(6 * kNe, 0.0);
    ratio.assign(kNe, 1.0);
    corner.assign(8 * kCornerStride * kNe, 0.0);
    ie.assign(kNe, 0.0);
    hg.assign(kNe, 0.0);
    dt.assign(kNe, 0.0);
    mf.assign(kNe, 1.0);
  }
  ElementView view() { return view_of(mat, 2e-5); }
};

struct Run {
  std::vector<double> fresh, out;  // states before; outputs after 4 cycles, then after 4 reversed
  material::Yld2004Plasticity::ReturnCounts counts;
};

/// A fresh model (its own counters) from `make`, run with f at `width`.
template <class Make>
Run run(ElementRangeFn f, int width, Make&& make) {
  const std::unique_ptr<material::Yld2004Plasticity> m = make();
  Cubes b(*m);
  Run r;
  r.fresh = b.state;
  const ElementView v = b.view();
  BOOST_REQUIRE(v.yld2004_lanes);
  for (int c = 0; c < 4; ++c) BOOST_REQUIRE(f(v, 0, kNe, width) == -1);
  r.out = b.outputs();
  for (auto* a : {&b.vx, &b.vy, &b.vz})
    for (double& s : *a) s = -s;
  for (int c = 0; c < 4; ++c) BOOST_REQUIRE(f(v, 0, kNe, width) == -1);
  const std::vector<double> second = b.outputs();
  r.out.insert(r.out.end(), second.begin(), second.end());
  r.counts = m->return_counts();
  return r;
}

bool same(const Run& a, const Run& b) {
  if (a.out.size() != b.out.size()) return false;
  for (std::size_t i = 0; i < a.out.size(); ++i)
    if (std::memcmp(&a.out[i], &b.out[i], sizeof(double)) != 0) return false;
  return a.counts.plastic == b.counts.plastic && a.counts.split == b.counts.split &&
         a.counts.fallback == b.counts.fallback;
}

material::Yld2004 fitted() {  // bench/bench_material.cpp's: the ESAFORM 2021 fit (c44 = c55 = 1)
  material::Yld2004 y;
  y.a = 8;
  y.c1 = {1.0059518, 1.1865517, 0.0087202487, 0.75613553, 1.1445682, 0.84840891, 1, 1, 0.17885443};
  y.c2 = {0.87834346, 1.1811921, 1.0479014, 1.2886127, 0.036486783, 1.5701502, 1, 1, 1.5886608};
  return y;
}
}  // namespace

BOOST_AUTO_TEST_CASE(yld2004_on_lanes_gives_the_scalar_bits_on_every_path) {
  const material::HardeningCurve curve({0, 0.001, 0.002, 0.004, 0.1, 1}, {100, 120, 130, 150, 200, 300});
  material::KinematicHardening none, split, chab;
  split.beta = 0.3;
  chab.chaboche = {{6000.0, 60.0}, {800.0, 5.0}};
  bool midpoint_seen = false, handed_back = false;
  for (const bool iso : {false, true})
    for (const auto* kin : {&none, &split, &chab}) {
      const std::string name = std::string(iso ? "isotropic set" : "fitted set") +
                               (kin == &none ? ", isotropic hardening" : kin == &split ? ", split" : ", Chaboche x2");
      BOOST_TEST_CONTEXT(name) {
        auto make = [&] {
          return std::make_unique<material::Yld2004Plasticity>(70000, 0.33, 2.7e-9, curve, *kin,
                                                                iso ? material::Yld2004::isotropic(8) : fitted());
        };
        const Run one = run(&baseline::element_range, 1, make);
        // Coverage from the scalar run.
        const int ns = make()->state_size();
        const std::size_t half = one.out.size() / 2, st0 = 12 * kNe;
        int elastic[2] = {0, 0}, plastic[2] = {0, 0}, close = 0;
        for (int i = 0; i < 2 * kNe; ++i) {
          const double e0 = one.fresh[static_cast<std::size_t>(i) * ns];
          const double e1 = one.out[st0 + static_cast<std::size_t>(i) * ns];
          const double e2 = one.out[half + st0 + static_cast<std::size_t>(i) * ns];
          (e1 != e0 ? plastic[0] : elastic[0]) += 1;
          (e2 != e1 ? plastic[1] : elastic[1]) += 1;
          if (iso && (i / 2) % kPaths == 0) {  // equibiaxial: C' = C'' = identity, X = dev(sigma) (axes = x, y, z)
            const double* s = &one.out[6 * static_cast<std::size_t>(i)];
            const double m = (s[0] + s[1] + s[2]) / 3.0;
            const double dev[6] = {s[0] - m, s[1] - m, s[2] - m, s[3], s[4], s[5]};
            double lam[3];
            material::sym_eigenvalues(dev, lam);
            const double big = std::max(std::abs(lam[0]), std::abs(lam[2]));
            if (big > 0 && (lam[0] - lam[1] <= 1e-5 * big || lam[1] - lam[2] <= 1e-5 * big)) ++close;
          }
        }
        BOOST_TEST_MESSAGE(name << ": elastic/plastic points " << elastic[0] << "/" << plastic[0] << ", reversed "
                                << elastic[1] << "/" << plastic[1] << "; coincident principal values " << close
                                << "; updates plastic " << one.counts.plastic << ", split " << one.counts.split
                                << ", fallback " << one.counts.fallback);
        BOOST_TEST(elastic[0] > 0);
        BOOST_TEST(plastic[0] > 0);
        BOOST_TEST(elastic[1] > 0);
        BOOST_TEST(plastic[1] > 0);
        midpoint_seen = midpoint_seen || close > 0;
        handed_back = handed_back || one.counts.split > 0;
        BOOST_TEST(same(one, run(&baseline::element_range, 4, make)));
#ifdef DRAWBEND_HAVE_AVX2_KERNEL
        if (avx2_kernel_available()) {
          BOOST_TEST(same(one, run(&avx2::element_range, 4, make)));
        } else {
          BOOST_TEST_MESSAGE("this CPU has no AVX2: the avx2 kernel not checked");
        }
#endif
#ifdef DRAWBEND_HAVE_AVX512_KERNEL
        if (avx512_kernel_available()) {
          BOOST_TEST(same(one, run(&avx512::element_range, 8, make)));
          BOOST_TEST(same(one, run(&avx512::element_range, 4, make)));
        } else {
          BOOST_TEST_MESSAGE("this CPU has no AVX-512F: the avx512 kernel not checked");
        }
#endif
      }
    }
  BOOST_TEST(midpoint_seen);
  BOOST_TEST(handed_back);
}
