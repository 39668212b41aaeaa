// loop_summary.json: the loop's result for programs (loop.hpp, summary_json).
// Keys in a fixed order; numbers with 8 significant digits, null when not
// finite; "computed_from_forces" only when the data have such a column.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "core/quote.hpp"
#include "loop/loop.hpp"

namespace drawbend::loop {

namespace {
std::string jstr(const std::string& s) { return string_literal(s); }  // a JSON string (core/quote.hpp)
std::string jnum(double v) { return std::isfinite(v) ? fmt(v, 8) : "null"; }
// A JSON list of strings, as ["a", "b"] (empty: []).
std::string jlist(const std::vector<std::string>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + jstr(v[i]);
  return s + "]";
}
}  // namespace

std::string summary_json(const LoopResult& r) {
  std::ostringstream o;
  o << "{\n  \"conclusion\": " << jstr(r.conclusion) << ",\n  \"bending\": " << jstr(r.bending)
    << ",\n  \"noise_N\": " << jnum(r.noise.sigma_N) << ",\n  \"heldout_rms_N\": " << jnum(r.cv.back().rms)
    << ",\n  \"ratio_to_noise\": " << jnum(r.ratio) << ",\n  \"at_noise_level\": " << (r.at_noise ? "true" : "false")
    << ",\n  \"base_model\": " << jstr(r.base_model) << ",\n  \"maps\": " << jstr(r.maps)
    << ",\n  \"cv\": " << jstr(r.cv_mode) << ",\n  \"steps\": [";
  for (size_t i = 0; i < r.steps.size(); ++i) {
    const Step& s = r.steps[i];
    o << (i ? "," : "") << "\n    {\"variable\": " << jstr(s.variable) << ", \"effect\": " << jstr(s.effect)
      << ", \"p_value\": " << jnum(s.p_value) << ", \"p_permutation\": " << jnum(s.p_permutation)
      << ", \"threshold\": " << jnum(s.threshold)
      << ", \"rms_before\": " << jnum(s.rms_before) << ", \"rms_after\": " << jnum(s.rms_after)
      << ", \"max_before\": " << jnum(s.max_before) << ", \"max_after\": " << jnum(s.max_after)
      << ", \"class\": " << jstr(s.cls) << ", \"channel\": " << jstr(s.channel)
      << ", \"contribution_N2\": " << jnum(s.contribution) << ", \"probe\": " << jstr(s.probe)
      << (s.meaning_note.empty() ? "" : ", \"note\": " + jstr(s.meaning_note))
      << (s.columns.empty() ? "" : ", \"columns\": " + jlist(s.columns))
      << (s.pair_note.empty() ? "" : ", \"pair_decision\": " + jstr(s.pair_note))
      << (s.far_note.empty() ? "" : ", \"far_rule\": " + jstr(s.far_note))
      << ", \"aliased_with\": " << jlist(s.aliased_with)
      << (s.same_effect_as.empty() ? "" : ", \"same_effect_as\": " + jlist(s.same_effect_as)) << ", \"parameters\": {";
    for (size_t k = 0; k < s.params.size(); ++k)
      o << (k ? ", " : "") << jstr(s.params[k].name) << ": {\"value\": " << jnum(s.params[k].value)
        << ", \"se\": " << jnum(s.params[k].se) << "}";
    o << "}" << (s.sign.empty() ? "" : ", \"sign\": " + jstr(s.sign)) << "}";
  }
  o << (r.steps.empty() ? "" : "\n  ") << "],\n  \"remaining\": " << jlist(r.remaining)
    << ",\n  \"screened_not_confirmed\": " << jlist(r.screened) << ",\n  \"removed_by_backfitting\": "
    << jlist(r.removed) << ",\n  \"undeclared_effects\": " << r.undeclared
    << ",\n  \"base_model_terms\": " << jlist(r.base_terms) << ",\n  \"base_model_mismatch\": "
    << jlist(r.base_mismatch);
  if (!r.response_columns.empty())  // only when there are any: files without them keep their bytes
    o << ",\n  \"computed_from_forces\": " << jlist(r.response_columns);
  o << ",\n  \"stopped_because\": " << jstr(r.stopped_because) << "\n}\n";
  return o.str();
}

}  // namespace drawbend::loop
