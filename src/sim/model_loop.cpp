// The model-level loop (sim/model_loop.hpp).
#include "sim/model_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/hash.hpp"
#include "material/swift_fit.hpp"
#include "sim/case_pool.hpp"
#include "sim/material_choice.hpp"

#include <filesystem>
#include <sstream>

#include <toml++/toml.h>

#include "core/strip_limits.hpp"
#include "core/toml_read.hpp"

namespace drawbend::sim {

std::vector<FbPoint> read_fb_points(const std::string& csv_path) {
  const CsvTable t = read_csv(csv_path);
  std::vector<std::string> problems;
  for (const char* col : {"pin_diameter_mm", "back_tension_N", "bending_force_N"})
    if (!t.has_column(col)) problems.push_back(t.path + ":1: missing column '" + col + "'");
  if (!problems.empty()) throw InputError(problems.front());
  std::vector<FbPoint> out;
  for (const auto& r : t.rows) {
    FbPoint p;
    p.where = t.path + ":" + std::to_string(r.line);
    try {
      p.pin_mm = t.number(r, "pin_diameter_mm");
      p.back_tension_N = t.number(r, "back_tension_N");
      p.bending_N = t.number(r, "bending_force_N");
    } catch (const InputError& e) {
      problems.push_back(e.what());
      continue;
    }
    if (p.pin_mm <= 0) problems.push_back(t.where(r, "pin_diameter_mm") + ": must be > 0 mm");
    if (p.pin_mm > kMaxPinDiameterMM)
      problems.push_back(t.where(r, "pin_diameter_mm") + ": expected a pin diameter up to " + fmt(kMaxPinDiameterMM) +
                         " mm (a draw-bend pin; check the units), found " + fmt(p.pin_mm) + " mm");
    if (p.back_tension_N <= 0) problems.push_back(t.where(r, "back_tension_N") + ": must be > 0 N");
    if (p.bending_N <= 0) problems.push_back(t.where(r, "bending_force_N") + ": must be > 0 N");
    // The same bound as `drawbend loop` (core/strip_limits.hpp): before it, a
    // back tension of 1e300 N went into the FE decks as a load.
    for (const auto& [col, v] : {std::pair{"back_tension_N", p.back_tension_N}, std::pair{"bending_force_N", p.bending_N}})
      if (v > kMaxStripForceN)
        problems.push_back(t.where(r, col) + ": expected a force below " + fmt(kMaxStripForceN) +
                           " N (a strip test; check the units), found " + fmt(v) + " N");
    out.push_back(p);
  }
  if (out.empty() && problems.empty()) problems.push_back(t.path + ": no data rows");
  if (!problems.empty()) {
    std::string all;
    for (const auto& s : problems) all += (all.empty() ? "" : "\n") + s;
    throw InputError(all);
  }
  return out;
}

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
      jobs.push_back({s, run_root + "/fb_" + hex64(fnv1a64(text))});
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

}  // namespace

