#pragma once
// Checks against the thesis.  Each check has an id, a quantity, the thesis
// value, our value, a tolerance with a one-line reason, a unit and a status:
//   pass     |ours - thesis| <= tolerance
//   fail     outside tolerance where agreement was expected
//   erratum  a re-derivation of a thesis value from the thesis's own inputs
//            disagrees, and data/thesis/errata.csv documents why.
//   disagree our simulation does not reproduce a published value within the
//            tolerance, and data/thesis/disagreements.csv records what the
//            investigation found (the report lists these as "not reproduced").
//            Agreement checks (ours vs published) and claims tested on our
//            simulations can be disagreements; the tolerance is never
//            widened to hide them.
// A documented erratum or disagreement whose check passes is reported as a
// failure (the explanation is stale), so neither list can hide a real change.
//
// Every check states its kind, what is compared (column `kind` of checks.csv;
// data/thesis/README.md gives the tolerance rule for each):
//   rederived     the thesis's own arithmetic (a printed value from other
//                 printed values); a documented miss is an erratum
//   simulated     our simulations against the thesis's simulation results
//   measured      our simulations against the thesis's measurements, blind:
//                 no parameter was fitted to this number and no model was
//                 chosen on it (the only kind the report counts as agreement
//                 with measurement)
//   fitted        a measured number a parameter of the compared model was
//                 fitted to (in-sample: agreement here is by construction)
//   selected      a measured number used to accept or reject a model (a
//                 candidate, a member, a tool radius); not blind either
//   verification  solver against a closed form or against our own input law
//   health        energy balance, hourglass share and similar invariants
//   software      our own data pipeline (generated files, input hygiene)
// Only `rederived` checks are excused by errata.csv; a miss of any other kind
// can only be a documented disagreement (an FE comparison that misses is never
// a thesis erratum).  The kind is a required argument: no default exists.
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace drawbend::study {

enum class Status { pass, fail, erratum, disagree };
std::string to_string(Status s);

enum class Kind { rederived, simulated, measured, fitted, selected, verification, health, software };
std::string to_string(Kind k);

struct Check {
  Kind kind;  ///< no default: every check states what it compares
  std::string id, quantity;
  double thesis = 0, ours = 0, tolerance = 0;
  std::string unit, note;
  Status status = Status::pass;
};

/// Documented thesis errata: id or id prefix (ending in '*') -> explanation;
/// one row may name several ids, separated by spaces, that share its explanation.
class Errata {
 public:
  /// With a `tier` column (disagreements.csv), rows whose tier is neither
  /// empty, `all` nor `tier` are left out: a disagreement seen on the quick
  /// mesh only is not applied to (and so cannot go stale on) the full one.
  static Errata load(const std::string& csv_path, const std::string& tier = "");
  /// Explanation for an id, or empty when none is documented.
  std::string explain(const std::string& id) const;
  /// Entries (ids or "prefix*") that match none of the given check ids.
  std::vector<std::string> unused(const std::vector<std::string>& ids) const;

 private:
  std::map<std::string, std::string> exact_, prefix_;
};

class Checks {
 public:
  Checks(std::string chapter, Errata errata, Errata disagreements = {});

  /// Agreement of `ours` with a reference value, within `tolerance`.
  const Check& agree(Kind kind, const std::string& id, const std::string& quantity, double thesis, double ours,
                     double tolerance, const std::string& unit, const std::string& reason);
  /// Re-derivation of a printed value from other printed values
  /// (agree with Kind::rederived).
  const Check& rederive(const std::string& id, const std::string& quantity, double thesis, double ours,
                        double tolerance, const std::string& unit, const std::string& reason);
  /// A yes/no claim of the thesis tested on numbers (1 = true, 0 = false).
  const Check& claim(Kind kind, const std::string& id, const std::string& quantity, bool ours, const std::string& reason);

  /// Replace every {{key}} in the checks' notes (the documented errata and
  /// disagreements) by `lookup(key)`, the run's value of that key (the
  /// chapter's values.csv), so that a note quotes this run's numbers, per
  /// tier.  A key the run does not hold throws InputError naming the check
  /// and the key: a note cannot quote a number the run did not produce.
  void fill_notes(const std::function<const std::string*(const std::string& key)>& lookup);

  const std::vector<Check>& all() const { return checks_; }
  int count(Status s) const;
  void write(const std::string& path) const;  ///< checks.csv
  void print_summary() const;

 private:
  /// The documented-explanation list that may excuse a miss follows from the
  /// kind: errata for re-derivations, disagreements for every other kind.
  const Check& add(Check c, const std::string& reason);
  std::string chapter_;
  Errata errata_, disagreements_;
  std::vector<Check> checks_;
};

}  // namespace drawbend::study
