// Chapter 7 steps 9 and 10: the held-out studies of issue 50, item 5.
// Step 9 (demonstration 4): generator 1 ("blind") on the seeds of
// heldout_protocol.md, 50500000 + i (Config::heldout_seed0); since
// heldout_protocol_v2.md these are development data.
// Step 10 (demonstration 5, heldout_protocol_v2.md and
// heldout_protocol_v2_wild.md; runs 13 and 14 on the seeds of
// heldout_protocol_v7.md, fixed before any run on them): generator 1 on
// 60300000 + i and generator 2 ("wild", src/loop/wild_synth.hpp) on
// 60400000 + i (runs 3-12 used 53100000, 54200000, 57100000, 57200000,
// 58100000, 58200000, 59100000, 59200000, 60100000 and 60200000 + i).
// Set i of a study has class classes[i % 6] and noise 3 N when (i / 6) is
// even, 8 N when odd.  Every set is written as a lab file (write_measured),
// read back (parse_measured) and given to the loop with the chapter's
// options; the loop is never told the class, variable or noise.
//   detected     the first step names one of the truth's aliases AND the
//                final held-out RMS <= 2 x the true noise sd;
//   false alarm  a null set on which the loop adds an effect of an
//                undeclared variable (a step of class "undeclared variable");
//                a null set whose only steps are on the model's own inputs
//                (class "base model": pin, pressure, speed, direction, back
//                tension) is counted apart as base-model mismatch (issue 50
//                item 4; until 2026-12-02 any effect counted as an alarm:
//                runs 1-6 of heldout_record.md were scored so).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "ch7_steps.hpp"
#include "loop/blind_synth.hpp"
#include "loop/wild_synth.hpp"

