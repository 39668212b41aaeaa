#include "io/deck_friction.hpp"

#include <cmath>

#include "core/csv.hpp"
#include "core/strip_limits.hpp"
#include "friction/stribeck_law.hpp"
#include "friction/surface_law.hpp"

namespace drawbend::io {

// friction = { law = "surface", nodes = "table_6_1.csv" | lines = "table_5_16.csv",
//              p_min, p_max, v_min, v_max (nodes only; default Sec. 6.3), interval = 100 }
static std::shared_ptr<friction::FrictionLaw> make_surface_friction(const DeckContext& c, const toml::table& t,
                                                                    const std::string& dir, const std::string& w) {
  const std::size_t before = c.count();
  c.allowed(t, w, {"law", "nodes", "lines", "interval", "p_min", "p_max", "v_min", "v_max"});
  const int interval = c.count_of(t, "interval", w, 100, 1);
  friction::SurfaceDomain d;
  d.p_min = c.num(t, "p_min", w, d.p_min);
  d.p_max = c.num(t, "p_max", w, d.p_max);
  d.v_min = c.num(t, "v_min", w, d.v_min);
  d.v_max = c.num(t, "v_max", w, d.v_max);
  if (!(d.p_min >= 0 && d.p_min < d.p_max))
    c.bad(t, w, "expected 0 <= p_min < p_max [MPa], found " + fmt_shortest(d.p_min) + " and " + fmt_shortest(d.p_max));
  if (!(d.v_min >= 0 && d.v_min < d.v_max))
    c.bad(t, w, "expected 0 <= v_min < v_max [mm/s], found " + fmt_shortest(d.v_min) + " and " + fmt_shortest(d.v_max));
  const auto* nodes = t.get("nodes");
  const auto* lines = t.get("lines");
  if (!nodes == !lines)
    c.bad(t, w, "expected exactly one of 'nodes' (Table 6.1 format) or 'lines' (Table 5.16 format)");
  if (lines && (t.get("v_min") || t.get("v_max")))
    c.bad(t, w, "with 'lines' the speed range is that of the outer lines; remove v_min/v_max");
  if (c.count() > before) return nullptr;
  const std::string key = nodes ? "nodes" : "lines";
  const std::string file = deck_relative(dir, c.str(t, key, w));
  if (c.count() > before) return nullptr;
  if (!readable_file(file)) c.fail(*t.get(key), w + "." + key, missing_file(c.str(t, key, w), dir));
  try {
    const auto [rd, td] = nodes ? friction::load_surface_nodes(file, d) : friction::load_surface_lines(file, d.p_min, d.p_max);
    return std::make_shared<friction::SurfaceLaw>(rd, td, interval);
  } catch (const InputError& e) {
    c.fail(*t.get(key), w + "." + key, e.what());
  } catch (const std::invalid_argument& e) {
    c.fail(*t.get(key), w + "." + key, file + ": " + e.what());
  }
}

std::shared_ptr<friction::FrictionLaw> make_friction(const DeckContext& c, const toml::table& t,
                                                     const std::string& dir, const std::string& w) {
  const std::size_t before = c.count();
  const std::string l = c.str(t, "law", w);
  if (l == "coulomb") {
    c.allowed(t, w, {"law", "mu"});
    const double mu = c.num(t, "mu", w);
    if (!std::isnan(mu) && !(mu >= 0)) c.bad(*t.get("mu"), w + ".mu", "expected a friction coefficient >= 0, found " + fmt_shortest(mu));
    else if (mu > kMaxFrictionCoefficient)
      c.bad(*t.get("mu"), w + ".mu", "expected a friction coefficient up to " + fmt(kMaxFrictionCoefficient) +
                                         " (sticking is reached far below), found " + fmt_shortest(mu));
    if (c.count() > before) return nullptr;
    return std::make_shared<friction::Coulomb>(mu);
  }
  if (l == "surface") return make_surface_friction(c, t, dir, w);
  if (l != "stribeck")
    c.fail(t.get("law") ? *t.get("law") : static_cast<const toml::node&>(t), w + ".law",
           "expected \"coulomb\", \"stribeck\" or \"surface\", found \"" + l + "\"");
  c.allowed(t, w, {"law", "table", "interval", "mu_BL", "mu_EHL", "L_BL", "L_EHL", "Ra_um", "eta_Pa_s"});
  const int interval = c.count_of(t, "interval", w, 100, 1);
  analysis::StribeckParams p;
  if (t.get("table")) {
    const std::string file = c.str(t, "table", w);
    if (c.count() > before) return nullptr;
    if (!readable_file(deck_relative(dir, file))) c.fail(*t.get("table"), w + ".table", missing_file(file, dir));
    // The table gives all six parameters: one given beside it was ignored (exit 0, before 2026-12-05).
    for (const char* k : {"mu_BL", "mu_EHL", "L_BL", "L_EHL", "Ra_um", "eta_Pa_s"})
      if (t.get(k)) c.bad(*t.get(k), w + "." + k, "not used with 'table' (the table gives every Stribeck parameter; give one or the other)");
    if (c.count() > before) return nullptr;
    try {
      p = analysis::load_stribeck(deck_relative(dir, file));
    } catch (const InputError& e) {  // the table's own file:line, with the deck line that named it
      c.fail(*t.get("table"), w + ".table", e.what());
    }
  } else {
    p.mu_BL = c.in_range(t, "mu_BL", w, NAN, 0.0, kMaxFrictionCoefficient);
    p.mu_EHL = c.in_range(t, "mu_EHL", w, NAN, 0.0, kMaxFrictionCoefficient);
    p.L_BL = c.positive(t, "L_BL", w);
    p.L_EHL = c.positive(t, "L_EHL", w);
    p.Ra_um = c.positive(t, "Ra_um", w);
    p.eta_Pa_s = c.positive(t, "eta_Pa_s", w);
    if (t.get("L_BL") && t.get("L_EHL") && !(p.L_BL < p.L_EHL))
      c.bad(*t.get("L_BL"), w + ".L_BL",
            "expected L_BL < L_EHL (boundary before hydrodynamic lubrication), found L_BL = " + fmt_shortest(p.L_BL) +
                " >= L_EHL = " + fmt_shortest(p.L_EHL));
    if (t.get("mu_BL") == nullptr || t.get("mu_EHL") == nullptr)
      c.bad(t, w, "missing required key 'mu_BL' or 'mu_EHL' (expected numbers >= 0)");
  }
  if (c.count() > before) return nullptr;
  try {
    return std::make_shared<friction::Stribeck>(p, interval);
  } catch (const std::invalid_argument& e) {
    c.fail(t, w, e.what());
  }
}

}  // namespace drawbend::io
