// drawbend loop DATA.csv --out DIR [--maps DIR] [...]
//   Closes the loop on measured data (format: README.md): base model, held-out
//   residuals, candidate ranking, library effects, iterate; writes loop.md,
//   loop_summary.json, tables/ and figures/ under DIR.  Data problems are
//   reported (file:line: column) and the usable rows analysed.
// drawbend synth --effect E --noise N --seed S --out DIR [--maps DIR]
//   Synthetic data with a hidden law: DIR/data.csv and DIR/truth.json.
// drawbend synth --from-thesis --out DIR [--data DIR] [--points 7]
//   The thesis fits sampled into the sample format: DIR/thesis_drawbend.csv.
// Exit codes: 0 ok, 2 bad input, 3 numerical failure.
#include "cli/exit_codes.hpp"
#include "core/install_paths.hpp"
#include "cli/loop_cmd.hpp"
#include "cli/threads.hpp"
#include "loop/blind_synth.hpp"
#include "loop/wild_synth.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>

#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "core/options.hpp"
#include "core/strip_limits.hpp"
#include "loop/loop.hpp"
#include "loop/report.hpp"
#include "loop/synth.hpp"
#include "loop/thesis_rows.hpp"
#include "loop/data_physics.hpp"

namespace drawbend::cli {

namespace fs = std::filesystem;
using namespace drawbend::loop;

namespace {
MapLibrary maps_for(const std::string& dir, const std::vector<double>& pins) {
  if (!dir.empty()) return MapLibrary::load_dir(dir);
  return MapLibrary::stand_in(pins);
}

}  // namespace

namespace {
/// The value of `--model X` / `--model=X` in argv (empty if absent); removes it
/// from args.  Throws InputError when --model has no value.
std::string take_model(std::vector<char*>& args) {
  std::string model;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string a = args[i];
    if (a == "--model") {
      if (i + 1 >= args.size()) throw InputError("--model: missing value (empirical or fe)");
      model = args[i + 1];
      args.erase(args.begin() + i, args.begin() + i + 2);
      return model;
    }
    if (a.rfind("--model=", 0) == 0) {
      model = a.substr(8);
      args.erase(args.begin() + i);
      return model;
    }
  }
  return model;
}
}  // namespace

