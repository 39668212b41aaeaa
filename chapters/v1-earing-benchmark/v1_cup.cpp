// One ESAFORM 2021 cup: the deck data/cases/esaform2021_cup.toml with a material
// variant, a mesh and a stroke set here; the measurements of the cup at the end.
#include "v1_cup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include <toml++/toml.h>

#include "core/csv.hpp"
#include "fe/contact_springs.hpp"
#include "fe/mesh.hpp"
#include "fe/solver.hpp"
#include "io/deck.hpp"
#include "io/case_reduction.hpp"
#include "io/run_case.hpp"
#include "sim/deck_job.hpp"

namespace v1 {

using namespace drawbend;

namespace fs = std::filesystem;

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

toml::table* tool_table(toml::table& root, const std::string& name) {
  if (auto* tools = root["tool"].as_array())
    for (auto& t : *tools)
      if (auto* tt = t.as_table(); tt && (*tt)["name"].value_or(std::string()) == name) return tt;
  return nullptr;
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
    if (name == "die" && spec.clearance > 0) {  // widen the opening: cylinder, shoulder torus and face r_min move out
      const double dr = spec.clearance - 1.2;
      for (auto& sn : *t["surface"].as_array()) {
        auto& sf = *sn.as_table();
        for (const char* k : {"radius", "r_min"})
          if (auto v = sf[k].value<double>()) sf.insert_or_assign(k, *v + dr);
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

}  // namespace

int region_of(double r, double z) {
  if (r < 25.0) return 0;
  if (r < 30.0) return 1;
  if (r >= kFlangeOutRadius) return 4;
  return z >= 11.04 ? 2 : 3;
}

std::string deck_text(const std::string& deck, const Variant& var, const RunSpec& spec) {
  toml::table root = deck_table(deck, var, spec);
  std::ostringstream text0;
  text0 << root;
  const io::Deck d = io::parse_deck(text0.str(), deck);
  const fe::Model& m = d.model;
  if (m.steps.size() != 2) throw InputError(deck + ": expected two steps (settle, draw)");
  auto* punch = tool_table(root, "punch");
  if (!punch) throw InputError(deck + ": no tool named 'punch'");
  // Mass scaling: the stroke in spec.cycles cycles.
  const double dt = spec.stroke / spec.speed / static_cast<double>(spec.cycles);
  root["numerics"].as_table()->insert_or_assign("target_dt", dt / m.dt_safety);
  // speed ramp: uniform acceleration over spec.ramp mm (time 2 ramp / speed), or over 2 % of the cycles
  const double tr = spec.ramp > 0 ? 2.0 * spec.ramp / spec.speed : 0.02 * static_cast<double>(spec.cycles) * dt;
  punch->insert_or_assign("speed", toml::table{{"t", toml::array{0.0, tr}}, {"v", toml::array{0.0, spec.speed}}});
  auto* steps = root["step"].as_array();
  steps->get(0)->as_table()->insert_or_assign("duration", 200 * dt);
  steps->get(0)->as_table()->insert_or_assign("damping", 1.0 / (50 * dt));
  steps->get(1)->as_table()->insert_or_assign("duration", spec.stroke / spec.speed + 0.5 * tr);
  for (const auto& t : m.tools)
    if (t.drive == fe::Tool::Drive::force)
      tool_table(root, t.name)->insert_or_assign("mass", fe::tool_mass_half_omega_dt(fe::tool_contact_stiffness(m, t.name), dt));
  // What the chapter measures, kept by the run (io/case_reduction.hpp, kind earing_cup).
  if (!root["output"].as_table()) root.insert_or_assign("output", toml::table{});
  root["output"].as_table()->insert_or_assign(
      "reduce", toml::table{{"kind", "earing_cup"}, {"tool", "punch"}, {"step", m.steps[1].name}, {"stroke", spec.stroke},
                            {"every", static_cast<int64_t>(std::max(1L, spec.cycles / 300))}});
  std::ostringstream o;
  o << "# ESAFORM 2021 cup, variant " << var.id << ", written by chapter v1-earing-benchmark (v1_cup.cpp) from " << deck
    << ".\n# Stroke " << spec.stroke << " mm in " << spec.cycles << " cycles.  Units: mm, N, MPa, s, t/mm^3.  Rerun with: "
    << "drawbend run deck.toml --out DIR\n"
    << root << "\n";
  return o.str();
}

CupResult read_run(const std::string& dir, const RunSpec& spec) {
  const std::string where = (fs::path(dir) / io::kReductionFile).string();
  const auto rows = io::read_reduction(where);
  const io::Deck d = io::read_deck((fs::path(dir) / "deck.toml").string());
  const fe::Mesh& mesh = d.model.mesh;
  CupResult r;
  r.elements = mesh.num_elements();
  r.layers = spec.through;
  r.cycles = static_cast<long>(io::reduced(rows, "cycles", where));
  r.kinetic_ratio = io::reduced(rows, "kinetic_ratio", where);
  r.max_kinetic_ratio = io::reduced(rows, "max_kinetic_ratio", where);
  r.hourglass_ratio = io::reduced(rows, "hourglass_ratio", where);
  r.balance_error = io::reduced(rows, "balance_error", where);
  r.added_mass_ratio = io::reduced(rows, "added_mass_ratio", where);
  {  // the material's event counts, which the run writes to its summary (io/run_case.cpp)
    const CsvTable sum = read_csv((fs::path(dir) / "summary.csv").string());
    for (const auto& row : sum.rows)
      if (const std::string& q = sum.text(row, "quantity"); q.rfind("material_", 0) == 0)
        r.material_counts[q.substr(9)] = std::lround(sum.number(row, "value"));
  }
  std::vector<double> X, Y, Z;  // the sheet's nodes at the end
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& row = rows[k];
    if (row.quantity == "curve") r.curve.push_back({row.x, row.value});
    if (row.quantity == "node") X.push_back(row.x), Y.push_back(row.y), Z.push_back(row.value);
    if (row.quantity != "hourglass") continue;
    // Where the hourglass energy is at this snapshot, by region (kRegions).
    if (k + 2 * mesh.hex.size() >= rows.size()) throw InputError(where + ": a hourglass snapshot without its elements");
    std::array<std::array<double, 6>, 5> acc{};
    for (std::size_t e = 0; e < mesh.hex.size(); ++e) {
      const auto& w = rows[k + 1 + 2 * e];
      const auto& st = rows[k + 2 + 2 * e];
      if (w.quantity != "hg_work" || st.quantity != "hg_stored") throw InputError(where + ": a hourglass snapshot cut short");
      auto& a = acc[region_of(w.x, w.y)];
      a[2] += w.value;
      a[3] += st.x, a[4] += st.y, a[5] += st.value;
    }
    for (int g = 0; g < 5; ++g) {
      acc[g][0] = row.x, acc[g][1] = g;
      r.hourglass_regions.push_back(acc[g]);
    }
  }
  if (X.size() != static_cast<std::size_t>(mesh.num_nodes()))
    throw InputError(where + ": " + std::to_string(X.size()) + " node rows for " + std::to_string(mesh.num_nodes()) + " nodes");
  r.volume_ratio = sheet_volume(mesh, X, Y, Z) / sheet_volume(mesh, mesh.x, mesh.y, mesh.z);
  // Columns of nodes through the thickness, by reference plan position.
  const double t = *std::max_element(mesh.z.begin(), mesh.z.end());
  std::map<std::pair<long, long>, std::vector<int>> columns;
  const auto key = [&](int i) {
    return std::make_pair(std::lround(mesh.x[i] * 1e6), std::lround(mesh.y[i] * 1e6));
  };
  for (int i = 0; i < mesh.num_nodes(); ++i) columns[key(i)].push_back(i);
  // The cup's outer bottom: the top face at the centre.
  double z_bottom = -1e30;
  for (int i : columns.at({0L, 0L})) z_bottom = std::max(z_bottom, Z[i]);
  const double R = std::hypot(mesh.x[mesh.node_set("rim").front()], mesh.y[mesh.node_set("rim").front()]);
  r.rim_z_min = 1e30;
  for (const auto& [k, col] : columns) {
    const int i0 = col.front();
    const double rr = std::hypot(mesh.x[i0], mesh.y[i0]);
    const double ang = std::atan2(mesh.y[i0], mesh.x[i0]) * 180.0 / kPi;
    if (std::abs(rr - R) < 1e-6 * R) {  // rim column
      double zm = 0, rm = 0;
      for (int i : col) {
        zm += Z[i] / static_cast<double>(col.size());
        rm += std::hypot(X[i], Y[i]) / static_cast<double>(col.size());
        r.rim_r_max = std::max(r.rim_r_max, std::hypot(X[i], Y[i]));
        r.rim_z_min = std::min(r.rim_z_min, Z[i]);
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
    const double mx = 0.5 * (X[top] + X[bot]), my = 0.5 * (Y[top] + Y[bot]);
    r.thickness.push_back({line, rr, std::hypot(mx, my), 0.5 * (Z[top] + Z[bot]),
                           std::sqrt(std::pow(X[top] - X[bot], 2) + std::pow(Y[top] - Y[bot], 2) +
                                     std::pow(Z[top] - Z[bot], 2))});
  }
  std::sort(r.height.begin(), r.height.end());
  std::sort(r.outline.begin(), r.outline.end());
  std::sort(r.thickness.begin(), r.thickness.end());
  return r;
}


CupResult draw(const std::string& deck, const Variant& var, const RunSpec& spec, const std::string& vtu,
               const std::string& dir, bool reuse) {
  sim::run_deck_job(fs::path(dir).filename().string(), deck_text(deck, var, spec), dir, reuse);
  CupResult r = read_run(dir, spec);
  if (!vtu.empty()) {  // the end-of-stroke fields: the run's last snapshot
    int k = 0;
    while (fs::exists(fs::path(dir) / ("fields_" + std::to_string(k + 1) + ".vtu"))) ++k;
    fs::copy_file(fs::path(dir) / ("fields_" + std::to_string(k) + ".vtu"), vtu, fs::copy_options::overwrite_existing);
  }
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
