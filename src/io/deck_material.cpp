#include "io/deck_material.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include "core/csv.hpp"
#include "fe/disk.hpp"
#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/linear_elastic.hpp"
#include "material/yld2004_plasticity.hpp"
#include "friction/stribeck_law.hpp"
#include "friction/surface_law.hpp"

namespace drawbend::io {

namespace {
std::string relative_to(const std::string& dir, const std::string& file) {
  std::filesystem::path p(file);
  if (p.is_relative()) p = std::filesystem::path(dir) / p;
  return p.string();
}

bool readable(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

/// "cannot open FILE" with the rule that found it (a relative path is the deck folder's).
std::string missing(const std::string& file, const std::string& dir) {
  if (!std::filesystem::path(file).is_relative()) return "cannot open '" + file + "' for reading";
  return "cannot open '" + file + "' for reading (relative paths are resolved against the deck's folder, " +
         (dir.empty() ? std::string(".") : dir) + ")";
}

}  // namespace

namespace {
// hardening = "curve.csv" | { plastic_strain = [...], true_stress_MPa = [...] } | yield [+ tangent] | voce = { sigma0, Q, b } | swift = { K, e0, n }.
std::optional<material::HardeningCurve> read_curve(const DeckContext& c, const toml::table& t, const std::string& dir) {
  const std::size_t before = c.count();
  const int forms = (t.get("hardening") != nullptr) + (t.get("yield") != nullptr) + (t.get("voce") != nullptr) +
                    (t.get("swift") != nullptr);
  if (forms != 1) {
    c.bad(t, "material", "expected exactly one flow curve: hardening = \"curve.csv\" or { plastic_strain, true_stress_MPa }, yield [MPa] (+ tangent), "
                         "voce = { sigma0, Q, b } or swift = { K, e0, n }");
    return std::nullopt;
  }
  if (const auto* inl = t.get_as<toml::table>("hardening")) {  // { plastic_strain = [...], true_stress_MPa = [...] }
    const std::string w = "material.hardening";
    c.allowed(*inl, w, {"plastic_strain", "true_stress_MPa"});
    std::vector<double> col[2];
    const char* keys[2] = {"plastic_strain", "true_stress_MPa"};
    for (int k = 0; k < 2; ++k) {
      const auto* a = inl->get_as<toml::array>(keys[k]);
      if (!a || a->empty()) {
        c.bad(*inl, w + "." + keys[k], "expected a non-empty array of numbers");
        continue;
      }
      for (const auto& v : *a) {
        const auto x = v.value<double>();
        if (!x || !std::isfinite(*x)) c.bad(v, w + "." + keys[k], "expected a finite number");
        col[k].push_back(x.value_or(0.0));
      }
    }
    if (c.count() == before && col[0].size() != col[1].size())
      c.bad(*inl, w, "plastic_strain and true_stress_MPa differ in length (" + std::to_string(col[0].size()) + " and " +
                         std::to_string(col[1].size()) + ")");
    if (c.count() > before) return std::nullopt;
    try {
      return material::HardeningCurve(col[0], col[1], "the inline curve");
    } catch (const InputError& e) {
      c.bad(*inl, w, e.what());
      return std::nullopt;
    }
  }
  if (t.get("hardening")) {
    const std::string file = c.str(t, "hardening", "material");
    if (c.count() > before) return std::nullopt;
    if (!readable(relative_to(dir, file))) {  // a missing file is named with the deck line that asked for it
      c.bad(*t.get("hardening"), "material.hardening", missing(file, dir));
      return std::nullopt;
    }
    return material::HardeningCurve::load(relative_to(dir, file));
  }
  if (t.get("yield")) {
    const double sy = c.positive(t, "yield", "material");
    const double H = c.in_range(t, "tangent", "material", 0.0, 0.0);
    if (c.count() > before) return std::nullopt;
    // Linear hardening as a two-point table (constant extrapolation of the slope).
    return material::HardeningCurve({0.0, 1.0}, {sy, sy + H}, c.where(t, "material"));
  }
  const bool voce = t.get("voce") != nullptr;
  const std::string key = voce ? "voce" : "swift";
  const toml::table* f = c.table(t, key, "material", true);
  const std::string w = "material." + key;
  c.allowed(*f, w, voce ? std::set<std::string>{"sigma0", "Q", "b"} : std::set<std::string>{"K", "e0", "n"});
  const double a = c.positive(*f, voce ? "sigma0" : "K", w);
  const double b = voce ? c.in_range(*f, "Q", w, NAN, 0.0) : c.positive(*f, "e0", w);
  const double d = c.in_range(*f, voce ? "b" : "n", w, NAN, 0.0);
  if (c.count() > before) return std::nullopt;
  return voce ? material::HardeningCurve::voce(a, b, d) : material::HardeningCurve::swift(a, b, d);
}

// kinematic = { beta = 0.3 } | { C = [MPa, ...], gamma = [...] } (1 to 3 terms).
material::KinematicHardening read_kinematic(const DeckContext& c, const toml::table& t) {
  material::KinematicHardening k;
  const toml::table* f = c.table(t, "kinematic", "material", true);
  const std::string w = "material.kinematic";
  c.allowed(*f, w, {"beta", "C", "gamma"});
  if (f->get("beta")) {
    if (f->get("C") || f->get("gamma")) c.bad(*f, w, "expected either beta (split form) or C and gamma (Chaboche), not both");
    k.beta = c.in_range(*f, "beta", w, 0.0, 0.0, 1.0);
    return k;
  }
  const auto* C = f->get_as<toml::array>("C");
  const auto* g = f->get_as<toml::array>("gamma");
  if (!C || !g) {
    c.bad(*f, w, "expected beta in [0, 1], or arrays C = [MPa, ...] and gamma = [...] of 1 to 3 terms");
    return k;
  }
  if (C->size() != g->size() || C->empty() || C->size() > 3) {
    c.bad(*f, w + ".C", "expected C and gamma of the same length, 1 to 3 terms, found " + std::to_string(C->size()) +
                            " and " + std::to_string(g->size()));
    return k;
  }
  for (std::size_t i = 0; i < C->size(); ++i) {
    const auto Ci = (*C)[i].value<double>();
    const auto gi = (*g)[i].value<double>();
    if (!Ci || !(*Ci >= 0) || !std::isfinite(*Ci))
      c.bad((*C)[i], w + ".C", "expected a kinematic modulus >= 0 MPa, found " + (Ci ? fmt_shortest(*Ci) : "no number"));
    if (!gi || !(*gi >= 0) || !std::isfinite(*gi))
      c.bad((*g)[i], w + ".gamma", "expected a recovery rate >= 0, found " + (gi ? fmt_shortest(*gi) : "no number"));
    k.chaboche.push_back({Ci.value_or(0.0), gi.value_or(0.0)});
  }
  return k;
}

// hill48 = { r0, r45, r90 } | { s45, s90, sb } (yield-stress ratios to RD).
material::Hill48 read_hill(const DeckContext& c, const toml::table& t) {
  const toml::table* f = c.table(t, "hill48", "material", true);
  const std::string w = "material.hill48";
  c.allowed(*f, w, {"r0", "r45", "r90", "s45", "s90", "sb"});
  const bool r = f->get("r0") || f->get("r45") || f->get("r90");
  const bool s = f->get("s45") || f->get("s90") || f->get("sb");
  if (r == s) {
    c.bad(*f, w, "expected r-values { r0, r45, r90 } or yield-stress ratios to RD { s45, s90, sb }, not both");
    return {};
  }
  const std::size_t before = c.count();
  const double a = c.positive(*f, r ? "r0" : "s45", w), b = c.positive(*f, r ? "r45" : "s90", w),
               d = c.positive(*f, r ? "r90" : "sb", w);
  if (c.count() > before) return {};
  try {
    return r ? material::Hill48::from_r_values(a, b, d) : material::Hill48::from_stress_ratios(a, b, d);
  } catch (const std::invalid_argument& e) {
    c.bad(*f, w, e.what());
    return {};
  }
}

// yld2004 = { a = 8, c1 = [c12, c13, c21, c23, c31, c32, c44, c55, c66], c2 = [...] } (Yld2004-18p, C' and C'').
material::Yld2004 read_yld2004(const DeckContext& c, const toml::table& t) {
  material::Yld2004 y;
  const toml::table* f = c.table(t, "yld2004", "material", true);
  const std::string w = "material.yld2004";
  c.allowed(*f, w, {"a", "c1", "c2"});
  y.a = c.in_range(*f, "a", w, NAN, 2.0);
  for (const char* key : {"c1", "c2"}) {
    auto& dst = key[1] == '1' ? y.c1 : y.c2;
    const auto* arr = f->get_as<toml::array>(key);
    if (!arr || arr->size() != 9) {
      c.bad(arr ? static_cast<const toml::node&>(*arr) : static_cast<const toml::node&>(*f), w + "." + key,
            "expected 9 numbers c12, c13, c21, c23, c31, c32, c44, c55, c66" +
                (arr ? ", found " + std::to_string(arr->size()) : std::string()));
      continue;
    }
    for (std::size_t i = 0; i < 9; ++i) {
      const auto x = (*arr)[i].value<double>();
      if (!x || !std::isfinite(*x)) c.bad((*arr)[i], w + "." + key, "expected a finite number");
      dst[i] = x.value_or(0.0);
    }
  }
  return y;
}
}  // namespace

std::shared_ptr<const material::Material> make_material(const DeckContext& c, const toml::table& t,
                                                        const std::string& dir) {
  const std::size_t before = c.count();
  const std::string ty = c.str(t, "type", "material");
  if (ty != "elastic" && ty != "j2" && ty != "j2_combined" && ty != "hill48" && ty != "yld2004")
    c.fail(t.get("type") ? *t.get("type") : static_cast<const toml::node&>(t), "material.type",
           "expected \"elastic\", \"j2\", \"j2_combined\", \"hill48\" or \"yld2004\", found \"" + ty + "\"");
  const std::set<std::string> curve_keys = {"hardening", "yield", "tangent", "voce", "swift"};
  std::set<std::string> keys = {"type", "E", "nu", "density"};
  if (ty != "elastic") keys.insert(curve_keys.begin(), curve_keys.end());
  if (ty == "j2_combined" || ty == "hill48" || ty == "yld2004") keys.insert("kinematic");
  if (ty == "hill48") keys.insert("hill48");
  if (ty == "yld2004") keys.insert("yld2004");
  c.allowed(t, "material", keys);
  const double E = c.positive(t, "E", "material"), rho = c.positive(t, "density", "material");
  const double nu = c.num(t, "nu", "material");
  if (!std::isnan(nu) && !(nu > -1.0 && nu < 0.5))
    c.bad(*t.get("nu"), "material.nu", "expected Poisson's ratio in (-1, 0.5), found " + fmt_shortest(nu));
  if (ty == "elastic") {
    if (c.count() > before) return nullptr;
    return std::make_shared<material::LinearElastic>(E, nu, rho);
  }
  auto curve = read_curve(c, t, dir);
  material::KinematicHardening kin;
  if (ty == "j2_combined" || ((ty == "hill48" || ty == "yld2004") && t.get("kinematic"))) kin = read_kinematic(c, t);
  material::Hill48 hill;
  if (ty == "hill48") hill = read_hill(c, t);
  material::Yld2004 yld;
  if (ty == "yld2004") yld = read_yld2004(c, t);
  if (c.count() > before || !curve) return nullptr;
  if (ty == "j2") return std::make_shared<material::J2Isotropic>(E, nu, rho, std::move(*curve));
  try {
    if (ty == "yld2004") {
      try {
        return std::make_shared<material::Yld2004Plasticity>(E, nu, rho, std::move(*curve), kin, yld);
      } catch (const std::invalid_argument& e) {
        c.fail(*t.get("yld2004"), "material.yld2004", e.what());
      }
    }
    return std::make_shared<material::CombinedPlasticity>(E, nu, rho, std::move(*curve), kin, hill);
  } catch (const std::invalid_argument& e) {
    c.fail(t, "material", e.what());
  }
}

// friction = { law = "surface", nodes = "table_6_1.csv" | lines = "table_5_16.csv",
//              p_min, p_max, v_min, v_max (nodes only; default Sec. 6.3), interval = 100 }
static std::shared_ptr<friction::FrictionLaw> make_surface_friction(const DeckContext& c, const toml::table& t,
                                                                    const std::string& dir) {
  const std::string w = "contact.friction";
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
  const std::string file = relative_to(dir, c.str(t, key, w));
  if (c.count() > before) return nullptr;
  if (!readable(file)) c.fail(*t.get(key), w + "." + key, missing(c.str(t, key, w), dir));
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
                                                     const std::string& dir) {
  const std::string w = "contact.friction";
  const std::size_t before = c.count();
  const std::string l = c.str(t, "law", w);
  if (l == "coulomb") {
    c.allowed(t, w, {"law", "mu"});
    const double mu = c.num(t, "mu", w);
    if (!std::isnan(mu) && !(mu >= 0)) c.bad(*t.get("mu"), w + ".mu", "expected a friction coefficient >= 0, found " + fmt_shortest(mu));
    if (c.count() > before) return nullptr;
    return std::make_shared<friction::Coulomb>(mu);
  }
  if (l == "surface") return make_surface_friction(c, t, dir);
  if (l != "stribeck")
    c.fail(t.get("law") ? *t.get("law") : static_cast<const toml::node&>(t), w + ".law",
           "expected \"coulomb\", \"stribeck\" or \"surface\", found \"" + l + "\"");
  c.allowed(t, w, {"law", "table", "interval", "mu_BL", "mu_EHL", "L_BL", "L_EHL", "Ra_um", "eta_Pa_s"});
  const int interval = c.count_of(t, "interval", w, 100, 1);
  analysis::StribeckParams p;
  if (t.get("table")) {
    const std::string file = c.str(t, "table", w);
    if (c.count() > before) return nullptr;
    if (!readable(relative_to(dir, file))) c.fail(*t.get("table"), w + ".table", missing(file, dir));
    p = analysis::load_stribeck(relative_to(dir, file));
  } else {
    p.mu_BL = c.in_range(t, "mu_BL", w, NAN, 0.0);
    p.mu_EHL = c.in_range(t, "mu_EHL", w, NAN, 0.0);
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

fe::Mesh make_quarter_disk(const DeckContext& c, const toml::table& t) {
  const std::size_t before = c.count();
  c.allowed(t, "mesh", {"kind", "radius", "thickness", "core_fraction", "core", "ring", "through",
                          "polar_radius"});
  fe::QuarterDiskSpec s;
  s.radius = c.positive(t, "radius", "mesh");
  s.thickness = c.positive(t, "thickness", "mesh");
  s.core_fraction = c.positive(t, "core_fraction", "mesh", s.core_fraction);
  s.core = c.count_of(t, "core", "mesh", s.core, 1);
  s.ring = c.count_of(t, "ring", "mesh", s.ring, 1);
  s.through = c.count_of(t, "through", "mesh", s.through, 1);
  if (t.contains("polar_radius")) s.polar_radius = c.positive(t, "polar_radius", "mesh");
  if (c.count() > before) return {};
  try {
    return fe::quarter_disk(s);
  } catch (const std::invalid_argument& e) {
    c.fail(t, "mesh", e.what());
  }
}

}  // namespace drawbend::io