namespace {
/// The values of `drawbend loop`'s options, bound to its Options by
/// add_loop_options (a LoopArgs does not move once bound).
struct LoopArgs {
  LoopOptions lo;
  std::string out = "loop-out", maps_dir, bending = "linear", figures = drawbend::figures_dir(), gnuplot = "gnuplot";
  int seed = static_cast<int>(lo.seed), threads = 0;
  std::string exports = "lsdyna,openradioss,abaqus", export_parts;
  loop::ExportOptions eo;
  std::string model_help = "empirical";  // --model, read by take_model before the parse; listed by --help
  std::string noise_floor = "data";
};

/// `drawbend loop`'s options, with their ranges and examples, in --help's order.
void add_loop_options(Options& opt, LoopArgs& a) {
  LoopOptions& lo = a.lo;
  opt.add(a.out, "out", "output directory");
  opt.add(a.maps_dir, "maps", "directory of FE maps pin_<d>mm.csv (empty: analytic stand-in, not FE)");
  opt.add(lo.cv, "cv", "cross-validation folds: auto, test, bt-block");
  opt.add(lo.folds, "folds", "number of folds");
  opt.add(lo.permutations, "permutations", "cap of the sequential permutation test per candidate");
  opt.add(lo.min_effect, "min-effect", "minimum held-out error reduction of a step, in units of the replicate noise");
  opt.add(a.seed, "seed", "random seed of the permutation test");
  opt.add(lo.alpha, "alpha", "family-wise significance level (Bonferroni over candidates)");
  opt.add(lo.max_steps, "max-steps", "maximum number of effects to add");
  opt.add(lo.pooled_inputs, "pooled-inputs", "per-input probes of test-level variables also pooled over cells (compares the tests of one pin, direction or lubricant across cells)");
  opt.add(lo.pair_probes, "pair-probes", "pairs of numeric columns probed together (the product of the centred columns; one permutation family)");
  opt.add(lo.far_ratio, "far-ratio", "with no significant step while the held-out RMS is above this x the measured replicate noise, the candidates with the largest held-out gain (up to 3; after the first, those with at least half its gain) are given their forms, and a step must be a form of at most 9 parameters and take half the excess over the noise (0: off)");
  opt.add(a.noise_floor, "noise-floor", "opt-in (development): data (the replicate noise of the measured forces) or model (after every step, the smaller of that and the same scatter of the current model's held-out residual)");
  opt.add(lo.cell_probes, "cell-probes", "opt-in (development): screen and forms for effects confined to one pin, speed, direction or lubricant");
  opt.add(lo.product_forms, "product-forms", "forms for a column that changes mu's pressure or speed slope (its slope, step, smooth or levels times the centred nominal pressure or log speed); false: without them");
  opt.add(a.threads, "threads", "threads of the screen, candidates screened at once (0: one, the default; results identical for any count; the fits run on one thread)");
  // Every number range-checked as it is parsed (issue 53: --folds 0 ended on a
  // floating-point exception, --folds 1, negative permutations and alpha
  // outside (0, 1) ran and concluded differently).  Folds: at least 2 (one
  // fold has nothing held out), at most 100.  Permutations: at least 19 (the
  // smallest count that can reach p = 0.05), at most 1e6 (minutes per
  // candidate).  Steps and the minimum effect: 0 (the base model only / no
  // minimum) up to 100 steps and 100 noise sd.
  opt.range("folds", 2, 100).range("permutations", 19, 1e6).range("alpha", 0, 1, "", true, true);
  opt.range("max-steps", 0, 100).range("min-effect", 0, 100, "replicate noise sd").range("far-ratio", 0, 100, "replicate noise sd");
  // A seed is a whole number from 0 to 1e9 (the studies' seeds are below 7e7;
  // a negative one wrapped to 2^64 - k and ran, and 1e9 keeps the message plain).
  opt.range("seed", 0, 1e9);
  opt.add(a.bending, "bending",
          "bending force: linear (b0 + b1 F_back) or constant, from the rotating-pin rows; for pins without "
          "rotating-pin rows: swift (Eq. 2.1), fe (the FE map's bending_force_N) or none (F_B = 0)");
  opt.add(a.figures, "figures", "directory of the gnuplot scripts (empty: no figures)");
  opt.add(a.gnuplot, "gnuplot", "gnuplot executable");
  opt.add(a.exports, "export", "friction-model exports written next to friction_model.toml: none or a list of lsdyna, "
                               "openradioss, abaqus (drawbend export --help for the other options)");
  opt.add(a.export_parts, "parts", "SHEET,TOOL part IDs written in the exports (default 1,2, marked in each file "
                                   "as placeholders to set by hand)");
  opt.add(a.eo.direction, "direction", "direction of the isotropic exports: rd, td, mean (ortho: both, see drawbend export)");
  opt.add(a.model_help, "model",
          "empirical (this analysis-level loop) or fe: re-run the draw-bend FE model with candidate effects "
          "against measured bending forces (drawbend loop DATA.csv --model fe --help lists its options)");
  opt.example("drawbend loop data/measured/thesis_drawbend.csv --out my-loop    # read my-loop/loop.md");
  opt.example("drawbend synth --effect depletion --noise 5 --seed 21 --out my-synth");
  opt.example("drawbend loop my-synth/data.csv --out my-synth-loop --figures ''");
}

/// The parsed options checked and applied before any data are read (threads,
/// bending source, figures folder, cross-validation, exports, output folder).
BendingSource apply_loop_options(const Options& opt, LoopArgs& a) {
  apply_threads(a.threads);
  // Eigen's matrix products stay on one thread: under 1 % of the loop's time
  // (perf, 50,000 rows, 2026-12-01), while on a busy machine its OpenMP
  // threads spin against the other load (a 1,455-row set took 4.2 s with two
  // threads against 0.77 s with one; a 12,360-row set 8.2 s CPU against 3.8,
  // issue 50 item 6).  --threads N > 1 screens N candidates at once
  // (rank_candidates; results identical for any N); the default is one.
  Eigen::setNbThreads(1);
  a.lo.threads = a.threads > 0 ? a.threads : 1;  // the screen's candidates (issue 50 item 6)
  const BendingSource bsrc = bending_source(a.bending);  // throws on an unknown name
  // A --figures folder given is checked before the analysis (before, a
  // missing folder gave "figures could not be drawn ('gnuplot' failed or is
  // missing)", blaming gnuplot); the default one, when missing, stays the
  // warning that loop.md repeats.
  if (opt.given("figures") && !a.figures.empty() &&
      !std::filesystem::is_regular_file(std::filesystem::path(a.figures) / "loop_residual.gp"))
    throw InputError("--figures '" + clip_for_message(a.figures) + "': expected the folder of the loop's gnuplot "
                     "scripts (with loop_residual.gp: figures/ of the source tree; '' for no figures), found " +
                     (std::filesystem::is_directory(a.figures) ? "a folder without them"
                      : std::filesystem::exists(a.figures) ? "a path that is not a folder" : "nothing there"));
  if (a.noise_floor != "data" && a.noise_floor != "model")
    throw InputError("--noise-floor: expected data or model, found '" + clip_for_message(a.noise_floor) + "'");
  a.lo.model_noise = a.noise_floor == "model";
  if (a.lo.cv != "auto" && a.lo.cv != "test" && a.lo.cv != "bt-block")  // before the data are read, named
    throw InputError("--cv: expected auto, test or bt-block, found '" + clip_for_message(a.lo.cv) + "'");
  a.lo.bending_linear = a.bending != "constant";
  a.lo.progress = true;
  a.lo.seed = static_cast<std::uint64_t>(a.seed);
  opt.only_when(a.exports != "none", {"parts", "direction"}, "with exports (--export is none)");
  a.eo.parts_placeholder = a.export_parts.empty();
  loop::set_list_options(a.eo, a.eo.parts_placeholder ? "1,2" : a.export_parts, "", "");
  a.eo.validate("lsdyna");
  if (a.exports != "none")  // the list checked before the analysis, not after it
    (void)loop::write_exports({}, a.exports, a.eo);
  ensure_writable_dir(a.out, "--out");  // before the analysis, not after it
  return bsrc;
}

/// The measured data, with its format note, problems and row counts reported;
/// throws InputError when no row is usable.
Dataset read_loop_data(const std::string& data_path) {
  Dataset data = read_measured(data_path);
  if (!data.format_note.empty()) std::cout << data_path << ": " << data.format_note << "\n";
  for (const auto& p : data.problems) std::cerr << "data problem: " << p.str() << "\n";
  std::cout << data_path << ": " << data.rows_read << " rows read, " << data.rows.size() << " used, "
            << data.rows_dropped << " dropped, " << data.problems.size() << " problems\n";
  if (data.rows.empty()) throw InputError(data_path + ": no usable rows");
  // The rows together (every force in kN, no fixed pin, ...): exit 2 or a
  // warning that loop.md's problem list keeps too (loop/data_physics.hpp).
  for (auto& w : check_data_physics(data)) {
    std::cerr << "warning: " << w.str() << "\n";
    w.message = "warning: " + w.message;
    data.problems.push_back(std::move(w));
  }
  return data;
}

/// The loop's answer on stdout: bending, base RMS, the steps, the conclusion.
void print_loop_result(const LoopResult& r, const std::string& out) {
  std::cout << "bending: " << r.bending << "\nbase held-out RMS " << fmt(r.cv.front().rms, 4) << " N; "
            << r.steps.size() << " step(s)";
  for (const auto& s : r.steps)
    std::cout << "; " << s.variable << " -> " << s.effect << " (p " << fmt(s.p_value, 3) << ", RMS "
              << fmt(s.rms_before, 4) << " -> " << fmt(s.rms_after, 4) << " N)";
  std::cout << "\n" << r.conclusion << "\nstopped: " << r.stopped_because << "\nwrote " << out << "/loop.md, " << out
            << "/loop_summary.json\n";
}
}  // namespace

