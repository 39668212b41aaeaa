#pragma once
// What the materials' lane twins (material/lanes/) read and write of the
// element loop's state: a view (the element kernel's fe::ElementView,
// fe/element_view.hpp) with these members, plain pointers into the solver's
// structure-of-arrays records (core/lane_records.hpp) and the bound
// material's constants:
//   double* sig       12 per element: the two integration points' stresses [MPa]
//   double* state     2 * ns per element: the points' material states
//   double* ie_inc    1 per element: internal energy increment [mJ]
//   int ns            material state size per point
//   bool spin         the material rotates its own state (Material::uses_spin)
//   bool j2_lanes, J2Isotropic::LaneParams j2                  (j2_lanes.hpp)
//   bool combined_lanes, CombinedPlasticity::LaneParams combined  (combined_lanes.hpp)
//   bool yld2004_lanes, Yld2004Plasticity::LaneParams yld2004     (yld2004_lanes.hpp)
//   double dtp        length of the interval the velocities act over [s]
// The twins take the view as a template parameter, so that no twin includes
// an fe/ header and the kernel's view keeps its own layout (the machine code
// of the kernels is that of the view's); is_points_view() checks a view's
// members and their types at compile time (fe/element_view.hpp asserts it).
#include <type_traits>

#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/yld2004_plasticity.hpp"

namespace drawbend::material::lanes {

/// True when View has the members above with their types.
template <class View>
constexpr bool is_points_view() {
  return std::is_same_v<decltype(View::sig), double*> && std::is_same_v<decltype(View::state), double*> &&
         std::is_same_v<decltype(View::ie_inc), double*> && std::is_same_v<decltype(View::ns), int> &&
         std::is_same_v<decltype(View::spin), bool> && std::is_same_v<decltype(View::j2_lanes), bool> &&
         std::is_same_v<decltype(View::j2), J2Isotropic::LaneParams> &&
         std::is_same_v<decltype(View::combined_lanes), bool> &&
         std::is_same_v<decltype(View::combined), CombinedPlasticity::LaneParams> &&
         std::is_same_v<decltype(View::yld2004_lanes), bool> &&
         std::is_same_v<decltype(View::yld2004), Yld2004Plasticity::LaneParams> &&
         std::is_same_v<decltype(View::dtp), double>;
}

}  // namespace drawbend::material::lanes
