#pragma once
// The loop's memo of model fits (loop.cpp).
//
// The fits are deterministic, so a model's cross-validation, joint fit and
// full fit on the same data and folds are computed once per run and reused
// (the base model was cross-validated three times and jointly fitted three
// times in a run with one step; issue 50 item 6).  Keyed by everything that
// defines the model: the bending option and each effect in order, with its
// parameters (lambda to the last bit).
#include <map>
#include <string>

#include "loop/candidates.hpp"
#include "loop/model.hpp"

namespace drawbend::loop {

/// The key of a model specification: the bending option and each effect in
/// order, with its parameters (lambda to the last bit).
std::string spec_key(const ModelSpec& s);

/// Cross-validation, joint fit and full fit of a model, each computed once per
/// run (the fits are deterministic on the same data and folds).
class FitMemo {
 public:
  FitMemo(const Design& d, const Folds& f) : d_(d), f_(f) {}
  CvResult cv(const ModelSpec& s) {
    const std::string k = spec_key(s);
    auto it = cv_.find(k);
    if (it == cv_.end()) it = cv_.emplace(k, cross_validate(d_, s, f_)).first;
    return it->second;
  }
  JointFit joint(const ModelSpec& s) {
    const std::string k = spec_key(s);
    auto it = joint_.find(k);
    if (it == joint_.end()) it = joint_.emplace(k, fit_joint(d_, s)).first;
    return it->second;
  }
  Fit fit(const ModelSpec& s) {
    const std::string k = spec_key(s);
    auto it = fit_.find(k);
    if (it == fit_.end()) it = fit_.emplace(k, fit_model(d_, s)).first;
    return it->second;
  }
  /// Results computed elsewhere (a form's trial) for model s.
  void remember(const ModelSpec& s, const CvResult& cv, const JointFit& j) {
    cv_.emplace(spec_key(s), cv);
    joint_.emplace(spec_key(s), j);
  }

 private:
  const Design& d_;
  const Folds& f_;
  std::map<std::string, CvResult> cv_;
  std::map<std::string, JointFit> joint_;
  std::map<std::string, Fit> fit_;
};

}  // namespace drawbend::loop
