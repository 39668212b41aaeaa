// One ESAFORM 2021 cup: the deck data/cases/esaform2021_cup.toml with a material
// variant, a mesh and a stroke set here; the measurements of the cup at the end.
#include "v1_cup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/csv.hpp"
#include "fe/contact_springs.hpp"
#include "fe/mesh.hpp"
#include "fe/solver.hpp"
#include "io/case_spec.hpp"
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

io::MaterialType type_of(const std::string& name) {
  for (io::MaterialType t : {io::MaterialType::elastic, io::MaterialType::j2, io::MaterialType::j2_combined,
                             io::MaterialType::hill48, io::MaterialType::yld2004})
    if (name == io::type_name(t)) return t;
  throw InputError("v1: unknown material type \"" + name + "\"");
}

// The deck with the variant's material (none for an empty type), the mesh and the process alternatives of `spec`.
io::CaseSpec case_of(const std::string& deck, const Variant& var, const RunSpec& spec) {
  io::CaseSpec c = io::read_case(deck);
  if (!c.mesh || !c.material) throw InputError(deck + ": expected [mesh] and [material]");
  io::MeshSpec& mesh = *c.mesh;
  mesh.core = spec.core, mesh.ring = spec.ring, mesh.through = spec.through;
  if (spec.polar_radius == 0) mesh.polar_radius.reset();
  if (spec.polar_radius > 0) mesh.polar_radius = spec.polar_radius;
  io::MaterialSpec& mat = *c.material;
  if (!var.type.empty()) mat.type = type_of(var.type);
  if (spec.voce) {  // the published alternative 330.2 - 190 exp(-12.4 eps_p) (aa6016_t4_esaform2021.csv header)
    mat.curve = io::CurveVoce{330.2 - 190.0, 190.0, 12.4};
    c.material_sections.insert(io::key_of(*mat.curve));
  }
  for (io::ToolSpec& t : c.tools) {
    if (t.name == "die" && spec.gap > 0) {  // shift the die by (gap - deck's gap): its face, shoulder and opening
      const double shift = spec.gap - 1.04;
      for (io::SurfaceSpec& sf : t.surfaces) {
        if (sf.origin) (*sf.origin)[2] += shift;
        if (sf.z_min) *sf.z_min += shift;
      }
    }
    if (t.name == "die" && spec.clearance > 0) {  // widen the opening: cylinder, shoulder torus and face r_min move out
      const double dr = spec.clearance - 1.2;
      for (io::SurfaceSpec& sf : t.surfaces) {
        if (sf.radius) *sf.radius += dr;
        if (sf.r_min) *sf.r_min += dr;
      }
    }
    if (t.name == "holder" && spec.holder_force > 0) {  // force-driven (keeps the deck's stop, if any)
      t.drive = "force";
      t.direction = io::Vec3Spec{0.0, 0.0, 1.0};
      t.force = spec.holder_force;
      t.rest.erase("force");
    }
    if (t.name == "holder" && spec.holder_force < 0) {  // held fixed at the gap, as before issue 54's runs
      t.drive = "fixed";
      t.direction.reset(), t.force.reset(), t.mass.reset(), t.stop.reset();
      for (const char* k : {"direction", "force", "mass", "stop"}) t.rest.erase(k);
    }
    if (t.drive == "force" && !t.mass && !t.rest.contains("mass")) t.mass = 1.0;  // set from the contact stiffness and dt
  }
  if (spec.mu >= 0)
    for (io::ContactSpec& p : c.contacts)
      if (p.friction) p.friction->mu = spec.mu;
  if (var.type == "hill48") {
    if (var.r0 > 0) mat.surface = io::Hill48R{var.r0, var.r45, var.r90};
    else mat.surface = io::Hill48S{var.s45, var.s90, var.sb};
    c.material_sections.insert(io::key_of(mat.surface));
  }
  if (var.type == "yld2004") {
    mat.surface = io::Yld2004Surface{var.a, var.c1, var.c2};
    c.material_sections.insert(io::key_of(mat.surface));
  }
  return c;
}

}  // namespace

int region_of(double r, double z) {
  if (r < 25.0) return 0;
  if (r < 30.0) return 1;
  if (r >= kFlangeOutRadius) return 4;
  return z >= 11.04 ? 2 : 3;
}

std::string deck_text(const std::string& deck, const Variant& var, const RunSpec& spec) {
  io::CaseSpec c = case_of(deck, var, spec);
  const io::Deck d = io::parse_deck(io::to_toml(c), deck);
  const fe::Model& m = d.model;
  if (m.steps.size() != 2) throw InputError(deck + ": expected two steps (settle, draw)");
  io::ToolSpec& punch = c.tool("punch", deck);
  // Mass scaling: the stroke in spec.cycles cycles.
  const double dt = spec.stroke / spec.speed / static_cast<double>(spec.cycles);
  if (!c.numerics) c.numerics.emplace();
  c.numerics->target_dt = dt / m.dt_safety;
  // speed ramp: uniform acceleration over spec.ramp mm (time 2 ramp / speed), or over 2 % of the cycles
  const double tr = spec.ramp > 0 ? 2.0 * spec.ramp / spec.speed : 0.02 * static_cast<double>(spec.cycles) * dt;
  punch.speed = io::HistorySpec{{0.0, tr}, {0.0, spec.speed}};
  c.steps[0].duration = 200 * dt;
  c.steps[0].damping = 1.0 / (50 * dt);
  c.steps[1].duration = spec.stroke / spec.speed + 0.5 * tr;
  for (const auto& t : m.tools)
    if (t.drive == fe::Tool::Drive::force)
      c.tool(t.name, deck).mass = fe::tool_mass_half_omega_dt(fe::tool_contact_stiffness(m, t.name), dt);
  // What the chapter measures, kept by the run (io/case_reduction.hpp, kind earing_cup).
  c.reduce = io::ReduceSpec{"earing_cup", "punch", m.steps[1].name, {}, spec.stroke, {}, std::max(1L, spec.cycles / 300)};
  std::ostringstream stroke;
  stroke << "Stroke " << spec.stroke << " mm in " << spec.cycles << " cycles.  Units: mm, N, MPa, s, t/mm^3.  Rerun with: "
         << "drawbend run deck.toml --out DIR";
  c.comment = {"ESAFORM 2021 cup, variant " + var.id + ", written by chapter v1-earing-benchmark (v1_cup.cpp) from " +
                   deck + ".",
               stroke.str()};
  return io::to_toml(c);
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
  const io::MeshSpec mesh = *case_of(deck, Variant{}, spec).mesh;
  const double R = mesh.radius.value_or(0.0), cf = mesh.core_fraction.value_or(0.5);
  const double pr = mesh.polar_radius.value_or(0.0), a = cf * R;
  return pr > 0 ? a + (R - a) * std::floor(spec.ring * (pr - a) / (R - a)) / spec.ring : 0.0;
}

double mesh_angular_error(const std::string& deck, const RunSpec& spec, double r) {
  // The ring of the O-grid (src/fe/disk.hpp): line k runs straight from the k-th core boundary point to its
  // point at k/(2n) x 90 deg on the circle of radius rp (the rim, or the start of the polar part), then
  // radially.  Where does it cross radius r?
  const io::MeshSpec mesh = *case_of(deck, Variant{}, spec).mesh;
  const double R = mesh.radius.value_or(0.0), cf = mesh.core_fraction.value_or(0.5);
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
