// The effect table: for each EffectKind of effects.hpp, how many friction
// parameters it has, the term it adds to mu of a fixed-pin row, and the names
// of its parameters.  Adding an effect kind means adding one rule here.
#include <algorithm>
#include <cmath>

#include "core/csv.hpp"
#include "loop/model_parts.hpp"

namespace drawbend::loop::detail {

namespace {

using Names = std::vector<std::string>;

int one(const Design&, const Effect&) { return 1; }
void unnamed(const Design&, const Effect&, const Names&, int, Names&) {}

// mu(p) = mu0 + a1 p per cell (the new method); p from the map (Eq. 2.2 scaling in predict_row).
const EffectRule kPressureMu{
    [](const Design& d, const Effect&) { return static_cast<int>(d.cells.size()); },
    [](const EffectArgs& a, Terms& t) { t.a1 = a.th[a.r.cell]; },
    [](const Design& d, const Effect&, const Names&, int s, Names& n) {
      for (size_t c = 0; c < d.cells.size(); ++c) n[s + c] = "a1 [" + d.cells[c] + "] (1/MPa)";
    }};

// mu (1 + beta lg L), lg L centred (Eq. 3.1's lubricant number, see make_design).
const EffectRule kStribeck{one, [](const EffectArgs& a, Terms& t) { t.factor += a.th[0] * a.r.lgL; },
                           [](const Design&, const Effect&, const Names&, int s, Names& n) {
                             n[s] = "beta per decade of L";
                           }};

const EffectRule kDepletion{
    one,
    [](const EffectArgs& a, Terms& t) { t.factor -= a.th[0] * (1 - std::exp(-a.r.sliding / a.e.lambda_mm)); },
    [](const Design&, const Effect& e, const Names&, int s, Names& n) {
      n[s] = "beta depletion (lambda = " + fmt(e.lambda_mm) + " mm)";
    }};

const EffectRule kDirectionHarmonic{one, [](const EffectArgs& a, Terms& t) { t.factor += a.th[0] * a.r.sin2; },
                                    [](const Design&, const Effect&, const Names&, int s, Names& n) {
                                      n[s] = "beta sin^2(2 phi)";
                                    }};

// drift and generic_linear: mu (1 + beta z).
const EffectRule kLinear{one, [](const EffectArgs& a, Terms& t) { t.factor += a.th[0] * a.f.drift_z[a.k][a.i]; },
                         [](const Design&, const Effect& e, const Names&, int s, Names& n) {
                           n[s] = "beta per SD of " + e.variable;
                         }};

const EffectRule kSaturating{
    one, [](const EffectArgs& a, Terms& t) { t.factor += a.th[0] * std::tanh(a.f.drift_z[a.k][a.i]); },
    [](const Design&, const Effect& e, const Names&, int s, Names& n) { n[s] = "beta tanh(z) of " + e.variable; }};

const EffectRule kCategorical{
    [](const Design&, const Effect& e) { return std::max(0, e.n_levels - 1); },
    [](const EffectArgs& a, Terms& t) {
      const int l = a.f.level[a.k][a.i];
      if (l > 0) t.factor += a.th[l - 1];
    },
    [](const Design&, const Effect& e, const Names& level_names, int s, Names& n) {
      for (int l = 1; l < e.n_levels; ++l) n[s + l - 1] = "g [" + e.variable + " = " + level_names[l] + "]";
    }};

const EffectRule kDirectionLevel{
    [](const Design& d, const Effect&) { return d.n_dir_params; },
    [](const EffectArgs& a, Terms& t) {
      if (a.r.dir >= 0 && a.d.dir_param[a.r.dir] >= 0) t.factor += a.th[a.d.dir_param[a.r.dir]];
    },
    [](const Design& d, const Effect&, const Names&, int s, Names& n) {
      for (size_t k = 0; k < d.fixed_directions.size(); ++k)
        if (d.dir_param[k] >= 0) n[s + d.dir_param[k]] = "g [direction " + fmt(d.fixed_directions[k]) + " deg]";
    }};

const EffectRule kDirectionFourier{
    [](const Design&, const Effect&) { return 2; },
    [](const EffectArgs& a, Terms& t) { t.factor += a.th[0] * a.r.sin2 + a.th[1] * a.r.four2; },
    [](const Design&, const Effect&, const Names&, int s, Names& n) {
      n[s] = "c1 sin^2(2 phi)";
      n[s + 1] = "c2 (cos 2phi - cos 6phi)/2";
    }};

const EffectRule kPinSurface{
    [](const Design& d, const Effect&) { return static_cast<int>(d.pins.size()) - 1; },
    [](const EffectArgs& a, Terms& t) {
      if (a.r.pin > 0) t.pinf += a.th[a.r.pin - 1];
    },
    [](const Design& d, const Effect&, const Names&, int s, Names& n) {
      for (size_t p = 1; p < d.pins.size(); ++p) n[s + p - 1] = "s_pin " + fmt(d.pins[p]) + " mm";
    }};

// Acts on the bending line (fit_bending), not on mu: no friction parameter.
const EffectRule kBendingTension{[](const Design&, const Effect&) { return 0; }, nullptr, unnamed};

}  // namespace

const EffectRule& rule(EffectKind k) {
  switch (k) {
    case EffectKind::pressure_mu: return kPressureMu;
    case EffectKind::stribeck: return kStribeck;
    case EffectKind::depletion: return kDepletion;
    case EffectKind::direction_harmonic: return kDirectionHarmonic;
    case EffectKind::pin_surface: return kPinSurface;
    case EffectKind::drift:
    case EffectKind::generic_linear: return kLinear;
    case EffectKind::bending_tension: return kBendingTension;
    case EffectKind::categorical: return kCategorical;
    case EffectKind::generic_saturating: return kSaturating;
    case EffectKind::direction_level: return kDirectionLevel;
    case EffectKind::direction_fourier: return kDirectionFourier;
  }
  return kBendingTension;  // not reached: every kind is listed above
}

Layout layout(const Design& d, const ModelSpec& spec) {
  Layout L;
  for (size_t c = 0; c < d.cells.size(); ++c) {
    L.mu_rd.push_back(d.cell_rd[c] ? L.n++ : -1);
    L.mu_td.push_back(d.cell_td[c] ? L.n++ : -1);
  }
  for (const auto& e : spec.effects) {
    L.eff_start.push_back(L.n);
    L.n += rule(e.kind).count(d, e);
  }
  return L;
}

std::vector<std::string> friction_names(const Design& d, const ModelSpec& spec, const Layout& L,
                                        const std::vector<std::vector<std::string>>& level_names) {
  std::vector<std::string> n(L.n);
  for (size_t c = 0; c < d.cells.size(); ++c) {
    if (L.mu_rd[c] >= 0) n[L.mu_rd[c]] = "mu_RD [" + d.cells[c] + "]";
    if (L.mu_td[c] >= 0) n[L.mu_td[c]] = "mu_TD [" + d.cells[c] + "]";
  }
  for (size_t k = 0; k < spec.effects.size(); ++k)
    rule(spec.effects[k].kind).name(d, spec.effects[k], level_names[k], L.eff_start[k], n);
  return n;
}

}  // namespace drawbend::loop::detail