// `--model fe` hands the command to the model-level loop (model_loop_cmd.cpp):
// the FE model re-run with candidate effects against measured bending forces.
int loop_main(int argc, char** argv) {
  std::vector<char*> args(argv, argv + argc);
  std::string model;
  if (const int rc = with_exit_codes([&] { model = take_model(args); return 0; }); rc != 0) return rc;
  if (model == "fe") return with_exit_codes([&] {
      return model_loop_command(static_cast<int>(args.size()), args.data(), "drawbend loop DATA.csv --model fe");
    });
  if (!model.empty() && model != "empirical") {
    std::cerr << "input error: --model: expected 'empirical' (the analysis-level loop) or 'fe' (the FE model re-run "
                 "with candidate effects), found '" << model << "'\n";
    return 2;
  }
  argc = static_cast<int>(args.size());
  argv = args.data();
  const bool help = argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h");
  const std::string data_path = argc >= 2 ? argv[1] : "";
  LoopArgs a;
  Options opt("drawbend loop DATA.csv",
              "Close the loop on measured draw-bend data: fit the base model (bending force per pin, constant mu "
              "per cell by Eq. 5.1), rank every extra column by held-out error and a permutation test, add the "
              "library effects that explain it, and write DIR/loop.md (read it first: the data problems, the base "
              "model, each step with its p-value and held-out RMS, and why the loop stopped), loop_summary.json, "
              "tables/ and figures/. DATA.csv: one row per sample with full-strip forces in N (README.md, "
              "'Your own measured data').");
  add_loop_options(opt, a);
  if (help) {
    const char* argv_help[] = {"drawbend loop", "--help"};
    opt.parse(2, const_cast<char**>(argv_help));
    return 0;
  }
  if (data_path.rfind("--", 0) == 0) {  // as `run`: the option that stands where DATA.csv belongs is named
    std::cerr << "input error: drawbend loop: expected DATA.csv first, found the option '" << clip_for_message(data_path)
              << "' (drawbend loop DATA.csv --out DIR; --help lists the options)\n";
    return 2;
  }
  if (data_path.empty()) {
    std::cerr << "input error: drawbend loop: missing DATA.csv (drawbend loop --help lists the options)\n";
    return 2;
  }
  return with_exit_codes([&] {
    if (!opt.parse(argc - 1, argv + 1)) return 0;
    const BendingSource bsrc = apply_loop_options(opt, a);
    const Dataset data = read_loop_data(data_path);
    std::set<double> pins;
    for (const auto& s : data.rows) pins.insert(s.pin_d_mm);
    const MapLibrary maps = maps_for(a.maps_dir, {pins.begin(), pins.end()});
    const Design d = make_design(data, maps, 0.4, bsrc);  // exits 2 without rotating rows and --bending
    if (d.missing_rotating) std::cout << d.notes.front() << "\n";
    const LoopResult r = run_loop(d, a.lo);
    if (r.cv.empty() || !std::isfinite(r.cv.front().rms))  // never exit 0 with a meaningless answer
      throw std::runtime_error("the base model's held-out RMS is " +
                               (r.cv.empty() ? std::string("missing") : fmt(r.cv.front().rms)) +
                               ": the data cannot be analysed (no outputs written)");
    write_loop_outputs(d, r, a.out, a.figures, a.gnuplot, a.exports, a.eo);
    if (!std::isfinite(r.cv.back().rms))
      throw std::runtime_error("the held-out error is not finite: rows that no model can predict");
    print_loop_result(r, a.out);
    return 0;
  });
}