namespace ch7 {

using namespace drawbend;
using namespace drawbend::loop;

namespace {
constexpr double kNoiseOdd = 8, kNoiseEven = 3;    // N, heldout_protocol.md
constexpr double kDetectRatio = 2;                 // final RMS / true noise sd
constexpr double kKMin = 2.5, kKMax = 6;           // effect RMS / noise sd, as drawn

struct ClassSum {
  int sets = 0, detected = 0, named_rms_high = 0, wrong_first = 0, no_step = 0;
  int base_only = 0;  ///< null sets with steps on the model's own inputs only (base-model mismatch)
  /// Effect sets whose planted effect is carried by at least kSupportMin tests
  /// (kSupportShare of its sum of squares; BlindTruth::support_tests), and their detections.
  int wide = 0, wide_detected = 0;
};
// An effect that fewer tests carry can hardly be named from the data: every
// numeric test-level column singles out one test, and many of them two
// (heldout_record.md, h50-cvperm).
constexpr int kSupportMin = 3;
}  // namespace

namespace {
// One held-out study: which generator, which seeds, and the names its
// tables, values and checks are written under.
struct Study {
  std::string generator;  ///< blind or wild
  std::string demo;       ///< "demonstration 4 (held out)" ...
  std::string runs_table, summary_table;
  std::string value, class_value;  ///< prefixes of the chapter values ("h", "hc_")
  std::string check;               ///< check id prefix ("ch7.heldout")
  std::string protocol;            ///< the protocol file the checks cite
  int sets = 0, seed0 = 0;
  std::string scope = "held-out";  ///< in the check texts; "development-data" once the seeds are spent
};

// What a study's sets add up to: filled by run_sets and summary_table, read by study_checks.
struct Tally {
  std::map<std::string, ClassSum> sum;
  bool generator_ok = true, null_base_ok = true;
  std::string generator_note, null_note;
  double worst_null_base = 0;
  int eff_sets = 0, eff_det = 0, null_sets = 0, null_alarm = 0;
  int null_base_terms = 0;  ///< null sets with base-model terms only (not alarms)
  double rate = 0;
};

// Step 1: every set generated, written as a lab file, read back, given to the
// loop and scored; one row each in the runs table.
Tally run_sets(Chapter& c, const Config& cfg, const Study& st, const std::vector<std::string>& classes,
               const LoopOptions& o) {
  const bool wild = st.generator == "wild";
  const MapLibrary maps = cfg.maps_dir.empty() ? MapLibrary::stand_in({12.7, 25.4, 42}) : MapLibrary::load_dir(cfg.maps_dir);
  auto w = c.table({"set", "seed", "class", "noise_N", "rows", "variable", "aliases", "shape", "channel", "cell",
                    "k_effect_over_noise", "support_tests", "steps", "outcome", "base_over_noise", "final_over_noise"},
                   st.demo + ": every " + st.generator + " set; k = planted effect RMS / noise sd; support_tests = the "
                   "fewest tests that carry " + fmt(100 * kSupportShare) + " % of the planted effect's sum of squares; the RMS ratios "
                   "are held-out RMS of the outlet force over the true noise sd");
  Tally tally;
  std::map<std::string, ClassSum>& sum = tally.sum;
  bool &generator_ok = tally.generator_ok, &null_base_ok = tally.null_base_ok;
  std::string &generator_note = tally.generator_note, &null_note = tally.null_note;
  double& worst_null_base = tally.worst_null_base;
  const std::string tmp = c.out("heldout_set.csv");
  for (int i = 0; i < st.sets; ++i) {
    const std::string cls = classes[i % classes.size()];
    const double noise = (i / 6) % 2 ? kNoiseOdd : kNoiseEven;
    BlindTruth truth;
    const auto seed = static_cast<std::uint64_t>(st.seed0) + static_cast<std::uint64_t>(i);
    const Dataset gen = wild ? synthesize_wild({cls, noise, seed}, truth) : synthesize_blind({cls, noise, seed}, truth);
    write_measured(tmp, gen);
    std::ifstream in(tmp, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const Dataset data = parse_measured(text.str(), st.generator + " set " + std::to_string(i));
    const bool null = cls == "null";
    const double k = truth.effect_rms_N / noise;
    if (!data.problems.empty() || data.rows.size() != gen.rows.size() ||
        (!null && !(k >= kKMin * (1 - 1e-6) && k <= kKMax * (1 + 1e-6)))) {
      generator_ok = false;
      generator_note += " set " + std::to_string(i) + ": " + std::to_string(data.problems.size()) + " problems, " +
                        std::to_string(data.rows.size()) + "/" + std::to_string(gen.rows.size()) + " rows, k " + fmt(k, 4) + ";";
    }
    const Design d = make_design(data, maps);
    const LoopResult r = run_loop(d, o);
    std::string steps;
    for (const auto& s : r.steps) steps += (steps.empty() ? "" : "; ") + s.variable + " -> " + s.effect;
    const double base = r.cv.front().rms / noise, fin = r.cv.back().rms / noise;
    const bool named = !r.steps.empty() &&
                       std::find(truth.aliases.begin(), truth.aliases.end(), r.steps[0].variable) != truth.aliases.end();
    std::string outcome;
    ClassSum& s = sum[cls];
    s.sets++;
    if (null) {
      int undeclared = 0;
      for (const auto& x : r.steps) undeclared += x.cls == "undeclared variable";
      outcome = undeclared ? "FALSE ALARM" : r.steps.empty() ? "quiet" : "base-model mismatch (not an alarm)";
      s.wrong_first += undeclared > 0;
      s.base_only += undeclared == 0 && !r.steps.empty();
      worst_null_base = std::max(worst_null_base, base);
      if (!(base <= o.noise_ratio)) null_base_ok = false, null_note += " set " + std::to_string(i) + ": " + fmt(base, 3) + ";";
    } else if (named && fin <= kDetectRatio) {
      outcome = "detected", s.detected++;
      s.wide_detected += truth.support_tests >= kSupportMin;
    } else if (named) {
      outcome = "named, RMS above 2 sd", s.named_rms_high++;
    } else if (r.steps.empty()) {
      outcome = "no step", s.no_step++;
    } else {
      outcome = "wrong first step", s.wrong_first++;
    }
    if (!null) s.wide += truth.support_tests >= kSupportMin;
    std::string aliases;
    for (const auto& a : truth.aliases) aliases += (aliases.empty() ? "" : " ") + a;
    w.row({std::to_string(i), std::to_string(truth.seed), cls, fmt(noise), std::to_string(data.rows.size()),
           null ? "-" : truth.variable, null ? "-" : aliases, null ? "-" : truth.shape, null ? "-" : truth.channel,
           truth.cell.empty() ? "-" : truth.cell, null ? "-" : fmt(k, 3),
           null ? "-" : std::to_string(truth.support_tests), steps.empty() ? "none" : steps, outcome,
           fmt(base, 3), fmt(fin, 3)});
  }
  std::filesystem::remove(tmp);
  c.save(w, st.runs_table);
  return tally;
}

// Step 2: the per-class table and the study's values.
void summary_table(Chapter& c, const Study& st, const std::vector<std::string>& classes, Tally& tally) {
  std::map<std::string, ClassSum>& sum = tally.sum;
  const double worst_null_base = tally.worst_null_base;
  auto t = c.table({"class", "sets", "detected", "named_but_rms_above_2sd", "wrong_first_step", "no_step",
                    "false_alarms", "base_model_mismatch_only"},
                   st.demo + ": per class; null sets count false alarms (an effect of an undeclared variable added) "
                   "and, apart, the sets whose only steps are on the model's own inputs (base-model mismatch)");
  int &eff_sets = tally.eff_sets, &eff_det = tally.eff_det, &null_sets = tally.null_sets, &null_alarm = tally.null_alarm;
  int wide = 0, wide_det = 0;
  for (const auto& cls : classes) {
    const ClassSum& s = sum[cls];
    const bool null = cls == "null";
    t.row({cls, std::to_string(s.sets), null ? "-" : std::to_string(s.detected), null ? "-" : std::to_string(s.named_rms_high),
           null ? "-" : std::to_string(s.wrong_first), null ? "-" : std::to_string(s.no_step),
           null ? std::to_string(s.wrong_first) : "-", null ? std::to_string(s.base_only) : "-"});
    if (null) null_sets += s.sets, null_alarm += s.wrong_first, tally.null_base_terms += s.base_only;
    else eff_sets += s.sets, eff_det += s.detected, wide += s.wide, wide_det += s.wide_detected;
    const std::string key = cls == "test-level" ? "test_level" : cls;
    c.value(st.class_value + key + "_sets", std::to_string(s.sets));
    c.value(st.class_value + key + "_hits", std::to_string(null ? s.wrong_first : s.detected));
  }
  c.save(t, st.summary_table);
  const double rate = tally.rate = static_cast<double>(eff_det) / std::max(1, eff_sets);
  const double fa = static_cast<double>(null_alarm) / std::max(1, null_sets);
  c.value(st.value + "_sets", std::to_string(st.sets));
  c.value(st.value + "_effect_sets", std::to_string(eff_sets));
  c.value(st.value + "_detected", std::to_string(eff_det));
  c.value(st.value + "_detection_rate", fmt(100 * rate, 3), "%");
  c.value(st.value + "_support_share", fmt(100 * kSupportShare), "%");
  c.value(st.value + "_wide_sets", std::to_string(wide));
  c.value(st.value + "_wide_detected", std::to_string(wide_det));
  c.value(st.value + "_narrow_sets", std::to_string(eff_sets - wide));
  c.value(st.value + "_narrow_detected", std::to_string(eff_det - wide_det));
  c.value(st.value + "_null_sets", std::to_string(null_sets));
  c.value(st.value + "_null_alarm", std::to_string(null_alarm));
  c.value(st.value + "_null_base_terms", std::to_string(tally.null_base_terms));
  c.value(st.value + "_false_alarm_rate", fmt(100 * fa, 3), "%");
  c.value(st.value + "_seed0", std::to_string(st.seed0));
  c.value(st.value + "_seed_last", std::to_string(static_cast<long long>(st.seed0) + st.sets - 1));
  c.value(st.value + "_worst_null_base", fmt(worst_null_base, 3));
}

// Step 3: the study's four checks (heldout_protocol.md checks 1-4).
void study_checks(Chapter& c, const Study& st, const LoopOptions& o, const Tally& tally) {
  const bool generator_ok = tally.generator_ok, null_base_ok = tally.null_base_ok;
  const std::string &generator_note = tally.generator_note, &null_note = tally.null_note;
  const int eff_det = tally.eff_det, eff_sets = tally.eff_sets, null_alarm = tally.null_alarm, null_sets = tally.null_sets;
  const double rate = tally.rate;
  c.checks().claim(study::Kind::software, st.check + ".generator",
                   "every " + st.generator + " set reads back with no problems and all its rows, and its planted "
                   "effect's RMS is 2.5-6 x the noise sd" + (generator_ok ? std::string() : ":" + generator_note),
                   generator_ok, st.protocol + " check 1: the generator writes valid data of the stated size");
  c.checks().claim(study::Kind::health, st.check + ".null_base",
                   "on every null " + st.generator + " set the base model's held-out RMS is <= " + fmt(o.noise_ratio) +
                       " x the noise sd" + (null_base_ok ? std::string() : ":" + null_note),
                   null_base_ok, st.protocol + " check 2: null data are the base model plus noise, so a larger "
                   "error would be a generator the loop's base cannot represent, not a false alarm of the loop");
  c.checks().claim(study::Kind::simulated, st.check + ".detected",
                   st.scope + " detection rate (" + st.generator + ") >= 90 % (" + std::to_string(eff_det) + " of " +
                       std::to_string(eff_sets) + ")",
                   rate >= 0.9, st.protocol + " check 3: issue 50's goal on data the loop was not written for");
  c.checks().claim(study::Kind::simulated, st.check + ".null",
                   st.scope + " false alarms (" + st.generator + ") on at most 1/12 of the null sets (" +
                       std::to_string(null_alarm) + " of " + std::to_string(null_sets) + "; an alarm is an effect of an "
                       "undeclared variable, and " + std::to_string(tally.null_base_terms) + " null set(s) had only "
                       "base-model terms, reported apart as base-model mismatch)",
                   12 * null_alarm <= null_sets, st.protocol + " check 4: issue 50's goal (at most 1 in 12); issue 50 "
                   "item 4: mismatch of the base model's own terms is not an undeclared effect");
}

// One held-out study: its sets run and scored, the summary, the checks.
void run_study(Chapter& c, const Config& cfg, const Study& st) {
  const std::vector<std::string>& classes = st.generator == "wild" ? wild_classes() : blind_classes();
  LoopOptions o;
  o.permutations = cfg.permutations;
  Tally tally = run_sets(c, cfg, st, classes, o);
  summary_table(c, st, classes, tally);
  study_checks(c, st, o, tally);
}

}  // namespace

void heldout_study(Chapter& c, const Config& cfg) {
  // The first protocol's seeds were run twice in the session that wrote them;
  // heldout_protocol_v2.md made them development data (the loop has since been
  // changed after looking at them), so their checks no longer say held out.
  run_study(c, cfg, {"blind", "demonstration 4 (the first protocol's seeds, development data since heldout_protocol_v2.md)",
                     "heldout_runs", "heldout_summary", "h", "hc_", "ch7.heldout", "heldout_protocol.md",
                     cfg.heldout_sets, cfg.heldout_seed0, "development-data"});
}

void heldout2_study(Chapter& c, const Config& cfg) {
  const bool protocol_seeds = cfg.heldout2_blind_seed0 == kHeldout2BlindSeed0 && cfg.heldout2_wild_seed0 == kHeldout2WildSeed0;
  c.value("h2_seeds", protocol_seeds ? "the protocols' held-out seeds"
                                     : "NOT the protocols' held-out seeds (development seeds chosen by option): not a "
                                       "held-out result");
  run_study(c, cfg, {"blind", "demonstration 5 (held out, generator 1, fresh seeds)", "heldout_runs_blind",
                     "heldout_summary_blind", "h2b", "h2bc_", "ch7.heldout2.blind", "heldout_protocol_v6.md",
                     cfg.heldout2_sets, cfg.heldout2_blind_seed0});
  run_study(c, cfg, {"wild", "demonstration 5 (held out, generator 2)", "heldout_runs_wild", "heldout_summary_wild",
                     "h2w", "h2wc_", "ch7.heldout2.wild", "heldout_protocol_v6.md", cfg.heldout2_sets,
                     cfg.heldout2_wild_seed0});
}

}  // namespace ch7
