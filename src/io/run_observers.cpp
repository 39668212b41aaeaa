#include "io/run_observers.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "core/run_output.hpp"
#include "io/run_result.hpp"
#include "io/vtu.hpp"

namespace drawbend::io::observe {

namespace fs = std::filesystem;

namespace {

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

double raw_signal(const fe::Solver& s, const HistorySignal& h, int element);
/// A history signal in the deck's units times its `scale` (io/deck.hpp: e.g. the full-strip columns).
double signal(const fe::Solver& s, const HistorySignal& h, int element) { return h.scale * raw_signal(s, h, element); }

double raw_signal(const fe::Solver& s, const HistorySignal& h, int element) {
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

std::vector<std::string> history_header(const Deck& deck) {
  std::vector<std::string> header = run_output::run_history_columns();
  for (const auto& h : deck.output.history) header.push_back(h.name);
  return header;
}

void write_checkpoint_now(Run& run, const History& history) {
  history.keep(run);
  write_checkpoint(run.checkpoint_path, run.deck.hash, run.solver, run.rs);
  run.r.checkpoint = run.checkpoint_path;
}

}  // namespace

void follow_step(Run& run, const fe::Progress& p) {
  if (p.step_index == run.rs.current_step) return;
  run.rs.current_step = p.step_index;
  run.rs.next_hist = p.time - p.step_time;
  run.rs.next_field = run.rs.next_hist + p.step->duration / std::max(1, run.deck.output.fields_per_step);
}

History::History(Run& run) : run_(run), table_(history_header(run.deck)) {
  for (const auto& h : run.deck.output.history)
    elements_.push_back(h.kind == "strain" ? std::max(0, fe::nearest_element(run.deck.model.mesh, h.point[0], h.point[1], h.point[2])) : -1);
  table_.comment("time histories of " + run.deck.path + " (energies in mJ = N mm)");
  for (const auto& note : history_notes(run.deck)) table_.comment(note);  // basis and signs (io/run_result.hpp)
  for (const auto& row : run.rs.history_rows) table_.row(row);  // a restart's rows so far
}

void History::operator()(const fe::Progress& p) {
  const Deck& deck = run_.deck;
  const double interval = deck.output.history_interval > 0 ? deck.output.history_interval : p.step->duration / 200.0;
  if (!(p.time >= run_.rs.next_hist - 1e-15)) return;
  const auto& e = run_.solver.energies();
  // The run's own columns, in the order of run_output::run_history_columns().
  std::vector<std::string> row{fmt(p.time, 10), p.step->name, fmt(p.dt, 6), fmt(e.kinetic, 8), fmt(e.internal, 8),
                               fmt(e.hourglass, 8), fmt(e.external_work, 8), fmt(e.friction, 8),
                               fmt(e.damping, 8), fmt(e.balance_error(), 4)};
  for (std::size_t k = 0; k < deck.output.history.size(); ++k)
    row.push_back(fmt(signal(run_.solver, deck.output.history[k], elements_[k]), 8));
  table_.row(row);
  run_.rs.next_hist += interval;
}

void History::save() const { table_.save((fs::path(run_.opt.out_dir) / run_output::kHistoryFile).string()); }

void Fields::snapshot() {
  RunState& rs = run_.rs;
  const std::string name = "fields_" + std::to_string(rs.snap) + ".vtu";
  const VtkFormat format = run_.deck.output.vtk_ascii ? VtkFormat::ascii : VtkFormat::zlib;
  write_fields(run_.solver, (fs::path(run_.opt.out_dir) / name).string(), format);
  write_tool_frames(run_.solver, run_.opt.out_dir, rs.snap, format);
  // The frame as one multiblock dataset: the sheet and each tool (fields.pvd lists the same as parts).
  std::vector<std::pair<std::string, std::string>> blocks{{"sheet", name}};
  for (const auto& t : run_.deck.model.tools) blocks.push_back({t.name, tool_frame_name(t.name, rs.snap)});
  write_vtm((fs::path(run_.opt.out_dir) / ("fields_" + std::to_string(rs.snap) + ".vtm")).string(), blocks);
  write_contact_maps(run_.solver, run_.opt.out_dir, rs.snap);
  rs.snapshots.push_back({run_.solver.time(), name});
  ++rs.snap;
}

void Fields::operator()(const fe::Progress& p) {
  if (p.step_time >= p.step->duration * (1 - 1e-12) || p.time >= run_.rs.next_field - 1e-15) {
    snapshot();
    run_.rs.next_field += p.step->duration / std::max(1, run_.deck.output.fields_per_step);
  }
}

Progress::Progress(Run& run)
    : run_(run), last_(std::chrono::steady_clock::now()), start_(last_), cycle0_(run.solver.cycles()) {}

void Progress::operator()(const fe::Progress& p) {
  const auto now = std::chrono::steady_clock::now();
  if (run_.opt.quiet || !(std::chrono::duration<double>(now - last_).count() > run_.opt.progress_every_s)) return;
  last_ = now;
  // Time left = wall time per cycle so far x the cycles still to run at the
  // current stable step (the step only shrinks, so this is a lower bound).
  const double el = std::chrono::duration<double>(now - start_).count();
  const double frac = p.time / run_.total;
  const double done = static_cast<double>(p.cycle - cycle0_);
  const double to_go = std::max(0.0, run_.total - p.time) / run_.solver.dt();
  std::ostringstream line;  // its own stream: the log's number format stays as it was
  line << "\r  " << std::fixed << std::setprecision(1) << 100 * frac << " %  t = " << std::scientific
       << std::setprecision(3) << p.time << " s  dt = " << p.dt << " s  step " << p.step->name << "  cycle " << p.cycle
       << " of ~" << static_cast<long>(p.cycle + to_go) << "  left ~" << std::fixed << std::setprecision(0)
       << (done > 0 ? el / done * to_go : 0.0) << " s   ";
  run_.log << line.str() << std::flush;
  run_.printed = true;
}

void signal_stop(Run& run, const History& history, const fe::Progress&) {
  const int sig = run.opt.stop ? static_cast<int>(*run.opt.stop) : 0;
  if (sig == 0) return;
  write_checkpoint_now(run, history);
  run.r.interrupted = sig;
  throw Halt{};
}

Checkpoints::Checkpoints(Run& run)
    : run_(run), next_time_(run.opt.checkpoint_every_s > 0 ? run.solver.time() + run.opt.checkpoint_every_s : 0) {}

void Checkpoints::operator()(const History& history, const fe::Progress& p) {
  const RunOptions& opt = run_.opt;
  const bool by_cycles = opt.checkpoint_every_cycles > 0 && p.cycle % opt.checkpoint_every_cycles == 0;
  const bool by_time = opt.checkpoint_every_s > 0 && p.time >= next_time_;
  if (!by_cycles && !by_time) return;
  if (by_time) {
    // The next time after p.time.  An interval far below the time's spacing
    // of doubles (--checkpoint-every 1e-300s at t = 1e-7 s) adds nothing to
    // next_time_, and the loop of additions never ended (a hang that SIGTERM
    // could not stop); after a few additions, jump straight past p.time.
    for (int adds = 0; next_time_ <= p.time; ++adds) {
      const double next = next_time_ + opt.checkpoint_every_s;
      if (adds >= 64 || !(next > next_time_)) {
        next_time_ = std::nextafter(p.time, HUGE_VAL);
        break;
      }
      next_time_ = next;
    }
  }
  write_checkpoint_now(run_, history);
  if (opt.halt_after_cycles > 0 && p.cycle >= opt.halt_after_cycles) throw Halt{};
}

}  // namespace drawbend::io::observe
