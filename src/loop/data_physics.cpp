// Whole-data-set plausibility of measured draw-bend data; see data_physics.hpp.
#include "loop/data_physics.hpp"

#include <algorithm>
#include <map>

#include "core/csv.hpp"
#include "core/strip_limits.hpp"

namespace drawbend::loop {

std::vector<Problem> check_data_physics(const Dataset& d) {
  std::vector<Problem> warnings;
  if (d.rows.empty()) return warnings;  // read_loop_data refuses that already
  double max_force = 0, max_pin = 0, max_speed = 0;
  double bt_lo = d.rows.front().back_tension_N, bt_hi = bt_lo;
  double out_lo = d.rows.front().outlet_force_N, out_hi = out_lo;
  int fixed = 0;
  for (const auto& s : d.rows) {
    max_force = std::max({max_force, s.back_tension_N, s.outlet_force_N});
    max_pin = std::max(max_pin, s.pin_d_mm);
    max_speed = std::max(max_speed, s.speed_mm_s);
    bt_lo = std::min(bt_lo, s.back_tension_N), bt_hi = std::max(bt_hi, s.back_tension_N);
    out_lo = std::min(out_lo, s.outlet_force_N), out_hi = std::max(out_hi, s.outlet_force_N);
    fixed += s.rotating ? 0 : 1;
  }
  const std::string rows = " (" + std::to_string(d.rows.size()) + " usable rows)";
  for (const std::string& m : {force_unit_problem(d.path, "columns 'back_tension_N', 'outlet_force_N'", max_force, rows),
                                pin_unit_problem(d.path, max_pin, rows)})
    if (!m.empty()) throw InputError(m);
  if (fixed == 0)
    throw InputError(d.path + ": column 'pin': every usable row is 'rotating'" + rows +
                     "; a rotating pin measures the bending force only, so friction needs rows with pin = fixed");
  if (d.rows.size() >= 3 && out_lo == out_hi && bt_lo < bt_hi)
    throw InputError(d.path + ": column 'outlet_force_N': every usable row has the same outlet force " + fmt(out_lo) +
                     " N while the back tension goes from " + fmt(bt_lo) + " to " + fmt(bt_hi) + " N" + rows +
                     "; the outlet force is the back tension plus friction and bending, so it rises with the back "
                     "tension (a value filled down the column?)");
  // One test is one strip drawn over one pin: its rows share the pin, the pin's
  // kind, the direction and the lubricant (a test_id filled down the column made
  // every row one "test", and the replicate noise came from rows on different pins,
  // 2026-12-04: "the model explains the data to the noise level", exit 0).
  // In file order (the rows come in canonical order, measured.hpp): the
  // message names a test's first line in the file and its first line that
  // disagrees with it.
  std::vector<const Sample*> by_line;
  for (const auto& s : d.rows) by_line.push_back(&s);
  std::stable_sort(by_line.begin(), by_line.end(), [](const Sample* a, const Sample* b) { return a->line < b->line; });
  std::map<std::string, const Sample*> first;
  for (const Sample* sp : by_line) {
    const Sample& s = *sp;
    const Sample*& f = first[s.test_id];
    if (!f) {
      f = &s;
      continue;
    }
    const char* col = s.pin_d_mm != f->pin_d_mm ? "pin_diameter_mm"
                      : s.rotating != f->rotating ? "pin"
                      : s.direction_deg != f->direction_deg ? "direction_deg"
                      : s.lubricant != f->lubricant ? "lubricant" : nullptr;
    if (!col) continue;
    auto said = [&](const Sample& r) {
      const std::string c = col;
      return c == "pin_diameter_mm" ? fmt(r.pin_d_mm) + " mm"
             : c == "pin"           ? std::string(r.rotating ? "rotating" : "fixed")
             : c == "direction_deg" ? fmt(r.direction_deg) + " deg"
                                    : "'" + r.lubricant + "'";
    };
    throw InputError(d.path + ":" + std::to_string(s.line) + ": column '" + col + "': test '" + s.test_id + "' has " +
                     said(s) + " here and " + said(*f) + " on line " + std::to_string(f->line) +
                     "; a test is one strip drawn over one pin (one pin, pin kind, direction and lubricant): give "
                     "each strip its own test_id");
  }
  double max_dir = 0;
  for (const auto& s : d.rows) max_dir = std::max(max_dir, s.direction_deg);
  if (max_dir > 0 && max_dir < 2)
    warnings.push_back({d.path, 0, "direction_deg",
                        "every direction is below 2 deg (largest " + fmt(max_dir) +
                            "); directions to RD are 0 to 90 deg: check the unit (radians? 90 deg is 1.5708 rad)"});
  if (max_speed < 1)
    warnings.push_back({d.path, 0, "speed_mm_s",
                        "every speed is below 1 mm/s (largest " + fmt(max_speed) +
                            " mm/s); draw-bend tests slide at a few to a few hundred mm/s: check the unit (m/s "
                            "times 1000?)"});
  return warnings;
}

}  // namespace drawbend::loop
