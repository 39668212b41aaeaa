// Pressure-map sources for the loop; see maps.hpp.
#include "loop/maps.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "core/csv.hpp"
#include "core/run_output.hpp"
#include "core/strip_limits.hpp"

namespace drawbend::loop {

namespace fs = std::filesystem;

namespace {

// The largest contact pressure [MPa] and nodal area [mm^2] of an FE map: 100
// GPa is above the elastic modulus of any sheet and 1 m^2 above any strip's
// contact patch; beyond them a value is a unit or typing error.
constexpr double kMaxMapPressureMPa = 1e5;
constexpr double kMaxMapAreaMM2 = 1e6;

// A number of a map file (a comment's value or a .ref file), in (lo, hi] ([lo, hi] with `closed`):
// InputError naming the file and the value's key (a bare std::stod ended with
// "input error: stod", or "error: stod" and exit 3 for 1e999).
double map_number(const std::string& text, const std::string& file, const std::string& key, double lo, double hi,
                  bool closed = false) {
  std::size_t b = text.find_first_not_of(" \t\r\n"), e = text.find_last_not_of(" \t\r\n");
  std::string t = b == std::string::npos ? "" : text.substr(b, e - b + 1);
  // The number may carry a note in brackets after it, as our own maps write it
  // ("1512.4 (full strip; the map is the half model's, ...)").
  const std::size_t sp = t.find_first_of(" \t");
  if (sp != std::string::npos) {
    const std::size_t rest = t.find_first_not_of(" \t", sp);
    if (rest != std::string::npos && t[rest] == '(') t = t.substr(0, sp);
  }
  double v = NAN;
  std::size_t used = 0;
  try {
    v = std::stod(t, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (t.empty() || used != t.size() || hex_number(t) || !std::isfinite(v))
    throw InputError(file + ": " + key + " expected a number, found '" + t + "'");
  if (!((closed ? v >= lo : v > lo) && v <= hi))
    throw InputError(file + ": " + key + " expected a value in " + (closed ? "[" : "(") + fmt(lo) + ", " + fmt(hi) +
                     "] N, found " + t);
  return v;
}

void finish(PinMap& m) {
  m.map.validate();
  m.S1 = m.map.moment(1);
  m.S2 = m.map.moment(2);
  if (!(m.S1 > 0)) throw InputError(m.provenance + ": map carries no normal force");
}
}  // namespace

PinMap stand_in_map(double d, const StandInParams& p) {
  PinMap m;
  m.pin_d_mm = d;
  m.fref_N = p.fref_N;
  const double R = d / 2, arc = R * p.wrap_rad, ds = arc / p.nodes;
  const double belt = p.fref_N / (R * p.width_mm);  // Eq. (2.2), F_x = F_y = F_ref
  const double delta = std::sqrt(R * p.thickness_mm);
  const double Mp = p.sigma_y_MPa * p.thickness_mm * p.thickness_mm * p.width_mm / 4;
  const double peak = (Mp / delta) / (delta * p.width_mm);  // edge force M_p/delta spread over delta
  for (int i = 0; i < p.nodes; ++i) {
    const double s = (i + 0.5) * ds;
    m.map.p_MPa.push_back(belt + peak * (std::exp(-s / delta) + std::exp(-(arc - s) / delta)));
    m.map.area_mm2.push_back(ds * p.width_mm);
  }
  m.map.label = "pin " + fmt(d) + " mm, analytic stand-in, not FE";
  m.provenance = "analytic stand-in, not FE (uniform belt pressure + edge peaks, delta = sqrt(R t))";
  finish(m);
  return m;
}

MapLibrary MapLibrary::stand_in(const std::vector<double>& pins, const StandInParams& p) {
  MapLibrary lib;
  lib.stand_in_ = true;
  lib.source_ = "analytic stand-in, not FE";
  for (double d : pins)
    if (!lib.has(d)) lib.maps_.push_back(stand_in_map(d, p));
  std::sort(lib.maps_.begin(), lib.maps_.end(), [](auto& a, auto& b) { return a.pin_d_mm < b.pin_d_mm; });
  return lib;
}

MapLibrary MapLibrary::load_dir(const std::string& dir) {
  if (!fs::is_directory(dir)) throw InputError(dir + ": maps directory not found");
  MapLibrary lib;
  lib.source_ = "FE maps from " + dir;
  const std::regex name(R"(pin_([0-9]+(\.[0-9]+)?)mm\.csv)");  // run_output::pin_map_name
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::smatch m;
    const std::string fn = f.filename().string();
    if (!std::regex_match(fn, m, name)) continue;
    PinMap pm;
    pm.pin_d_mm = std::stod(m[1].str());
    const run_output::PressureColumns t = run_output::read_pressure_columns(f.string());
    const std::string kref = run_output::kReferenceBackTension, kbend = run_output::kBendingForce;
    for (const auto& c : t.comments) {
      const auto k = c.find(kref);
      if (k != std::string::npos) pm.fref_N = map_number(c.substr(k + kref.size()), f.string(), kref, 0, kMaxStripForceN);
      const auto b = c.find(kbend);
      if (b != std::string::npos)
        pm.fbend_N = map_number(c.substr(b + kbend.size()), f.string(), kbend, 0, kMaxStripForceN, true);
    }
    fs::path side = f;
    side.replace_extension(".ref");
    if (pm.fref_N <= 0 && fs::exists(side))
      pm.fref_N = map_number(read_file(side.string()), side.string(), "reference back tension:", 0, kMaxStripForceN);
    if (!(pm.fref_N > 0))
      throw InputError(f.string() + ": no reference back tension (comment '# reference_back_tension_N: N' or " +
                       side.filename().string() + ")");
    for (std::size_t r = 0; r < t.pressure.size(); ++r) {
      if (t.pressure[r] > kMaxMapPressureMPa || t.area[r] > kMaxMapAreaMM2)
        throw InputError(f.string() + ":" + std::to_string(t.line[r]) + ": expected a contact pressure up to " +
                         fmt(kMaxMapPressureMPa) + " MPa and a nodal area up to " + fmt(kMaxMapAreaMM2) +
                         " mm^2 (check the units), found " + fmt(t.pressure[r]) + " MPa and " + fmt(t.area[r]) + " mm^2");
      if (t.pressure[r] <= 0) continue;  // out of contact
      pm.map.p_MPa.push_back(t.pressure[r]);
      pm.map.area_mm2.push_back(2.0 * t.area[r]);  // half model -> full strip
    }
    pm.map.label = "pin " + fmt(pm.pin_d_mm) + " mm, FE " + fn;
    pm.provenance = "FE contact map " + f.string() + " (half model, areas doubled)";
    finish(pm);
    lib.maps_.push_back(std::move(pm));
  }
  if (lib.maps_.empty()) throw InputError(dir + ": no pin_<diameter>mm.csv map files");
  std::sort(lib.maps_.begin(), lib.maps_.end(), [](auto& a, auto& b) { return a.pin_d_mm < b.pin_d_mm; });
  return lib;
}

bool MapLibrary::has(double d) const {
  for (const auto& m : maps_)
    if (std::abs(m.pin_d_mm - d) < 0.05) return true;
  return false;
}

const PinMap& MapLibrary::at(double d) const {
  for (const auto& m : maps_)
    if (std::abs(m.pin_d_mm - d) < 0.05) return m;
  throw InputError("no pressure map for the " + fmt(d) + " mm pin (" + label() + ")");
}

std::string MapLibrary::label() const { return source_; }

}  // namespace drawbend::loop
