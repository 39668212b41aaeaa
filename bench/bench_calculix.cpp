// make bench: CalculiX's explicit solver (ccx) and ours on the same bar, in
// the same run, on 1 thread each (bench_calculix.hpp; the deck:
// bench_ccx_deck.cpp).
//
// What is measured: each solver runs the bar of bench_models.hpp over a short
// and a long simulated window (kWindow, from t = 0); cost = (wall(long) -
// wall(short)) / ((cycles(long) - cycles(short)) x elements), which removes
// set-up (ours: building the solver; ccx: process start, reading the deck,
// the matrix structure, and its one output at the end).  ccx is timed as a
// child process (wall clock around fork and wait; CPU = user + system from
// wait4), ours in this process (best of kOursRepeats: ours is cheap to repeat,
// ccx is not).  ccx's time includes whatever else it does per increment
// (its general nonlinear driver, one iteration per explicit increment; about
// a tenth of its CPU time is system time; not profiled further).  ccx's explicit step picks its own stable
// increment (about 0.38 l/c for 1 mm cubes, ours 0.8 l/c), so it takes about
// twice our cycles for the same window: the summary gives the ratio per
// element-cycle and per simulated time.
// First measured 2026-11-26 on an AMD EPYC with 2 cores (AVX-512), with
// other jobs on the machine: the numbers are loaded; compare only those of
// one run.
#include "bench_calculix.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include <omp.h>

#include "bench_ccx_deck.hpp"
#include "bench_models.hpp"
#include "fe/solver.hpp"

extern char** environ;
using namespace drawbend;

namespace {
constexpr double kWindow[2] = {2e-5, 1.2e-4};  // simulated seconds: 0.4 and 2.4 mm of pull at 20 m/s
constexpr int kOursRepeats = 3;
constexpr double kTimeout = 300;     // s: a ccx run still going then is ended and reported
constexpr double kMaxEstimate = 60;  // s: the 8,000 bar runs only if ccx's estimated time is below this

struct ChildRun {
  bool ok = false;
  double wall = 0, cpu = 0;  // [s]
  std::string why;
};

// ccx -i JOB in `dir` on one thread, its stdout and stderr into `log`.
ChildRun run_ccx(const std::string& ccx, const std::string& dir, const std::string& job, const std::string& log) {
  // Everything the child needs is built before fork (no allocation after it).
  std::vector<std::string> env;
  const std::vector<std::string> one = {"OMP_NUM_THREADS=1", "NUMBER_OF_CPUS=1", "CCX_NPROC_EQUATION_SOLVER=1",
                                        "CCX_NPROC_RESULTS=1", "CCX_NPROC_STIFFNESS=1"};
  for (char** e = environ; *e; ++e) {
    const std::string s(*e);
    if (std::none_of(one.begin(), one.end(), [&](const std::string& o) { return s.rfind(o.substr(0, o.find('=') + 1), 0) == 0; }))
      env.push_back(s);
  }
  env.insert(env.end(), one.begin(), one.end());
  std::vector<char*> envp, argv;
  for (auto& s : env) envp.push_back(s.data());
  envp.push_back(nullptr);
  std::string a0 = ccx, a1 = "-i", a2 = job;
  argv = {a0.data(), a1.data(), a2.data(), nullptr};
  ChildRun r;
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) {
    r.why = "fork failed";
    return r;
  }
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || chdir(dir.c_str()) != 0) _exit(126);
    dup2(fd, 1);
    dup2(fd, 2);
    execve(ccx.c_str(), argv.data(), envp.data());
    _exit(127);
  }
  int status = 0;
  rusage ru{};
  for (;;) {
    const pid_t w = wait4(pid, &status, WNOHANG, &ru);
    if (w == pid) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > kTimeout) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &ru);
      r.why = "no result in " + fmt(kTimeout, 3) + " s (ended)";
      return r;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu = ru.ru_utime.tv_sec + ru.ru_stime.tv_sec + 1e-6 * (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!r.ok) r.why = "ccx exit status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + " (see " + log + ")";
  return r;
}

double process_cpu() {  // [s], all threads of this process
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

struct OursRun {
  double wall = 0, cpu = 0, dt0 = 0;
  long cycles = 0;
  Vec3 rf{0, 0, 0}, u{0, 0, 0};
};

struct WindowOver {};  // the window is over

// Ours on one thread from t = 0 to the first cycle ending at or after `T`.
OursRun run_ours(const fe::Model& model, double T, int probe) {
  fe::Model m = model;
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = process_cpu();
  fe::Solver s(m);
  OursRun r;
  r.dt0 = s.dt();
  try {
    s.run_step(0, [&](const fe::Progress& p) {
      if (p.time >= T) throw WindowOver{};
    });
  } catch (const WindowOver&) {
  }
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu = process_cpu() - c0;
  r.cycles = s.cycles();
  r.rf = s.reaction("xmin");
  r.u = {s.x()[probe] - m.mesh.x[probe], s.y()[probe] - m.mesh.y[probe], s.z()[probe] - m.mesh.z[probe]};
  return r;
}

// Mid-length node on the edge y = ymax, z = zmax.
int probe_node(const fe::Mesh& mesh) {
  const double xm = *std::max_element(mesh.x.begin(), mesh.x.end()) / 2;
  const double ym = *std::max_element(mesh.y.begin(), mesh.y.end()), zm = *std::max_element(mesh.z.begin(), mesh.z.end());
  int best = 0;
  for (int n = 1; n < mesh.num_nodes(); ++n) {
    auto d = [&](int k) { return std::abs(mesh.x[k] - xm) + std::abs(mesh.y[k] - ym) + std::abs(mesh.z[k] - zm); };
    if (d(n) < d(best)) best = n;
  }
  return best;
}

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-30); }

