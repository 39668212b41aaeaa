#include "study/thesis_data.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drawbend::study {

bool same(double a, double b) { return std::abs(a - b) < 1e-9 * (1.0 + std::abs(a)); }

namespace {
Printed parse_cell(const CsvTable& t, const CsvRow& r, const std::string& col) {
  const std::string& s = t.text(r, col);
  try {
    return analysis::parse_printed(s);
  } catch (const std::exception&) {
    throw InputError(t.where(r, col) + ": expected a number, found '" + s + "'");
  }
}
}  // namespace

Printed printed(const CsvTable& t, const CsvRow& r, const std::string& col) {
  // The thesis drops trailing zeros ("0.091" in a column of 4-decimal slopes,
  // where 0.0285 + 0.0625 = 0.0910), so a cell's precision is the column's:
  // the finest half unit printed anywhere in the column.
  Printed p = parse_cell(t, r, col);
  for (const auto& other : t.rows) p.half_ulp = std::min(p.half_ulp, parse_cell(t, other, col).half_ulp);
  return p;
}

Printed scalar(const std::string& path, const std::string& id) {
  const CsvTable t = read_csv(path);
  for (const auto& r : t.rows)
    if (t.text(r, "id") == id) return parse_cell(t, r, "value");  // own precision: the column mixes quantities
  throw InputError(path + ": no scalar with id '" + id + "'");
}
analysis::LinearFit FitEntry::fit() const {
  analysis::LinearFit f;
  f.slope = slope.value;
  f.intercept = intercept.value;
  f.range = range;
  f.label = source + " " + direction + (speed_mm_s > 0 ? " " + fmt(speed_mm_s) + " mm/s" : "") + " " +
            fmt(pin_mm) + " mm pin";
  return f;
}

std::vector<FitEntry> load_fits(const std::string& path, const std::string& source) {
  const CsvTable t = read_csv(path);
  std::vector<FitEntry> out;
  for (const auto& r : t.rows) {
    FitEntry e;
    e.direction = t.has_column("direction") ? t.text(r, "direction") : "RD";
    e.speed_mm_s = t.has_column("speed_mm_s") ? t.number(r, "speed_mm_s") : 0.0;
    e.pin_mm = t.number(r, "pin_diameter_mm");
    e.slope = printed(t, r, "slope");
    e.intercept = printed(t, r, "intercept_N");
    if (t.has_column("fback_min_N")) {
      e.range = analysis::Range{t.number(r, "fback_min_N"), t.number(r, "fback_max_N")};
      if (e.range->empty()) throw InputError(t.where(r, "fback_max_N") + ": range maximum below minimum");
    }
    e.source = source;
    out.push_back(e);
  }
  return out;
}

const FitEntry& find_fit(const std::vector<FitEntry>& fits, const std::string& dir, double speed, double pin) {
  for (const auto& f : fits)
    if (f.direction == dir && same(f.speed_mm_s, speed) && same(f.pin_mm, pin)) return f;
  throw std::out_of_range("no fit for " + dir + " " + fmt(speed) + " mm/s, " + fmt(pin) + " mm pin");
}

std::vector<CaseValue> load_cases(const std::string& path, const std::string& value_column) {
  const CsvTable t = read_csv(path);
  std::vector<CaseValue> out;
  for (const auto& r : t.rows)
    out.push_back({t.text(r, "direction"), t.number(r, "speed_mm_s"), t.number(r, "pin_diameter_mm"),
                   printed(t, r, value_column)});
  return out;
}

const CaseValue& find_case(const std::vector<CaseValue>& v, const std::string& dir, double speed, double pin) {
  for (const auto& c : v)
    if (c.direction == dir && same(c.speed_mm_s, speed) && same(c.pin_mm, pin)) return c;
  throw std::out_of_range("no case " + dir + " " + fmt(speed) + " mm/s, " + fmt(pin) + " mm pin");
}

}  // namespace drawbend::study

