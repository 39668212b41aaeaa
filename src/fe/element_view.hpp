#pragma once
// The element loop's data, as plain pointers into the solver's
// structure-of-arrays state, and its entry points per instruction set.
//
// The loop is written once (fe/element_kernel.hpp) and compiled three times:
// `baseline` (the x86-64 baseline, SSE2) and, where the compiler and machine
// allow it, `avx2` (4 doubles per instruction, no FMA) and `avx512` (8 elements
// side by side, 8 doubles per instruction, no FMA).  All give the same
// bits (core/lanes.hpp says why), which tests/unit/test_element_kernel.cpp
// checks; the solver picks the widest one the CPU has.
#include <array>
#include <cstdint>

#include "fe/node_view.hpp"
#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/yld2004_plasticity.hpp"
#include "material/lanes/points_view.hpp"
#include "material/material.hpp"

namespace drawbend::fe {

/// Doubles per corner slot: fx, fy, fz [N].  (Four, with a zero, would make a
/// slot one 32-byte store in the vector kernels: no faster on the 1,600-element
/// bar than the two stores of fe/corner_slots.hpp, and 5 % slower on the
/// 64,000-element bar, whose corner buffer then outgrows the caches by a third
/// more: make bench, 2026-11-27.)
inline constexpr int kCornerStride = 3;

/// The part the materials' lane twins read and write (sig, state, ie_inc, ns,
/// spin, the bound flags and constants, dtp) is their contract,
/// material/lanes/points_view.hpp, checked below.
struct ElementView {
  const std::array<int, 8>* hex = nullptr;  ///< connectivity
  /// The nodes (Solver::node_view()); the element loop only reads their
  /// positions x, y, z [mm] and velocities vx, vy, vz [mm/s].
  NodeView nodes;
  double* sig = nullptr;         ///< 12 per element: the two integration points' stresses [MPa]
  double* state = nullptr;       ///< 2 * ns per element: the points' material states
  double* hgq = nullptr;         ///< 6 per element: hourglass generalised forces
  double* hg_ratio = nullptr;    ///< 1 per element: relaxed tangent ratio
  double* corner = nullptr;      ///< corner forces [N], kCornerStride per corner slot
  /// 8 per element: the slot of corner a of element e in `corner` (the solver's
  /// are node-major, so that the nodal sums read in order); nullptr: slot 8e + a.
  const int* corner_slot = nullptr;
  double* ie_inc = nullptr;      ///< 1 per element: internal energy increment [mJ]
  double* hg_inc = nullptr;      ///< 1 per element: hourglass energy increment [mJ]
  double* dt_elem = nullptr;     ///< 1 per element: stable time step [s]
  const double* sqrt_mass_factor = nullptr;  ///< 1 per element: sqrt of its mass scaling factor (set once)
  const material::Material* mat = nullptr;
  int ns = 0;                    ///< material state size per point
  bool spin = false;             ///< the material rotates its own state (Material::uses_spin)
  bool j2_lanes = false;         ///< mat is J2 isotropic: its update runs on the lanes (bind_lanes)
  material::J2Isotropic::LaneParams j2{};  ///< its constants, when j2_lanes
  bool combined_lanes = false;   ///< mat is CombinedPlasticity (von Mises or Hill'48): on the lanes too
  material::CombinedPlasticity::LaneParams combined{};  ///< its constants, when combined_lanes
  bool yld2004_lanes = false;    ///< mat is Yld2004Plasticity: on the lanes too
  material::Yld2004Plasticity::LaneParams yld2004{};  ///< its constants, when yld2004_lanes
  double E0 = 0, G0 = 0;         ///< elastic moduli [MPa]
  double hourglass = 0;          ///< hourglass stiffness scale
  double c_elastic = 0;          ///< nu / (1 - nu)
  double dtp = 0;                ///< length of the interval the velocities act over [s]
  double wave_speed = 0;         ///< dilatational wave speed [mm/s]
  /// When set (make bench's per-phase split, fe/phase_times.hpp): += the
  /// time-stamp-counter ticks spent in the material updates (atomic, per block).
  std::uint64_t* material_ticks = nullptr;
};

static_assert(material::lanes::is_points_view<ElementView>(), "the lane twins' view (material/lanes/points_view.hpp)");

/// Process elements [begin, end), `width` (1, 4, or 8 in the avx512 kernel)
/// side by side and the rest one by one.  Returns the lowest inverted element in the range, or -1.
using ElementRangeFn = int (*)(const ElementView&, int begin, int end, int width);

namespace baseline {
int element_range(const ElementView& v, int begin, int end, int width);
}
namespace avx2 {
int element_range(const ElementView& v, int begin, int end, int width);
}
namespace avx512 {
int element_range(const ElementView& v, int begin, int end, int width);
}

/// Sets v.j2_lanes, v.j2, v.combined_lanes, v.combined, v.yld2004_lanes and v.yld2004 from v.mat: the lane
/// version of its update where it has one (J2 isotropic, CombinedPlasticity, Yld2004Plasticity:
/// the material says so through Material::bind_lanes, material/lane_binding.hpp),
/// else the scalar one.  Call after setting v.mat.
void bind_lanes(ElementView& v);

/// The widest kernel this build and this CPU can run ("avx512", "avx2" or
/// "baseline"), unless DRAWBEND_ISA names a narrower one; `width`: the
/// elements it takes side by side (8, 4, 4).
ElementRangeFn element_kernel(const char** name = nullptr, int* width = nullptr);
/// Whether this build has the avx2 (avx512) kernel and the CPU runs it.
bool avx2_kernel_available();
bool avx512_kernel_available();

}  // namespace drawbend::fe
