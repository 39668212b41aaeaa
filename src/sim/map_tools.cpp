// Contact-map reductions for the draw-bend chapters.  See map_tools.hpp.
#include "sim/map_tools.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace drawbend::sim {

std::vector<Row> rows_of(const std::vector<MapNode>& map) {
  std::map<long long, Row> by_y;  // keyed by y in nm: rows of a structured strip share y exactly
  for (const auto& q : map) {
    auto& r = by_y[std::llround(q.y * 1e6)];
    r.y = q.y;
    r.nodes.push_back(q);
  }
  std::vector<Row> out;
  for (auto& [k, r] : by_y) {
    std::sort(r.nodes.begin(), r.nodes.end(), [](const MapNode& a, const MapNode& b) { return a.angle_deg < b.angle_deg; });
    out.push_back(std::move(r));
  }
  return out;
}

ContactArc contact_arc(const Row& r, double threshold) {
  const auto& n = r.nodes;
  int first = -1, last = -1;
  for (int i = 0; i < static_cast<int>(n.size()); ++i)
    if (n[i].pressure > threshold) {
      if (first < 0) first = i;
      last = i;
    }
  if (first < 0) return {};
  auto cross = [&](int a, int b) {  // angle where p crosses the threshold between nodes a (below) and b (above)
    const double pa = n[a].pressure, pb = n[b].pressure;
    return n[a].angle_deg + (threshold - pa) / (pb - pa) * (n[b].angle_deg - n[a].angle_deg);
  };
  ContactArc arc;
  arc.start_deg = first > 0 ? cross(first - 1, first) : n[first].angle_deg;
  arc.end_deg = last + 1 < static_cast<int>(n.size()) ? cross(last + 1, last) : n[last].angle_deg;
  return arc;
}

Peaks peaks(const Row& r) {
  Peaks p;
  for (const auto& q : r.nodes) {
    if (q.angle_deg < 45.0 && q.pressure > p.entry) p.entry = q.pressure, p.entry_deg = q.angle_deg;
    if (q.angle_deg >= 45.0 && q.pressure > p.exit) p.exit = q.pressure, p.exit_deg = q.angle_deg;
  }
  const auto& n = r.nodes;
  for (std::size_t i = 0; i + 1 < n.size(); ++i)
    if (n[i].angle_deg <= 45.0 && n[i + 1].angle_deg > 45.0) {
      const double f = (45.0 - n[i].angle_deg) / (n[i + 1].angle_deg - n[i].angle_deg);
      p.middle = n[i].pressure + f * (n[i + 1].pressure - n[i].pressure);
    }
  return p;
}

double max_pressure(const Row& r) {
  double m = 0;
  for (const auto& q : r.nodes) m = std::max(m, q.pressure);
  return m;
}

std::vector<double> area_by_pressure(const std::vector<MapNode>& map, const std::vector<double>& edges) {
  std::vector<double> a(edges.size(), 0.0);
  for (const auto& q : map) {
    if (!(q.pressure > 0)) continue;
    int k = static_cast<int>(std::upper_bound(edges.begin(), edges.end(), q.pressure) - edges.begin()) - 1;
    if (k < 0) continue;
    a[k] += q.area;
  }
  return a;
}

namespace {
/// Pressure of a row at angle a: linear between its nodes, zero outside them.
double row_pressure(const Row& r, double a) {
  const auto& n = r.nodes;
  for (std::size_t i = 0; i + 1 < n.size(); ++i)
    if (n[i].angle_deg <= a && a <= n[i + 1].angle_deg) {
      const double h = n[i + 1].angle_deg - n[i].angle_deg;
      const double f = h > 0 ? (a - n[i].angle_deg) / h : 0.0;
      return n[i].pressure + f * (n[i + 1].pressure - n[i].pressure);
    }
  return 0.0;
}
/// The common angle grid of a map: half the median node spacing of the first
/// row, from the smallest to the largest node angle, clipped to [lo, hi].
std::vector<double> common_angles(const std::vector<Row>& rows, double lo, double hi, const std::string& path) {
  if (rows.empty() || rows.front().nodes.size() < 2) throw InputError(path + ": empty contact map");
  double a0 = INFINITY, a1 = -INFINITY;
  for (const auto& r : rows)
    for (const auto& q : r.nodes) a0 = std::min(a0, q.angle_deg), a1 = std::max(a1, q.angle_deg);
  const auto& c = rows.front().nodes;
  std::vector<double> gaps;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) gaps.push_back(c[i + 1].angle_deg - c[i].angle_deg);
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  const double step = std::max(gaps[gaps.size() / 2] / 2, 1e-3);
  std::vector<double> v;
  for (double a = std::max(a0, lo); a <= std::min(a1, hi) + 1e-9; a += step) v.push_back(a);
  return v;
}
}  // namespace

void save_map_grid(const std::vector<MapNode>& map, const std::string& path, const std::string& what, double lo,
                   double hi) {
  // Rows of a deformed strip do not share their nodes' angles; a heat map
  // drawn through the nodes themselves comes out as slanted parallelograms.
  // Each row is interpolated onto one angle grid, so the map is a regular
  // (angle x width) grid.
  const auto rows = rows_of(map);
  const auto angles = common_angles(rows, lo, hi, path);
  std::string text = "# " + what + "\n# angle_deg,y_mm,pressure_MPa (gnuplot grid: one block per row; each row "
                     "interpolated linearly between its nodes onto a common angle grid, zero beyond its ends)\n";
  for (const auto& r : rows) {
    for (double a : angles) text += fmt(a, 6) + "," + fmt(r.y, 6) + "," + fmt(row_pressure(r, a), 6) + "\n";
    text += "\n";
  }
  write_file_atomic(path, text);
}


void save_row_profiles(const std::vector<MapNode>& map, const std::string& path, const std::string& what) {
  const auto rows = rows_of(map);
  std::vector<std::string> header{"angle_deg"};
  for (const auto& r : rows) header.push_back("p_y" + fmt(r.y, 4));
  CsvWriter w(header);
  w.comment(what);
  w.comment("pressure [MPa] along each row of nodes (y [mm] from the strip centre), interpolated linearly between "
            "the row's nodes onto a common angle grid (half the nodes' spacing; zero beyond a row's ends); angle "
            "from the inlet tangent point");
  for (double a : common_angles(rows, -20.0, 110.0, path)) {
    std::vector<std::string> row{fmt(a, 6)};
    for (const auto& r : rows) row.push_back(fmt(row_pressure(r, a), 6));
    w.row(row);
  }
  w.save(path);
}

}  // namespace drawbend::sim
