// Reading the strip back from a run's snapshot.  See strip_fields.hpp.
#include "sim/strip_fields.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "core/csv.hpp"
#include "io/vtu.hpp"

namespace drawbend::sim {

namespace fs = std::filesystem;

namespace {

/// The values of the DataArray called `name` (any encoding io::write_vtu writes).
std::vector<double> data_array(const std::string& text, const std::string& name, const std::string& path) {
  return io::read_vtu_array(path, text, name);
}

using Vec = std::array<double, 3>;
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const Vec& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/// n . sigma . n for a unit vector n and sigma as XX, YY, ZZ, XY, YZ, XZ.
double normal_stress(const std::array<double, 6>& t, const Vec& n) {
  return t[0] * n[0] * n[0] + t[1] * n[1] * n[1] + t[2] * n[2] * n[2] +
         2 * (t[3] * n[0] * n[1] + t[4] * n[1] * n[2] + t[5] * n[0] * n[2]);
}

}  // namespace

StripFields read_fields_vtu(const std::string& path) {
  const std::string text = read_file(path);
  StripFields f;
  const auto pts = data_array(text, "Points", path), disp = data_array(text, "displacement_mm", path);
  const auto conn = data_array(text, "connectivity", path), sg = data_array(text, "stress_MPa", path);
  f.plastic_strain = data_array(text, "plastic_strain", path);
  const auto tv = data_array(text, "TimeValue", path);
  const std::size_t n = pts.size() / 3, ne = conn.size() / 8;
  if (pts.size() != 3 * n || disp.size() != pts.size() || conn.size() != 8 * ne || sg.size() != 6 * ne ||
      f.plastic_strain.size() != ne || tv.size() != 1)
    throw InputError(path + ": array sizes do not match (" + std::to_string(n) + " points, " + std::to_string(ne) +
                     " cells)");
  f.time = tv[0];
  for (std::size_t i = 0; i < n; ++i) {
    f.x.push_back({pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]});
    f.x0.push_back({pts[3 * i] - disp[3 * i], pts[3 * i + 1] - disp[3 * i + 1], pts[3 * i + 2] - disp[3 * i + 2]});
  }
  for (std::size_t e = 0; e < ne; ++e) {
    std::array<int, 8> h{};
    for (int a = 0; a < 8; ++a) {
      const double k = conn[8 * e + a];
      if (!(k >= 0) || k >= static_cast<double>(n)) throw InputError(path + ": node index out of range");
      h[a] = static_cast<int>(k);
    }
    f.hex.push_back(h);
    f.stress.push_back({sg[6 * e], sg[6 * e + 1], sg[6 * e + 2], sg[6 * e + 3], sg[6 * e + 4], sg[6 * e + 5]});
  }
  return f;
}

std::string last_fields_vtu(const std::string& run_dir) {
  int best = -1;
  for (const auto& e : fs::directory_iterator(run_dir)) {
    const std::string nm = e.path().filename().string();
    if (nm.rfind("fields_", 0) == 0 && nm.size() > 11 && nm.substr(nm.size() - 4) == ".vtu")
      best = std::max(best, std::stoi(nm.substr(7, nm.size() - 11)));
  }
  if (best < 0) throw InputError(run_dir + ": no fields_<k>.vtu snapshot");
  return (fs::path(run_dir) / ("fields_" + std::to_string(best) + ".vtu")).string();
}

