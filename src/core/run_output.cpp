// The run-output contract (core/run_output.hpp): history columns, contact maps and pin maps.
#include "core/run_output.hpp"

#include <algorithm>
#include <filesystem>

#include "core/csv.hpp"

namespace drawbend::run_output {

namespace fs = std::filesystem;

const char* signal_name(Signal s) {
  switch (s) {
    case Signal::time: return "time_s";
    case Signal::step: return "step";
    case Signal::dt: return "dt_s";
    case Signal::kinetic: return "kinetic_mJ";
    case Signal::internal: return "internal_mJ";
    case Signal::hourglass: return "hourglass_mJ";
    case Signal::external_work: return "external_work_mJ";
    case Signal::friction: return "friction_mJ";
    case Signal::damping: return "damping_mJ";
    case Signal::balance_error: return "balance_error";
    case Signal::outlet_force: return "outlet_force_N";
    case Signal::back_tension: return "back_tension_N";
    case Signal::inlet_x: return "inlet_x_mm";
    case Signal::pin_force_x: return "pin_force_x_N";
    case Signal::pin_force_z: return "pin_force_z_N";
    case Signal::strain_inside: return "strain_inside";
    case Signal::plastic_strain_inside: return "plastic_strain_inside";
    case Signal::strain_outside: return "strain_outside";
    case Signal::plastic_strain_outside: return "plastic_strain_outside";
    case Signal::outlet_force_full: return "F_Y_full_strip_N";
    case Signal::back_tension_full: return "F_X_full_strip_N";
  }
  return "?";  // unreachable: every enumerator is named above (-Wswitch warns on a new one)
}

std::vector<std::string> run_history_columns() {
  std::vector<std::string> c;
  for (int k = static_cast<int>(Signal::time); k <= static_cast<int>(Signal::balance_error); ++k)
    c.push_back(signal_name(static_cast<Signal>(k)));
  return c;
}

std::string mid_wrap_strain(int k) { return "eps_mid_" + std::to_string(k); }

const std::vector<std::string>& contact_map_columns() {
  static const std::vector<std::string> c{"node", "x_mm", "y_mm", "z_mm", "x0_mm", "y0_mm", "z0_mm", "surface",
                                          "u_tool", "v_tool_mm", "pressure_MPa", "area_mm2", "normal_force_N",
                                          "tangential_force_N", "slip_speed_mm_s", "penetration_mm"};
  return c;
}

std::string contact_map_name(int snapshot, int pair) {
  return "contact_" + std::to_string(snapshot) + "_" + std::to_string(pair) + ".csv";
}

void write_contact_map(const std::string& path, const std::vector<std::string>& comments,
                       const std::vector<ContactMapRow>& rows) {
  CsvWriter w(contact_map_columns());
  for (const auto& c : comments) w.comment(c);
  for (const auto& r : rows)
    w.row({std::to_string(r.node), fmt(r.x, 9), fmt(r.y, 9), fmt(r.z, 9), fmt(r.x0, 9), fmt(r.y0, 9), fmt(r.z0, 9),
           std::to_string(r.surface), fmt(r.u_tool, 9), fmt(r.v_tool, 9), fmt(r.pressure, 8), fmt(r.area, 8),
           fmt(r.normal_force, 8), fmt(r.tangential_force, 8), fmt(r.slip_speed, 8), fmt(r.penetration, 6)});
  w.save(path);
}

ContactMap read_contact_map(const std::string& path) {
  const CsvTable t = read_csv(path);
  const auto& col = contact_map_columns();
  ContactMap m;
  m.path = path;
  m.comments = t.comments;
  for (const auto& row : t.rows) {
    double v[16];
    for (int k = 0; k < 16; ++k) v[k] = t.number(row, col[k]);
    ContactMapRow r;
    r.node = static_cast<int>(v[0]);
    r.x = v[1], r.y = v[2], r.z = v[3], r.x0 = v[4], r.y0 = v[5], r.z0 = v[6];
    r.surface = static_cast<int>(v[7]);
    r.u_tool = v[8], r.v_tool = v[9], r.pressure = v[10], r.area = v[11], r.normal_force = v[12];
    r.tangential_force = v[13], r.slip_speed = v[14], r.penetration = v[15];
    m.rows.push_back(r);
  }
  return m;
}

PressureColumns read_pressure_columns(const std::string& path) {
  const CsvTable t = read_csv(path);
  const std::string& p = contact_map_columns()[10];
  const std::string& a = contact_map_columns()[11];
  PressureColumns c;
  c.comments = t.comments;
  for (const auto& row : t.rows) {
    c.pressure.push_back(t.number(row, p));
    c.area.push_back(t.number(row, a));
    c.line.push_back(row.line);
  }
  return c;
}

std::string last_contact_map(const std::string& dir, int pair) {
  const std::string tail = "_" + std::to_string(pair) + ".csv";
  int best = -1;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (n.rfind("contact_", 0) != 0 || n.size() <= 8 + tail.size() || n.substr(n.size() - tail.size()) != tail) continue;
    const std::string k = n.substr(8, n.size() - 8 - tail.size());
    if (k.empty() || k.find_first_not_of("0123456789") != std::string::npos) continue;
    best = std::max(best, std::stoi(k));
  }
  if (best < 0) throw InputError(dir + ": no contact map");
  return (fs::path(dir) / contact_map_name(best, pair)).string();
}

std::string pin_map_name(const std::string& diameter_text) { return "pin_" + diameter_text + "mm.csv"; }

std::string pin_map_header(double reference_back_tension_N, const std::string& what) {
  return std::string("# ") + kReferenceBackTension + " " + fmt(reference_back_tension_N, 8) + " (" + what + ")\n";
}

}  // namespace drawbend::run_output
