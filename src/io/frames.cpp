// The ParaView frames of a run: the sheet (fields_<k>.vtu) and the tools
// (tool_<name>_<k>.vtp).  The fields are listed in data/cases/README.md and
// docs/paraview.md; see io/run_case.hpp.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "io/run_case.hpp"
#include "io/sheet_geometry.hpp"
#include "io/tool_mesh.hpp"
#include "io/vtu.hpp"

namespace drawbend::io {

void write_fields(const fe::Solver& s, const std::string& path, VtkFormat format) {
  const fe::Model& m = s.model();
  const int n = m.mesh.num_nodes(), ne = m.mesh.num_elements();
  const double *X = s.x().data(), *Y = s.y().data(), *Z = s.z().data();
  std::vector<double> disp(3 * n), vel(3 * n), pres(n, 0.0), vm(ne), ep(ne);
  for (int i = 0; i < n; ++i) {
    disp[3 * i] = X[i] - m.mesh.x[i];
    disp[3 * i + 1] = Y[i] - m.mesh.y[i];
    disp[3 * i + 2] = Z[i] - m.mesh.z[i];
    vel[3 * i] = s.vx()[i];
    vel[3 * i + 1] = s.vy()[i];
    vel[3 * i + 2] = s.vz()[i];
  }
  for (int p = 0; p < s.num_contact_pairs(); ++p)
    for (const auto& c : s.contact_nodes(p)) pres[c.node] = std::max(pres[c.node], c.pressure);
  const std::vector<double> sg = s.stress();
  for (int e = 0; e < ne; ++e) {
    const double* t = &sg[6 * e];
    vm[e] = std::sqrt(0.5 * ((t[0] - t[1]) * (t[0] - t[1]) + (t[1] - t[2]) * (t[1] - t[2]) + (t[2] - t[0]) * (t[2] - t[0])) +
                      3 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
    ep[e] = s.plastic_strain(e);
  }
  std::vector<int> hex(8 * ne);
  for (int e = 0; e < ne; ++e)
    for (int a = 0; a < 8; ++a) hex[8 * e + a] = m.mesh.hex[e][a];
  VtuMesh mesh{static_cast<std::size_t>(n), X, Y, Z, static_cast<std::size_t>(ne), hex.data()};
  // Contact: friction traction (tangential force on the sheet per tributary
  // area), slip rate, stick/slip status and the local friction coefficient
  // |f_t| / f_n of each node in contact (zero elsewhere; the largest pressure
  // wins when a node touches several tools).  The accumulated slip adds every
  // pair's: the distance the node slid over all the tools.
  std::vector<double> trac(3 * n, 0.0), slip_rate(n, 0.0), mu(n, 0.0), slip(n, 0.0), status(n, 0.0);
  for (int p = 0; p < s.num_contact_pairs(); ++p)
    for (const auto& c : s.contact_nodes(p)) {
      slip[c.node] += c.slip;
      if (!(c.pressure > 0) || c.pressure < pres[c.node] || !(c.area > 0)) continue;
      for (int k = 0; k < 3; ++k) trac[3 * c.node + k] = c.ft[k] / c.area;
      slip_rate[c.node] = c.slip_speed;
      status[c.node] = c.status;
      const double ft = std::sqrt(c.ft[0] * c.ft[0] + c.ft[1] * c.ft[1] + c.ft[2] * c.ft[2]);
      mu[c.node] = c.normal_force > 0 ? ft / c.normal_force : 0.0;
    }
  // The sheet's thickness through all its layers (io/sheet_geometry.hpp), per
  // node, and per element the mean of its 8 nodes'; now and over its initial value.
  const SheetColumns cols = sheet_columns(m.mesh);
  const std::vector<double> node_thick = node_thickness(cols, X, Y, Z),
                            h0 = node_thickness(cols, m.mesh.x.data(), m.mesh.y.data(), m.mesh.z.data());
  std::vector<double> thick(ne, 0.0), ratio(ne, 0.0);
  for (int e = 0; e < ne; ++e) {
    double ref = 0;
    for (int a : m.mesh.hex[e]) thick[e] += node_thick[a] / 8, ref += h0[a] / 8;
    ratio[e] = ref > 0 ? thick[e] / ref : 1.0;
  }
  // Strain, back stress and the material's axes (mean of the two integration points).
  const material::Material& mat = *m.material;
  const int ns = mat.state_size();
  std::vector<double> strain(6 * ne), back(6 * ne, 0.0), rd(3 * ne, 0.0), nd(3 * ne, 0.0);
  bool axes = false;
  for (int e = 0; e < ne; ++e) {
    log_strain(m.mesh, X, Y, Z, e, &strain[6 * e]);
    for (int gp = 0; gp < 2; ++gp) {
      const double* st = s.material_state().data() + (2 * static_cast<std::size_t>(e) + gp) * ns;
      double al[6], r[3], q[3];
      mat.back_stress(st, al);
      for (int c = 0; c < 6; ++c) back[6 * e + c] += 0.5 * al[c];
      if (mat.sheet_axes(st, r, q)) {
        axes = true;
        for (int c = 0; c < 3; ++c) rd[3 * e + c] += 0.5 * r[c], nd[3 * e + c] += 0.5 * q[c];
      }
    }
  }
  std::vector<VtuField> cells{{"stress_MPa", 6, sg.data()},
                              {"von_mises_MPa", 1, vm.data()},
                              {"plastic_strain", 1, ep.data()},
                              {"log_strain", 6, strain.data()},
                              {"sheet_thickness_mm", 1, thick.data()},
                              {"sheet_thickness_ratio", 1, ratio.data()}};
  if (mat.has_back_stress()) cells.push_back({"back_stress_MPa", 6, back.data()});
  if (axes) cells.push_back({"rolling_direction", 3, rd.data()}), cells.push_back({"normal_direction", 3, nd.data()});
  write_vtu(path, mesh,
            {{"displacement_mm", 3, disp.data()},
             {"velocity_mm_s", 3, vel.data()},
             {"contact_pressure_MPa", 1, pres.data()},
             {"friction_traction_MPa", 3, trac.data()},
             {"slip_rate_mm_s", 1, slip_rate.data()},
             {"slip_mm", 1, slip.data()},
             {"contact_status", 1, status.data()},
             {"local_mu", 1, mu.data()},
             {"sheet_thickness_mm", 1, node_thick.data()}},
            cells, s.time(), format);
}

std::string tool_frame_name(const std::string& tool, int snapshot) {
  std::string safe = tool;  // a file name whatever the deck calls its tool
  for (char& ch : safe)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_')) ch = '_';
  return "tool_" + safe + "_" + std::to_string(snapshot) + ".vtp";
}

void write_tool_frames(const fe::Solver& s, const std::string& dir, int snapshot, VtkFormat format) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t i = 0; i < s.x().size(); ++i) {
    const double p[3] = {s.x()[i], s.y()[i], s.z()[i]};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  for (const fe::Tool& tool : s.model().tools) {
    const ToolMesh t = tool_mesh(tool, s.tool_offset(tool.name), lo, hi);
    VtuMesh mesh{t.x.size(), t.x.data(), t.y.data(), t.z.data(), t.surface.size(), t.quads.data(), 4, 9};
    write_vtp((std::filesystem::path(dir) / tool_frame_name(tool.name, snapshot)).string(), mesh, {},
              {{"surface", 1, t.surface.data()}}, s.time(), format);
  }
}

}  // namespace drawbend::io
