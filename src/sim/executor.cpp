#include "sim/executor.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

namespace drawbend::sim {

namespace fs = std::filesystem;

namespace {

std::mutex g_mutex;
bool g_set = false;
ExecutorConfig g_exec;

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

/// A word for /bin/sh: single-quoted, with embedded quotes closed and escaped.
std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Run `cmd` under /bin/sh; its standard output (stderr joined) and exit status.
std::pair<std::string, int> shell(const std::string& cmd) {
  std::string out;
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return {"cannot start /bin/sh", 127};
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  const int st = pclose(p);
  const int code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
  return {out, code};
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  std::size_t a = 0;
  while (a < s.size() && s[a] == ' ') ++a;
  return s.substr(a);
}

/// The last lines of a log, for a failure message.
std::string tail(const fs::path& p, int lines = 6) {
  std::ifstream in(p);
  std::vector<std::string> all;
  for (std::string l; std::getline(in, l);) all.push_back(l);
  std::string t;
  for (std::size_t i = all.size() > static_cast<std::size_t>(lines) ? all.size() - lines : 0; i < all.size(); ++i)
    t += "\n    | " + all[i];
  return t;
}

bool complete(const std::string& dir) { return fs::exists(fs::path(dir) / "summary.csv"); }

/// A failed job's summary.csv (if it wrote one) is removed: a rerun reads a
/// case with a summary.csv as finished and would reuse it.
void discard_summary(const std::string& dir) {
  std::error_code ec;
  fs::remove(fs::path(dir) / "summary.csv", ec);
}

/// The job's command line: the same run the local path makes (run.log is its
/// standard output; stderr, the job's own log, goes to job.log).
/// The deck is named by the same path the local path gives the solver (the
/// run folder as the caller named it, relative to the working directory, which
/// a job keeps), so that files quoting it are the same bits.
std::string deck_path(const std::string& dir) { return (fs::path(dir) / "deck.toml").string(); }

std::string job_line(const ExecutorConfig& e, const std::string& dir, int cores, const std::string& run_args) {
  return "exec " + quote(e.drawbend) + " run " + quote(deck_path(dir)) + " --out " + quote(dir) + " " + run_args +
         " --quiet --threads " + std::to_string(cores) + " > " + quote(dir + "/run.log") + " 2> " +
         quote(dir + "/job.log");
}

int minutes_of(double m) { return std::max(1, static_cast<int>(std::ceil(m))); }

/// `scontrol show job` (one line): JobState and ExitCode; "" when Slurm no
/// longer knows the job.
std::pair<std::string, std::string> job_state(const std::string& id) {
  const auto shown = shell("scontrol -o show job " + quote(id));
  const std::string& out = shown.first;  // a plain reference: lambdas may not capture structured bindings (C++17)
  if (shown.second != 0) return {"", ""};
  auto field = [&](const std::string& key) {
    const std::size_t a = out.find(key + "=");
    if (a == std::string::npos) return std::string();
    const std::size_t b = a + key.size() + 1;
    return out.substr(b, out.find_first_of(" \n", b) - b);
  };
  return {field("JobState"), field("ExitCode")};
}

bool running_state(const std::string& s) {
  return s == "PENDING" || s == "RUNNING" || s == "CONFIGURING" || s == "COMPLETING" || s == "REQUEUED" ||
         s == "RESIZING" || s == "SUSPENDED" || s == "STAGE_OUT" || s == "SIGNALING";
}

/// One sbatch job to its end: (job id, final state).
std::pair<std::string, std::string> sbatch_and_wait(const ExecutorConfig& e, const std::string& name,
                                                    const std::string& dir, const JobNeeds& n, const std::string& args) {
  const std::string d = fs::absolute(dir).string();
  std::ostringstream cmd;
  cmd << "sbatch --parsable --job-name=" << quote("drawbend-" + name) << " --output=" << quote(d + "/slurm.log")
      << " --chdir=" << quote(fs::current_path().string())
      << " --ntasks=1 --cpus-per-task=" << n.cores << " --mem=" << static_cast<long>(std::ceil(n.memory_mb))
      << "M --time=" << minutes_of(n.minutes) << " " << e.slurm_args << " --wrap=" << quote(job_line(e, dir, n.cores, args));
  const auto [out, code] = shell(cmd.str());
  const std::string id = trim(out.substr(0, out.find(';')));
  if (code != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw JobFailed("case " + name + ": sbatch refused the job (exit " + std::to_string(code) + "): " + trim(out));
  std::string state;
  for (;;) {
    std::this_thread::sleep_for(std::chrono::duration<double>(e.poll_seconds));
    const auto [q, qc] = shell("squeue -h -j " + quote(id) + " -o %T");
    const std::string s = trim(q);
    if (qc == 0 && running_state(s)) continue;
    const auto [st, ec] = job_state(id);
    if (running_state(st)) continue;
    state = st.empty() ? (complete(dir) ? "COMPLETED" : "UNKNOWN (purged by Slurm)") : st;
    if (!ec.empty() && state == "COMPLETED" && ec != "0:0") state = "FAILED";
    break;
  }
  return {id, state};
}

void run_slurm(const ExecutorConfig& e, const std::string& name, const std::string& dir, JobNeeds n,
               const std::string& args) {
  const fs::path log = fs::path(dir) / "job.log";
  if (!env("SLURM_JOB_ID").empty() && env("DRAWBEND_SLURM_SBATCH").empty()) {
    // Inside an allocation: one job step per case.
    std::ostringstream cmd;
    cmd << "srun --exclusive --nodes=1 --ntasks=1 --cpus-per-task=" << n.cores
        << " --mem=" << static_cast<long>(std::ceil(n.memory_mb)) << "M --time=" << minutes_of(n.minutes)
        << " --job-name=" << quote("drawbend-" + name) << " " << e.slurm_args << " sh -c "
        << quote(job_line(e, dir, n.cores, args));
    const auto [out, code] = shell(cmd.str());
    if (code != 0) discard_summary(dir);
    if (code != 0 || !complete(dir))
      throw JobFailed("case " + name + ": srun job step ended with exit " + std::to_string(code) + " in " +
                      fs::absolute(dir).string() + ": " + trim(out) + tail(log));
    return;
  }
  for (int attempt = 1;; ++attempt) {
    const auto [id, state] = sbatch_and_wait(e, name, dir, n, args);
    if (state == "COMPLETED" && complete(dir)) return;
    const bool again = attempt == 1 && (state == "NODE_FAIL" || state == "PREEMPTED" || state == "BOOT_FAIL" ||
                                        state == "TIMEOUT" || state == "OUT_OF_MEMORY");
    const std::string what = "case " + name + ": Slurm job " + id + " ended " + state + " without a complete run in " +
                             fs::absolute(dir).string();
    // A job that did not end COMPLETED may still have written its summary.csv
    // (cancelled or killed after the solver finished, before the job ended):
    // it is not trusted, so that a later run does not read the case as done.
    discard_summary(dir);
    if (!again) throw JobFailed(what + (attempt > 1 ? " (after one retry)" : "") + tail(log));
    if (state == "TIMEOUT") n.minutes *= 2;
    if (state == "OUT_OF_MEMORY") n.memory_mb *= 2;
    std::fprintf(stderr, "  executor: %s; retrying once\n", what.c_str());
  }
}

void run_command(const ExecutorConfig& e, const std::string& name, const std::string& dir, const JobNeeds& n,
                 const std::string& args) {
  std::string cmd = e.command;
  const std::string d = fs::absolute(dir).string();
  auto sub = [&](const std::string& key, const std::string& value) {
    for (std::size_t a; (a = cmd.find(key)) != std::string::npos;) cmd.replace(a, key.size(), value);
  };
  sub("{drawbend}", quote(e.drawbend));
  sub("{deck}", quote(deck_path(dir)));
  sub("{dir}", quote(dir));
  sub("{name}", quote(name));
  sub("{cores}", std::to_string(n.cores));
  sub("{args}", args);
  sub("{memory_mb}", std::to_string(static_cast<long>(std::ceil(n.memory_mb))));
  sub("{minutes}", std::to_string(minutes_of(n.minutes)));
  const auto [out, code] = shell(cmd);
  if (code != 0) discard_summary(dir);
  if (code != 0 || !complete(dir))
    throw JobFailed("case " + name + ": the executor command ended with exit " + std::to_string(code) +
                    (code == 0 ? " but left no summary.csv" : "") + " in " + d + ": " + trim(out).substr(0, 2000));
}

}  // namespace

const char* executor_name(ExecutorKind k) {
  switch (k) {
    case ExecutorKind::slurm: return "slurm";
    case ExecutorKind::command: return "command";
    default: return "local";
  }
}

ExecutorConfig parse_executor(const std::string& spec_in, const std::string& where_in) {
  std::string spec = spec_in, where = where_in;
  if (spec.empty()) {
    spec = env("DRAWBEND_EXECUTOR");
    where = "DRAWBEND_EXECUTOR";
  }
  ExecutorConfig e;
  e.drawbend = env("DRAWBEND_BIN");
#ifdef DRAWBEND_CLI_PATH
  if (e.drawbend.empty()) e.drawbend = DRAWBEND_CLI_PATH;
#endif
  e.slurm_args = env("DRAWBEND_SLURM_ARGS");
  if (const std::string p = env("DRAWBEND_EXECUTOR_POLL"); !p.empty()) {
    char* end = nullptr;
    const double v = std::strtod(p.c_str(), &end);
    if (end == p.c_str() || *end || !(v > 0 && v <= 600))
      throw std::invalid_argument("DRAWBEND_EXECUTOR_POLL: expected seconds in (0, 600], found '" + p + "'");
    e.poll_seconds = v;
  }
  if (spec.empty() || spec == "local") return e;
  if (spec == "slurm") {
    e.kind = ExecutorKind::slurm;
  } else if (spec == "command" || spec.rfind("command:", 0) == 0) {
    e.kind = ExecutorKind::command;
    e.command = spec == "command" ? env("DRAWBEND_EXECUTOR_COMMAND") : spec.substr(8);
    if (e.command.find("{deck}") == std::string::npos && e.command.find("{dir}") == std::string::npos)
      throw std::invalid_argument(where + ": a command executor needs a template naming {deck} or {dir} (e.g. "
                                  "'command:{drawbend} run {deck} --out {dir} --quiet > {dir}/run.log'), found '" +
                                  e.command.substr(0, 200) + "'");
  } else {
    throw std::invalid_argument(where + ": expected local, slurm or command:TEMPLATE, found '" + spec.substr(0, 200) +
                                "'");
  }
  if (e.drawbend.empty() || !fs::exists(e.drawbend))
    throw std::invalid_argument(where + ": the " + std::string(executor_name(e.kind)) +
                                " executor runs the drawbend binary, not found at '" + e.drawbend +
                                "' (set DRAWBEND_BIN)");
  e.drawbend = fs::absolute(e.drawbend).string();
  return e;
}

const ExecutorConfig& executor() {
  std::lock_guard<std::mutex> lock(g_mutex);
  if (!g_set) {
    g_exec = parse_executor("");
    g_set = true;
  }
  return g_exec;
}

void set_executor(const ExecutorConfig& e) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_exec = e;
  g_set = true;
}

void run_deck_external(const ExecutorConfig& e, const std::string& name, const std::string& dir, const JobNeeds& n,
                       const std::string& run_args) {
  discard_summary(dir);
  if (e.kind == ExecutorKind::slurm) return run_slurm(e, name, dir, n, run_args);
  if (e.kind == ExecutorKind::command) return run_command(e, name, dir, n, run_args);
  throw std::logic_error("run_deck_external: the local executor runs in process");
}

int executor_jobs(const ExecutorConfig& e, int local_default) {
  if (!env("DRAWBEND_JOBS").empty()) return local_default;  // default_case_jobs() already read it
  return e.kind == ExecutorKind::slurm ? 256 : local_default;
}

}  // namespace drawbend::sim