std::vector<StripElement> strip_elements(const StripFields& f, const DrawBendSpec& s, double E, double nu) {
  const double R = s.pin_diameter / 2, t = s.thickness, Rm = R + t / 2, Lw = wrap_length(s);
  // The three pairs of opposite faces of a hexahedron (as in io/run_case.cpp).
  static const int faces[3][2][4] = {{{0, 1, 2, 3}, {4, 5, 6, 7}}, {{0, 1, 5, 4}, {3, 2, 6, 7}},
                                     {{0, 3, 7, 4}, {1, 2, 6, 5}}};
  // Position along the strip of a current point (x, z).
  auto along = [&](const Vec& c) {
    const double ang = std::atan2(c[0], c[2]);  // from the top of the pin towards the outlet
    return ang < 0 ? c[0] : (ang <= M_PI / 2 ? Rm * ang : Lw - c[2]);
  };
  std::vector<StripElement> out;
  for (std::size_t e = 0; e < f.hex.size(); ++e) {
    const auto& h = f.hex[e];
    Vec c{0, 0, 0}, c0{0, 0, 0};
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) c[k] += f.x[h[a]][k] / 8, c0[k] += f.x0[h[a]][k] / 8;
    // Face-centroid axes, current and reference; each pair is named by the
    // reference axis it spans (x: along the strip, y: across, z: through).
    Vec axis[3], axis0[3];
    double s_ends[2] = {0, 0};  // positions along the strip of the two end faces (reference x low, high)
    for (int d = 0; d < 3; ++d) {
      Vec a{0, 0, 0}, b{0, 0, 0}, a0{0, 0, 0}, b0{0, 0, 0};
      for (int q : faces[d][0])
        for (int k = 0; k < 3; ++k) a[k] += f.x[h[q]][k] / 4, a0[k] += f.x0[h[q]][k] / 4;
      for (int q : faces[d][1])
        for (int k = 0; k < 3; ++k) b[k] += f.x[h[q]][k] / 4, b0[k] += f.x0[h[q]][k] / 4;
      const Vec r0 = sub(b0, a0);
      int dir = 0;  // the reference axis this pair spans
      for (int k = 1; k < 3; ++k)
        if (std::abs(r0[k]) > std::abs(r0[dir])) dir = k;
      const double sign = r0[dir] < 0 ? -1.0 : 1.0;  // orient towards increasing reference coordinate
      const Vec r = sub(b, a);
      axis[dir] = {sign * r[0], sign * r[1], sign * r[2]};
      axis0[dir] = {sign * r0[0], sign * r0[1], sign * r0[2]};
      if (dir == 0) s_ends[0] = along(sign > 0 ? a : b), s_ends[1] = along(sign > 0 ? b : a);
    }
    StripElement el;
    const double l = norm(axis[0]), l0 = norm(axis0[0]);
    el.ds = s_ends[1] - s_ends[0];
    el.eps_L = std::log(l / l0);
    Vec n[3];
    for (int d = 0; d < 3; ++d) {
      const double m = norm(axis[d]);
      n[d] = {axis[d][0] / m, axis[d][1] / m, axis[d][2] / m};
    }
    el.sigma_L = normal_stress(f.stress[e], n[0]);
    const double sigma_W = normal_stress(f.stress[e], n[1]), sigma_N = normal_stress(f.stress[e], n[2]);
    el.eps_pL = el.eps_L - (el.sigma_L - nu * (sigma_W + sigma_N)) / E;
    el.eps_p = f.plastic_strain[e];
    el.x0 = c0[0];
    el.y0 = c0[1];
    el.depth = (c0[2] - R) / t;
    el.s = along(c);
    out.push_back(el);
  }
  std::sort(out.begin(), out.end(), [](const StripElement& a, const StripElement& b) {
    return a.y0 != b.y0 ? a.y0 < b.y0 : (a.s != b.s ? a.s < b.s : a.depth < b.depth);
  });
  return out;
}

StripSection section_at(const StripFields& f, const DrawBendSpec& s, double angle_deg) {
  const double R = s.pin_diameter / 2;
  // Inside centre nodes: reference y = 0 and z = R.
  double best = 1e300, x0 = NAN, ang_best = NAN;
  for (std::size_t i = 0; i < f.x.size(); ++i) {
    if (std::abs(f.x0[i][1]) > 1e-6 || std::abs(f.x0[i][2] - R) > 1e-6) continue;
    const double ang = std::atan2(f.x[i][0], f.x[i][2]) * 180.0 / M_PI;
    if (std::abs(ang - angle_deg) < best) best = std::abs(ang - angle_deg), x0 = f.x0[i][0], ang_best = ang;
  }
  if (std::isnan(x0)) throw InputError("section_at: no inside centre node (reference y = 0, z = R)");
  StripSection sec;
  sec.x0 = x0;
  sec.angle_deg = ang_best;
  for (std::size_t i = 0; i < f.x.size(); ++i)
    if (std::abs(f.x0[i][0] - x0) < 1e-6)
      sec.nodes.push_back({f.x0[i][1], f.x0[i][2], f.x[i][1], std::hypot(f.x[i][0], f.x[i][2]) - R});
  std::sort(sec.nodes.begin(), sec.nodes.end(), [](const StripSection::Node& a, const StripSection::Node& b) {
    return a.z0 != b.z0 ? a.z0 < b.z0 : a.y0 < b.y0;
  });
  return sec;
}

}  // namespace drawbend::sim