namespace {
/// The values of `drawbend synth`'s options, bound to its Options by
/// add_synth_options (a SynthArgs does not move once bound).
struct SynthArgs {
  SynthOptions so;
  std::string out = "synth-out", maps_dir, data_dir = drawbend::data_dir();
  int seed = 1, points = 7, threads = 0;
  bool from_thesis = false;
  std::string generator = "library", blind_class = "random";
};

/// `drawbend synth`'s options, with their ranges and examples, in --help's order.
void add_synth_options(Options& opt, SynthArgs& a) {
  SynthOptions& so = a.so;
  opt.add(a.out, "out", "output directory");
  opt.add(so.effect, "effect", "hidden law: none, depletion, pin_surface, speed, drift, direction, pressure, curvature, batch, temperature");
  opt.add(so.noise_N, "noise", "measurement noise sd on the outlet force [N]");
  opt.add(a.seed, "seed", "random seed");
  opt.add(so.amplitude, "amplitude", "amplitude of the hidden law (negative: its default)");
  opt.add(so.tests_per_pin, "tests-per-pin", "fixed-pin tests per pin");
  opt.add(so.rows_per_test, "rows-per-test", "rows per test");
  opt.add(a.maps_dir, "maps", "directory of FE maps pin_<d>mm.csv (empty: analytic stand-in, not FE)");
  opt.add_flag(a.from_thesis, "from-thesis", "write the thesis fits as sample rows (thesis_drawbend.csv)");
  opt.add(a.data_dir, "data", "data directory (with thesis/) for --from-thesis");
  opt.example("drawbend synth --effect depletion --noise 5 --seed 21 --out my-synth    # my-synth/truth.json: the hidden law");
  opt.example("drawbend synth --from-thesis --out my-thesis");
  opt.add(a.points, "points", "rows per thesis fit for --from-thesis");
  opt.range("points", 2, 10000);
  opt.range("seed", 0, 1e9);  // as loop's --seed: a negative seed wrapped to 2^64 - k
  // A hidden law's amplitude (N or a fraction, by law) above 1e6 gives forces
  // beyond a strip test (core/strip_limits.hpp) whatever the law.
  opt.range("amplitude", -kMaxStripForceN, kMaxStripForceN);
  opt.add(a.threads, "threads", "OpenMP threads (0: OMP_NUM_THREADS or all)");
  opt.add(a.generator, "generator",
          "library (the hidden laws of --effect) or blind (a random design, decoys and effect drawn from a wide "
          "family, src/loop/blind_synth.hpp; uses --class, --noise and --seed only) or wild (generator 2 of the "
          "held-out study, src/loop/wild_synth.hpp; the same options)");
  opt.add(a.blind_class, "class", "--generator blind: level, smooth, interaction, bending, test-level, null or random; "
          "wild: level, smooth, interaction, channel, test-level, null or random");
}

/// The parsed options checked before any work: the generator, the options it
/// reads, the hidden law's name, and sizes and noise a data set can have.
void check_synth_options(const Options& opt, const SynthArgs& a) {
  const SynthOptions& so = a.so;
  if (a.generator != "library" && a.generator != "blind" && a.generator != "wild")
    throw InputError("--generator: expected library, blind or wild, found '" + a.generator + "'");
  // An option the chosen generator does not read is refused, not ignored
  // (before, --class with the library generator and --data without
  // --from-thesis were accepted and did nothing).
  const bool held_out = a.generator != "library";
  opt.only_when(a.from_thesis, {"data", "points"}, "with --from-thesis");
  opt.only_when(!a.from_thesis, {"effect", "noise", "seed", "amplitude", "tests-per-pin", "rows-per-test", "maps",
                                 "generator", "class"}, "without --from-thesis (it writes the thesis fits as they are)");
  opt.only_when(held_out, {"class"}, "with --generator blind or wild");
  opt.only_when(!held_out, {"effect", "amplitude", "tests-per-pin", "rows-per-test", "maps"},
                "with --generator library (blind and wild read --class, --noise and --seed only)");
  // --effect none has no hidden law: an amplitude was written into truth.json beside it (exit 0, before 2026-12-05).
  opt.only_when(so.effect != "none", {"amplitude"}, "with an --effect other than none (none has no hidden law)");
  // Sizes and noise a draw-bend data set can have (before 2026-11-29,
  // --rows-per-test -5 ended in "cannot create std::vector larger than
  // max_size()" with exit 3, 1e8 ran for minutes, and --noise -1 wrote data).
  auto bad = [](const std::string& what) { throw InputError(what); };
  {  // the hidden law's name, before any work, with the valid ones listed
    const auto& names = synth_effects();
    if (std::find(names.begin(), names.end(), so.effect) == names.end()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      bad("--effect: expected one of " + list + ", found '" + clip_for_message(so.effect) + "'");
    }
  }
  if (!(so.noise_N >= 0 && so.noise_N <= kMaxStripForceN))
    bad("--noise: expected a noise sd in [0, " + fmt(kMaxStripForceN) + "] N (a strip test), found " + fmt(so.noise_N));
  if (so.tests_per_pin < 1 || so.tests_per_pin > 10000)
    bad("--tests-per-pin: expected 1 to 10000 tests, found " + std::to_string(so.tests_per_pin));
  if (so.rows_per_test < 1 || so.rows_per_test > 10000)
    bad("--rows-per-test: expected 1 to 10000 rows, found " + std::to_string(so.rows_per_test));
  if (static_cast<double>(so.tests_per_pin) * so.rows_per_test > 1e6)
    bad("--tests-per-pin x --rows-per-test: expected at most 1e6 rows per pin, found " +
        fmt(static_cast<double>(so.tests_per_pin) * so.rows_per_test));
}

/// --generator blind or wild: the held-out generators (1 and 2).
void write_held_out_set(const SynthArgs& a) {
  const bool wild = a.generator == "wild";
  const auto& cl = wild ? wild_classes() : blind_classes();
  if (a.blind_class != "random" && std::find(cl.begin(), cl.end(), a.blind_class) == cl.end()) {
    std::string list;
    for (const auto& c : cl) list += c + ", ";
    throw InputError("--class: expected " + list.substr(0, list.size() - 2) + " or random, found '" + a.blind_class + "'");
  }
  BlindTruth truth;
  const auto seed = static_cast<std::uint64_t>(a.seed);
  const Dataset d = wild ? synthesize_wild({a.blind_class, a.so.noise_N, seed}, truth)
                         : synthesize_blind({a.blind_class, a.so.noise_N, seed}, truth);
  write_measured(a.out + "/data.csv", d);
  write_file_atomic(a.out + "/truth.json", wild ? wild_truth_json(truth) : blind_truth_json(truth));
  std::cout << "wrote " << a.out << "/data.csv (" << d.rows.size() << " rows) and " << a.out << "/truth.json\n";
}

/// --generator library: a hidden law of --effect on the stand-in or FE maps.
void write_library_set(SynthArgs& a) {
  SynthOptions& so = a.so;
  so.seed = static_cast<std::uint64_t>(a.seed);
  const MapLibrary maps = maps_for(a.maps_dir, {12.7, 25.4, 42.0});
  SynthTruth truth;
  const Dataset d = synthesize(so, maps, truth);
  // The hidden law's amplitude is the law's own unit: check what it made.
  for (const auto& r : d.rows)
    if (!(std::isfinite(r.outlet_force_N) && std::abs(r.outlet_force_N) <= kMaxStripForceN))
      // Named as given: a negative --amplitude is the law's default (it read "--amplitude -1"
      // for `--noise 1e6` alone, 2026-12-04).
      throw InputError((so.amplitude < 0 ? std::string("--noise ") + fmt(so.noise_N) + " (with --effect " + so.effect +
                                               "'s default amplitude)"
                                         : "--amplitude " + fmt(so.amplitude) + " with --noise " + fmt(so.noise_N)) +
                       ": an outlet force of " + fmt(r.outlet_force_N) + " N, beyond a strip test (" +
                       fmt(kMaxStripForceN) + " N); choose a smaller " + (so.amplitude < 0 ? "noise" : "amplitude or noise"));
  write_measured(a.out + "/data.csv", d);
  write_file_atomic(a.out + "/truth.json", truth_json(truth));
  std::cout << "wrote " << a.out << "/data.csv (" << d.rows.size() << " rows) and " << a.out << "/truth.json\n";
}
}  // namespace

