#pragma once
// Reading a draw-bend contact-pressure map the way Chapters 2-4 do: row
// profiles round the pin, the real contact angle, the entry/exit and edge
// peaks, and the contact area per pressure range (Fig. 4.11).
// Angles in degrees from the inlet tangent point (0) to the outlet one (90);
// y across the half width from the strip centre (0) to the edge; MPa, mm^2.
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "sim/drawbend_case.hpp"

namespace drawbend::sim {

/// The nodes of one row along the strip (one y), sorted by angle.
struct Row {
  double y = 0;
  std::vector<MapNode> nodes;
};

/// Rows of the map (nodes grouped by y to 1e-6 mm), centre row first.
std::vector<Row> rows_of(const std::vector<MapNode>& map);

struct ContactArc {
  double start_deg = 0, end_deg = 0;  ///< first and last angle with pressure > threshold (linearly interpolated)
  double angle() const { return end_deg - start_deg; }
};

/// The contact arc of one row: where the pressure first and last exceeds
/// `threshold` [MPa], interpolated between nodes.  Zero arc when no contact.
ContactArc contact_arc(const Row& r, double threshold);

struct Peaks {
  double entry = 0, entry_deg = 0;  ///< largest pressure in the first half of the wrap (< 45 deg)
  double exit = 0, exit_deg = 0;    ///< largest pressure in the second half (>= 45 deg)
  double middle = 0;                ///< pressure at the wrap's middle (45 deg), interpolated
};
Peaks peaks(const Row& r);

/// Largest pressure of a row [MPa].
double max_pressure(const Row& r);

/// Contact area [mm^2] per pressure bin [edges[k], edges[k+1]) (last bin open above).
std::vector<double> area_by_pressure(const std::vector<MapNode>& map, const std::vector<double>& edges);

/// Write the map as gnuplot grid blocks (one block per row, blank-line
/// separated): angle_deg,y_mm,pressure_MPa, nodes within [lo, hi] deg.
void save_map_grid(const std::vector<MapNode>& map, const std::string& path, const std::string& what, double lo = -20,
                   double hi = 110);

/// Write row profiles: angle_deg then one pressure column per row (rows must
/// share their angles, as on a structured strip).
void save_row_profiles(const std::vector<MapNode>& map, const std::string& path, const std::string& what);

}  // namespace drawbend::sim
