#pragma once
// Which lane twin (the element kernel's vector version of a material's
// update, material/lanes/j2_lanes.hpp, combined_lanes.hpp and yld2004_lanes.hpp) a material
// has, with its constants: filled by Material::bind_lanes(), read by
// fe::bind_lanes() (fe/element_forces.cpp).  A model with a new lane twin
// adds its flag and constants here and overrides bind_lanes().
#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/yld2004_plasticity.hpp"

namespace drawbend::material {

struct LaneBinding {
  bool j2 = false;  ///< J2 isotropic on the lanes
  J2Isotropic::LaneParams j2_params{};
  bool combined = false;  ///< CombinedPlasticity (von Mises or Hill'48) on the lanes
  CombinedPlasticity::LaneParams combined_params{};
  bool yld2004 = false;  ///< Yld2004Plasticity on the lanes (material/lanes/yld2004_lanes.hpp)
  Yld2004Plasticity::LaneParams yld2004_params{};
};

}  // namespace drawbend::material
