#pragma once
// The plans of the forms try_forms tries (forms.hpp): a plan is one form, its
// effects (parts); FormPlans lists a candidate's plans in the order they are
// tried.  Internal to the loop: forms.cpp (the library's and the generic
// forms), form_products.cpp (a column that changes mu's pressure or speed
// slope).
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "loop/candidates.hpp"
#include "loop/effects.hpp"
#include "loop/model.hpp"

namespace drawbend::loop::detail {

/// Whether effect k on column var may be added to model s (one generic effect
/// of a kind per column, the data has what the effect reads).
bool applicable(const Design& d, const ModelSpec& s, EffectKind k, const std::string& var);

/// Is group g of model input `by` a union of the model's cells (every cell's
/// fixed-pin rows all in it or none)?  Then each cell's mu carries the group's
/// mean, and a one-cell form needs no factor of its own.
bool union_of_cells(const Design& d, const std::string& by, int g);

/// What a product form (Effect::times) means, for the report.
std::string product_meaning(EffectKind k, bool levels, const std::string& times);

/// What a bump form (Effect::bump_width) of kind k (generic_smooth or
/// force_offset) means, for the report (form_bumps.cpp).
std::string bump_meaning(EffectKind k);

/// What a step form (Effect::step) of kind k (generic_smooth or force_offset)
/// means, for the report (form_bumps.cpp).
std::string step_meaning(EffectKind k);


// A form to try: its effects (one, or several together).
struct Part {
  EffectKind k;
  std::string by;
  int nb = 0;     // generic_smooth: spline dof
  int cell = -1;  // >= 0: confined to that group of `by`
  bool scaled = false;  // force_offset: times the pin's relative bending force
  std::string var;      // the column of the effect ("": the candidate's own)
  bool offset = false;  // one-cell forms: the cell's own factor too (Effect::cell_offset)
  std::string times;    // Effect::times: the shape times this centred model-input quantity
  bool levels = false;  // generic_smooth with times: the column's levels as the basis (Effect::level_basis)
  double centre = 0, width = 0;  // width > 0: a bump (Effect::bump_centre, bump_width; nb 1)
  bool step = false;             // a step at centre (Effect::step, step_at; nb 1, width 0)
};
struct Plan {
  std::vector<Part> parts;
};

// The forms to try for candidate c: the library's, and the generic forms of a
// column (plans, in the order they are tried).
struct FormPlans {
  const Design& d;
  const ModelSpec& spec;
  const Candidate& c;
  std::vector<Plan> plans;
  bool with_products = false;  // LoopOptions::product_forms: products() plans its forms
  const CvResult* cur = nullptr;  // the current model's held-out result (bumps() scans its residual; null: no bumps)
  void add(EffectKind k, const std::string& by = "") {
    if (applicable(d, spec, k, c.name)) plans.push_back({{{k, by}}});
  }
  // A column of the data with 3 or 4 distinct numeric values (levels per group, as a categorical one).
  bool few_levels(const std::set<double>& distinct) const {
    return distinct.size() >= 3 && distinct.size() <= 4 && d.data->extra_index(c.name) >= 0 &&
           replicated(distinct.size());
  }
  // 3 to 8 distinct numeric values, replicated: the column's levels as a form.
  bool some_levels(const std::set<double>& distinct) const {
    return distinct.size() >= 3 && distinct.size() <= 8 && replicated(distinct.size());
  }
  // A column the file measures that is no model input: an extra column, or
  // the run's own time or sliding distance (row-level columns: a bump or a
  // one-cell force form of them was never tried, so an effect local in the
  // sliding distance was left to a spline of too few dof).
  bool measured_column() const {
    return d.data->extra_index(c.name) >= 0 || (c.name == "time_s" && d.data->has_time) ||
           (c.name == "sliding_distance_mm" && d.data->has_sliding);
  }
  // Per-level forms only for levels of at least two rows on average
  // (levels_replicated, candidates.hpp: a level of one row is fitted exactly
  // by its own parameter, not identifiable apart from that row's noise).
  bool replicated(size_t levels) const {
    size_t rows = 0;
    for (double v : c.x) rows += std::isfinite(v) ? 1 : 0;
    return levels_replicated(levels, rows);
  }
  void categorical(const std::vector<std::string>& bys);
  void numeric(const std::vector<std::string>& bys);
  void force_and_bending(const std::set<double>& distinct);
  void in_cell(const std::string& cell_by, int cell_group, int max_nb = 8, bool force = true);
  void force_in_cell(const std::string& cell_by, int cell_group, bool levels, const std::set<double>& distinct,
                     int max_nb);
  void split_cells(const std::string& input);
  void scanned_split(const std::string& input, const CvResult& cur);
  void products(bool levels);
  void bumps(const std::set<double>& distinct, const std::string& cell_by = "", int cell_group = -1, bool force = true);
};

}  // namespace drawbend::loop::detail
