#include "io/run_case.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "core/csv.hpp"
#include "core/run_output.hpp"
#include "io/case_reduction.hpp"
#include "io/run_checkpoint.hpp"
#include "io/run_observers.hpp"
#include "io/run_result.hpp"
#include "io/vtu.hpp"

namespace drawbend::io {

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
  // At most 1e15 cycles (a long holds it; 1e300 cycles was cast to a long,
  // undefined behaviour) and 1e6 simulated seconds (no case simulates more).
  const bool ok = used == num.size() && !num.empty() && v > 0 && std::isfinite(v) && (seconds || v == std::floor(v)) &&
                  v <= (seconds ? 1e6 : 1e15);
  if (!ok)
    throw std::invalid_argument("--checkpoint-every: expected a whole number of cycles (e.g. 500, at most 1e15) or "
                                "simulated seconds with an 's' (e.g. 2e-3s, at most 1e6s), found '" + spec + "'");
  if (seconds) opt.checkpoint_every_s = v;
  else opt.checkpoint_every_cycles = static_cast<long>(v);
}

namespace {

void log_header(const Deck& deck, const RunOptions& opt, const fe::Solver& solver, double total, std::ostream& log) {
  const fe::Model& m = deck.model;
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
}

/// fields.pvd: per snapshot k, the sheet (part 0) and each tool (parts 1, 2, ...).
std::vector<PvdEntry> frame_collection(const fe::Model& m, const std::vector<std::pair<double, std::string>>& snaps) {
  std::vector<PvdEntry> out;
  for (std::size_t k = 0; k < snaps.size(); ++k) {
    out.push_back({snaps[k].first, 0, "sheet", snaps[k].second});
    for (std::size_t t = 0; t < m.tools.size(); ++t)
      out.push_back({snaps[k].first, static_cast<int>(t + 1), m.tools[t].name,
                     tool_frame_name(m.tools[t].name, static_cast<int>(k))});
  }
  return out;
}

/// A stop by Halt: the interrupted or halted summary and how to continue.
RunSummary halted(observe::Run& run) {
  const fe::Solver& solver = run.solver;
  if (run.printed) run.log << "\n";
  if (run.r.interrupted)
    run.log << "interrupted at t = " << solver.time() << " s, cycle " << solver.cycles()
            << "; continue with: drawbend run " << run.deck.path << " --out " << run.opt.out_dir << " --restart "
            << run.checkpoint_path << "\n";
  else
    run.log << "halted after cycle " << solver.cycles() << " (t = " << solver.time() << " s); continue with --restart "
            << run.checkpoint_path << "\n";
  run.r.halted = true;
  run.r.time = solver.time();
  run.r.cycles = solver.cycles();
  return run.r;
}

/// summary.csv: the end-of-run invariants and the friction laws' event counts;
/// returns the warnings about clamped friction evaluations for the log.
std::string write_summary(const observe::Run& run) {
  const RunSummary& r = run.r;
  const fe::Solver& solver = run.solver;
  const fe::Model& m = run.deck.model;
  CsvWriter sum({"quantity", "value", "unit"});
  sum.comment("end-of-run summary of " + run.deck.path);
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
  // The material's own event counts (material/material.hpp, event_counts: e.g. Yld2004-18p's returns), over
  // the whole run; a restarted run's material counted only since the restart, so it writes none.
  if (m.material && run.opt.restart.empty())
    for (const auto& [name, n] : m.material->event_counts())
      sum.row({"material_" + name, std::to_string(n), "point updates"});
  sum.save((std::filesystem::path(run.opt.out_dir) / "summary.csv").string());
  return flog;
}

/// The energy line, which adds up as printed: the work done on the sheet
/// equals what it holds and what was removed, plus the residual the balance
/// check measures (fe/solver.hpp, Energies::balance_error).
void log_energies(const observe::Run& run, const std::string& friction_warnings) {
  const RunSummary& r = run.r;
  const auto& e = run.solver.energies();
  const double held = e.kinetic + e.internal + e.hourglass + e.damping - e.initial_kinetic;
  // One number of decimals for every term (4 significant digits of the largest), so the sum reads exactly.
  double big = std::abs(e.external_work);
  for (double v : {e.kinetic, e.internal, e.hourglass, e.damping, e.initial_kinetic}) big = std::max(big, std::abs(v));
  const int dec = big > 0 ? std::clamp(3 - static_cast<int>(std::floor(std::log10(big))), 0, 12) : 3;
  auto E = [dec](double v) { return fmt_fixed(v, dec); };
  run.log << "summary: " << r.cycles << " cycles in " << fmt(r.wall_seconds, 3) << " s wall\n";
  if (std::isfinite(r.cpu_seconds)) run.log << "  cpu: " << fmt(r.cpu_seconds, 4) << " s (the run's one thread)\n";
  run.log
          << "  energy [mJ]: work on the sheet " << E(e.external_work) << " = kinetic " << E(e.kinetic) << " + internal "
          << E(e.internal) << " + hourglass " << E(e.hourglass) << " + damping " << E(e.damping)
          << (e.initial_kinetic != 0 ? " - initial kinetic " + E(e.initial_kinetic) : "") << " + residual "
          << E(e.external_work - held) << "\n"
          << "  (the work is that of loads, supports and tools, friction included: friction dissipated "
          << fmt(e.friction, 4) << " mJ; the contact penalty springs hold " << fmt(e.contact_stored, 4) << " mJ)\n"
          << "  energy balance error " << fmt(100 * r.energy_balance_error, 3) << " % of the largest energy flow; "
          << "hourglass/internal " << fmt(100 * r.hourglass_ratio, 3) << " %; kinetic/internal "
          << fmt(100 * r.kinetic_ratio, 3) << " %; mass scaling x" << fmt(1 + r.added_mass_ratio, 4)
          << "; max penetration " << fmt(r.max_penetration, 3) << " mm\n"
          << friction_warnings;
}

/// The end-of-run invariants into run.r.
/// CPU seconds used by the calling thread so far.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void fill_summary(observe::Run& run, std::chrono::steady_clock::time_point wall0, double cpu0) {
  const fe::Solver& solver = run.solver;
  const auto& e = solver.energies();
  RunSummary& r = run.r;
  r.time = solver.time();
  r.cycles = solver.cycles();
  r.energy_balance_error = e.balance_error();
  r.hourglass_ratio = e.internal > 0 ? e.hourglass / e.internal : 0;
  r.kinetic_ratio = e.internal > 0 ? e.kinetic / e.internal : 0;
  r.added_mass_ratio = solver.added_mass() / solver.physical_mass();
  r.max_penetration = solver.max_penetration();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (omp_get_max_threads() == 1) r.cpu_seconds = thread_cpu_seconds() - cpu0;
}

}  // namespace

