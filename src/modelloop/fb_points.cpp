// Measured bending forces in, a points table out (modelloop/model_loop.hpp).
#include "modelloop/model_loop.hpp"

#include <algorithm>
#include <utility>

#include "core/csv.hpp"
#include "core/strip_limits.hpp"

namespace drawbend::modelloop {

std::vector<FbPoint> read_fb_points(const std::string& csv_path) {
  const CsvTable t = read_csv(csv_path);
  std::vector<std::string> problems;
  for (const char* col : {"pin_diameter_mm", "back_tension_N", "bending_force_N"})
    if (!t.has_column(col)) problems.push_back(t.path + ":1: missing column '" + col + "'");
  if (!problems.empty()) throw InputError(problems.front());
  std::vector<FbPoint> out;
  for (const auto& r : t.rows) {
    FbPoint p;
    p.where = t.path + ":" + std::to_string(r.line);
    try {
      p.pin_mm = t.number(r, "pin_diameter_mm");
      p.back_tension_N = t.number(r, "back_tension_N");
      p.bending_N = t.number(r, "bending_force_N");
    } catch (const InputError& e) {
      problems.push_back(e.what());
      continue;
    }
    if (p.pin_mm <= 0) problems.push_back(t.where(r, "pin_diameter_mm") + ": must be > 0 mm");
    if (p.pin_mm > kMaxPinDiameterMM)
      problems.push_back(t.where(r, "pin_diameter_mm") + ": expected a pin diameter up to " + fmt(kMaxPinDiameterMM) +
                         " mm (a draw-bend pin; check the units), found " + fmt(p.pin_mm) + " mm");
    if (p.back_tension_N <= 0) problems.push_back(t.where(r, "back_tension_N") + ": must be > 0 N");
    if (p.bending_N <= 0) problems.push_back(t.where(r, "bending_force_N") + ": must be > 0 N");
    // The same bound as `drawbend loop` (core/strip_limits.hpp): before it, a
    // back tension of 1e300 N went into the FE decks as a load.
    for (const auto& [col, v] : {std::pair{"back_tension_N", p.back_tension_N}, std::pair{"bending_force_N", p.bending_N}})
      if (v > kMaxStripForceN)
        problems.push_back(t.where(r, col) + ": expected a force below " + fmt(kMaxStripForceN) +
                           " N (a strip test; check the units), found " + fmt(v) + " N");
    // An exact copy of an earlier point (a pasted row) would count twice in the
    // fit and the choice; `drawbend loop` drops its duplicate rows as data
    // problems, and model-loop, which stops on any problem, refuses it.
    for (std::size_t k = 0; k < out.size(); ++k)
      if (out[k].pin_mm == p.pin_mm && out[k].back_tension_N == p.back_tension_N && out[k].bending_N == p.bending_N) {
        problems.push_back(p.where + ": duplicate of " + out[k].where + " (the same pin, back tension and bending force)");
        break;
      }
    out.push_back(p);
  }
  if (out.empty() && problems.empty()) problems.push_back(t.path + ": no data rows");
  // The rows together, as `drawbend loop` judges them (core/strip_limits.hpp):
  // every force in kN or every pin in metres would start FE runs on a strip
  // loaded at a thousandth of its yield, or meshed round a 0.01 mm pin.
  if (problems.empty()) {
    double max_force = 0, max_pin = 0;
    for (const auto& p : out) max_force = std::max({max_force, p.back_tension_N, p.bending_N}), max_pin = std::max(max_pin, p.pin_mm);
    for (std::string m : {force_unit_problem(t.path, "columns 'back_tension_N', 'bending_force_N'", max_force),
                          pin_unit_problem(t.path, max_pin)})
      if (!m.empty()) problems.push_back(std::move(m));
  }
  if (!problems.empty()) {
    std::string all;
    for (const auto& s : problems) all += (all.empty() ? "" : "\n") + s;
    throw InputError(all);
  }
  return out;
}

void save_eval_csv(const ModelEval& e, const std::string& path) {
  CsvWriter w({"pin_diameter_mm", "back_tension_N", "measured_FB_N", "predicted_FB_N", "rel_error", "role", "run"});
  w.comment(" model: " + e.model + "; full-strip forces [N]; rel_error = predicted/measured - 1");
  for (const auto& p : e.points)
    w.row({fmt(p.measured.pin_mm), fmt(p.measured.back_tension_N), fmt(p.measured.bending_N, 5),
           fmt_fixed(p.predicted_N, 1), fmt(p.rel_error(), 4), p.held_out ? "held-out" : "fit", p.run_dir});
  w.save(path);
}

}  // namespace drawbend::modelloop
