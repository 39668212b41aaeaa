// make bench: the ccx deck of a bench bar and its outputs read back
// (bench_ccx_deck.hpp).  Checked against CalculiX 2.20 (Debian calculix-ccx
// 2.20-1) on 2026-11-26: C3D8R runs in *DYNAMIC, EXPLICIT; ccx picks its own
// stable increment and keeps it through the step; the .sta of an explicit
// step lists no increments, so their count is read from the .frd record of
// the last increment (ccx always writes the step's last increment).
#include "bench_ccx_deck.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "material/j2_isotropic.hpp"

using namespace drawbend;

namespace {
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

void node_set(std::ostringstream& d, const std::string& name, const std::vector<int>& nodes) {
  d << "*NSET, NSET=" << name << "\n";
  for (std::size_t i = 0; i < nodes.size(); ++i) d << nodes[i] + 1 << (i % 8 == 7 || i + 1 == nodes.size() ? "\n" : ", ");
}

bool fixed_as(const fe::Step& s, const std::string& set, std::array<bool, 3> dof) {
  for (const auto& f : s.fixed)
    if (f.set == set) return f.dof == dof;
  return false;
}

// The line after the first line of `text` containing `key` that is not blank.
std::optional<std::string> line_after(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  std::string line;
  bool found = false;
  while (std::getline(in, line)) {
    if (!found) {
      found = line.find(key) != std::string::npos;
    } else if (line.find_first_not_of(" \t\r") != std::string::npos) {
      return line;
    }
  }
  return std::nullopt;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

std::string ccx_bar_deck(const fe::Model& m, double duration, int probe) {
  const auto* j2 = dynamic_cast<const material::J2Isotropic*>(m.material.get());
  if (!j2) throw std::invalid_argument("ccx deck: the bar's material is not J2Isotropic");
  if (m.steps.empty() || m.steps[0].velocities.size() != 1 || !m.steps[0].forces.empty() || !m.tools.empty())
    throw std::invalid_argument("ccx deck: the model is not a bench bar (one step, one velocity, no loads or tools)");
  const fe::Step& s = m.steps[0];
  const fe::VelocityBC& v = s.velocities[0];
  if (v.set != "xmax" || v.direction != Vec3{1, 0, 0} || !fixed_as(s, "xmin", {true, true, true}) ||
      !fixed_as(s, "xmax", {false, true, true}) || m.mass_scaling != 1.0 || m.target_dt > 0)
    throw std::invalid_argument("ccx deck: the model is not a bench bar (xmin held, xmax pulled along x)");
  const double speed = v.speed(0.0);  // constant [mm/s]
  const fe::Mesh& mesh = m.mesh;
  std::ostringstream d;
  d << "** drawbend make bench: bar of " << mesh.num_elements() << " 1 mm hexahedra (bench/bench_models.cpp)\n"
    << "** units mm, N, MPa, s, t/mm^3\n*NODE, NSET=NALL\n";
  for (int n = 0; n < mesh.num_nodes(); ++n)
    d << n + 1 << ", " << num(mesh.x[n]) << ", " << num(mesh.y[n]) << ", " << num(mesh.z[n]) << "\n";
  d << "*ELEMENT, TYPE=C3D8R, ELSET=EALL\n";  // our corner order (VTK hexahedron) is ccx's
  for (int e = 0; e < mesh.num_elements(); ++e) {
    d << e + 1;
    for (int a = 0; a < 8; ++a) d << ", " << mesh.hex[e][a] + 1;
    d << "\n";
  }
  node_set(d, "XMIN", mesh.node_set("xmin"));
  node_set(d, "XMAX", mesh.node_set("xmax"));
  node_set(d, "PROBE", {probe});
  d << "*MATERIAL, NAME=BAR\n*ELASTIC\n" << num(j2->youngs_modulus()) << ", " << num(j2->poisson_ratio())
    << "\n*DENSITY\n" << num(j2->density()) << "\n*PLASTIC\n";  // true stress [MPa], equivalent plastic strain
  const auto& curve = j2->curve();
  for (std::size_t i = 0; i < curve.size(); ++i)
    d << num(curve.stresses()[i]) << ", " << num(curve.plastic_strains()[i]) << "\n";
  d << "*SOLID SECTION, ELSET=EALL, MATERIAL=BAR\n"
    << "*INITIAL CONDITIONS, TYPE=VELOCITY\nXMAX, 1, " << num(speed) << "\n"
    << "*AMPLITUDE, NAME=PULL\n0., 0., " << num(duration) << ", " << num(speed * duration) << "\n"
    << "*STEP, NLGEOM, INC=100000000\n*DYNAMIC, EXPLICIT\n"
    << num(duration / 1000) << ", " << num(duration) << "\n"  // a first guess; ccx takes its stable increment
    << "*BOUNDARY\nXMIN, 1, 3, 0.\nXMAX, 2, 3, 0.\n*BOUNDARY, AMPLITUDE=PULL\nXMAX, 1, 1, 1.\n"
    << "*NODE PRINT, NSET=XMIN, TOTALS=ONLY, FREQUENCY=100000000\nRF\n"
    << "*NODE PRINT, NSET=PROBE, FREQUENCY=100000000\nU\n"
    << "*NODE FILE, NSET=PROBE, FREQUENCY=100000000\nU\n*END STEP\n";
  return d.str();
}

std::optional<CcxOutput> read_ccx_output(const std::string& dir, const std::string& job, const std::string& log,
                                         std::string& why) {
  CcxOutput o;
  const std::string text = slurp(log), dat = slurp(dir + "/" + job + ".dat"), frd = slurp(dir + "/" + job + ".frd");
  if (auto p = text.find("CalculiX Version "); p != std::string::npos) {
    const auto b = p + 17, e = text.find_first_of(", \n", b);
    o.version = text.substr(b, e - b);
  }
  if (auto p = text.find("SELECTED time increment:"); p != std::string::npos) o.dt = std::atof(text.c_str() + p + 24);
  const auto rf = line_after(dat, "total force (fx,fy,fz) for set XMIN");
  const auto u = line_after(dat, "displacements (vx,vy,vz) for set PROBE");
  long node = 0;
  if (!rf || std::sscanf(rf->c_str(), "%lf %lf %lf", &o.reaction[0], &o.reaction[1], &o.reaction[2]) != 3 || !u ||
      std::sscanf(u->c_str(), "%ld %lf %lf %lf", &node, &o.probe_u[0], &o.probe_u[1], &o.probe_u[2]) != 4) {
    why = "no reaction or probe displacement in " + job + ".dat";
    return std::nullopt;
  }
  // The last record header "    1PSTEP   <record>   <increment>   <step>".
  if (auto p = frd.rfind("1PSTEP"); p != std::string::npos) {
    long record = 0;
    std::sscanf(frd.c_str() + p + 6, "%ld %ld", &record, &o.increments);
  }
  if (o.increments <= 0 || o.dt <= 0) {
    why = "no increment count in " + job + ".frd or no time increment in the log";
    return std::nullopt;
  }
  return o;
}
