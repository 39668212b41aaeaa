// Thesis fits -> sample rows; see thesis_rows.hpp.
#include "loop/thesis_rows.hpp"

#include <cmath>

#include "core/csv.hpp"
#include "study/thesis_data.hpp"

namespace drawbend::loop {

Dataset thesis_dataset(const std::string& dir, int points) {
  if (points < 2) throw std::invalid_argument("--points must be at least 2");
  Dataset d;
  d.path = "data/measured/thesis_drawbend.csv";
  d.extra_columns = {"source"};
  d.comments = {
      " source: thesis Tables 5.3, 5.5-5.10, 5.13, 5.17 (data/thesis/), sampled by `drawbend synth --from-thesis`",
      " units: pin_diameter_mm: mm; direction_deg: deg (0 = RD, 90 = TD); speed_mm_s: mm/s; back_tension_N: N;"
      " outlet_force_N: N (full-strip measured forces)",
      " note: DERIVED FROM FITS, not raw measurements: each fit (source = fit:Table X) is sampled at " +
          std::to_string(points) + " evenly spaced back tensions over its stated range, outlet = F_back + fit value",
      " note: rotating-pin rows (Table 5.3) are RD strips at 25.4 mm/s (Sec. 5.4, Figs. 5.7-5.9); their lubricant"
      " is not stated",
      " note: Table 5.17 (undiluted) gives one friction force per pin and speed at an unstated back tension; rows"
      " are placed at the Table 5.13 back tension of the pin (assumption) with outlet = F_back + F_bend + F_fric",
  };
  const auto bending = study::load_fits(dir + "/table_5_3.csv", "Table 5.3");
  auto sample = [&](const study::FitEntry& e, bool rotating, const std::string& lub, double speed, const std::string& dir_) {
    const auto fit = e.fit();
    const std::string id = (rotating ? "rot" : "fix") + std::string("-") + dir_ + "-v" + fmt(speed) + "-d" + fmt(e.pin_mm);
    for (int k = 0; k < points; ++k) {
      Sample s;
      s.test_id = id;
      s.pin_d_mm = e.pin_mm;
      s.rotating = rotating;
      s.direction_deg = dir_ == "TD" ? 90 : 0;
      s.speed_mm_s = speed;
      s.lubricant = lub;
      s.back_tension_N = fit.range->lo + (fit.range->hi - fit.range->lo) * k / (points - 1);
      s.outlet_force_N = s.back_tension_N + fit(s.back_tension_N);
      s.sliding_mm = s.time_s = std::nan("");
      s.extra = {"fit:" + e.source};
      d.rows.push_back(s);
    }
  };
  for (const auto& b : bending) sample(b, true, "not stated", 25.4, "RD");
  for (int t = 5; t <= 10; ++t)
    for (const auto& e : study::load_fits(dir + "/table_5_" + std::to_string(t) + ".csv", "Table 5." + std::to_string(t)))
      sample(e, false, "MP404 diluted", e.speed_mm_s, e.direction);
  const CsvTable t513 = read_csv(dir + "/table_5_13.csv");
  for (const auto& c : study::load_cases(dir + "/table_5_17.csv", "ffric_N")) {
    double fb = 0;
    for (const auto& r : t513.rows)
      if (study::same(t513.number(r, "pin_diameter_mm"), c.pin_mm)) fb = t513.number(r, "fback_N");
    const auto& bend = study::find_fit(bending, "RD", 0.0, c.pin_mm).fit();
    Sample s;
    s.test_id = "fix-" + c.direction + "-v" + fmt(c.speed_mm_s) + "-d" + fmt(c.pin_mm) + "-undiluted";
    s.pin_d_mm = c.pin_mm;
    s.direction_deg = c.direction == "TD" ? 90 : 0;
    s.speed_mm_s = c.speed_mm_s;
    s.lubricant = "MP404 undiluted";
    s.back_tension_N = fb;
    s.outlet_force_N = fb + bend(fb) + c.value.value;
    s.sliding_mm = s.time_s = std::nan("");
    s.extra = {"table:Table 5.17 at F_back of Table 5.13 (assumed)"};
    d.rows.push_back(s);
  }
  return d;
}

}  // namespace drawbend::loop
