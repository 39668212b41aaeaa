// The studies' reductions kept by the run.  See case_reduction.hpp.
#include "io/case_reduction.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/csv.hpp"
#include "material/material.hpp"

namespace drawbend::io {

namespace {


ReducedValue scalar(const std::string& q, double v) { return {q, NAN, NAN, v}; }

/// Block sliding (sim/block_case): friction ratios over the last third of the slide.
class BlockSlide : public CaseReduction {
 public:
  BlockSlide(const ReductionSpec& r, const fe::Model& m) : r_(r), w_(reduction_place(r, m)), duration_(m.steps[w_.step].duration) {}
  void cycle(const fe::Solver& s, const fe::Progress& p) override {
    if (p.step_index != w_.step || p.step_time < duration_ * 2.0 / 3.0) return;
    const auto F = s.tool_force(r_.tool);
    fx_ += F[0];
    fy_ += F[1];
    fz_ += std::abs(F[2]);
  }
  std::vector<ReducedValue> finish(const fe::Solver& s) const override {
    double p_min = 1e30, p_max = 0, v_mean = 0;
    const auto& nodes = s.contact_nodes(w_.pair);
    for (const auto& c : nodes) {
      p_min = std::min(p_min, c.pressure);
      p_max = std::max(p_max, c.pressure);
      v_mean += c.slip_speed / static_cast<double>(nodes.size());
    }
    return {scalar("mu_x", fx_ / fz_), scalar("mu_y", fy_ / fz_), scalar("p_min", p_min), scalar("p_max", p_max),
            scalar("v_mean", v_mean), scalar("cycles", static_cast<double>(s.cycles()))};
  }

 private:
  ReductionSpec r_;
  ReductionPlace w_;
  double duration_;
  double fx_ = 0, fy_ = 0, fz_ = 0;
};

/// The strip draw (sim/strip_draw_case): mu of the die and the slip speed of a probe node under it.
class StripDraw : public CaseReduction {
 public:
  StripDraw(const ReductionSpec& r, const fe::Model& m) : r_(r), w_(reduction_place(r, m)), duration_(m.steps[w_.step].duration) {
    const auto [xmin, xmax] = std::minmax_element(m.mesh.x.begin(), m.mesh.x.end());
    const auto [ymin, ymax] = std::minmax_element(m.mesh.y.begin(), m.mesh.y.end());
    cx_ = 0.5 * (*xmin + *xmax);
    cy_ = 0.5 * (*ymin + *ymax);
  }
  void cycle(const fe::Solver& s, const fe::Progress& p) override {
    if (p.step_index < w_.step) {  // the probe and the clock as the step will begin (the last such cycle wins)
      probe_ = nearest(s);
      t0_ = p.time;
      return;
    }
    if (p.step_index != w_.step) return;
    if (probe_ < 0) probe_ = nearest(s);  // the step is the first: the reference state (no cycle before it)
    const double vs = s.contact_nodes(w_.pair)[probe_].slip_speed;
    if (p.cycle % 20 == 0) trace_.push_back({p.time - t0_, vs});
    if (p.step_time < r_.ramp) ramp_v_max_ = std::max(ramp_v_max_, vs);
    if (p.step_time < duration_ * 2.0 / 3.0) return;
    const auto F = s.tool_force(r_.tool);
    sft_ += std::abs(F[0]);  // mu = mean F_t / mean F_n over the last third
    sfn_ += std::abs(F[2]);
    sv_ += vs;
    sv2_ += vs * vs;
    v_min_ = std::min(v_min_, vs);
    v_max_ = std::max(v_max_, vs);
    ++n_;
  }
  std::vector<ReducedValue> finish(const fe::Solver& s) const override {
    const double v_mean = sv_ / n_;
    std::vector<ReducedValue> out{scalar("mu", sfn_ > 0 ? sft_ / sfn_ : NAN), scalar("v_mean", v_mean),
                                  scalar("v_std", std::sqrt(std::max(0.0, sv2_ / n_ - v_mean * v_mean))),
                                  scalar("v_min", v_min_), scalar("v_max", v_max_), scalar("ramp_v_max", ramp_v_max_)};
    const fe::Mesh& mesh = s.model().mesh;
    double pmin = 1e30, pmax = 0, psum = 0;
    const auto& nodes = s.contact_nodes(w_.pair);
    for (const auto& c : nodes) {
      out.push_back({"pressure", mesh.x[c.node], mesh.y[c.node], c.pressure});
      pmin = std::min(pmin, c.pressure);
      pmax = std::max(pmax, c.pressure);
      psum += c.pressure;
    }
    out.push_back(scalar("p_min", pmin));
    out.push_back(scalar("p_max", pmax));
    out.push_back(scalar("p_mean", psum / nodes.size()));
    out.push_back(scalar("cycles", static_cast<double>(s.cycles())));
    for (const auto& [t, v] : trace_) out.push_back({"trace", t, NAN, v});
    return out;
  }

 private:
  /// The contact node nearest the centre (current x, y); the first on ties.
  int nearest(const fe::Solver& s) const {
    int probe = 0;
    double best = 1e30;
    const auto& nodes = s.contact_nodes(w_.pair);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const double dd = std::hypot(s.x()[nodes[k].node] - cx_, s.y()[nodes[k].node] - cy_);
      if (dd < best) {
        best = dd;
        probe = static_cast<int>(k);
      }
    }
    return probe;
  }

