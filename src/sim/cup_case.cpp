// The cup-drawing builder: see cup_case.hpp.
#include "sim/cup_case.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/csv.hpp"
#include "fe/contact_springs.hpp"
#include "fe/solver.hpp"
#include "io/case_spec.hpp"
#include "io/deck.hpp"
#include "io/case_reduction.hpp"
#include "io/run_case.hpp"
#include "material/material.hpp"
#include "sim/deck_job.hpp"
#include "sim/material_choice.hpp"

namespace drawbend::sim {

namespace fs = std::filesystem;

namespace {

double elapsed_s(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The punch: flat face r <= Rw - Rp, corner torus (tube Rp, centre z = -Rp),
// wall cylinder r = Rw below z = -Rp.  Rw (the wall radius) is kept.
void set_punch_radius(io::CaseSpec& c, double rp, const std::string& where) {
  io::ToolSpec* punch = nullptr;
  for (auto& t : c.tools)
    if (t.name == "punch") punch = &t;
  io::SurfaceSpec *plane = punch ? punch->surface("plane") : nullptr, *torus = punch ? punch->surface("torus") : nullptr,
                  *wall = punch ? punch->surface("cylinder") : nullptr;
  if (!plane || !torus || !wall) throw InputError(where + ": the punch needs plane, torus and cylinder surfaces");
  if (!wall->radius) throw InputError(where + ": punch cylinder: expected a number 'radius'");
  const double rw = *wall->radius;
  if (!(rp > 0 && rp < rw)) throw InputError(where + ": punch radius " + fmt(rp) + " mm must lie in (0, " + fmt(rw) + ")");
  plane->r_max = rw - rp;
  torus->radius = rw - rp;
  torus->tube_radius = rp;
  torus->origin = io::Vec3Spec{0.0, 0.0, -rp};
  wall->z_max = -rp;
}

// The upper die: flat face r >= Rh + Rd at z = t, corner torus (tube Rd,
// centre z = t + Rd), hole cylinder r = Rh above z = t + Rd.  Rh is kept.
void set_die_radius(io::CaseSpec& c, double rd, const std::string& where) {
  io::ToolSpec* die = nullptr;
  for (auto& t : c.tools)
    if (t.name == "upper_die") die = &t;
  io::SurfaceSpec *plane = die ? die->surface("plane") : nullptr, *torus = die ? die->surface("torus") : nullptr,
                  *hole = die ? die->surface("cylinder") : nullptr;
  if (!plane || !torus || !hole) throw InputError(where + ": the upper die needs plane, torus and cylinder surfaces");
  if (!hole->radius) throw InputError(where + ": upper-die cylinder: expected a number 'radius'");
  const double rh = *hole->radius;
  if (!plane->origin) throw InputError(where + ": upper-die plane needs an origin");
  const double zt = (*plane->origin)[2];
  if (!(rd > 0 && rd < 20)) throw InputError(where + ": die radius " + fmt(rd) + " mm must lie in (0, 20)");
  plane->r_min = rh + rd;
  torus->radius = rh + rd;
  torus->tube_radius = rd;
  torus->origin = io::Vec3Spec{0.0, 0.0, zt + rd};
  hole->z_min = zt + rd;
}

// The base deck with the spec's mesh, radii, material and friction; relative
// paths made absolute (the deck is written elsewhere).
io::CaseSpec base_case(const CupSpec& spec) {
  if (spec.refine < 1) throw InputError(spec.deck + ": refine must be >= 1");
  io::CaseSpec c = io::read_case(spec.deck);
  const fs::path dir = fs::path(spec.deck).parent_path();
  auto absolute = [&](std::string& p) {
    if (fs::path(p).is_relative()) p = (dir / p).lexically_normal().string();
  };
  if (c.mesh)
    for (auto* n : {&c.mesh->core, &c.mesh->ring, &c.mesh->through})
      if (*n) **n *= spec.refine;
  io::CurveFile* file = c.material && c.material->curve ? std::get_if<io::CurveFile>(&*c.material->curve) : nullptr;
  if (!spec.material.empty())  // the user's material over the deck's own flow curve
    c.material = material_choice(spec.material, !file                              ? std::string()
                                                : fs::path(file->path).is_relative() ? (dir / file->path).lexically_normal().string()
                                                                                     : file->path);
  if (c.material && c.material->curve)
    if (auto* f = std::get_if<io::CurveFile>(&*c.material->curve)) absolute(f->path);
  if (!std::isnan(spec.punch_radius)) set_punch_radius(c, spec.punch_radius, spec.deck);
  if (!std::isnan(spec.die_radius)) set_die_radius(c, spec.die_radius, spec.deck);
  for (auto& p : c.contacts) {
    if (spec.friction == "none") {
      p.friction.reset();
      continue;
    }
    if (!spec.friction.empty() && (!p.friction || !p.friction->nodes))
      throw InputError(spec.deck + ": a contact pair without a Table 6.1 nodes friction");
    if (!spec.friction.empty()) p.friction->nodes = fs::absolute(spec.friction).lexically_normal().string();
    if (p.friction && p.friction->nodes) absolute(*p.friction->nodes);
  }
  return c;
}

}  // namespace

CupResult draw_cup(const CupSpec& spec) {
  const auto t_start = std::chrono::steady_clock::now();
  const double speed = spec.speed, stroke = spec.stroke;
  const long cycles = spec.cycles;
  const std::string& vtu = spec.vtu;
  const io::CaseSpec c = cup_case(spec);  // the deck cup_deck_text writes, read as `drawbend run` reads it
  io::Deck deck = io::parse_deck(io::to_toml(c), spec.deck);
  fe::Model& m = deck.model;
  const int layers = c.mesh && c.mesh->through ? static_cast<int>(*c.mesh->through) : 0;
  fe::Solver s(m);
  s.run_step(0);
  CupResult r;
  r.elements = m.mesh.num_elements();
  r.layers = layers;
  const double z0 = s.tool_offset("punch")[2];
  const long every = std::max(1L, cycles / 400), tenth = std::max(1L, cycles / 10);
  const long c0 = s.cycles();
  s.run_step(1, [&](const fe::Progress& p) {
    if ((p.cycle - c0) % tenth == 0 && p.cycle > c0) {  // progress: one line per 10 % of the stroke
      std::ostringstream line;
      line << "  cup " << speed << " mm/s: " << 10 * ((p.cycle - c0) / tenth) << " % of " << stroke
           << " mm, punch force " << -4e-3 * s.tool_force("punch")[2] << " kN, left ~"
           << static_cast<long>(elapsed_s(t_start) * (static_cast<double>(cycles) / static_cast<double>(p.cycle - c0) - 1))
           << " s\n";
      std::fputs(line.str().c_str(), stderr);  // one write per line: cases run side by side
    }
    if (p.cycle % every) return;
    const double d = s.tool_offset("punch")[2] - z0;
    r.curve.push_back({d, -4.0 * s.tool_force("punch")[2]});  // full blank: 4 quarters
    r.die_force = 4.0 * std::abs(s.tool_force("lower_die")[2]);
  });
  r.cycles = s.cycles();
  const auto& e = s.energies();
  r.kinetic_ratio = e.internal > 0 ? e.kinetic / e.internal : 0;
  r.hourglass_ratio = e.internal > 0 ? e.hourglass / e.internal : 0;
  r.added_mass_ratio = s.added_mass() / s.physical_mass();
  // Cup size: flange outer diameter along RD (x, on y = 0) and TD (y, on x = 0).
  const auto& mesh = m.mesh;
  for (int i : mesh.node_set("rim")) {
    if (mesh.y[i] == 0.0) r.size_rd = std::max(r.size_rd, 2.0 * s.x()[i]);
    if (mesh.x[i] == 0.0) r.size_td = std::max(r.size_td, 2.0 * s.y()[i]);
  }
  // Element fields (centroid, plastic strain, von Mises) and the largest
  // plastic strain: element centroid (radius, height above the blank's start).
  const std::vector<double> sig = s.stress();
  for (int el = 0; el < mesh.num_elements(); ++el) {
    const double ep = s.plastic_strain(el);
    double cx = 0, cy = 0, cz = 0;
    for (int a = 0; a < 8; ++a) {
      cx += s.x()[mesh.hex[el][a]] / 8;
      cy += s.y()[mesh.hex[el][a]] / 8;
      cz += s.z()[mesh.hex[el][a]] / 8;
    }
    r.field.push_back({cx, cy, cz, ep, material::von_mises(&sig[6 * static_cast<std::size_t>(el)])});
    const double angle = std::atan2(cy, cx) * 180.0 / std::acos(-1.0);
    if (angle <= 15.0) r.band_rd = std::max(r.band_rd, ep);
    if (angle >= 75.0) r.band_td = std::max(r.band_td, ep);
    if (ep <= r.max_strain) continue;
    r.max_strain = ep;
    r.max_strain_r = std::hypot(cx, cy);
    r.max_strain_z = cz;
    r.max_strain_angle = angle;
  }
  if (!vtu.empty()) io::write_fields(s, vtu);
  r.die_lift = s.tool_offset("lower_die")[2];  // how far the force-driven lower die moved
  r.wall_seconds = elapsed_s(t_start);
  return r;
}

CupResult read_cup_run(const CupSpec& spec, const std::string& dir) {
  const fs::path path = fs::path(dir) / io::kReductionFile;
  const auto rows = io::read_reduction(path.string());
  const std::string where = path.string();
  CupResult r;
  r.die_force = io::reduced(rows, "die_force", where);
  r.size_rd = io::reduced(rows, "size_rd", where);
  r.size_td = io::reduced(rows, "size_td", where);
  r.kinetic_ratio = io::reduced(rows, "kinetic_ratio", where);
  r.hourglass_ratio = io::reduced(rows, "hourglass_ratio", where);
  r.added_mass_ratio = io::reduced(rows, "added_mass_ratio", where);
  r.die_lift = io::reduced(rows, "die_lift", where);
  r.cycles = static_cast<long>(io::reduced(rows, "cycles", where));
  if (const io::CaseSpec c = base_case(spec); c.mesh && c.mesh->through) r.layers = static_cast<int>(*c.mesh->through);
  const io::ReducedValue* centroid = nullptr;
  for (const auto& row : rows) {
    if (row.quantity == "curve") r.curve.push_back({row.x, row.value});
    if (row.quantity == "centroid") centroid = &row;
    if (row.quantity != "state") continue;
    if (!centroid) throw InputError(where + ": a state row without its centroid row");
    // As draw_cup: the bands and the largest plastic strain with its place.
    const double cx = centroid->x, cy = centroid->y, cz = centroid->value, ep = row.x;
    r.field.push_back({cx, cy, cz, ep, row.y});
    const double angle = std::atan2(cy, cx) * 180.0 / std::acos(-1.0);
    if (angle <= 15.0) r.band_rd = std::max(r.band_rd, ep);
    if (angle >= 75.0) r.band_td = std::max(r.band_td, ep);
    if (ep <= r.max_strain) continue;
    r.max_strain = ep;
    r.max_strain_r = std::hypot(cx, cy);
    r.max_strain_z = cz;
    r.max_strain_angle = angle;
  }
  r.elements = static_cast<int>(r.field.size());
  const CsvTable sum = read_csv((fs::path(dir) / "summary.csv").string());
  for (const auto& row : sum.rows)
    if (sum.text(row, "quantity") == "wall_time") r.wall_seconds = sum.number(row, "value");
  if (!spec.vtu.empty()) {  // the end-of-stroke fields: the run's last snapshot
    int k = 0;
    while (fs::exists(fs::path(dir) / ("fields_" + std::to_string(k + 1) + ".vtu"))) ++k;
    fs::copy_file(fs::path(dir) / ("fields_" + std::to_string(k) + ".vtu"), spec.vtu, fs::copy_options::overwrite_existing);
  }
  return r;
}

CupResult draw_cup_job(const CupSpec& spec, const std::string& dir, bool reuse) {
  run_deck_job(fs::path(dir).filename().string(), cup_deck_text(spec), dir, reuse);
  return read_cup_run(spec, dir);
}

double force_at(const CupResult& r, double d) {
  for (std::size_t k = 1; k < r.curve.size(); ++k)
    if (r.curve[k].first >= d) {
      const auto& [d0, f0] = r.curve[k - 1];
      const auto& [d1, f1] = r.curve[k];
      return f0 + (f1 - f0) * (d - d0) / (d1 - d0);
    }
  return NAN;
}


io::CaseSpec cup_case(const CupSpec& spec) {
  io::CaseSpec c = base_case(spec);
  const io::Deck deck = io::parse_deck(io::to_toml(c), spec.deck);
  const fe::Model& m = deck.model;
  // The stroke in `cycles` cycles (mass scaling to target_dt); the speed ramp takes 2 % of the cycles.
  const double dt = spec.stroke / spec.speed / spec.cycles, tr = 0.02 * spec.cycles * dt;
  if (!c.numerics) c.numerics.emplace();
  c.numerics->target_dt = dt / m.dt_safety;
  io::set_threads(c, spec.threads);
  if (c.steps.size() != 2) throw InputError(spec.deck + ": expected two steps (clamp, draw)");
  c.steps[0].duration = 400 * dt;
  c.steps[0].damping = 1.0 / (50 * dt);  // velocities relax in ~50 cycles while clamping
  c.steps[1].duration = spec.stroke / spec.speed + 0.5 * tr;
  c.tool("punch", spec.deck).speed = io::HistorySpec{{0.0, tr}, {0.0, spec.speed}};
  for (const auto& t : m.tools)
    if (t.drive == fe::Tool::Drive::force)
      c.tool(t.name, spec.deck).mass = fe::tool_mass_half_omega_dt(fe::tool_contact_stiffness(m, t.name), dt);
  // The chapter's reduction, kept by the run (io/case_reduction.hpp): draw_cup's curve and end state.
  c.reduce = io::ReduceSpec{"cup_draw", "punch", m.steps[1].name, "lower_die", {}, {}, std::max(1L, spec.cycles / 400)};
  return c;
}

std::string cup_deck_text(const CupSpec& spec) {
  io::CaseSpec c = cup_case(spec);
  std::ostringstream run;
  run << "Punch speed " << spec.speed << " mm/s, stroke " << spec.stroke << " mm in " << spec.cycles
      << " cycles, mesh refinement " << spec.refine << ".";
  c.comment = {"Cup-drawing deck written by drawbend's builder (src/sim/cup_case.cpp) from " + spec.deck + ".", run.str(),
               "Units: mm, N, MPa, s, t/mm^3.  Rerun with: drawbend run deck.toml --out DIR"};
  return io::to_toml(c);
}

void write_isotropic_nodes(const std::string& table_6_1, const std::string& out_csv) {
  const CsvTable t = read_csv(table_6_1);
  std::ofstream o(out_csv);
  if (!o) throw InputError(out_csv + ": cannot write");
  o << "# derived from " << table_6_1 << ": mu_RD = mu_TD = (mu_RD + mu_TD) / 2 at every node (isotropic friction at the\n"
    << "# same mean level, for the attribution study of Chapter 8); units: node: -; mu_RD: -; mu_TD: -\n"
    << "node,mu_RD,mu_TD\n";
  for (const auto& r : t.rows) {
    const double mu = 0.5 * (t.number(r, "mu_RD") + t.number(r, "mu_TD"));
    o << t.text(r, "node") << "," << fmt_shortest(mu) << "," << fmt_shortest(mu) << "\n";
  }
  if (!o) throw InputError(out_csv + ": write failed");
}

}  // namespace drawbend::sim
