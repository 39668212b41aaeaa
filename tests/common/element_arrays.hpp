#pragma once
// The element loop's records for a test block of elements, solver-like
// arrays behind an fe::ElementView (fe/element_view.hpp): the fixtures of
// tests/unit/test_element_kernel.cpp and test_yld2004_lanes.cpp build their
// elements into these and compare outputs() bit for bit.
#include <array>
#include <vector>

#include "fe/element_view.hpp"
#include "material/material.hpp"

namespace drawbend::testing {

struct ElementArrays {
  std::vector<std::array<int, 8>> hex;
  std::vector<double> x, y, z, vx, vy, vz, sig, state, hgq, ratio, corner, ie, hg, dt, mf;

  /// The view of these arrays for material `mat` (its lane twin bound, fe::bind_lanes), with the
  /// velocities acting over dtp [s]; hourglass scale 0.1 and nu = 0.33's elastic ratio.
  fe::ElementView view_of(const material::Material& mat, double dtp) {
    fe::ElementView v;
    v.hex = hex.data();
    v.nodes.n = static_cast<int>(x.size());
    v.nodes.x = x.data(), v.nodes.y = y.data(), v.nodes.z = z.data();
    v.nodes.vx = vx.data(), v.nodes.vy = vy.data(), v.nodes.vz = vz.data();
    v.sig = sig.data(), v.state = state.data(), v.hgq = hgq.data(), v.hg_ratio = ratio.data();
    v.corner = corner.data(), v.ie_inc = ie.data(), v.hg_inc = hg.data(), v.dt_elem = dt.data();
    v.sqrt_mass_factor = mf.data();
    v.mat = &mat;
    v.ns = mat.state_size();
    v.spin = mat.uses_spin();
    v.E0 = mat.youngs_modulus(), v.G0 = mat.shear_modulus();
    v.hourglass = 0.1;
    v.c_elastic = 0.33 / 0.67;
    v.dtp = dtp;
    v.wave_speed = mat.wave_speed();
    fe::bind_lanes(v);
    return v;
  }
  /// Everything the kernel writes, for bitwise comparison.
  std::vector<double> outputs() const {
    std::vector<double> o;
    for (const auto* a : {&sig, &state, &hgq, &ratio, &corner, &ie, &hg, &dt}) o.insert(o.end(), a->begin(), a->end());
    return o;
  }
};

}  // namespace drawbend::testing
