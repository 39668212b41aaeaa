// The model-level loop's selection: members chosen on the fit pin, candidates
// accepted on the selection pins, and the leave-one-pin-out folds
// (modelloop/model_loop.hpp).
#include "modelloop/model_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>

#include "core/csv.hpp"
#include "core/hash.hpp"
#include "io/portable_paths.hpp"
#include "sim/case_pool.hpp"

namespace drawbend::modelloop {

using namespace drawbend::sim;

std::vector<DrawBendResult> run_cached(std::vector<DrawBendSpec> specs, const std::string& run_root, bool reuse,
                                       double* wall_s, const std::vector<std::string>& runs_from) {
  std::vector<CaseJob> jobs;
  std::vector<std::size_t> job_of;
  std::map<std::string, std::size_t> index;
  for (auto& s : specs) {
    s.name = "fb";
    const std::string text = deck_text(s);
    auto it = index.find(text);
    if (it == index.end()) {
      it = index.emplace(text, jobs.size()).first;
      jobs.push_back({s, run_root + "/fb_" + hex64(io::portable_fingerprint(text))});
    }
    job_of.push_back(it->second);
  }
  const auto res = run_drawbend_all(jobs, reuse, runs_from);
  if (wall_s)
    for (const auto& r : res) *wall_s += r.wall_seconds;
  std::vector<DrawBendResult> out;
  for (std::size_t j : job_of) out.push_back(res[j]);
  return out;
}

DrawBendSpec spec_for_point(const DrawBendSpec& base, const FbPoint& p) {
  DrawBendSpec s = base;
  s.pin_diameter = p.pin_mm;
  s.back_tension = p.back_tension_N / 2.0;  // half model
  return s;
}

namespace {

bool same_pin(double a, double b) { return std::abs(a - b) < 1e-6 * std::max(1.0, std::abs(a)); }

double rms(const std::vector<double>& v) {
  if (v.empty()) return std::nan("");
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s / v.size());
}

/// Runs specs once each (by deck text) over the whole loop; F_B full strip per spec.
class Runner {
 public:
  explicit Runner(const ModelLoopConfig& cfg) : cfg_(cfg) {}
  /// F_B of every spec; a point is marked held out when it is not on `fit_pin`.
  std::vector<PointResult> evaluate(std::vector<DrawBendSpec> specs, const std::vector<FbPoint>& pts, double fit_pin) {
    std::vector<std::string> keys;
    std::vector<DrawBendSpec> todo;
    for (auto& s : specs) {
      s.name = "fb";
      keys.push_back(deck_text(s));
      if (!done_.count(keys.back())) todo.push_back(s);
    }
    if (!todo.empty()) {
      // Overall progress: cases done of those the loop can ask for (an upper bound: a deck
      // asked for twice runs once), and the time left at the wall time per case so far.
      const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      const double left = done_.empty() ? 0.0 : el / static_cast<double>(done_.size()) *
                                                     static_cast<double>(std::max(0, planned_ - runs()));
      std::cout << "model loop: " << todo.size() << " FE case(s) to run or read (" << done_.size()
                << " done so far of at most " << planned_ << " in all"
                << (done_.empty() ? std::string() : "; about " + fmt_fixed(left / 60.0, 1) + " min left if all run")
                << ")\n"
                << std::flush;
      const auto res = run_cached(todo, cfg_.run_root, cfg_.reuse, &wall_, cfg_.runs_from);
      for (const auto& r : res) done_[deck_text(r.spec)] = {2.0 * r.tension_rise(), 2.0 * r.F_out_std, r.dir};
    }
    std::vector<PointResult> out;
    for (std::size_t i = 0; i < specs.size(); ++i) {
      PointResult r;
      r.measured = pts[i];
      r.held_out = !same_pin(pts[i].pin_mm, fit_pin);
      const Done& d = done_.at(keys[i]);
      r.predicted_N = d.fb;
      r.predicted_sd_N = d.sd;
      r.run_dir = d.dir;
      out.push_back(r);
    }
    return out;
  }
  int runs() const { return static_cast<int>(done_.size()); }
  void set_planned(int n) { planned_ = n; }
  double wall() const { return wall_; }

