#include "study/checks.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "core/csv.hpp"

namespace drawbend::study {

std::string to_string(Status s) {
  switch (s) {
    case Status::pass: return "pass";
    case Status::fail: return "fail";
    case Status::erratum: return "erratum";
    case Status::disagree: return "disagree";
  }
  return "?";
}

std::string to_string(Kind k) {
  switch (k) {
    case Kind::rederived: return "rederived";
    case Kind::simulated: return "simulated";
    case Kind::measured: return "measured";
    case Kind::fitted: return "fitted";
    case Kind::selected: return "selected";
    case Kind::verification: return "verification";
    case Kind::health: return "health";
    case Kind::software: return "software";
  }
  throw std::logic_error("check kind out of range");
}

Errata Errata::load(const std::string& path, const std::string& tier) {
  Errata e;
  const CsvTable t = read_csv(path);
  const bool has_tier = std::find(t.header.begin(), t.header.end(), "tier") != t.header.end();
  for (const auto& r : t.rows) {
    const std::string id = t.text(r, "id");
    if (has_tier) {
      const std::string rt = t.text(r, "tier");
      if (rt != "" && rt != "all" && rt != "quick" && rt != "full")
        throw InputError(t.where(r, "tier") + ": expected quick, full, all or empty, found '" + rt + "'");
      if (!tier.empty() && rt != "" && rt != "all" && rt != tier) continue;
    }
    const std::string ex = t.text(r, "explanation");
    if (ex.empty()) throw InputError(t.where(r, "explanation") + ": empty explanation");
    // One explanation may serve several checks: their ids separated by spaces.
    std::istringstream ids(id);
    int n = 0;
    for (std::string one; ids >> one; ++n) {
      if (one == "*") throw InputError(t.where(r, "id") + ": an erratum must name a check id or an id prefix");
      if (one.back() == '*')
        e.prefix_[one.substr(0, one.size() - 1)] = ex;
      else
        e.exact_[one] = ex;
    }
    if (n == 0) throw InputError(t.where(r, "id") + ": an erratum must name a check id or an id prefix");
  }
  return e;
}

std::string Errata::explain(const std::string& id) const {
  if (auto it = exact_.find(id); it != exact_.end()) return it->second;
  std::string best;
  std::size_t best_len = 0;
  for (const auto& [p, ex] : prefix_)
    if (id.rfind(p, 0) == 0 && p.size() >= best_len) {
      best = ex;
      best_len = p.size();
    }
  return best;
}

std::vector<std::string> Errata::unused(const std::vector<std::string>& ids) const {
  std::vector<std::string> out;
  for (const auto& [id, ex] : exact_)
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) out.push_back(id);
  for (const auto& entry : prefix_) {
    const std::string& p = entry.first;  // not a structured binding: clang 14 cannot capture one in a lambda
    if (std::none_of(ids.begin(), ids.end(), [&](const std::string& i) { return i.rfind(p, 0) == 0; }))
      out.push_back(p + "*");
  }
  return out;
}

Checks::Checks(std::string chapter, Errata errata, Errata disagreements)
    : chapter_(std::move(chapter)), errata_(std::move(errata)), disagreements_(std::move(disagreements)) {}

const Check& Checks::add(Check c, const std::string& reason) {
  (void)to_string(c.kind);  // throws on a kind outside the enumeration
  const bool rederived = c.kind == Kind::rederived;
  const Errata& excuse = rederived ? errata_ : disagreements_;
  const Status excused = rederived ? Status::erratum : Status::disagree;
  for (const auto& o : checks_)
    if (o.id == c.id) throw std::logic_error("duplicate check id " + c.id);
  // Allow floating-point round-off (1e-9 relative) on top of the stated tolerance.
  const double roundoff = 1e-9 * std::max(std::abs(c.thesis), std::abs(c.ours));
  const bool finite = std::isfinite(c.ours);
  const bool within = finite && std::abs(c.ours - c.thesis) <= c.tolerance + roundoff;
  const std::string why = excuse.explain(c.id);
  if (within) {
    c.status = why.empty() ? Status::pass : Status::fail;
    c.note = why.empty() ? reason
                         : "documented " + to_string(excused) + " no longer reproduces (stale): " + why;
  } else if (!why.empty() && finite) {
    c.status = excused;
    c.note = why;
  } else {
    c.status = Status::fail;
    c.note = "outside tolerance (" + reason + ")";
  }
  checks_.push_back(std::move(c));
  return checks_.back();
}

const Check& Checks::agree(Kind kind, const std::string& id, const std::string& q, double thesis, double ours,
                           double tol, const std::string& unit, const std::string& reason) {
  return add({kind, id, q, thesis, ours, tol, unit, "", Status::pass}, reason);
}

const Check& Checks::rederive(const std::string& id, const std::string& q, double thesis, double ours,
                              double tol, const std::string& unit, const std::string& reason) {
  return add({Kind::rederived, id, q, thesis, ours, tol, unit, "", Status::pass}, reason);
}

const Check& Checks::claim(Kind kind, const std::string& id, const std::string& q, bool ours,
                           const std::string& reason) {
  return add({kind, id, q, 1.0, ours ? 1.0 : 0.0, 0.0, "true=1", "", Status::pass}, reason);
}

void Checks::fill_notes(const std::function<const std::string*(const std::string& key)>& lookup) {
  for (auto& c : checks_) {
    std::string out;
    std::size_t pos = 0;
    for (;;) {
      const auto open = c.note.find("{{", pos);
      if (open == std::string::npos) break;
      const auto close = c.note.find("}}", open + 2);
      if (close == std::string::npos) throw InputError("note of check " + c.id + ": unclosed '{{'");
      const std::string key = c.note.substr(open + 2, close - open - 2);
      const std::string* v = lookup(key);
      if (!v)
        throw InputError("note of check " + c.id + " quotes {{" + key + "}}, which this run's values.csv does not hold");
      out += c.note.substr(pos, open - pos) + *v;
      pos = close + 2;
    }
    c.note = out + c.note.substr(pos);
  }
}

int Checks::count(Status s) const {
  int n = 0;
  for (const auto& c : checks_) n += c.status == s;
  return n;
}

void Checks::write(const std::string& path) const {
  CsvWriter w({"id", "kind", "quantity", "thesis", "ours", "tolerance", "unit", "status", "note"});
  w.comment("checks of chapter " + chapter_ + " against the thesis (drawbend " DRAWBEND_VERSION ")");
  for (const auto& c : checks_)
    w.row({c.id, to_string(c.kind), c.quantity, fmt(c.thesis, 8), fmt(c.ours, 8), fmt(c.tolerance, 3), c.unit, to_string(c.status),
           c.note});
  w.save(path);
}

void Checks::print_summary() const {
  std::cout << "checks[" << chapter_ << "]: " << count(Status::pass) << " pass, " << count(Status::fail)
            << " fail, " << count(Status::erratum) << " erratum, " << count(Status::disagree) << " disagree\n";
  for (const auto& c : checks_)
    if (c.status == Status::fail)
      std::cout << "  FAIL " << c.id << ": thesis " << fmt(c.thesis) << ", ours " << fmt(c.ours) << " (tol "
                << fmt(c.tolerance, 3) << " " << c.unit << ") " << c.note << "\n";
}

}  // namespace drawbend::study