void compare(const std::string& name, const fe::Model& model, const std::string& ccx, const std::string& dir,
             PeerResult& r) {
  const int probe = probe_node(model.mesh);
  omp_set_num_threads(1);
  for (int k = 0; k < 2; ++k) {
    r.window[k] = kWindow[k];
    OursRun best;
    for (int rep = 0; rep < kOursRepeats; ++rep) {
      const OursRun o = run_ours(model, kWindow[k], probe);
      if (rep == 0 || o.wall < best.wall) best = o;
    }
    r.ours_wall[k] = best.wall;
    r.ours_cpu[k] = best.cpu;
    r.ours_cycles[k] = best.cycles;
    r.ours_dt = best.dt0;
    r.ours_rf = best.rf;
    r.ours_u = best.u;
    const std::string job = name + "_" + std::to_string(k), log = dir + "/" + job + ".log";
    std::ofstream(dir + "/" + job + ".inp") << ccx_bar_deck(model, kWindow[k], probe);
    const ChildRun c = run_ccx(ccx, dir, job, log);
    std::string why = c.why;
    const auto out = c.ok ? read_ccx_output(dir, job, log, why) : std::nullopt;
    if (!out) {
      r.note = "ccx failed on " + job + ": " + why;
      return;
    }
    r.ccx_wall[k] = c.wall;
    r.ccx_cpu[k] = c.cpu;
    r.ccx_incs[k] = out->increments;
    r.ccx_dt = out->dt;
    r.version = out->version;
    r.ccx_rf = out->reaction;
    r.ccx_u = out->probe_u;
  }
  const double ne = static_cast<double>(r.elements);
  r.ccx_ns = (r.ccx_wall[1] - r.ccx_wall[0]) / ((r.ccx_incs[1] - r.ccx_incs[0]) * ne) * 1e9;
  r.ccx_cpu_ns = (r.ccx_cpu[1] - r.ccx_cpu[0]) / ((r.ccx_incs[1] - r.ccx_incs[0]) * ne) * 1e9;
  r.ours_ns = (r.ours_wall[1] - r.ours_wall[0]) / ((r.ours_cycles[1] - r.ours_cycles[0]) * ne) * 1e9;
  r.ours_cpu_ns = (r.ours_cpu[1] - r.ours_cpu[0]) / ((r.ours_cycles[1] - r.ours_cycles[0]) * ne) * 1e9;
  const double unorm = std::hypot(r.ours_u[0], r.ours_u[1], r.ours_u[2]);
  r.mismatch = rel(std::abs(r.ccx_rf[0]), std::abs(r.ours_rf[0]));
  for (int i = 0; i < 3; ++i) r.mismatch = std::max(r.mismatch, std::abs(r.ccx_u[i] - r.ours_u[i]) / unorm);
}

std::string thousands(long n) {
  std::string s = std::to_string(n);
  for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3) s.insert(i, ",");
  return s;
}

std::string vec(const Vec3& v) { return fmt(v[0], 4) + " " + fmt(v[1], 4) + " " + fmt(v[2], 4); }
}  // namespace

std::string find_ccx() {
  const char* path = std::getenv("PATH");
  std::string p = path ? path : "";
  for (std::size_t b = 0; b <= p.size();) {
    const std::size_t e = std::min(p.find(':', b), p.size());
    const std::string cand = (e > b ? p.substr(b, e - b) : ".") + "/ccx";
    if (access(cand.c_str(), X_OK) == 0) return cand;
    b = e + 1;
  }
  return "";
}