ModelLoopResult run_model_loop(const DrawBendSpec& base, const std::vector<FbPoint>& points,
                               const std::vector<ModelCandidate>& candidates, const ModelLoopConfig& cfg) {
  Runner run(cfg);
  // Progress: baseline, then per candidate its members on the fit pin and the chosen one held out.
  std::size_t planned = points.size(), on_fit = 0;
  for (const auto& p : points) on_fit += same_pin(p.pin_mm, cfg.fit_pin);
  for (const auto& c : candidates) planned += c.members.size() * on_fit + (points.size() - on_fit);
  run.set_planned(static_cast<int>(planned));
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
    f.fit_pin_mm = pins.front() == left ? pins[1] : pins.front();
    for (double d : pins)
      if (!same_pin(d, left) && std::abs(d - cfg.fit_pin) < std::abs(f.fit_pin_mm - cfg.fit_pin)) f.fit_pin_mm = d;
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

namespace {

/// The [material] table of a spec's material (empty: the isotropic J2 model on
/// the spec's hardening curve; '{...}': an inline table; else a TOML file).
toml::table material_table(const std::string& material) {
  if (material.empty()) return toml::table{{"type", "j2"}};
  if (material.front() != '{') {
    toml::table file = parse_toml_file(material);
    if (const auto* t = file["material"].as_table()) return *t;
    throw InputError(material + ": expected a [material] table");
  }
  toml::table w = parse_toml("material = " + material, "--material");
  if (const auto* t = w["material"].as_table()) return *t;
  throw InputError("--material: expected a TOML inline table, found " + material);
}

void inline_all(toml::table& t) {
  for (auto&& [k, v] : t)
    if (auto* sub = v.as_table()) {
      inline_all(*sub);
      sub->is_inline(true);
    }
}

/// `current` with the keys of `add` set (a flow-curve key replaces the
/// others), as an inline table: candidates compose (Voce or Hill'48 on top of
/// an accepted combined-hardening model keep its back stress).
std::string merged_material(const std::string& current, const toml::table& add) {
  toml::table m = material_table(current);
  if (io::has_flow_curve(add))
    for (const char* k : io::kFlowCurveKeys) m.erase(k);
  for (auto&& [k, v] : add) m.insert_or_assign(k, v);
  inline_all(m);
  m.is_inline(true);
  std::ostringstream o;
  o << m;
  return o.str();
}

/// One key of a material file's [material] table (InputError if missing).
toml::node_view<const toml::node> file_key(const toml::table& file_material, const std::string& path,
                                           const char* key) {
  if (!file_material.contains(key)) throw InputError(path + ": [material] has no '" + key + "'");
  return file_material[key];
}


/// The flow curve of a [material] table, read by the typed reader
/// (io/material_spec.hpp; `default_table`, a CSV path, when it names none).
material::HardeningCurve curve_of(const toml::table& m, const std::string& default_table) {
  toml::table filled = m;
  const io::MaterialSpec spec = material_choice(filled, default_table, "--material");
  return io::make_flow_curve(spec.curve.value_or(io::CurveFile{default_table}), "");
}

/// The flow curve a spec's material uses (curve_of on its material).
material::HardeningCurve current_curve(const DrawBendSpec& s) { return curve_of(material_table(s.material), s.hardening); }

/// An inline hardening table of plastic strains x and stresses r.
toml::table hardening_table(const std::vector<double>& x, const std::vector<double>& r) {
  toml::array ax, ay;
  for (std::size_t i = 0; i < x.size(); ++i) {
    ax.push_back(x[i]);
    ay.push_back(r[i]);
  }
  toml::table h;
  h.insert("plastic_strain", ax);
  h.insert("true_stress_MPa", ay);
  return h;
}

/// A new flow curve (`add`'s swift or voce) on a model with Chaboche back
/// stresses: the curve is the monotonic response, so it is carved by the
/// model's back-stress terms (X_k = C_k / gamma_k) as the chaboche candidate
/// carves the table, and goes in as an inline hardening table.  Otherwise the
/// back stress would come on top of the new curve and raise every flow stress
/// by X_sat.  `add` unchanged when the model has no Chaboche terms.
toml::table carved_curve(const DrawBendSpec& s, toml::table add) {
  const toml::table cur = material_table(s.material);
  const auto* C = cur["kinematic"]["C"].as_array();
  const auto* g = cur["kinematic"]["gamma"].as_array();
  if (!C || !g || C->size() != g->size() || C->empty()) return add;
  material::HardeningCurve c = curve_of(add, s.hardening);
  std::vector<double> r;
  for (std::size_t k = 0; k < C->size(); ++k) {
    const double gk = (*g)[k].value_or(0.0);
    if (!(gk > 0))  // gamma 0 is linear (Prager) hardening: no saturation X_sat to carve
      throw InputError("material: a new flow curve cannot be carved by the linear kinematic term C = " +
                       fmt((*C)[k].value_or(0.0)) + " MPa with gamma " + fmt(gk) + " (no saturated back stress)");
    const double xk = (*C)[k].value_or(0.0) / gk;
    r = carved_isotropic_part(c, xk, gk);
    c = material::HardeningCurve(c.plastic_strains(), r, "the carved curve");
  }
  for (const char* k : {"voce", "swift"}) add.erase(k);
  add.insert_or_assign("hardening", hardening_table(c.plastic_strains(), c.stresses()));
  return add;
}

/// The chaboche candidate's material (see carved_isotropic_part).
toml::table chaboche_material(const DrawBendSpec& s, double x_sat, double gamma) {
  const material::HardeningCurve c = current_curve(s);
  const toml::table h = hardening_table(c.plastic_strains(), carved_isotropic_part(c, x_sat, gamma));
  toml::table k;
  k.insert("C", toml::array{gamma * x_sat});
  k.insert("gamma", toml::array{gamma});
  toml::table add;
  add.insert("hardening", h);
  add.insert("kinematic", k);
  return add;
}
}  // namespace

std::vector<double> carved_isotropic_part(const material::HardeningCurve& c, double x_sat, double gamma) {
  const std::vector<double>& x = c.plastic_strains();
  std::vector<double> r = c.stresses();
  for (std::size_t i = 0; i < x.size(); ++i) r[i] -= x_sat * (1.0 - std::exp(-gamma * x[i]));
  for (std::size_t i = r.size() - 1; i-- > 0;) r[i] = std::min(r[i], r[i + 1]);
  if (!(r.front() > 0)) throw InputError("candidate chaboche: X_sat " + fmt(x_sat) + " MPa leaves no elastic range");
  return r;
}

ModelCandidate named_candidate(const std::string& name, const std::string& data_dir) {
  ModelCandidate c;
  c.name = name;
  const auto colon = name.find(':');
  const std::string kind = name.substr(0, colon);
  const std::string arg = colon == std::string::npos ? "" : name.substr(colon + 1);
  auto values_of = [&](const std::string& a) {
    std::vector<double> v;
    std::size_t pos = 0;
    while (pos <= a.size()) {
      const auto slash = a.find('/', pos);
      const std::string tok = a.substr(pos, slash == std::string::npos ? std::string::npos : slash - pos);
      char* end = nullptr;
      const double x = std::strtod(tok.c_str(), &end);
      if (tok.empty() || *end != '\0' || !std::isfinite(x))
        throw InputError("candidate '" + name + "': '" + tok + "' is not a number");
      v.push_back(x);
      if (slash == std::string::npos) break;
      pos = slash + 1;
    }
    return v;
  };
  auto values = [&]() { return values_of(arg); };
  if (kind == "split") {
    c.what = "split combined hardening (kinematic fraction beta fitted on the fit pin)";
    for (double b : values()) {
      if (b < 0 || b > 1) throw InputError("candidate '" + name + "': beta must lie in [0, 1]");
      c.members.push_back({"split beta " + fmt(b), [b](DrawBendSpec& s) {
                             // replaces the model's material, and with it a Chaboche back stress
                             s.material = "{ type = \"j2_combined\", kinematic = { beta = " + fmt_shortest(b) + " } }";
                           }});
    }
  } else if ((kind == "voce" || kind == "hill48") && arg.empty()) {
    // Only the named part changes: Voce replaces the flow curve (yield surface
    // and back stress kept); Hill'48 replaces the yield surface (flow curve
    // and back stress kept), so each effect is judged alone.
    const std::string f = data_dir + (kind == "voce" ? "/materials/aa5754_o_voce_hou2020.toml"
                                                      : "/materials/aa5754_o_hill48_hou2020.toml");
    const toml::table fm = material_table(f);
    toml::table add;
    if (kind == "voce") {
      c.what = "published Voce flow curve (Hou 2020) instead of the tabulated RD (Swift) curve";
      add.insert("voce", *file_key(fm, f, "voce").node());
    } else {
      c.what = "Hill'48 yield surface, published r-values (Hou 2020), on the same flow curve";
      add.insert("type", "hill48");
      add.insert("hill48", *file_key(fm, f, "hill48").node());
    }
    c.members.push_back({kind == "voce" ? "Voce flow curve" : "Hill'48", [add](DrawBendSpec& s) {
                           // hill48 on a combined model keeps its back stress (hill48 takes `kinematic`);
                           // Voce on it is carved by that back stress
                           s.material = merged_material(s.material, carved_curve(s, add));
                         }});
  } else if (kind == "offset" && arg.empty()) {
    // The low-strain flow curve: Table 5.1's 0.2 % offset yield stress is the
    // flow stress at eps_p = 0.002, not at 0 as the shipped RD table takes it
    // (data/materials/aa5754_o_rd.csv, fit condition 1).  Same UTS and n.
    const std::string f = data_dir + "/thesis/table_5_1.csv";
    const CsvTable t51 = read_csv(f);
    const CsvRow* rd = nullptr;
    for (const auto& r : t51.rows)
      if (t51.text(r, "direction") == "RD") rd = &r;
    if (!rd) throw InputError(f + ": no RD row");
    const material::SwiftLaw law = material::fit_swift(t51.number(*rd, "YS02_MPa"), t51.number(*rd, "UTS_MPa"),
                                                        t51.number(*rd, "n"), 0.002);
    c.what = "Swift refitted with Table 5.1's 0.2 % offset yield stress at eps_p = 0.002 (K " + fmt(law.K, 5) +
             " MPa, e0 " + fmt(law.eps0, 4) + ", n " + fmt(law.n) + "; initial yield " + fmt(law.stress(0), 4) +
             " MPa): the flow curve below 1 % strain";
    toml::table sw;
    sw.insert("K", law.K);
    sw.insert("e0", law.eps0);
    sw.insert("n", law.n);
    toml::table add;
    add.insert("swift", sw);
    c.members.push_back({"Swift at 0.2 % offset",
                         [add](DrawBendSpec& s) { s.material = merged_material(s.material, carved_curve(s, add)); }});
  } else if (kind == "chaboche") {
    // One Armstrong-Frederick back stress carved out of the flow curve: early
    // re-yielding on unbending, which weighs most at small bending strain
    // (large R/t).  chaboche:X1/X2...[@G1/G2...]: every (X_sat, gamma) pair is
    // a member, chosen on the fit pin.  Without @ the rate is gamma = 300
    // (95 % saturated at eps_p = 1 %), an assumption: no published AA5754-O
    // reverse-loading data (data/materials/README.md).  One point on the fit
    // pin does not identify both parameters: the chosen pair is one of many
    // that fit it (Chapter 8's beam trace shows how far they differ on the
    // other pins).
    const auto at = arg.find('@');
    const std::vector<double> xs_list = values_of(arg.substr(0, at));
    const std::vector<double> g_list = at == std::string::npos ? std::vector<double>{300.0} : values_of(arg.substr(at + 1));
    c.what = at == std::string::npos
                 ? "Chaboche back stress (gamma 300, X_sat fitted on the fit pin) carved out of the flow curve"
                 : "Chaboche back stress (X_sat and gamma fitted on the fit pin) carved out of the flow curve";
    for (double g : g_list) {
      if (!(g > 0)) throw InputError("candidate '" + name + "': gamma must be > 0");
      for (double xs : xs_list) {
        if (!(xs > 0)) throw InputError("candidate '" + name + "': X_sat must be > 0 MPa");
        const std::string label = "Chaboche X_sat " + fmt(xs) + " MPa" + (at == std::string::npos ? "" : ", gamma " + fmt(g));
        c.members.push_back({label, [xs, g](DrawBendSpec& s) {
                               // replaces split's beta: the solver takes one form of back stress
                               toml::table add = chaboche_material(s, xs, g);
                               toml::table cur = material_table(s.material);
                               if (cur["type"].value_or(std::string()) != "hill48") add.insert("type", "j2_combined");
                               s.material = merged_material(s.material, add);
                             }});
      }
    }
  } else if (kind == "ms") {
    c.what = "mass scaling (numerical: should change nothing when converged)";
    for (double x : values()) {
      if (x < 1) throw InputError("candidate '" + name + "': mass scaling must be >= 1");
      c.members.push_back({"mass scaling " + fmt(x), [x](DrawBendSpec& s) { s.mass_scaling = x; }});
    }
  } else if (kind == "across") {
    c.what = "elements across the half width (numerical)";
    for (double x : values()) {
      if (x < 1 || x != std::floor(x)) throw InputError("candidate '" + name + "': across must be a positive integer");
      const int n = static_cast<int>(x);
      c.members.push_back({std::to_string(n) + " across", [n](DrawBendSpec& s) { s.across = n; }});
    }
  } else {
    throw InputError("unknown candidate '" + name + "' (expected split:B1/B2..., chaboche:X1/X2...[@G1/G2...], voce, hill48, offset, ms:X, across:N)");
  }
  return c;
}

void save_eval_csv(const ModelEval& e, const std::string& path) {
  CsvWriter w({"pin_diameter_mm", "back_tension_N", "measured_FB_N", "predicted_FB_N", "rel_error", "role", "run"});
  w.comment(" model: " + e.model + "; full-strip forces [N]; rel_error = predicted/measured - 1");
  for (const auto& p : e.points)
    w.row({fmt(p.measured.pin_mm), fmt(p.measured.back_tension_N), fmt(p.measured.bending_N, 5),
           fmt_fixed(p.predicted_N, 1), fmt(p.rel_error(), 4), p.held_out ? "held-out" : "fit", p.run_dir});
  w.save(path);
}

}  // namespace drawbend::sim
