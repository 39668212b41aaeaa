// One ESAFORM 2021 cup: the deck data/cases/esaform2021_cup.toml with a material
// variant, a mesh and a stroke set here; the measurements of the cup at the end.
#include "v1_cup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include <toml++/toml.h>

#include "core/csv.hpp"
#include "fe/contact_springs.hpp"
#include "fe/mesh.hpp"
#include "fe/solver.hpp"
#include "io/deck.hpp"
#include "io/run_case.hpp"

namespace v1 {

using namespace drawbend;

namespace {

constexpr double kPi = 3.14159265358979323846;

double sheet_volume(const fe::Mesh& mesh, const std::vector<double>& x, const std::vector<double>& y,
                    const std::vector<double>& z) {
  double v = 0;
  for (const auto& h : mesh.hex) {
    double ex[8], ey[8], ez[8];
    for (int a = 0; a < 8; ++a) {
      ex[a] = x[h[a]];
      ey[a] = y[h[a]];
      ez[a] = z[h[a]];
    }
    v += fe::hex_volume(ex, ey, ez);
  }
  return v;
}

toml::table deck_table(const std::string& deck, const Variant& var, const RunSpec& spec) {
  toml::table root = toml::parse_file(deck);
  auto* mesh = root["mesh"].as_table();
  auto* mat = root["material"].as_table();
  if (!mesh || !mat) throw InputError(deck + ": expected [mesh] and [material]");
  mesh->insert_or_assign("core", int64_t{spec.core});
  mesh->insert_or_assign("ring", int64_t{spec.ring});
  mesh->insert_or_assign("through", int64_t{spec.through});
  if (spec.polar_radius == 0) mesh->erase("polar_radius");
  if (spec.polar_radius > 0) mesh->insert_or_assign("polar_radius", spec.polar_radius);
  mat->insert_or_assign("type", var.type);
  if (spec.voce) {  // the published alternative 330.2 - 190 exp(-12.4 eps_p) (aa6016_t4_esaform2021.csv header)
    mat->erase("swift");
    mat->insert_or_assign("voce", toml::table{{"sigma0", 330.2 - 190.0}, {"Q", 190.0}, {"b", 12.4}});
  }
  auto* tools = root["tool"].as_array();
  if (!tools) throw InputError(deck + ": expected [[tool]] tables");
  for (auto& node : *tools) {
    auto& t = *node.as_table();
    const std::string name = t["name"].value_or(std::string());
    if (name == "die" && spec.gap > 0) {  // shift the die by (gap - deck's gap): its face, shoulder and opening
      const double shift = spec.gap - 1.04;
      for (auto& sn : *t["surface"].as_array()) {
        auto& sf = *sn.as_table();
        auto* o = sf["origin"].as_array();
        o->replace(o->begin() + 2, o->at(2).value_or(0.0) + shift);
        if (auto z = sf["z_min"].value<double>()) sf.insert_or_assign("z_min", *z + shift);
      }
    }
    if (name == "holder" && spec.holder_force > 0) {  // force-driven (keeps the deck's stop, if any)
      t.insert_or_assign("drive", "force");
      t.insert_or_assign("direction", toml::array{0.0, 0.0, 1.0});
      t.insert_or_assign("force", spec.holder_force);
    }
    if (name == "holder" && spec.holder_force < 0) {  // held fixed at the gap, as before issue 54's runs
      t.insert_or_assign("drive", "fixed");
      for (const char* k : {"direction", "force", "mass", "stop"}) t.erase(k);
    }
    if (t["drive"].value_or(std::string()) == "force" && !t.contains("mass"))
      t.insert_or_assign("mass", 1.0);  // set from the contact stiffness and dt in draw()
  }
  if (spec.mu >= 0)
    for (auto& node : *root["contact"].as_array())
      if (auto* f = node.as_table()->get("friction")) f->as_table()->insert_or_assign("mu", spec.mu);
  if (var.type == "hill48") {
    toml::table h;
    if (var.r0 > 0) {
      h.insert("r0", var.r0);
      h.insert("r45", var.r45);
      h.insert("r90", var.r90);
    } else {
      h.insert("s45", var.s45);
      h.insert("s90", var.s90);
      h.insert("sb", var.sb);
    }
    mat->insert_or_assign("hill48", h);
  }
  if (var.type == "yld2004") {
    toml::table y;
    toml::array c1, c2;
    for (int i = 0; i < 9; ++i) c1.push_back(var.c1[i]), c2.push_back(var.c2[i]);
    y.insert("a", var.a);
    y.insert("c1", c1);
    y.insert("c2", c2);
    mat->insert_or_assign("yld2004", y);
  }
  return root;
}

// Energy stored in the hourglass springs of every element [mJ], by mode group (in-plane xi*eta, twist
// xi*eta, xi*eta*zeta): 32 Q^2 / K per mode (Q += dt K/64 q, power Q q), with K of the element kernel
// (src/fe/element_kernel.hpp) on the element's current volume and half-lengths along its natural axes.
std::vector<std::array<double, 3>> hourglass_stored(const fe::Solver& s, const fe::Mesh& mesh, double E, double nu) {
  const double G = E / (2 * (1 + nu));
  const auto& q = s.hourglass_forces();
  std::vector<std::array<double, 3>> out(mesh.hex.size());
  for (std::size_t e = 0; e < mesh.hex.size(); ++e) {
    double ex[8], ey[8], ez[8];
    for (int a = 0; a < 8; ++a) ex[a] = s.x()[mesh.hex[e][a]], ey[a] = s.y()[mesh.hex[e][a]], ez[a] = s.z()[mesh.hex[e][a]];
    const double V = fe::hex_volume(ex, ey, ez);
    // half-lengths: half the mean length of the 4 edges along xi (0-1), eta (0-3), zeta (0-4)
    const int edges[3][4][2] = {{{0, 1}, {3, 2}, {4, 5}, {7, 6}}, {{0, 3}, {1, 2}, {4, 7}, {5, 6}}, {{0, 4}, {1, 5}, {2, 6}, {3, 7}}};
    double ih2[3];
    for (int d = 0; d < 3; ++d) {
      double len = 0;
      for (const auto& ed : edges[d])
        len += 0.25 * std::sqrt(std::pow(ex[ed[1]] - ex[ed[0]], 2) + std::pow(ey[ed[1]] - ey[ed[0]], 2) +
                                std::pow(ez[ed[1]] - ez[ed[0]], 2));
      ih2[d] = 4.0 / (len * len);
    }
    const double K2[3] = {E * V * ih2[0] / 3, E * V * ih2[1] / 3, G * V * (ih2[0] + ih2[1]) / 3};
    for (int i = 0; i < 3; ++i) {
      const double w2 = 32 * q[6 * e + i] * q[6 * e + i] / K2[i];
      const double w3 = 32 * q[6 * e + 3 + i] * q[6 * e + 3 + i] / (E * V * ih2[i] / 9);
      out[e][i < 2 ? 0 : 1] += w2;
      out[e][2] += w3;
    }
  }
  return out;
}

}  // namespace

int region_of(double r, double z) {
  if (r < 25.0) return 0;
  if (r < 30.0) return 1;
  if (r >= kFlangeOutRadius) return 4;
  return z >= 11.04 ? 2 : 3;
}

CupResult draw(const std::string& deck, const Variant& var, const RunSpec& spec, const std::string& vtu) {
  std::ostringstream text;
  const toml::table root = deck_table(deck, var, spec);
  text << root;
  const double young = root["material"]["E"].value_or(0.0), poisson = root["material"]["nu"].value_or(0.0);
  io::Deck d = io::parse_deck(text.str(), deck);
  fe::Model& m = d.model;
  if (m.steps.size() != 2) throw InputError(deck + ": expected two steps (settle, draw)");
  fe::Tool* punch = nullptr;
  for (auto& t : m.tools)
    if (t.name == "punch") punch = &t;
  if (!punch) throw InputError(deck + ": no tool named 'punch'");
  // Mass scaling: the stroke in spec.cycles cycles.
  const double dt = spec.stroke / spec.speed / static_cast<double>(spec.cycles);
  m.target_dt = dt / m.dt_safety;
  // speed ramp: uniform acceleration over spec.ramp mm (time 2 ramp / speed), or over 2 % of the cycles
  const double tr = spec.ramp > 0 ? 2.0 * spec.ramp / spec.speed : 0.02 * static_cast<double>(spec.cycles) * dt;
  punch->speed = {{0.0, tr}, {0.0, spec.speed}};
  m.steps[1].duration = spec.stroke / spec.speed + 0.5 * tr;
  m.steps[0].duration = 200 * dt;
  m.steps[0].damping = 1.0 / (50 * dt);
  for (auto& t : m.tools)
    if (t.drive == fe::Tool::Drive::force) t.mass = fe::tool_mass_half_omega_dt(fe::tool_contact_stiffness(m, t.name), dt);
  const fe::Mesh& mesh = m.mesh;
  const double v0 = sheet_volume(mesh, mesh.x, mesh.y, mesh.z);
  fe::Solver s(m);
  s.run_step(0);
  CupResult r;
  r.elements = mesh.num_elements();
  r.layers = spec.through;
  const double z0 = s.tool_offset("punch")[2];
  const long every = std::max(1L, spec.cycles / 300);
  const long c0 = s.cycles();
  int reported = 0;
  std::vector<double> hg_work(mesh.hex.size(), 0.0);
  const auto regions = [&](double travel) {  // where the hourglass energy is now
    const auto stored = hourglass_stored(s, mesh, young, poisson);
    std::array<std::array<double, 6>, 5> acc{};
    for (std::size_t e = 0; e < mesh.hex.size(); ++e) {
      double cx = 0, cy = 0, cz = 0;
      for (int a = 0; a < 8; ++a) cx += s.x()[mesh.hex[e][a]] / 8, cy += s.y()[mesh.hex[e][a]] / 8, cz += s.z()[mesh.hex[e][a]] / 8;
      auto& row = acc[region_of(std::hypot(cx, cy), cz)];
      row[2] += hg_work[e];
      for (int k = 0; k < 3; ++k) row[3 + k] += stored[e][k];
    }
    for (int g = 0; g < 5; ++g) {
      acc[g][0] = travel, acc[g][1] = g;
      r.hourglass_regions.push_back(acc[g]);
    }
  };
  s.run_step(1, [&](const fe::Progress& p) {
    const auto& inc = s.hourglass_increments();
    for (std::size_t e = 0; e < hg_work.size(); ++e) hg_work[e] += inc[e];
    const auto& e = s.energies();
    const double travel = s.tool_offset("punch")[2] - z0;  // [mm]
    if (e.internal > 0 && travel > 0.1 * spec.stroke) r.max_kinetic_ratio = std::max(r.max_kinetic_ratio, e.kinetic / e.internal);
    const int tenths = static_cast<int>(10.0 * travel / spec.stroke + 1e-9);
    if (tenths > reported) {  // progress: one line per tenth of the stroke
      reported = tenths;
      regions(travel);
      std::ostringstream line;
      line << "  cup " << var.id << ": " << 10 * tenths << " % of " << spec.stroke << " mm (cycle " << p.cycle - c0
           << "), punch force " << -4e-3 * s.tool_force("punch")[2] << " kN, kinetic/internal "
           << (e.internal > 0 ? e.kinetic / e.internal : 0) << ", hourglass/internal "
           << (e.internal > 0 ? e.hourglass / e.internal : 0) << "\n";
      std::fputs(line.str().c_str(), stderr);
    }
    if (p.cycle % every) return;
    r.curve.push_back({travel, -4.0 * s.tool_force("punch")[2]});  // full blank
  });
  if (reported < 10) regions(s.tool_offset("punch")[2] - z0);  // the end, when the last cycle fell short of it
  r.cycles = s.cycles();
  const auto& e = s.energies();
  r.kinetic_ratio = e.internal > 0 ? e.kinetic / e.internal : 0;
  r.hourglass_ratio = e.internal > 0 ? e.hourglass / e.internal : 0;
  r.balance_error = e.balance_error();
  r.added_mass_ratio = s.added_mass() / s.physical_mass();
  r.volume_ratio = sheet_volume(mesh, s.x(), s.y(), s.z()) / v0;
  // Columns of nodes through the thickness, by reference plan position.
  const double t = *std::max_element(mesh.z.begin(), mesh.z.end());
  std::map<std::pair<long, long>, std::vector<int>> columns;
  const auto key = [&](int i) {
    return std::make_pair(std::lround(mesh.x[i] * 1e6), std::lround(mesh.y[i] * 1e6));
  };
  for (int i = 0; i < mesh.num_nodes(); ++i) columns[key(i)].push_back(i);
  // The cup's outer bottom: the top face at the centre.
  double z_bottom = -1e30;
  for (int i : columns.at({0L, 0L})) z_bottom = std::max(z_bottom, s.z()[i]);
  const double R = std::hypot(mesh.x[mesh.node_set("rim").front()], mesh.y[mesh.node_set("rim").front()]);
  r.rim_z_min = 1e30;
  for (const auto& [k, col] : columns) {
    const int i0 = col.front();
    const double rr = std::hypot(mesh.x[i0], mesh.y[i0]);
    const double ang = std::atan2(mesh.y[i0], mesh.x[i0]) * 180.0 / kPi;
    if (std::abs(rr - R) < 1e-6 * R) {  // rim column
      double zm = 0, rm = 0;
      for (int i : col) {
        zm += s.z()[i] / static_cast<double>(col.size());
        rm += std::hypot(s.x()[i], s.y()[i]) / static_cast<double>(col.size());
        r.rim_r_max = std::max(r.rim_r_max, std::hypot(s.x()[i], s.y()[i]));
        r.rim_z_min = std::min(r.rim_z_min, s.z()[i]);
      }
      r.height.push_back({ang, z_bottom - zm});
      r.outline.push_back({ang, rm});
    }
    // Thickness lines along RD (y = 0), the 45-degree diagonal and TD (x = 0).
    double line = -1;
    if (std::abs(mesh.y[i0]) < 1e-9) line = 0;
    else if (std::abs(mesh.x[i0]) < 1e-9) line = 90;
    else if (std::abs(mesh.x[i0] - mesh.y[i0]) < 1e-9 * (1 + rr)) line = 45;
    if (line < 0) continue;
    int bot = col.front(), top = col.front();
    for (int i : col) {
      if (mesh.z[i] < mesh.z[bot]) bot = i;
      if (mesh.z[i] > mesh.z[top]) top = i;
    }
    if (mesh.z[top] - mesh.z[bot] < 0.5 * t) throw std::runtime_error("v1: a node column without top and bottom");
    const double mx = 0.5 * (s.x()[top] + s.x()[bot]), my = 0.5 * (s.y()[top] + s.y()[bot]);
    r.thickness.push_back({line, rr, std::hypot(mx, my), 0.5 * (s.z()[top] + s.z()[bot]),
                           std::sqrt(std::pow(s.x()[top] - s.x()[bot], 2) + std::pow(s.y()[top] - s.y()[bot], 2) +
                                     std::pow(s.z()[top] - s.z()[bot], 2))});
  }
  std::sort(r.height.begin(), r.height.end());
  std::sort(r.outline.begin(), r.outline.end());
  std::sort(r.thickness.begin(), r.thickness.end());
  if (!vtu.empty()) io::write_fields(s, vtu);
  return r;
}

Extrema extrema(const std::vector<std::pair<double, double>>& h) {
  Extrema x;
  const std::size_t n = h.size();
  for (std::size_t k = 0; k < n; ++k) {
    // Neighbours in the profile mirrored about 0 and 90 deg.
    const double left = k == 0 ? h[1].second : h[k - 1].second;
    const double right = k + 1 == n ? h[n - 2].second : h[k + 1].second;
    const double v = h[k].second;
    if (v > left && v > right) x.ears.push_back(h[k]);
    if (v < left && v < right) x.troughs.push_back(h[k]);
  }
  return x;
}

double polar_start(const std::string& deck, const RunSpec& spec) {
  const toml::table root = deck_table(deck, Variant{}, spec);
  const double R = root["mesh"]["radius"].value_or(0.0), cf = root["mesh"]["core_fraction"].value_or(0.5);
  const double pr = root["mesh"]["polar_radius"].value_or(0.0), a = cf * R;
  return pr > 0 ? a + (R - a) * std::floor(spec.ring * (pr - a) / (R - a)) / spec.ring : 0.0;
}

double mesh_angular_error(const std::string& deck, const RunSpec& spec, double r) {
  // The ring of the O-grid (src/fe/disk.hpp): line k runs straight from the k-th core boundary point to its
  // point at k/(2n) x 90 deg on the circle of radius rp (the rim, or the start of the polar part), then
  // radially.  Where does it cross radius r?
  const toml::table root = deck_table(deck, Variant{}, spec);
  const double R = root["mesh"]["radius"].value_or(0.0), cf = root["mesh"]["core_fraction"].value_or(0.5);
  const int n = spec.core;
  const double a = cf * R;
  const double rp = polar_start(deck, spec) > 0 ? polar_start(deck, spec) : R;
  if (r >= rp) return 0;  // radial lines at equal angles
  std::vector<double> phi;
  for (int k = 0; k <= 2 * n; ++k) {
    const double px = k <= n ? a : a * (2 * n - k) / n, py = k <= n ? a * k / n : a;
    const double th = 0.5 * kPi * k / (2 * n);
    const double ax = rp * std::cos(th), ay = rp * std::sin(th);
    double lo = 0, hi = 1;  // |P + s (A - P)| grows along the line
    for (int it = 0; it < 100; ++it) {
      const double sm = 0.5 * (lo + hi);
      (std::hypot(px + sm * (ax - px), py + sm * (ay - py)) < r ? lo : hi) = sm;
    }
    phi.push_back(std::atan2(py + lo * (ay - py), px + lo * (ax - px)));
  }
  const double mean = 0.5 * kPi / (2 * n);
  double err = 0;
  for (std::size_t k = 1; k < phi.size(); ++k) err = std::max(err, std::abs((phi[k] - phi[k - 1]) / mean - 1));
  return err;
}

}  // namespace v1
