#pragma once
// Where a case's deck runs: in this process (`local`, the default), as a Slurm
// job (`slurm`), or through a site's own launcher (`command`).
//
// Contract
// - Every back-end runs the same file-level job: `drawbend run DIR/deck.toml
//   --out DIR --quiet`, its standard output kept as DIR/run.log, exactly what
//   the local path writes.  A run folder is complete when its summary.csv
//   exists: the solver writes it last, and sim::run_drawbend removes it before
//   a case starts, so a job that failed, timed out or was cancelled never
//   leaves a folder that a later run would reuse.  Results do not depend on
//   the back-end (every case is deterministic whatever its thread count).
// - Chosen by `--executor` where a command offers it, else the environment
//   variable DRAWBEND_EXECUTOR, else `local`.  Values: `local`, `slurm`,
//   `command:TEMPLATE` (or `command` with the template in
//   DRAWBEND_EXECUTOR_COMMAND).  A template names the job with {drawbend}
//   {deck} {dir} {args} (more `drawbend run` options the case needs) {name}
//   {cores} {memory_mb} {minutes}; the command must return
//   only when the job has ended, with the job's exit status (e.g.
//   `ssh node{cores}... ` wrappers, `parallel --sshlogin host ...`).
// - slurm: `sbatch --parsable` with the cores, memory and time limit of
//   job_needs() (the cost model), or `srun` when called inside an allocation
//   (SLURM_JOB_ID set).  DRAWBEND_SLURM_ARGS adds sbatch/srun arguments
//   (partition, account, qos).  The state of each job is polled (squeue, then
//   scontrol); a job that ended without a complete run folder is reported with
//   its case, job id, state and the tail of its log.  NODE_FAIL, PREEMPTED and
//   BOOT_FAIL are retried once as they were; TIMEOUT once with twice the time;
//   OUT_OF_MEMORY once with twice the memory.  FAILED and CANCELLED are not
//   retried: a deterministic run fails the same way again, and a cancel is a
//   person's decision.  A rerun of the chapter reruns exactly the cases
//   without a complete folder.
// - The drawbend binary the jobs run: DRAWBEND_BIN, else the build tree's
//   (DRAWBEND_CLI_PATH, set by CMake).  On a cluster the run folders and the
//   binary must be on a file system every node sees (docs/cluster.md).
#include <stdexcept>
#include <string>

namespace drawbend::sim {

enum class ExecutorKind { local, slurm, command };

struct ExecutorConfig {
  ExecutorKind kind = ExecutorKind::local;
  std::string command;     ///< `command`: the template
  std::string drawbend;    ///< the binary the jobs run
  std::string slurm_args;  ///< extra sbatch/srun arguments (DRAWBEND_SLURM_ARGS)
  double poll_seconds = 1;
};

/// `spec` as given to --executor (`where` names the option in messages); an
/// empty spec reads DRAWBEND_EXECUTOR.  Throws std::invalid_argument (exit 2)
/// naming the option or the variable and the valid values.
ExecutorConfig parse_executor(const std::string& spec, const std::string& where = "--executor");

/// The executor of this process: set_executor() if called, else
/// parse_executor("") on first use.
const ExecutorConfig& executor();
void set_executor(const ExecutorConfig& e);
const char* executor_name(ExecutorKind k);

/// What a job asks of its node, from the cost model (cost_model.hpp).
struct JobNeeds {
  int cores = 1;
  double memory_mb = 256;
  double minutes = 10;  ///< the time limit asked for (a generous multiple of the prediction)
};

/// A job that ended without a complete run folder.
struct JobFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Run DIR/deck.toml (already written) as one job of `e` and return when DIR
/// holds a complete run; throws JobFailed otherwise.  Not for `local`.
/// `run_args`: more options of `drawbend run` (words without shell quoting:
/// the draw-bend reduction's --basis, --bending-force, --yield-stress).
void run_deck_external(const ExecutorConfig& e, const std::string& name, const std::string& dir, const JobNeeds& n,
                       const std::string& run_args = "");

/// Concurrent jobs a case pool keeps in flight for `e`: DRAWBEND_JOBS if set;
/// else the hardware threads (local, command) or 256 (slurm: the queue, not
/// this machine, runs them).
int executor_jobs(const ExecutorConfig& e, int local_default);

}  // namespace drawbend::sim
