#pragma once
// The draw-bend strip at the end of the draw, read back from the run's last
// ParaView snapshot (fields_<k>.vtu, written by io::run_case): node positions
// and element stresses, reduced to the quantities of the thesis's Figs. 2.8,
// 2.15 and 2.16 (section view of the strip, longitudinal stress and
// longitudinal plastic strain along the strip).  mm, MPa.
//
// Geometry of the builder's deck (sim/drawbend_case.hpp): the pin axis is
// the y axis, the strip lies along x on top of the pin (reference z from R to
// R + t), the wrap runs from the top of the pin (angle 0, the entry tangent
// point) to the outlet side (90 deg, the strip leaves along -z).
#include <array>
#include <string>
#include <vector>

#include "sim/drawbend_case.hpp"

namespace drawbend::sim {

/// A hexahedral mesh state as the solver wrote it.
struct StripFields {
  std::vector<std::array<double, 3>> x, x0;   ///< current and reference node positions [mm]
  std::vector<std::array<int, 8>> hex;        ///< node indices per element (VTK hexahedron order)
  std::vector<std::array<double, 6>> stress;  ///< Cauchy stress, global XX, YY, ZZ, XY, YZ, XZ [MPa]
  std::vector<double> plastic_strain;         ///< equivalent plastic strain per element
  double time = 0;                            ///< snapshot time [s]
};

/// Parse one of our own .vtu files (io/vtu.hpp, ASCII or binary): Points, connectivity,
/// PointData displacement_mm (reference = current - displacement), CellData
/// stress_MPa and plastic_strain.  Throws InputError naming the file if an
/// array is missing or its size does not match.
StripFields read_fields_vtu(const std::string& path);

/// The run's last snapshot, fields_<k>.vtu with the largest k in `run_dir`.
std::string last_fields_vtu(const std::string& run_dir);

/// One element of the strip, in the strip's own coordinates.
struct StripElement {
  double s = 0;       ///< position of the centroid along the strip from the entry tangent [mm]:
                      ///< x upstream, R_m * angle in the wrap, Lw + depth below the pin axis downstream
  double depth = 0;   ///< reference through-thickness position of the centroid, 0 = inside (pin side), 1 = outside
  double x0 = 0;      ///< reference position along the strip (centroid) [mm]: one value per column of elements
  double y0 = 0;      ///< reference position across the width (centroid) [mm]
  double ds = 0;      ///< the element's extent in s: s of its downstream end face less its upstream one [mm]
  double sigma_L = 0;  ///< longitudinal Cauchy stress e_L . sigma . e_L [MPa]
  double eps_L = 0;    ///< longitudinal log strain ln(l / l0) between the element's end-face centroids
  double eps_pL = 0;   ///< longitudinal plastic strain: eps_L - (sigma_L - nu (sigma_W + sigma_N)) / E
  double eps_p = 0;    ///< equivalent plastic strain (the solver's own)
};

/// The elements of `f` in strip coordinates, for the deck built from `s`;
/// E [MPa] and nu are the strip's elastic constants.
std::vector<StripElement> strip_elements(const StripFields& f, const DrawBendSpec& s, double E, double nu);

/// A cross-section of the strip through one plane of nodes (one reference x).
struct StripSection {
  double x0 = 0;         ///< the nodes' reference x [mm]
  double angle_deg = 0;  ///< current angle of its inside centre node round the pin (0 = entry tangent point)
  /// Per node: reference y and z, current position across the width [mm] and
  /// current radial distance from the pin surface (r - R) [mm].
  struct Node {
    double y0, z0, y, h;
  };
  std::vector<Node> nodes;
};

/// The node plane whose inside centre node lies closest to `angle_deg`.
StripSection section_at(const StripFields& f, const DrawBendSpec& s, double angle_deg);

}  // namespace drawbend::sim