 private:
  struct Done {
    double fb, sd;
    std::string dir;
  };
  const ModelLoopConfig& cfg_;
  std::map<std::string, Done> done_;
  double wall_ = 0;
  int planned_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

ModelEval summarise(std::string model, std::vector<PointResult> pts) {
  ModelEval e;
  e.model = std::move(model);
  std::vector<double> fit, held;
  for (const auto& p : pts) {
    (p.held_out ? held : fit).push_back(p.rel_error());
    if (p.held_out) e.held_max = std::max(e.held_max, std::abs(p.rel_error()));
  }
  e.fit_rms = rms(fit);
  e.held_rms = rms(held);
  e.points = std::move(pts);
  return e;
}

std::vector<DrawBendSpec> specs_of(const DrawBendSpec& base, const std::vector<FbPoint>& pts) {
  std::vector<DrawBendSpec> s;
  for (const auto& p : pts) s.push_back(spec_for_point(base, p));
  return s;
}

}  // namespace

namespace {

/// The loop of the header on `points`, members chosen on `fit_pin`,
/// candidates judged on every other pin in `points`; runs through `run`.
ModelLoopResult loop_on(Runner& run, const DrawBendSpec& base, const std::vector<FbPoint>& points,
                        const std::vector<ModelCandidate>& candidates, double fit_pin, double min_gain,
                        bool verbose) {
  std::vector<FbPoint> fit_pts, held_pts;
  for (const auto& p : points) (same_pin(p.pin_mm, fit_pin) ? fit_pts : held_pts).push_back(p);
  if (fit_pts.empty()) throw InputError("model loop: no measured point on the fit pin " + fmt(fit_pin) + " mm");
  if (held_pts.empty()) throw InputError("model loop: no measured point off the fit pin " + fmt(fit_pin) +
                                         " mm: nothing is held out");
  ModelLoopResult out;
  DrawBendSpec model = base;
  std::string label = "isotropic";
  out.baseline = summarise(label, run.evaluate(specs_of(model, points), points, fit_pin));
  ModelEval current = out.baseline;
  for (const auto& c : candidates) {
    if (c.members.empty()) throw std::invalid_argument("model loop: candidate " + c.name + " has no member");
    StepRecord step;
    step.candidate = c.name;
    step.what = c.what;
    // 1. every member on the fit pin only; choose the best there.
    std::vector<DrawBendSpec> specs;
    std::vector<FbPoint> pts;
    for (const auto& m : c.members) {
      DrawBendSpec s = model;
      m.apply(s);
      for (const auto& p : fit_pts) {
        specs.push_back(spec_for_point(s, p));
        pts.push_back(p);
      }
    }
    const auto fitres = run.evaluate(specs, pts, fit_pin);
    std::size_t best = 0;
    double best_rms = 1e300;
    for (std::size_t k = 0; k < c.members.size(); ++k) {
      std::vector<double> e;
      for (std::size_t j = 0; j < fit_pts.size(); ++j) e.push_back(fitres[k * fit_pts.size() + j].rel_error());
      step.member_fit_rms.emplace_back(c.members[k].label, rms(e));
      if (rms(e) < best_rms) best_rms = rms(e), best = k;
    }
    // 2. the chosen member on every point (held-out pins only now).
    DrawBendSpec chosen = model;
    c.members[best].apply(chosen);
    step.member = c.members[best].label;
    step.spec = chosen;
    step.eval = summarise(label + " + " + step.member, run.evaluate(specs_of(chosen, points), points, fit_pin));
    const double gain = current.held_rms - step.eval.held_rms;
    if (gain > min_gain) {
      step.decision = "accepted";
      model = chosen;
      label = step.eval.model;
      current = step.eval;
    } else {
      step.decision = "rejected: held-out RMS " + fmt_fixed(100 * current.held_rms, 1) + " % -> " +
                      fmt_fixed(100 * step.eval.held_rms, 1) + " %";
    }
    if (verbose)
      std::cout << "model loop: " << c.name << " (" << step.member << "): held-out RMS "
                << fmt_fixed(100 * step.eval.held_rms, 1) << " %, " << step.decision << "\n"
                << std::flush;
    out.steps.push_back(std::move(step));
  }
  out.final_model = current;
  out.final_spec = model;
  return out;
}

/// The distinct pins of `points`, in the order they first appear.
std::vector<double> pins_of(const std::vector<FbPoint>& points) {
  std::vector<double> pins;
  for (const auto& p : points)
    if (std::none_of(pins.begin(), pins.end(), [&](double d) { return same_pin(d, p.pin_mm); })) pins.push_back(p.pin_mm);
  return pins;
}

/// Progress bound of one loop: the baseline, then per candidate its members on
/// the fit pin and the chosen one on the other pins (a deck asked for twice runs once).
std::size_t planned_runs(const std::vector<FbPoint>& points, const std::vector<ModelCandidate>& candidates,
                         double fit_pin) {
  std::size_t planned = points.size(), on_fit = 0;
  for (const auto& p : points) on_fit += same_pin(p.pin_mm, fit_pin);
  for (const auto& c : candidates) planned += c.members.size() * on_fit + (points.size() - on_fit);
  return planned;
}

/// The fit pin of the fold that leaves `left` out: the remaining pin nearest the
/// loop's fit pin (the fit pin itself when it remains).
double fold_fit_pin(const std::vector<double>& pins, double left, double fit_pin) {
  double f = same_pin(pins.front(), left) ? pins[1] : pins.front();
  for (double d : pins)
    if (!same_pin(d, left) && std::abs(d - fit_pin) < std::abs(f - fit_pin)) f = d;
  return f;
}

}  // namespace

ModelLoopResult run_model_loop(const DrawBendSpec& base, const std::vector<FbPoint>& points,
                               const std::vector<ModelCandidate>& candidates, const ModelLoopConfig& cfg) {
  Runner run(cfg);
  run.set_planned(static_cast<int>(planned_runs(points, candidates, cfg.fit_pin)));
  ModelLoopResult out = loop_on(run, base, points, candidates, cfg.fit_pin, cfg.min_gain, true);
  out.runs = run.runs();
  out.run_wall_s = run.wall();
  return out;
}

BlindLoopResult run_model_loop_blind(const DrawBendSpec& base, const std::vector<FbPoint>& points,
                                     const CandidatesFor& candidates_for, const ModelLoopConfig& cfg) {
  const std::vector<double> pins = pins_of(points);
  if (pins.size() < 3)
    throw InputError("model loop: the leave-one-pin-out split needs measured points on at least 3 pins (one to "
                     "fit, one to choose, one left out), found " + std::to_string(pins.size()));
  Runner run(cfg);
  // Progress bound: the in-sample loop, then per fold its loop and the left-out pin's two models.
  std::size_t planned = planned_runs(points, candidates_for(cfg.fit_pin), cfg.fit_pin);
  for (double left : pins) {
    std::vector<FbPoint> seen;
    for (const auto& p : points)
      if (!same_pin(p.pin_mm, left)) seen.push_back(p);
    const double fit = fold_fit_pin(pins, left, cfg.fit_pin);
    planned += planned_runs(seen, candidates_for(fit), fit) + 2 * (points.size() - seen.size());
  }
  run.set_planned(static_cast<int>(planned));
  BlindLoopResult out;
  out.in_sample = loop_on(run, base, points, candidates_for(cfg.fit_pin), cfg.fit_pin,
                          cfg.min_gain, true);
  for (double left : pins) {
    BlindFold f;
    f.pin_mm = left;
    std::vector<FbPoint> seen, unseen;
    for (const auto& p : points) (same_pin(p.pin_mm, left) ? unseen : seen).push_back(p);
    // The fold's fit pin: the remaining pin nearest the loop's fit pin (the
    // fit pin itself when it remains); every other remaining pin chooses.
    f.fit_pin_mm = fold_fit_pin(pins, left, cfg.fit_pin);
    for (double d : pins)
      if (!same_pin(d, left) && !same_pin(d, f.fit_pin_mm)) f.select_pins.push_back(d);
    std::cout << "model loop, fold without the " << fmt(left) << " mm pin: fit on " << fmt(f.fit_pin_mm) << " mm\n"
              << std::flush;
    const ModelLoopResult r = loop_on(run, base, seen, candidates_for(f.fit_pin_mm), f.fit_pin_mm, cfg.min_gain, true);
    f.model = r.final_model.model;
    for (const auto& st : r.steps) f.decisions.push_back(st.candidate + " (" + st.member + "): " + st.decision);
    // Only now the left-out pin: the fold's baseline and final model on it.
    f.baseline = run.evaluate(specs_of(base, unseen), unseen, f.fit_pin_mm);
    f.final_model = run.evaluate(specs_of(r.final_spec, unseen), unseen, f.fit_pin_mm);
    out.folds.push_back(std::move(f));
  }
  out.runs = run.runs();
  out.run_wall_s = run.wall();
  return out;
}

}  // namespace drawbend::modelloop
