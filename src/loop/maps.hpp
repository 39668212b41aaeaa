#pragma once
// Frictionless (rotating-pin) pressure maps per pin diameter, for the new
// method inside the loop (thesis Ch. 4).  Two sources, one interface:
//
//  * FE maps: a directory with files pin_<diameter>mm.csv (e.g. pin_12.7mm.csv),
//    each a contact-map CSV of our solver (columns node,x_mm,y_mm,z_mm,surface,
//    u_tool,v_tool_mm,pressure_MPa,area_mm2,normal_force_N,...; '#' comments).
//    They are half-model maps: areas are doubled so that sum(p A) is a
//    full-strip normal force.  The back tension the map was computed at must be
//    stated in a comment line "# reference_back_tension_N: <full-strip N>"
//    (or in a sidecar file pin_<d>mm.ref holding that one number).
//  * the analytic stand-in ("analytic stand-in, not FE"): a uniform belt
//    pressure T/(R w) (Eq. 2.2 with F_x = F_y = T) plus an exponential edge peak
//    at entry and exit that carries the bending moment (peak force M_p/delta
//    over delta = sqrt(R t), M_p = sigma_y t^2 w / 4).
//
// The loop scales a map to another back tension with the mean strip tension of
// Eq. 2.2 (model.hpp: map_pressure), not with the back tension alone.
// weighted_pressure(F) below is the plain back-tension scaling, kept for
// tables.  Units: MPa, mm^2, N, mm.
#include <string>
#include <vector>

#include "analysis/new_method.hpp"

namespace drawbend::loop {

struct PinMap {
  double pin_d_mm = 0;
  double fref_N = 0;            ///< full-strip back tension of the map
  double fbend_N = -1;          ///< full-strip bending force of the FE run (comment '# bending_force_N: N'); < 0 absent
  analysis::PressureMap map;    ///< full-strip areas
  std::string provenance;
  double S1 = 0, S2 = 0;        ///< moments sum(p A), sum(p^2 A) at fref
  /// Normal-force-weighted mean pressure sum(p^2 A)/sum(p A) at back tension F [MPa].
  double weighted_pressure(double F) const { return S2 / S1 * F / fref_N; }
};

struct StandInParams {
  double thickness_mm = 1.04;   ///< Sec. 5.2
  double width_mm = 25.4;       ///< strip width, Sec. 5.2
  double sigma_y_MPa = 99.71;   ///< Table 5.1 RD 0.2 % proof stress
  double fref_N = 1500;         ///< reference full-strip back tension
  double wrap_rad = 1.5707963267948966;
  int nodes = 90;               ///< nodes along the wrap
};

class MapLibrary {
 public:
  /// Load every pin_<d>mm.csv of a directory; throws InputError naming the file.
  static MapLibrary load_dir(const std::string& dir);
  /// Analytic stand-in maps for the given pin diameters.
  static MapLibrary stand_in(const std::vector<double>& pins_mm, const StandInParams& p = {});

  bool has(double pin_d_mm) const;
  const PinMap& at(double pin_d_mm) const;  ///< throws InputError when missing
  const std::vector<PinMap>& maps() const { return maps_; }
  bool is_stand_in() const { return stand_in_; }
  std::string label() const;  ///< e.g. "analytic stand-in, not FE" or "FE maps from DIR"

 private:
  std::vector<PinMap> maps_;
  bool stand_in_ = false;
  std::string source_;
};

/// One stand-in map (exposed for tests).
PinMap stand_in_map(double pin_d_mm, const StandInParams& p);

}  // namespace drawbend::loop
