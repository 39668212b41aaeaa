// `drawbend model-loop DATA.csv --out DIR [options]`, also reached as
// `drawbend loop DATA.csv --model fe ...` (loop_cmd.cpp): the model-level loop
// (src/modelloop/model_loop.hpp) on a user's measured bending forces.  DATA.csv has
// the columns pin_diameter_mm, back_tension_N, bending_force_N (full strip,
// rotating = frictionless pin).  The points on --fit-pin train; the others
// choose the model (in-sample); with 3 or more pins each pin's blind error
// comes from the leave-one-pin-out split (--blind, model_loop_report.hpp).  Candidates (--candidates, comma separated, tried in order):
// split:B1/B2/... (split combined hardening, beta chosen on the fit pin),
// chaboche:X1/X2/...[@G1/G2/...] (one back stress, X and gamma chosen on the fit pin), voce,
// hill48, offset, ms:X (mass scaling), across:N.  FE runs are cached in
// DIR/runs by deck hash.  The run folder, like `drawbend loop`'s: DIR/model_loop.md
// (read first), DIR/chosen_model.toml (the chosen model's [material] table, a
// drawbend-deck --material file), DIR/steps.csv (every candidate tried),
// DIR/baseline.csv, DIR/final.csv, DIR/inputs/ (a copy of DATA.csv and the
// options in effect).  Units: mm, N, mm/s.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/csv.hpp"
#include "core/list_option.hpp"
#include "core/quote.hpp"
#include "core/install_paths.hpp"
#include "core/file_gate.hpp"
#include "io/deck.hpp"
#include "cli/loop_cmd.hpp"
#include "cli/option_bounds.hpp"
#include "cli/threads.hpp"
#include "sim/case_pool.hpp"
#include "sim/executor.hpp"
#include "core/options.hpp"
#include "sim/fe_options.hpp"
#include "sim/material_choice.hpp"
#include "modelloop/model_loop.hpp"
#include "material/hardening_curve.hpp"
#include "cli/model_loop_report.hpp"

