// Chapter 7 step 7 (demonstration 3): synthetic data with undeclared effects.
// Every data set has the same design; the loop runs with the same options on
// all of them and is never told what was hidden.  A planted effect counts as
// detected when the loop's first step names one of the truth's variables
// (truth.aliases: e.g. a per-pin factor may be named by pin, pin diameter, 1/R
// or pin Ra, which the design confounds).  A null set is a false alarm when
// the loop adds any effect.
#include <algorithm>
#include <cmath>
#include <map>

#include "ch7_steps.hpp"
#include "loop/report.hpp"
#include "loop/synth.hpp"

namespace ch7 {

using namespace drawbend;
using namespace drawbend::loop;

void synthetic_detection(Chapter& c, const Config& cfg) {
  const MapLibrary maps = cfg.maps_dir.empty() ? MapLibrary::stand_in({12.7, 25.4, 42}) : MapLibrary::load_dir(cfg.maps_dir);
  const double noises[3] = {2, 5, 10};
  auto w = c.table({"effect", "noise_N", "seed", "truth_variable", "steps", "detected", "wrong_steps", "flagged",
                    "rms_base_N", "rms_final_N", "final_over_noise"},
                   "demonstration 3: the loop on synthetic data (hidden law in truth, not given to the loop); "
                   "held-out RMS of the outlet force in N; flagged = screened variables reported without an effect");
  struct Sum {
    int sets = 0, detected = 0, wrong = 0, flagged = 0, null_alarm = 0;
    double worst_ratio = 0;
  };
  std::map<std::pair<std::string, double>, Sum> sum;
  Sum all_eff, all_null;
  size_t n_rows = 0;
  LoopOptions o;
  o.permutations = cfg.permutations;
  for (double noise : noises)
    for (const auto& effect : synth_effects()) {
      const bool null = effect == "none";
      const int seeds = null ? cfg.null_seeds : cfg.effect_seeds;
      for (int k = 0; k < seeds; ++k) {
        SynthOptions so;
        so.effect = effect;
        so.noise_N = noise;
        so.seed = 1000 + 17 * k + static_cast<int>(noise);
        SynthTruth truth;
        const Dataset data = synthesize(so, maps, truth);
        n_rows = data.rows.size();
        const Design d = make_design(data, maps);
        const LoopResult r = run_loop(d, o);
        std::string steps;
        int wrong = 0;
        for (const auto& s : r.steps) {
          steps += (steps.empty() ? "" : "; ") + s.variable + " -> " + s.effect;
          wrong += std::find(truth.aliases.begin(), truth.aliases.end(), s.variable) == truth.aliases.end();
        }
        const bool detected = !null && !r.steps.empty() &&
                              std::find(truth.aliases.begin(), truth.aliases.end(), r.steps[0].variable) !=
                                  truth.aliases.end();
        const double ratio = r.cv.back().rms / noise;
        w.row({effect, fmt(noise), std::to_string(so.seed), truth.variable, steps.empty() ? "none" : steps,
               null ? "-" : (detected ? "yes" : "no"), std::to_string(wrong), std::to_string(r.unexplained.size()),
               fmt(r.cv.front().rms, 4), fmt(r.cv.back().rms, 4), fmt(ratio, 3)});
        Sum& s = sum[{effect, noise}];
        Sum& a = null ? all_null : all_eff;
        for (Sum* t : {&s, &a}) {
          t->sets++;
          t->detected += detected;
          t->wrong += wrong;
          t->flagged += !r.unexplained.empty();
          t->null_alarm += null && !r.steps.empty();
          if (detected || null) t->worst_ratio = std::max(t->worst_ratio, ratio);
        }
        if (effect == "drift" && noise == 5 && k == 0) {  // one example, plotted
          c.save(residuals_table(d, r), "synth_example_residuals");
          for (size_t i = 0; i < r.candidates.size(); ++i)
            if (r.candidates[i].name == "test_order")
              c.plot("loop_residual", "synth_example_test_order",
                     {{"datafile", c.out("tables/synth_example_residuals.csv")}, {"xcol", std::to_string(6 + i)},
                      {"xname", "test_order (hidden drift, noise 5 N)"}});
        }
      }
    }
  c.save(w, "synth_runs");
  auto t = c.table({"effect", "noise_N", "sets", "detected", "wrong_steps", "sets_flagged", "null_sets_with_a_step",
                    "worst_final_over_noise"},
                   "demonstration 3 summary: detection of hidden effects and false alarms on null sets");
  for (const auto& [k, s] : sum)
    t.row({k.first, fmt(k.second), std::to_string(s.sets), k.first == "none" ? "-" : std::to_string(s.detected),
           std::to_string(s.wrong), std::to_string(s.flagged), k.first == "none" ? std::to_string(s.null_alarm) : "-",
           k.first == "none" ? "-" : fmt(s.worst_ratio, 3)});
  c.save(t, "synth_summary");
  c.value("s_effect_sets", std::to_string(all_eff.sets));
  c.value("s_detected", std::to_string(all_eff.detected));
  c.value("s_wrong", std::to_string(all_eff.wrong));
  c.value("s_null_sets", std::to_string(all_null.sets));
  c.value("s_null_alarm", std::to_string(all_null.null_alarm));
  c.value("s_null_flagged", std::to_string(all_null.flagged));
  c.value("s_worst_ratio", fmt(all_eff.worst_ratio, 3));
  c.value("s_maps", maps.label());
  c.checks().claim(study::Kind::verification, "ch7.synth.detected", "every hidden effect is named by the loop's first step (all noise levels)",
                   all_eff.detected == all_eff.sets,
                   "effects were sized to be detectable at the largest noise (10 N against 150-300 N friction forces)");
  // False alarms: the loop's family-wise level is alpha per data set; allow
  // alpha plus two binomial standard deviations for the number of null sets.
  const double alpha = o.alpha, rate = static_cast<double>(all_null.null_alarm) / std::max(1, all_null.sets);
  const double allowed = alpha + 2 * std::sqrt(alpha * (1 - alpha) / std::max(1, all_null.sets));
  c.value("s_alpha", fmt(alpha));
  c.value("s_null_rate_allowed", fmt(100 * allowed, 3), "%");
  c.checks().claim(study::Kind::verification, "ch7.synth.null", "false-alarm rate on null sets at most alpha + 2 binomial SD (" +
                                         fmt(100 * allowed, 3) + " % for " + std::to_string(all_null.sets) + " sets)",
                   rate <= allowed,
                   "Bonferroni over candidates plus the F test give a family-wise level of about alpha per set");
  c.value("s_null_worst_ratio", fmt(all_null.worst_ratio, 3));
  // Reference: the null sets, where the base model is the true model, give the
  // held-out RMS / noise a correct model reaches under the same folds.
  c.checks().agree(study::Kind::verification, "ch7.synth.near_noise", "worst held-out RMS / noise sd after the loop, detected sets "
                   "(reference: worst of the null sets, fitted by the true model)", all_null.worst_ratio,
                   all_eff.worst_ratio, 2.0 / std::sqrt(2.0 * n_rows), "-",
                   "two sampling standard deviations of an RMS over the n rows of a set, 1/sqrt(2n) each; the null sets' "
                   "ratio already contains the bending-line and parameter uncertainty of a correct model");
}

}  // namespace ch7