std::vector<PeerResult> bench_calculix(const std::string& dir, CsvWriter& w, bool quick) {
  const std::string ccx = find_ccx();
  if (ccx.empty()) {
    w.comment("CalculiX: not installed (optional; scripts/install-deps.sh installs calculix-ccx)");
    std::cout << "CalculiX: not installed (optional; scripts/install-deps.sh installs calculix-ccx)\n";
    return {};
  }
  std::vector<PeerResult> peers;
  const std::vector<std::pair<std::string, fe::Model>> bars = {{"bar_1600", bar(40, 8, 5)}, {"bar_8000", bar(100, 16, 5)}};
  for (const auto& [name, model] : bars) {
    PeerResult r;
    r.name = name;
    r.elements = model.mesh.num_elements();
    const std::string run_dir = dir + "/ccx_" + name;
    try {
      if (!peers.empty()) {  // the larger bar only when it is quick enough
        const PeerResult& p = peers.front();
        const double est = (p.ccx_wall[0] + p.ccx_wall[1]) * r.elements / p.elements;
        if (quick) r.note = "skipped (--quick)";
        else if (!p.note.empty()) r.note = "skipped (" + p.name + " did not run)";
        else if (est > kMaxEstimate) r.note = "skipped: ccx estimated at " + fmt(est, 2) + " s";
      }
      if (r.note.empty()) {
        std::filesystem::remove_all(run_dir);
        std::filesystem::create_directories(run_dir);
        compare(name, model, ccx, run_dir, r);
      }
    } catch (const std::exception& e) {
      r.note = std::string("ccx comparison failed: ") + e.what();
    }
    peers.push_back(r);
    if (!r.note.empty()) {
      std::cout << "CalculiX " << name << ": " << r.note << "\n";
      w.comment("CalculiX " + name + ": " + r.note);
      continue;
    }
    std::filesystem::remove_all(run_dir);  // kept when ccx failed, for its log
    for (int k = 0; k < 2; ++k)
      std::cout << "CalculiX " << name << ", " << fmt(r.window[k] * 1e6, 3) << " us simulated: ccx " << r.ccx_incs[k]
                << " increments, " << fmt(r.ccx_wall[k], 4) << " s wall, " << fmt(r.ccx_cpu[k], 4)
                << " s CPU; ours " << r.ours_cycles[k] << " cycles, " << fmt(r.ours_wall[k], 4) << " s wall, "
                << fmt(r.ours_cpu[k], 4) << " s CPU\n";
    w.row({"calculix_" + name, std::to_string(r.elements), "1", fmt(r.ccx_ns, 5)});
    w.row({name + "_ccx_window", std::to_string(r.elements), "1", fmt(r.ours_ns, 5)});
    w.comment("CalculiX ccx " + r.version + " " + name + ": ratio ccx/ours " + fmt(r.ccx_ns / r.ours_ns, 3) +
              " per element-cycle (CPU " + fmt(r.ccx_cpu_ns / r.ours_cpu_ns, 3) + "); steps ccx " + fmt(r.ccx_dt, 4) + " s, ours " + fmt(r.ours_dt, 4) +
              " s; RF_x on xmin ccx " + fmt(r.ccx_rf[0], 4) + " N, ours " + fmt(r.ours_rf[0], 4) + " N");
  }
  return peers;
}

void print_calculix_summary(const std::vector<PeerResult>& peers, bool installed) {
  std::cout << "\nPeer (issue 22, item 6), 1 thread each, same bar over the same simulated windows:\n";
  if (!installed) std::cout << "CalculiX: not installed (optional; scripts/install-deps.sh installs calculix-ccx)\n";
  for (const auto& r : peers) {
    if (!r.note.empty()) {
      std::cout << "CalculiX " << r.name << ": " << r.note << "\n";
      continue;
    }
    const double sim = (r.ccx_wall[1] - r.ccx_wall[0]) / (r.ours_wall[1] - r.ours_wall[0]);
    std::cout << "CalculiX ccx " << r.version << " bar " << thousands(r.elements) << ": " << fmt(r.ccx_ns, 4)
              << " ns/element-cycle (1 thread), ours " << fmt(r.ours_ns, 4) << " ns: ratio "
              << fmt(r.ccx_ns / r.ours_ns, 3) << "\n  CPU time: ccx " << fmt(r.ccx_cpu_ns, 4) << " ns, ours "
              << fmt(r.ours_cpu_ns, 4) << " ns: ratio " << fmt(r.ccx_cpu_ns / r.ours_cpu_ns, 3) << "\n"
              << "  steps: ccx " << fmt(r.ccx_dt, 4) << " s (its own stable increment, fixed), ours " << fmt(r.ours_dt, 4)
              << " s at the start; cycles over " << fmt((r.window[1] - r.window[0]) * 1e6, 3) << " us: ccx "
              << r.ccx_incs[1] - r.ccx_incs[0] << ", ours " << r.ours_cycles[1] - r.ours_cycles[0]
              << "; ratio per simulated time " << fmt(sim, 3) << "\n"
              << "  at " << fmt(r.window[1] * 1e6, 3) << " us: RF_x on xmin ccx " << fmt(r.ccx_rf[0], 4) << " N, ours "
              << fmt(r.ours_rf[0], 4) << " N; mid-length corner u [mm] ccx " << vec(r.ccx_u) << ", ours "
              << vec(r.ours_u) << ": " << (r.agree() ? "same problem (within 5 %)" : "DIFFER")
              << " (largest difference " << fmt(100 * r.mismatch, 2) << " %)\n";
    const double waited = (r.ccx_wall[1] - r.ccx_wall[0]) / (r.ccx_cpu[1] - r.ccx_cpu[0]);
    if (waited > 1.2 || waited < 0.8)
      std::cout << "  note: ccx's wall time is " << fmt(waited, 3) << "x its CPU time: it shared a core with other "
                << "work (a loaded machine); the CPU ratio is the steadier one in this run\n";
  }
}