namespace drawbend::cli {

namespace {

/// The command's inputs: the base draw-bend spec and the loop's settings.
struct Args {
  sim::DrawBendSpec s;
  modelloop::ModelLoopConfig cfg;
  std::string data, out, candidates = "split:0.3/0.6", executor_spec;
  bool reuse = true, blind = true;
  int threads = 0;
  std::vector<modelloop::FbPoint> points;  ///< the data, read first
};

void add_options(Options& opt, Args& a) {
  sim::DrawBendSpec& s = a.s;
  opt.add(a.out, "out", "output directory (runs cached in OUT/runs)");
  opt.add(a.cfg.fit_pin, "fit-pin", "pin diameter whose points train [mm]; the others choose the model");
  opt.add(a.cfg.min_gain, "min-gain", "accept a candidate if the choice pins' RMS relative error falls by more than this");
  opt.add(a.candidates, "candidates", "comma-separated: split:B1/B2..., chaboche:X1/X2...[@G1/G2...], voce, hill48, offset, ms:X, across:N (empty: the baseline alone)");
  opt.add(a.blind, "blind",
          "with points on 3 or more pins, also run the whole loop once per pin with that pin left out and report "
          "each pin's blind error (true, the default); false: the in-sample loop only (its choice pins' error is not "
          "blind)");
  opt.add(a.reuse, "reuse", "read back finished runs with the identical deck (true) or rerun them (false)");
  opt.add(s.thickness, "thickness", "strip thickness [mm]");
  opt.add(s.width, "width", "modelled half width [mm]");
  opt.add(s.speed, "speed", "outlet speed [mm/s]");
  opt.add(s.mass_scaling, "mass-scaling",
          "base mass scaling (0: the quick tier's 1e4 at 100 mm/s scaled by (100/v)^2 at --speed, 4e4 at 50 mm/s)");
  opt.add(s.element_length, "element-length", "element length along the strip [mm]");
  opt.add(s.across, "across", "elements across the half width");
  opt.add(s.bend_inlet_slides, "bend-inlet-slides",
          "bend step with the inlet end sliding under the back tension (true, the default) or clamped as before "
          "issue 51 (false, for reproduction)");
  opt.add(s.hardening, "hardening", "hardening curve CSV of the base (isotropic) model");
  opt.add(a.threads, "threads",
          "threads of the FE runs in all: cases side by side times threads within a case (0: DRAWBEND_JOBS cases "
          "side by side on all hardware threads)");
  opt.add(a.executor_spec, "executor",
          "where the FE runs go: local (this machine's pool), slurm (sbatch/srun jobs), command:TEMPLATE (a launcher "
          "with {drawbend} {deck} {dir} {cores}); default DRAWBEND_EXECUTOR, else local (docs/cluster.md)");
  opt.example("drawbend model-loop data/measured/model_loop_points.csv --out my-model-loop --candidates offset "
              "--element-length 2 --across 1    # a few minutes; writes my-model-loop/model_loop.md");
  opt.example("drawbend model-loop data/measured/model_loop_points.csv --out my-model-loop --candidates offset "
              "--element-length 2 --across 1    # again: the finished runs are read back");
  using namespace bounds;  // every number range-checked as it is parsed (cli/option_bounds.hpp)
  opt.range("fit-pin", kMinLengthMM, kLengthMM, "mm", false).range("min-gain", 0, 1);
  opt.range("thickness", kMinThicknessMM, kThicknessMM, "mm", false).range("width", kMinLengthMM, kLengthMM, "mm", false);
  opt.range("speed", kMinSpeedMMs, kSpeedMMs, "mm/s", false).range("mass-scaling", 1, kMassScaling, "", false, false, true);
  opt.range("element-length", kMinLengthMM, kLengthMM, "mm", false).range("across", 1, kElements);
}

/// Problems found so far, one a line; thrown together as one InputError.
struct Problems {
  std::string text;
  void need(bool ok, const std::string& msg) {
    if (!ok) text += (text.empty() ? "" : "\n") + msg;
  }
  void throw_if_any() const {
    if (!text.empty()) throw InputError(text);
  }
};

/// The options and the candidates checked, all problems at once; sets the
/// executor, the case threads and the mass scaling of the quick tier's rule.
std::vector<modelloop::ModelCandidate> checked_candidates(Args& a) {
  sim::DrawBendSpec& s = a.s;
  Problems p;
  p.need(s.thickness > 0, "--thickness: expected a number > 0 mm, found " + fmt(s.thickness));
  p.need(s.width > 0, "--width: expected a number > 0 mm, found " + fmt(s.width));
  p.need(s.speed > 0, "--speed: expected a number > 0 mm/s, found " + fmt(s.speed));
  p.need(s.mass_scaling == 0 || s.mass_scaling >= 1,
         "--mass-scaling: expected 0 (the quick tier's rule) or a number >= 1, found " + fmt(s.mass_scaling));
  p.need(s.element_length > 0, "--element-length: expected a number > 0 mm, found " + fmt(s.element_length));
  p.need(s.across >= 1, "--across: expected a whole number >= 1, found " + std::to_string(s.across));
  name_input(s.hardening, "--hardening");  // the file gate names the option (core/file_gate.hpp)
  try {
    (void)read_input(s.hardening);  // a regular file of a stated size, never a FIFO or device
    // Absolute, as drawbend-deck's: the FE decks live in OUT/runs/*/, where a relative path was
    // resolved against the deck's folder and every run stopped with exit 2 (before 2026-12-05).
    s.hardening = std::filesystem::absolute(s.hardening).lexically_normal().string();
  } catch (const InputError& e) {
    p.need(false, e.what());
  }
  // The strip cannot carry more than its flow-stress bound over its full section: a point whose
  // outlet force F_X + F_B is above that is not a draw-bend test of this strip (bending forces in
  // N x 1000 started the FE runs before 2026-12-04).
  if (p.text.empty()) try {
      const double sigma = material::HardeningCurve::load(s.hardening).tension_bound();
      const double capacity = sigma * 2 * s.width * s.thickness;  // full strip: --width is the half width
      for (const auto& pt : a.points)
        if (pt.back_tension_N + pt.bending_N > capacity) {
          p.need(false, pt.where + ": column 'bending_force_N': back tension + bending force = " +
                            fmt(pt.back_tension_N + pt.bending_N, 4) + " N, above what the strip can carry, " +
                            fmt(capacity, 4) + " N (the flow stress of --hardening at 100 % plastic strain, " + fmt(sigma, 4) +
                            " MPa, over the full strip's " + fmt(2 * s.width, 4) + " x " + fmt(s.thickness, 4) +
                            " mm section): forces in another unit, or another strip (--width, --thickness)?");
          break;
        }
    } catch (const InputError& e) {
      p.need(false, std::string("--hardening: ") + e.what());
    }
  p.need(a.cfg.min_gain >= 0, "--min-gain: expected a number >= 0, found " + fmt(a.cfg.min_gain));
  p.need(good_threads(a.threads), bad_threads(a.threads));
  std::vector<modelloop::ModelCandidate> cands;
  std::vector<std::string> names;
  try {
    if (!a.candidates.empty()) names = list_items(a.candidates, "--candidates");  // empty: the baseline alone
  } catch (const std::invalid_argument& e) {
    p.need(false, e.what());
  }
  for (const std::string& tok : names) {
    try {
      cands.push_back(modelloop::named_candidate(tok, drawbend::data_dir()));
    } catch (const InputError& e) {
      p.need(false, std::string("--candidates: ") + e.what());
    }
  }
  try {
    sim::set_executor(sim::parse_executor(a.executor_spec));
  } catch (const std::invalid_argument& e) {
    p.need(false, e.what());
  }
  p.throw_if_any();
  sim::set_case_threads(a.threads);
  if (s.mass_scaling == 0) s.mass_scaling = sim::mass_scaling_for_speed(sim::kQuickMassScaling, s.speed);
  return cands;
}

/// Every deck the loop will run passes `drawbend run`'s checks (limits and
/// cost included) before the first FE run; a refusal names the user's
/// options or candidate, then the generated deck's key.  Then the fit pin
/// must hold a point.
void check_decks(const Args& a, const std::vector<modelloop::FbPoint>& points,
                 const std::vector<modelloop::ModelCandidate>& cands) {
  const sim::DrawBendSpec& s = a.s;
  auto deck_problem = [](const sim::DrawBendSpec& spec) -> std::string {
    try {
      (void)io::parse_deck(sim::deck_text(spec), "model-loop.toml");
      return "";
    } catch (const InputError& e) {
      return e.what();
    }
  };
  Problems p;
  const std::string base_opts = "--thickness " + fmt(s.thickness) + ", --width " + fmt(s.width) + ", --speed " +
                                fmt(s.speed) + ", --mass-scaling " + fmt(s.mass_scaling) + ", --element-length " +
                                fmt(s.element_length) + ", --across " + std::to_string(s.across);
  for (const auto& pt : points)
    if (const std::string m = deck_problem(modelloop::spec_for_point(s, pt)); !m.empty()) {
      p.need(false, base_opts + ": the FE deck of the point at " + pt.where + " fails the checks of `drawbend run`:\n" + m);
      break;
    }
  for (const auto& c : cands)
    for (const auto& member : c.members) {
      sim::DrawBendSpec cs = modelloop::spec_for_point(s, points.front());
      member.apply(cs);
      if (const std::string m = deck_problem(cs); !m.empty() && p.text.empty())
        p.need(false, "--candidates '" + clip_for_message(c.name) + "' (" + member.label +
                          "): its FE deck fails the checks of `drawbend run`:\n" + m);
    }
  p.throw_if_any();
  bool on_fit = false;
  for (const auto& pt : points) on_fit = on_fit || std::abs(pt.pin_mm - a.cfg.fit_pin) < 1e-6 * a.cfg.fit_pin;
  if (!on_fit)
    throw InputError(a.data + ": no point on the fit pin " + fmt(a.cfg.fit_pin) + " mm (--fit-pin names one of the "
                     "pin_diameter_mm values)");
}

/// The inputs beside the answer (as `drawbend loop` keeps its data): the
/// data as read and every option in effect, mass scaling resolved.
void write_inputs(const Args& a) {
  const sim::DrawBendSpec& s = a.s;
  std::filesystem::create_directories(a.out + "/inputs");
  write_file_atomic(a.out + "/inputs/data.csv", read_input(a.data));
  std::ostringstream o;
  o << "# drawbend model-loop: the options in effect (units mm, N, mm/s)\n[model_loop]\ndata = "
    << string_literal(a.data) << "\nfit_pin = " << fmt(a.cfg.fit_pin) << "\nmin_gain = " << fmt(a.cfg.min_gain)
    << "\ncandidates = " << string_literal(a.candidates) << "\nthickness = " << fmt(s.thickness) << "\nwidth = "
    << fmt(s.width) << "\nspeed = " << fmt(s.speed) << "\nmass_scaling = " << fmt(s.mass_scaling)
    << "\nelement_length = " << fmt(s.element_length) << "\nacross = " << s.across << "\nthrough = " << s.through
    << "\nhardening = " << string_literal(s.hardening) << "\n";
  write_file_atomic(a.out + "/inputs/options.toml", o.str());
}

/// OUT/chosen_model.toml, baseline.csv, final.csv, steps.csv and model_loop.md.
void write_outputs(const Args& a, const std::vector<modelloop::FbPoint>& points, const modelloop::BlindLoopResult& b,
                   const std::string& no_blind) {
  const std::string& out = a.out;
  const modelloop::ModelLoopResult& r = b.in_sample;
  write_file_atomic(out + "/chosen_model.toml",
                    "# The model chosen by drawbend model-loop: " + r.final_model.model + "\n" +
                        sim::material_section(r.final_spec.material, r.final_spec.hardening));
  modelloop::save_eval_csv(r.baseline, out + "/baseline.csv");
  modelloop::save_eval_csv(r.final_model, out + "/final.csv");
  CsvWriter w({"candidate", "member", "fit_rms", "heldout_rms", "heldout_max", "decision"});
  w.comment(" relative errors of F_B (fractions); fit pin " + fmt(a.cfg.fit_pin) + " mm");
  w.row({"baseline", r.baseline.model, fmt(r.baseline.fit_rms, 4), fmt(r.baseline.held_rms, 4),
         fmt(r.baseline.held_max, 4), ""});
  for (const auto& st : r.steps)
    w.row({st.candidate, st.member, fmt(st.eval.fit_rms, 4), fmt(st.eval.held_rms, 4), fmt(st.eval.held_max, 4),
           st.decision});
  w.save(out + "/steps.csv");
  if (!b.folds.empty()) save_blind_csv(b, out + "/blind.csv");
  write_model_loop_md(out + "/model_loop.md", a.data, points, a.s, a.cfg, b, no_blind);
}

}  // namespace

int model_loop_command(int argc, char** argv, const char* name) {
  const std::string me = name;
  Args a;
  a.s.hardening = drawbend::data_dir() + "/materials/aa5754_o_rd.csv";
  a.s.width = 12.7;
  a.s.speed = 50;
  sim::set_quick_mesh(a.s);  // the chapters' quick tier (sim/fe_options.hpp)
  a.s.mass_scaling = 0;      // 0: the quick tier's rule at --speed (set after parsing)
  Options opt(me, "Test modelling effects by re-running the draw-bend FE model (rotating = frictionless pin, "
                       "explicit, half strip) against measured bending forces. DATA.csv: one row per point with the "
                       "columns pin_diameter_mm, back_tension_N, bending_force_N (full strip, N; '#' comments). The "
                       "points on --fit-pin train each candidate's members; the other pins choose: a "
                       "candidate is accepted only if their RMS relative error falls by more than --min-gain, so that "
                       "error is not blind. With points on 3 or more pins the whole loop also runs once per pin with "
                       "that pin left out, and each pin's blind error comes from the fold that never saw it (--blind). FE "
                       "runs go through the case pool (DRAWBEND_JOBS at a time, progress with time left) and are "
                       "cached in OUT/runs by deck hash. Writes OUT/model_loop.md (read it first: the chosen model and its blind "
                       "errors, every candidate tried), OUT/chosen_model.toml (its [material] table), OUT/steps.csv (every candidate), "
                       "OUT/blind.csv (with 3 or more pins), OUT/baseline.csv, OUT/final.csv and OUT/inputs/ (the data and the options in effect).");
  add_options(opt, a);
  if (argc < 2 || std::string(argv[1]).rfind("-", 0) == 0) {
    if (!opt.parse(argc, argv)) return 0;
    throw InputError(me + ": missing DATA.csv (columns pin_diameter_mm, back_tension_N, bending_force_N; --help lists "
                     "the options)");
  }
  a.data = argv[1];
  if (!opt.parse(argc - 1, argv + 1)) return 0;
  opt.not_empty({"hardening"});  // a file option given as '' names the option
  if (a.out.empty()) throw InputError(me + ": --out DIR is required");
  // Every input is checked before the first FE run (runs take minutes).
  a.points = modelloop::read_fb_points(a.data);  // file:line: column for every bad cell
  const auto& points = a.points;
  const auto cands = checked_candidates(a);
  check_decks(a, points, cands);
  ensure_writable_dir(a.out, "--out");
  a.cfg.run_root = a.out + "/runs";
  a.cfg.reuse = a.reuse;
  write_inputs(a);
  // The in-sample loop and, with 3 or more pins, the leave-one-pin-out folds
  // (they share the runs: a deck run once is read by the others).
  std::vector<double> pins;
  for (const auto& pt : points)
    if (std::none_of(pins.begin(), pins.end(), [&](double d) { return std::abs(d - pt.pin_mm) <= 1e-6 * d; }))
      pins.push_back(pt.pin_mm);
  const std::string no_blind = !a.blind ? "--blind false"
                               : pins.size() < 3 ? "points on " + std::to_string(pins.size()) +
                                                       " pin(s); the leave-one-pin-out split needs 3 or more (one to "
                                                       "fit, one to choose, one left out)"
                                                 : "";
  modelloop::BlindLoopResult b;
  if (no_blind.empty()) {
    b = modelloop::run_model_loop_blind(a.s, points, [&](double) { return cands; }, a.cfg);
  } else {
    b.in_sample = modelloop::run_model_loop(a.s, points, cands, a.cfg);
    b.runs = b.in_sample.runs, b.run_wall_s = b.in_sample.run_wall_s;
  }
  write_outputs(a, points, b, no_blind);
  print_answer(b, no_blind);
  return 0;
}

}  // namespace drawbend::cli