  ReductionSpec r_;
  ReductionPlace w_;
  double duration_, cx_ = 0, cy_ = 0;
  int probe_ = -1;
  double t0_ = 0;
  std::vector<std::pair<double, double>> trace_;
  double ramp_v_max_ = 0, sft_ = 0, sfn_ = 0, sv_ = 0, sv2_ = 0, v_min_ = 1e30, v_max_ = -1e30;
  long n_ = 0;
};

/// Cup drawing (sim/cup_case), a quarter model: the punch curve and the cup at the end of the stroke.
class CupDraw : public CaseReduction {
 public:
  CupDraw(const ReductionSpec& r, const fe::Model& m) : r_(r), w_(reduction_place(r, m)) {
    bool holder = false;
    for (const auto& t : m.tools) holder = holder || t.name == r.holder;
    if (!holder) throw InputError("output.reduce.holder: no tool named \"" + r.holder + "\"");
    m.mesh.node_set("rim");  // throws naming the set if the mesh has none
  }
  void cycle(const fe::Solver& s, const fe::Progress& p) override {
    if (p.step_index < w_.step) {  // the punch's start and the cycle count as the step will begin
      z0_ = s.tool_offset(r_.tool)[2];
      return;
    }
    if (p.step_index != w_.step || p.cycle % r_.every) return;
    const double d = s.tool_offset(r_.tool)[2] - z0_;
    curve_.push_back({d, -4.0 * s.tool_force(r_.tool)[2]});  // full blank: 4 quarters
    die_force_ = 4.0 * std::abs(s.tool_force(r_.holder)[2]);
  }
  std::vector<ReducedValue> finish(const fe::Solver& s) const override {
    const auto& e = s.energies();
    const fe::Mesh& mesh = s.model().mesh;
    double size_rd = 0, size_td = 0;
    for (int i : mesh.node_set("rim")) {
      if (mesh.y[i] == 0.0) size_rd = std::max(size_rd, 2.0 * s.x()[i]);
      if (mesh.x[i] == 0.0) size_td = std::max(size_td, 2.0 * s.y()[i]);
    }
    std::vector<ReducedValue> out{scalar("die_force", die_force_), scalar("size_rd", size_rd), scalar("size_td", size_td),
                                  scalar("kinetic_ratio", e.internal > 0 ? e.kinetic / e.internal : 0),
                                  scalar("hourglass_ratio", e.internal > 0 ? e.hourglass / e.internal : 0),
                                  scalar("added_mass_ratio", s.added_mass() / s.physical_mass()),
                                  scalar("die_lift", s.tool_offset(r_.holder)[2]),
                                  scalar("cycles", static_cast<double>(s.cycles()))};
    for (const auto& [d, f] : curve_) out.push_back({"curve", d, NAN, f});
    // Per element: centroid (rows `centroid`: x, y, value = z) and state (rows `state`: x = plastic strain, y = von Mises).
    const std::vector<double> sig = s.stress();
    for (int el = 0; el < mesh.num_elements(); ++el) {
      double cx = 0, cy = 0, cz = 0;
      for (int a = 0; a < 8; ++a) {
        cx += s.x()[mesh.hex[el][a]] / 8;
        cy += s.y()[mesh.hex[el][a]] / 8;
        cz += s.z()[mesh.hex[el][a]] / 8;
      }
      out.push_back({"centroid", cx, cy, cz});
      out.push_back({"state", s.plastic_strain(el), material::von_mises(&sig[6 * static_cast<std::size_t>(el)]), NAN});
    }
    return out;
  }

 private:
  ReductionSpec r_;
  ReductionPlace w_;
  double z0_ = 0, die_force_ = 0;
  std::vector<std::pair<double, double>> curve_;
};

std::string cell(double v) { return std::isnan(v) ? std::string() : fmt_shortest(v); }

double parse_cell(const CsvTable& t, const CsvRow& row, const std::string& col) {
  const std::string& s = t.text(row, col);
  if (s.empty()) return NAN;
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) throw InputError(t.where(row, col) + ": not a number: '" + s + "'");
  return v;
}

}  // namespace


std::unique_ptr<CaseReduction> make_reduction(const ReductionSpec& r, const fe::Model& m) {
  if (r.kind == "block_slide") return std::make_unique<BlockSlide>(r, m);
  if (r.kind == "strip_draw") return std::make_unique<StripDraw>(r, m);
  if (r.kind == "cup_draw") return std::make_unique<CupDraw>(r, m);
  if (r.kind == "earing_cup") return make_earing_reduction(r, m);
  check_reduction(r, m);  // throws: the kind is none of the above
  throw InputError("output.reduce.kind: expected block_slide, strip_draw, cup_draw or earing_cup, found \"" + r.kind + "\"");
}

void write_reduction(const std::string& path, const std::string& what, const std::vector<ReducedValue>& rows) {
  CsvWriter w({"quantity", "x", "y", "value"});
  w.comment("reduction of " + what + " (io/case_reduction.hpp); numbers read back bit for bit; units mm, N, MPa, s");
  for (const auto& r : rows) w.row({r.quantity, cell(r.x), cell(r.y), r.value != r.value ? "nan" : cell(r.value)});
  w.save(path);
}

std::vector<ReducedValue> read_reduction(const std::string& path) {
  const CsvTable t = read_csv(path);
  std::vector<ReducedValue> out;
  for (const auto& row : t.rows)
    out.push_back({t.text(row, "quantity"), parse_cell(t, row, "x"), parse_cell(t, row, "y"), parse_cell(t, row, "value")});
  return out;
}

double reduced(const std::vector<ReducedValue>& rows, const std::string& quantity, const std::string& path) {
  for (const auto& r : rows)
    if (r.quantity == quantity && std::isnan(r.x)) return r.value;
  throw InputError(path + ": no row '" + quantity + "'");
}

}  // namespace drawbend::io
