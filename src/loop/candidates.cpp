// Folds, candidates and their ranking; see candidates.hpp.
#include "loop/candidates.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>

#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/special_functions/beta.hpp>

#include "core/csv.hpp"
#include "loop/effects.hpp"
#include "loop/fast_mod.hpp"
#include "loop/predict_row.hpp"

namespace drawbend::loop {

Folds make_folds(const Design& d, const std::string& mode_in, int k) {
  Folds f;
  f.k = k;
  const auto& rows = d.data->rows;
  const size_t n = rows.size();
  std::map<std::string, int> test_ix;
  f.block.resize(n);
  f.test.resize(n);
  for (size_t i = 0; i < n; ++i) {
    f.block[i] = d.rows[i].rotating ? 0 : 1 + d.rows[i].cell;
    f.test[i] = test_ix.emplace(rows[i].test_id, static_cast<int>(test_ix.size())).first->second;
  }
  // tests per (block, pin), in order of first appearance
  std::map<std::pair<int, int>, std::vector<int>> bp;
  std::vector<int> seen(test_ix.size(), 0);
  for (size_t i = 0; i < n; ++i)
    if (!seen[f.test[i]]++) bp[{f.block[i], d.rows[i].pin}].push_back(f.test[i]);
  std::string mode = mode_in;
  // Test folds need two tests in every group (the rotating-pin rows of a pin, a fixed-pin
  // cell): a group in one test leaves a fold with nothing to fit it on, and every held-out
  // error came out NaN, exit 3 (2026-12-04: --cv test on the thesis data).  Named, exit 2.
  if (mode == "test")
    for (const auto& [key, tests] : bp)
      if (tests.size() < 2) {
        size_t i = 0;
        while (i < n && !(f.block[i] == key.first && d.rows[i].pin == key.second)) ++i;
        throw std::invalid_argument(
            "--cv test: the " + std::string(key.first == 0 ? "rotating-pin rows" : "fixed-pin rows") + " of the " +
            fmt(rows[i].pin_d_mm) + " mm pin" + (key.first == 0 ? "" : " in the cell of test '" + rows[i].test_id + "'") +
            " are one test only, so leaving it out leaves nothing to fit them on; use --cv bt-block (or auto, "
            "which chooses it)");
      }
  if (mode == "auto") {
    mode = "test";
    for (const auto& [key, tests] : bp)
      if (tests.size() < 2) mode = "bt-block";
  }
  f.mode = mode;
  f.fold.assign(n, 0);
  if (mode == "test") {
    std::vector<int> tf(test_ix.size(), 0);
    for (const auto& [key, tests] : bp)
      for (size_t j = 0; j < tests.size(); ++j) tf[tests[j]] = static_cast<int>((j + key.second) % k);
    for (size_t i = 0; i < n; ++i) f.fold[i] = tf[f.test[i]];
  } else if (mode == "bt-block") {
    std::map<int, std::vector<int>> by_test;
    for (size_t i = 0; i < n; ++i) by_test[f.test[i]].push_back(static_cast<int>(i));
    for (auto& [t, ix] : by_test) {
      std::stable_sort(ix.begin(), ix.end(), [&](int a, int b) { return d.rows[a].fback < d.rows[b].fback; });
      for (size_t j = 0; j < ix.size(); ++j) f.fold[ix[j]] = static_cast<int>(j * k / ix.size());
    }
  } else {
    throw std::invalid_argument("unknown cross-validation mode '" + mode_in + "' (auto, test, bt-block)");
  }
  return f;
}

CvResult cross_validate(const Design& d, const ModelSpec& spec, const Folds& f) {
  const size_t n = d.rows.size();
  CvResult r;
  r.pred.assign(n, std::nan(""));
  r.resid.assign(n, std::nan(""));
  for (int k = 0; k < f.k; ++k) {
    std::vector<int> train;
    for (size_t i = 0; i < n; ++i)
      if (f.fold[i] != k) train.push_back(static_cast<int>(i));
    if (train.size() == n) continue;
    const Fit fit = fit_model(d, spec, train, false);  // theta only: no standard errors
    const detail::Layout L = detail::layout(d, fit.spec);  // predict()'s, made once per fold, not per row
    for (size_t i = 0; i < n; ++i)
      if (f.fold[i] == k) {
        r.pred[i] = detail::predict_row(d, fit, L, fit.theta, static_cast<int>(i), nullptr);
        r.resid[i] = d.rows[i].y - r.pred[i];
      }
  }
  double ss = 0;
  for (double e : r.resid)
    if (std::isfinite(e)) {
      ss += e * e;
      r.max_abs = std::max(r.max_abs, std::abs(e));
      ++r.n;
    }
  r.rms = r.n ? std::sqrt(ss / r.n) : std::nan("");
  return r;
}

namespace {

// The candidates as they are made, each with one value per row.
struct CandidateList {
  size_t n;
  std::vector<Candidate>& c;
  template <class Get>
  void numeric(const std::string& name, const std::string& kind, Get get) {
    Candidate k{name, kind, false, false, std::vector<double>(n), {}, ""};
    for (size_t i = 0; i < n; ++i) k.x[i] = get(i);
    c.push_back(std::move(k));
  }
  template <class Get>
  void categorical(const std::string& name, const std::string& kind, Get get) {
    Candidate k{name, kind, true, false, std::vector<double>(n), {}, ""};
    std::map<std::string, int> ix;
    for (size_t i = 0; i < n; ++i) {
      auto [it, fresh] = ix.emplace(get(i), static_cast<int>(k.levels.size()));
      if (fresh) k.levels.push_back(it->first);
      k.x[i] = it->second;
    }
    c.push_back(std::move(k));
  }
};

// The data's extra columns: numeric when every value is a number (or empty), else categorical.
void extra_columns(const Dataset& data, CandidateList& list) {
  const auto& R = data.rows;
  for (size_t e = 0; e < data.extra_columns.size(); ++e) {
    if (const auto x = numeric_extra(data, e))
      list.numeric(data.extra_columns[e], "column", [&x](size_t i) { return (*x)[i]; });
    else
      list.categorical(data.extra_columns[e], "column", [&](size_t i) { return R[i].extra[e]; });
  }
}

// Each column's model input that it is a function of (confounded_with).
void confounding(const Dataset& data, std::vector<Candidate>& c) {
  const size_t n = data.rows.size();
  const auto& R = data.rows;
  // Columns that are a function of one of the model's inputs.
  const std::vector<std::pair<std::string, std::function<std::string(size_t)>>> inputs = {
      {"pin", [&](size_t i) { return fmt(R[i].pin_d_mm); }},
      {"speed_mm_s", [&](size_t i) { return fmt(R[i].speed_mm_s); }},
      {"direction_deg", [&](size_t i) { return fmt(R[i].direction_deg); }},
      {"lubricant", [&](size_t i) { return R[i].lubricant; }}};
  // Each input's key per row as a code (the keys' text made once per input, not
  // once per row and column: a formatted number per row was ~1 % of a loop).
  const bool any_column = std::any_of(c.begin(), c.end(), [](const Candidate& k) { return k.kind == "column"; });
  std::vector<std::vector<int>> key_code(inputs.size(), std::vector<int>(any_column ? n : 0));
  std::vector<int> nkeys(inputs.size(), 0);
  for (size_t q = 0; q < inputs.size() && any_column; ++q) {
    std::map<std::string, int> ix;
    for (size_t i = 0; i < n; ++i) key_code[q][i] = ix.emplace(inputs[q].second(i), static_cast<int>(ix.size())).first->second;
    nkeys[q] = static_cast<int>(ix.size());
  }
  for (auto& k : c) {
    if (k.kind != "column") continue;
    for (size_t q = 0; q < inputs.size(); ++q) {
      const std::string& name = inputs[q].first;
      std::vector<double> first(nkeys[q]);  // the column's value at the key's first row
      std::vector<char> has(nkeys[q], 0);
      size_t seen = 0;
      bool fn = true;
      for (size_t i = 0; i < n && fn; ++i) {
        const int key = key_code[q][i];
        if (!has[key]) has[key] = 1, first[key] = k.x[i], ++seen;
        else fn = first[key] == k.x[i] || (std::isnan(first[key]) && std::isnan(k.x[i]));
      }
      if (fn && seen >= 2) {
        k.confounded_with = name;
        break;
      }
    }
  }
}

// Each candidate's level: test_level when constant within every test.
void test_levels(const Dataset& data, std::vector<Candidate>& c) {
  const size_t n = data.rows.size();
  const auto& R = data.rows;
  // Level of each candidate: constant within every test?
  std::map<std::string, std::vector<size_t>> by_test;
  for (size_t i = 0; i < n; ++i) by_test[R[i].test_id].push_back(i);
  for (auto& k : c) {
    k.test_level = true;
    for (const auto& [t, ix] : by_test)
      for (size_t j : ix)
        if (!(k.x[j] == k.x[ix[0]] || (std::isnan(k.x[j]) && std::isnan(k.x[ix[0]])))) k.test_level = false;
  }
}

}  // namespace

std::vector<Candidate> make_candidates(const Design& d, const std::vector<double>& pred) {
  const auto& data = *d.data;
  const size_t n = data.rows.size();
  std::vector<Candidate> c;
  CandidateList list{n, c};
  const auto& R = data.rows;
  // Columns beyond the model's inputs.
  if (data.has_sliding) list.numeric("sliding_distance_mm", "column", [&](size_t i) { return R[i].sliding_mm; });
  if (data.has_time) list.numeric("time_s", "column", [&](size_t i) { return R[i].time_s; });
  extra_columns(data, list);
  // Derived quantities.
  list.numeric("avg_pressure_MPa", "derived", [&](size_t i) {  // Eq. (2.2) at the predicted outlet force
    return (R[i].back_tension_N + pred[i]) / (R[i].pin_d_mm * kStripWidthMm);
  });
  list.numeric("inv_R_per_mm", "derived", [&](size_t i) { return 2.0 / R[i].pin_d_mm; });
  // The model's inputs.
  list.numeric("pin_diameter_mm", "input", [&](size_t i) { return R[i].pin_d_mm; });
  list.numeric("back_tension_N", "input", [&](size_t i) { return R[i].back_tension_N; });
  list.numeric("speed_mm_s", "input", [&](size_t i) { return R[i].speed_mm_s; });
  list.numeric("direction_deg", "input", [&](size_t i) { return R[i].direction_deg; });
  list.categorical("lubricant", "input", [&](size_t i) { return R[i].lubricant; });
  // Group identities.
  list.categorical("pin", "group", [&](size_t i) { return fmt(R[i].pin_d_mm) + " mm"; });
  list.categorical("test_id", "group", [&](size_t i) { return R[i].test_id; });
  confounding(data, c);
  test_levels(data, c);
  return c;
}


}  // namespace drawbend::loop