// The recipe: set up, start (or restart), run with the observers
// (io/run_observers.hpp), then the final outputs.
RunSummary run_case(Deck& deck, const RunOptions& opt, std::ostream& log) {
  namespace fs = std::filesystem;
  ensure_writable_dir(opt.out_dir, "output folder");
  const int threads = opt.threads > 0 ? opt.threads : deck.threads;
  if (threads > 0) omp_set_num_threads(threads);
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_seconds();
  for (const auto& w : deck.warnings) log << "warning: " << w << "\n";  // before the solver can fail
  fe::Solver solver(deck.model);
  solver.set_warning_handler([&log](const std::string& w) { log << "\nwarning: " << w << "\n"; });
  observe::Run run(deck, opt, solver, log);
  for (const auto& s : deck.model.steps) run.total += s.duration;
  run.checkpoint_path = (fs::path(opt.out_dir) / "checkpoint.bin").string();
  log_header(deck, opt, solver, run.total, log);

  if (!opt.restart.empty()) {
    run.rs = read_checkpoint(opt.restart, deck.hash, solver);
    log << "restarted from " << opt.restart << " at t = " << solver.time() << " s, cycle " << solver.cycles() << std::endl;  // flushed: a watcher may act on it
  }
  observe::History history(run);
  observe::Fields fields(run);
  if (opt.restart.empty()) fields.snapshot();
  observe::Progress progress(run);
  observe::Checkpoints checkpoints(run);
  // The study's own reduction (io/case_reduction.hpp): its sums need every cycle from the start.
  std::unique_ptr<CaseReduction> reduction;
  if (!deck.output.reduce.kind.empty()) {
    if (!opt.restart.empty())
      throw InputError(deck.path + ": output.reduce: a reduction needs the whole run; run the deck again without --restart");
    reduction = make_reduction(deck.output.reduce, deck.model);
  }
  try {
    solver.run([&](const fe::Progress& p) {
      if (reduction) reduction->cycle(solver, p);
      observe::follow_step(run, p);
      history(p);
      fields(p);
      progress(p);
      observe::signal_stop(run, history, p);
      checkpoints(history, p);
    });
  } catch (const fe::NumericalFault&) {
    // Keep what was recorded up to the fault: it shows how the run got there.
    if (run.printed) log << "\n";
    history.save();
    log << "history up to the fault: " << (fs::path(opt.out_dir) / run_output::kHistoryFile).string() << "\n";
    throw;
  } catch (const observe::Halt&) {
    return halted(run);
  }
  if (run.printed) log << "\n";
  history.save();
  write_pvd((fs::path(opt.out_dir) / "fields.pvd").string(), frame_collection(deck.model, run.rs.snapshots));
  if (reduction) write_reduction((fs::path(opt.out_dir) / kReductionFile).string(), "case '" + deck.model.name + "'",
                                   reduction->finish(solver));
  fill_summary(run, wall0, cpu0);
  log_energies(run, write_summary(run));
  write_run_result(deck, solver, opt.out_dir, opt.result, log);  // result.toml (io/run_result.hpp)
  return run.r;
}

}  // namespace drawbend::io
