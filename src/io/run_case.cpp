#include "io/run_case.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "core/csv.hpp"
#include "core/run_output.hpp"
#include "io/run_checkpoint.hpp"
#include "io/vtu.hpp"

namespace drawbend::io {

namespace {

/// The element whose reference centroid is nearest p (lowest index on ties).
int nearest_element(const fe::Mesh& m, const fe::Vec3& p) {
  int best = 0;
  double bd = INFINITY;
  for (int e = 0; e < m.num_elements(); ++e) {
    double c[3] = {0, 0, 0};
    for (int a : m.hex[e]) c[0] += m.x[a] / 8, c[1] += m.y[a] / 8, c[2] += m.z[a] / 8;
    const double d = (c[0] - p[0]) * (c[0] - p[0]) + (c[1] - p[1]) * (c[1] - p[1]) + (c[2] - p[2]) * (c[2] - p[2]);
    if (d < bd) bd = d, best = e;
  }
  return best;
}

/// Log strain along the element's reference x edges: ln of the mean current
/// length of its four x-edges (node pairs 0-1, 3-2, 4-5, 7-6) over the reference.
double edge_strain(const fe::Solver& s, int e) {
  const auto& m = s.model().mesh;
  const auto& h = m.hex[e];
  const int pairs[4][2] = {{0, 1}, {3, 2}, {4, 5}, {7, 6}};
  double L = 0, L0 = 0;
  for (const auto& pr : pairs) {
    const int a = h[pr[0]], b = h[pr[1]];
    L += std::hypot(s.x()[b] - s.x()[a], s.y()[b] - s.y()[a], s.z()[b] - s.z()[a]);
    L0 += std::hypot(m.x[b] - m.x[a], m.y[b] - m.y[a], m.z[b] - m.z[a]);
  }
  return std::log(L / L0);
}

double signal(const fe::Solver& s, const HistorySignal& h, int element) {
  if (h.kind == "strain") return h.component == 0 ? edge_strain(s, element) : s.plastic_strain(element);
  fe::Vec3 v{0, 0, 0};
  if (h.kind == "reaction") v = s.reaction(h.target);
  else if (h.kind == "applied") v = s.applied(h.target);
  else if (h.kind == "tool_force") v = s.tool_force(h.target);
  else if (h.kind == "tool_offset") v = s.tool_offset(h.target);
  else if (h.kind == "displacement") {  // mean displacement of the node set [mm]
    const auto& mesh = s.model().mesh;
    const auto& set = mesh.node_set(h.target);
    const std::vector<double>* cur[3] = {&s.x(), &s.y(), &s.z()};
    const std::vector<double>* ref[3] = {&mesh.x, &mesh.y, &mesh.z};
    double sum = 0;
    for (int n : set) sum += (*cur[h.component])[n] - (*ref[h.component])[n];
    return set.empty() ? 0.0 : sum / static_cast<double>(set.size());
  }
  return v[h.component];
}

}  // namespace

void write_contact_maps(const fe::Solver& s, const std::string& dir, int snapshot) {
  const fe::Model& m = s.model();
  for (int p = 0; p < s.num_contact_pairs(); ++p) {
    const auto& cp = m.contacts[p];
    const fe::Tool* tool = nullptr;
    for (const auto& t : m.tools)
      if (t.name == cp.tool) tool = &t;
    const fe::Vec3 off = s.tool_offset(cp.tool);
    const std::vector<std::string> comments{
        "contact map: faces '" + cp.faces + "' on tool '" + cp.tool + "' at t = " + fmt(s.time()) + " s",
        "x, y, z: current position; x0, y0, z0: reference (undeformed) position [mm]",
        "u_tool: angle about the surface axis [deg] (cylinder, torus) or in-plane coordinate [mm] (plane); "
        "v_tool: position along the axis [mm] (cylinder, torus) or second in-plane coordinate (plane)"};
    std::vector<run_output::ContactMapRow> rows;
    for (const auto& c : s.contact_nodes(p)) {
      const int i = c.node;
      double u = 0, v = 0;
      if (c.surface >= 0) {
        const auto& sf = tool->surfaces[c.surface];
        const double d[3] = {c.foot[0] - sf.origin[0] - off[0], c.foot[1] - sf.origin[1] - off[1],
                             c.foot[2] - sf.origin[2] - off[2]};
        const auto& a = sf.axis;
        const double along = d[0] * a[0] + d[1] * a[1] + d[2] * a[2];
        // A reference direction perpendicular to the axis.
        fe::Vec3 r1 = std::abs(a[2]) < 0.9 ? fe::Vec3{-a[1], a[0], 0} : fe::Vec3{0, -a[2], a[1]};
        const double rn = std::sqrt(r1[0] * r1[0] + r1[1] * r1[1] + r1[2] * r1[2]);
        for (double& q : r1) q /= rn;
        const fe::Vec3 r2{a[1] * r1[2] - a[2] * r1[1], a[2] * r1[0] - a[0] * r1[2], a[0] * r1[1] - a[1] * r1[0]};
        const double p1 = d[0] * r1[0] + d[1] * r1[1] + d[2] * r1[2], p2 = d[0] * r2[0] + d[1] * r2[1] + d[2] * r2[2];
        if (sf.kind == contact::Surface::Kind::plane) {
          u = p1;
          v = p2;
        } else {
          u = std::atan2(p2, p1) * 180.0 / M_PI;
          v = along;
        }
      }
      const double ft = std::sqrt(c.ft[0] * c.ft[0] + c.ft[1] * c.ft[1] + c.ft[2] * c.ft[2]);
      rows.push_back({i, s.x()[i], s.y()[i], s.z()[i], m.mesh.x[i], m.mesh.y[i], m.mesh.z[i], c.surface, u, v,
                      c.pressure, c.area, c.normal_force, ft, c.slip_speed, c.depth});
    }
    const std::filesystem::path file = std::filesystem::path(dir) / run_output::contact_map_name(snapshot, p);
    run_output::write_contact_map(file.string(), comments, rows);
  }
}

void write_fields(const fe::Solver& s, const std::string& path) {
  const fe::Model& m = s.model();
  const int n = m.mesh.num_nodes(), ne = m.mesh.num_elements();
  std::vector<double> disp(3 * n), vel(3 * n), pres(n, 0.0), vm(ne), ep(ne);
  for (int i = 0; i < n; ++i) {
    disp[3 * i] = s.x()[i] - m.mesh.x[i];
    disp[3 * i + 1] = s.y()[i] - m.mesh.y[i];
    disp[3 * i + 2] = s.z()[i] - m.mesh.z[i];
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
  VtuMesh vm_{static_cast<std::size_t>(n), s.x().data(), s.y().data(), s.z().data(), static_cast<std::size_t>(ne),
              hex.data()};
  // Contact: friction traction (tangential force on the sheet per tributary
  // area), slip rate and the local friction coefficient |f_t| / f_n of each
  // node in contact (zero elsewhere; the largest pressure wins when a node
  // touches several tools).
  std::vector<double> trac(3 * n, 0.0), slip(n, 0.0), mu(n, 0.0);
  for (int p = 0; p < s.num_contact_pairs(); ++p)
    for (const auto& c : s.contact_nodes(p)) {
      if (!(c.pressure > 0) || c.pressure < pres[c.node] || !(c.area > 0)) continue;
      for (int k = 0; k < 3; ++k) trac[3 * c.node + k] = c.ft[k] / c.area;
      slip[c.node] = c.slip_speed;
      const double ft = std::sqrt(c.ft[0] * c.ft[0] + c.ft[1] * c.ft[1] + c.ft[2] * c.ft[2]);
      mu[c.node] = c.normal_force > 0 ? ft / c.normal_force : 0.0;
    }
  // Thickness: each element's height across its thinnest initial direction
  // (the distance between the centroids of the two opposite faces that are
  // closest in the reference mesh), now and as a ratio to its initial value.
  std::vector<double> thick(ne), thick_ratio(ne);
  static const int faces[3][2][4] = {{{0, 1, 2, 3}, {4, 5, 6, 7}}, {{0, 1, 5, 4}, {3, 2, 6, 7}}, {{0, 3, 7, 4}, {1, 2, 6, 5}}};
  for (int e = 0; e < ne; ++e) {
    const auto& h = m.mesh.hex[e];
    auto height = [&](const double* x, const double* y, const double* z, int d) {
      double c[2][3] = {{0, 0, 0}, {0, 0, 0}};
      for (int f = 0; f < 2; ++f)
        for (int a : faces[d][f]) c[f][0] += x[h[a]] / 4, c[f][1] += y[h[a]] / 4, c[f][2] += z[h[a]] / 4;
      return std::sqrt((c[1][0] - c[0][0]) * (c[1][0] - c[0][0]) + (c[1][1] - c[0][1]) * (c[1][1] - c[0][1]) +
                       (c[1][2] - c[0][2]) * (c[1][2] - c[0][2]));
    };
    int d0 = 0;
    double h0 = INFINITY;
    for (int d = 0; d < 3; ++d) {
      const double hd = height(m.mesh.x.data(), m.mesh.y.data(), m.mesh.z.data(), d);
      if (hd < h0) h0 = hd, d0 = d;
    }
    thick[e] = height(s.x().data(), s.y().data(), s.z().data(), d0);
    thick_ratio[e] = h0 > 0 ? thick[e] / h0 : 1.0;
  }
  write_vtu(path, vm_,
            {{"displacement_mm", 3, disp.data()}, {"velocity_mm_s", 3, vel.data()}, {"contact_pressure_MPa", 1, pres.data()},
             {"friction_traction_MPa", 3, trac.data()}, {"slip_rate_mm_s", 1, slip.data()}, {"local_mu", 1, mu.data()}},
            {{"stress_MPa", 6, sg.data()}, {"von_mises_MPa", 1, vm.data()}, {"plastic_strain", 1, ep.data()},
             {"element_thickness_mm", 1, thick.data()}, {"thickness_ratio", 1, thick_ratio.data()}}, s.time());
}

void parse_checkpoint_every(const std::string& spec, RunOptions& opt) {
  const bool seconds = !spec.empty() && spec.back() == 's';
  const std::string num = seconds ? spec.substr(0, spec.size() - 1) : spec;
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(num, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const bool ok = used == num.size() && !num.empty() && v > 0 && std::isfinite(v) && (seconds || v == std::floor(v));
  if (!ok)
    throw std::invalid_argument("--checkpoint-every: expected a whole number of cycles (e.g. 500) or simulated seconds "
                                "with an 's' (e.g. 2e-3s), found '" + spec + "'");
  if (seconds) opt.checkpoint_every_s = v;
  else opt.checkpoint_every_cycles = static_cast<long>(v);
}

RunSummary run_case(Deck& deck, const RunOptions& opt, std::ostream& log) {
  namespace fs = std::filesystem;
  ensure_writable_dir(opt.out_dir, "output folder");
  const int threads = opt.threads > 0 ? opt.threads : deck.threads;
  if (threads > 0) omp_set_num_threads(threads);
  const auto wall0 = std::chrono::steady_clock::now();
  for (const auto& w : deck.warnings) log << "warning: " << w << "\n";  // before the solver can fail
  fe::Solver solver(deck.model);
  solver.set_warning_handler([&log](const std::string& w) { log << "\nwarning: " << w << "\n"; });
  const fe::Model& m = deck.model;
  double total = 0;
  for (const auto& s : m.steps) total += s.duration;
  log << "case " << m.name << ": " << m.mesh.num_elements() << " elements, " << m.mesh.num_nodes() << " nodes, "
      << m.steps.size() << " steps, " << total << " s simulated; dt = " << solver.stable_dt() << " s; mass scaling x"
      << fmt(1 + solver.added_mass() / solver.physical_mass(), 4) << " (units: mm, N, MPa, s)\n";
  if (deck.cost.cycles > 0)
    log << "  estimate: about " << fmt(deck.cost.cycles, 3) << " cycles at the initial step (limit "
        << fmt_shortest(deck.limits.max_cycles) << "), memory about " << fmt(deck.cost.memory_mb, 3) << " MB (limit "
        << fmt_shortest(deck.limits.max_memory_mb) << "), output about " << fmt(deck.cost.output_mb, 3)
        << " MB (limit " << fmt_shortest(deck.limits.max_output_mb) << "); [limits] in the deck raises them\n";
  log << "  threads: " << omp_get_max_threads() << " ("
      << (opt.threads > 0    ? "--threads"
          : deck.threads > 0 ? "the deck's [numerics] threads"
                             : "set by the process: OMP_NUM_THREADS, the calling command (drawbend-deck --run "
                               "--threads) or a case pool's share, else every hardware thread")
      << ")\n";
  // History file.
  std::vector<std::string> header = run_output::run_history_columns();
  std::vector<int> elements;  // per signal: the tracked element of a "strain" signal
  for (const auto& h : deck.output.history) {
    header.push_back(h.name);
    elements.push_back(h.kind == "strain" ? nearest_element(m.mesh, h.point) : -1);
  }
  CsvWriter hist(header);
  hist.comment("time histories of " + deck.path + " (energies in mJ = N mm)");
  RunState rs;
  auto snapshot = [&]() {
    const std::string name = "fields_" + std::to_string(rs.snap) + ".vtu";
    write_fields(solver, (fs::path(opt.out_dir) / name).string());
    write_contact_maps(solver, opt.out_dir, rs.snap);
    rs.snapshots.push_back({solver.time(), name});
    ++rs.snap;
  };
  if (opt.restart.empty()) {
    snapshot();
  } else {
    rs = read_checkpoint(opt.restart, deck.hash, solver);
    for (const auto& row : rs.history_rows) hist.row(row);
    log << "restarted from " << opt.restart << " at t = " << solver.time() << " s, cycle " << solver.cycles() << std::endl;  // flushed: a watcher may act on it
  }
  double& next_hist = rs.next_hist;
  double& next_field = rs.next_field;
  int& current_step = rs.current_step;
  double last_print = -1;
  RunSummary r;
  const std::string ckpt_path = (fs::path(opt.out_dir) / "checkpoint.bin").string();
  double next_ckpt_time = opt.checkpoint_every_s > 0 ? solver.time() + opt.checkpoint_every_s : 0;
  struct Halt {};
  auto wall_last = std::chrono::steady_clock::now();
  const auto wall_run0 = wall_last;  // the time left comes from the cycles done in this run
  const long cycle0 = solver.cycles();
  try {
  solver.run([&](const fe::Progress& p) {
    const double interval =
        deck.output.history_interval > 0 ? deck.output.history_interval : p.step->duration / 200.0;
    if (p.step_index != current_step) {
      current_step = p.step_index;
      next_hist = p.time - p.step_time;
      next_field = next_hist + p.step->duration / std::max(1, deck.output.fields_per_step);
    }
    const auto& e = solver.energies();
    if (p.time >= next_hist - 1e-15) {
      // The run's own columns, in the order of run_output::run_history_columns().
      std::vector<std::string> row{fmt(p.time, 10), p.step->name, fmt(p.dt, 6), fmt(e.kinetic, 8), fmt(e.internal, 8),
                                   fmt(e.hourglass, 8), fmt(e.external_work, 8), fmt(e.friction, 8),
                                   fmt(e.damping, 8), fmt(e.balance_error(), 4)};
      for (std::size_t k = 0; k < deck.output.history.size(); ++k)
        row.push_back(fmt(signal(solver, deck.output.history[k], elements[k]), 8));
      hist.row(row);
      next_hist += interval;
    }
    if (p.step_time >= p.step->duration * (1 - 1e-12) || p.time >= next_field - 1e-15) {
      snapshot();
      next_field += p.step->duration / std::max(1, deck.output.fields_per_step);
    }
    const auto now = std::chrono::steady_clock::now();
    if (!opt.quiet && std::chrono::duration<double>(now - wall_last).count() > opt.progress_every_s) {
      wall_last = now;
      // Time left = wall time per cycle so far x the cycles still to run at the
      // current stable step (the step only shrinks, so this is a lower bound).
      const double el = std::chrono::duration<double>(now - wall_run0).count();
      const double frac = p.time / total;
      const double done = static_cast<double>(p.cycle - cycle0);
      const double to_go = std::max(0.0, total - p.time) / solver.dt();
      std::ostringstream line;  // its own stream: the log's number format stays as it was
      line << "\r  " << std::fixed << std::setprecision(1) << 100 * frac << " %  t = " << std::scientific
           << std::setprecision(3) << p.time << " s  dt = " << p.dt << " s  step " << p.step->name << "  cycle "
           << p.cycle << " of ~" << static_cast<long>(p.cycle + to_go) << "  left ~" << std::fixed
           << std::setprecision(0) << (done > 0 ? el / done * to_go : 0.0) << " s   ";
      log << line.str() << std::flush;
      last_print = p.time;
    }
    const bool by_cycles = opt.checkpoint_every_cycles > 0 && p.cycle % opt.checkpoint_every_cycles == 0;
    const bool by_time = opt.checkpoint_every_s > 0 && p.time >= next_ckpt_time;
    const int sig = opt.stop ? static_cast<int>(*opt.stop) : 0;
    if (sig != 0) {  // SIGINT/SIGTERM: checkpoint at this cycle boundary and stop
      rs.history_rows = hist.rows();
      write_checkpoint(ckpt_path, deck.hash, solver, rs);
      r.checkpoint = ckpt_path;
      r.interrupted = sig;
      throw Halt{};
    }
    if (by_cycles || by_time) {
      if (by_time)
        while (next_ckpt_time <= p.time) next_ckpt_time += opt.checkpoint_every_s;
      rs.history_rows = hist.rows();
      write_checkpoint(ckpt_path, deck.hash, solver, rs);
      r.checkpoint = ckpt_path;
      if (opt.halt_after_cycles > 0 && p.cycle >= opt.halt_after_cycles) throw Halt{};
    }
  });
  } catch (const fe::NumericalFault&) {
    // Keep what was recorded up to the fault: it shows how the run got there.
    if (last_print >= 0) log << "\n";
    hist.save((fs::path(opt.out_dir) / run_output::kHistoryFile).string());
    log << "history up to the fault: " << (fs::path(opt.out_dir) / run_output::kHistoryFile).string() << "\n";
    throw;
  } catch (const Halt&) {
    if (last_print >= 0) log << "\n";
    if (r.interrupted)
      log << "interrupted at t = " << solver.time() << " s, cycle " << solver.cycles()
          << "; continue with: drawbend run " << deck.path << " --out " << opt.out_dir << " --restart " << ckpt_path
          << "\n";
    else
      log << "halted after cycle " << solver.cycles() << " (t = " << solver.time() << " s); continue with --restart "
          << ckpt_path << "\n";
    r.halted = true;
    r.time = solver.time();
    r.cycles = solver.cycles();
    return r;
  }
  if (last_print >= 0) log << "\n";
  hist.save((fs::path(opt.out_dir) / run_output::kHistoryFile).string());
  write_pvd((fs::path(opt.out_dir) / "fields.pvd").string(), rs.snapshots);
  const auto& e = solver.energies();
  r.time = solver.time();
  r.cycles = solver.cycles();
  r.energy_balance_error = e.balance_error();
  r.hourglass_ratio = e.internal > 0 ? e.hourglass / e.internal : 0;
  r.kinetic_ratio = e.internal > 0 ? e.kinetic / e.internal : 0;
  r.added_mass_ratio = solver.added_mass() / solver.physical_mass();
  r.max_penetration = solver.max_penetration();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  CsvWriter sum({"quantity", "value", "unit"});
  sum.comment("end-of-run summary of " + deck.path);
  sum.row({"time", fmt(r.time), "s"});
  sum.row({"cycles", std::to_string(r.cycles), "-"});
  sum.row({"energy_balance_error", fmt(r.energy_balance_error, 4), "-"});
  sum.row({"hourglass_over_internal", fmt(r.hourglass_ratio, 4), "-"});
  sum.row({"kinetic_over_internal", fmt(r.kinetic_ratio, 4), "-"});
  sum.row({"added_mass_ratio", fmt(r.added_mass_ratio, 4), "-"});
  sum.row({"max_penetration", fmt(r.max_penetration, 4), "mm"});
  sum.row({"wall_time", fmt(r.wall_seconds, 4), "s"});
  // Friction-law event counts (e.g. evaluations clamped to the mu(p, v) domain), once per run.
  std::string flog;
  for (int p = 0; p < solver.num_contact_pairs(); ++p)
    if (const auto& law = m.contacts[p].friction)
      for (const auto& [name, n] : law->counters(solver.friction_state(p))) {
        sum.row({"contact" + std::to_string(p) + "_" + name, fmt(n, 12), "evaluations"});
        if (n > 0 && name.rfind("clamped", 0) == 0)
          flog += "  warning: contact " + std::to_string(p) + " (" + m.contacts[p].tool + "): " + fmt(n, 12) + " " +
                  name + " (friction evaluated at the domain edge)\n";
      }
  sum.save((fs::path(opt.out_dir) / "summary.csv").string());
  // The energy line adds up as printed: the work done on the sheet equals
  // what it holds and what was removed, plus the residual the balance check
  // measures (fe/solver.hpp, Energies::balance_error).
  const double held = e.kinetic + e.internal + e.hourglass + e.damping - e.initial_kinetic;
  // One number of decimals for every term (4 significant digits of the largest), so the sum reads exactly.
  double big = std::abs(e.external_work);
  for (double v : {e.kinetic, e.internal, e.hourglass, e.damping, e.initial_kinetic}) big = std::max(big, std::abs(v));
  const int dec = big > 0 ? std::clamp(3 - static_cast<int>(std::floor(std::log10(big))), 0, 12) : 3;
  auto E = [dec](double v) { return fmt_fixed(v, dec); };
  log << "summary: " << r.cycles << " cycles in " << fmt(r.wall_seconds, 3) << " s wall\n"
      << "  energy [mJ]: work on the sheet " << E(e.external_work) << " = kinetic " << E(e.kinetic) << " + internal "
      << E(e.internal) << " + hourglass " << E(e.hourglass) << " + damping " << E(e.damping)
      << (e.initial_kinetic != 0 ? " - initial kinetic " + E(e.initial_kinetic) : "") << " + residual "
      << E(e.external_work - held) << "\n"
      << "  (the work is that of loads, supports and tools, friction included: friction dissipated "
      << fmt(e.friction, 4) << " mJ; the contact penalty springs hold " << fmt(e.contact_stored, 4) << " mJ)\n"
      << "  energy balance error " << fmt(100 * r.energy_balance_error, 3) << " % of the largest energy flow; "
      << "hourglass/internal " << fmt(100 * r.hourglass_ratio, 3) << " %; kinetic/internal "
      << fmt(100 * r.kinetic_ratio, 3) << " %; mass scaling x" << fmt(1 + r.added_mass_ratio, 4)
      << "; max penetration " << fmt(r.max_penetration, 3) << " mm\n" << flog;
  return r;
}

}  // namespace drawbend::io