int synth_main(int argc, char** argv) {
  SynthArgs a;
  Options opt("drawbend synth", "Write synthetic draw-bend data with a hidden law, or the thesis data set.");
  add_synth_options(opt, a);
  return with_exit_codes([&] {
    if (!opt.parse(argc, argv)) return 0;
    apply_threads(a.threads);
    check_synth_options(opt, a);
    ensure_writable_dir(a.out, "--out");
    if (a.from_thesis) {
      // Named by its option (before 2026-12-04: "/nonexistent/thesis/table_5_3.csv: cannot open file").
      if (std::error_code ec; !std::filesystem::is_directory(a.data_dir + "/thesis", ec))
        throw InputError("--data '" + a.data_dir + "': expected the repository's data folder (holding thesis/), found " +
                         (std::filesystem::is_directory(a.data_dir, ec) ? "a folder without thesis/"
                          : std::filesystem::exists(a.data_dir, ec)    ? "a file"
                                                                       : "nothing there"));
      const Dataset d = thesis_dataset(a.data_dir + "/thesis", a.points);
      write_measured(a.out + "/thesis_drawbend.csv", d);
      std::cout << "wrote " << a.out << "/thesis_drawbend.csv (" << d.rows.size() << " rows)\n";
    } else if (a.generator == "blind" || a.generator == "wild") {
      write_held_out_set(a);
    } else {
      write_library_set(a);
    }
    return 0;
  });
}

}  // namespace drawbend::cli
