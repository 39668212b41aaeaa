#include "io/deck_material.hpp"

#include <filesystem>
#include <set>

#include "core/csv.hpp"
#include "fe/disk.hpp"
#include "material/j2_isotropic.hpp"
#include "material/linear_elastic.hpp"
#include "friction/stribeck_law.hpp"
#include "friction/surface_law.hpp"
#include "study/thesis_data.hpp"

namespace drawbend::io {

namespace {
std::string at(const toml::node& n, const std::string& deck) { return deck + ":" + std::to_string(n.source().begin.line); }

void check_keys(const toml::table& t, const std::string& deck, const std::string& what, const std::set<std::string>& keys) {
  for (const auto& [k, v] : t)
    if (!keys.count(std::string(k.str()))) {
      std::string list;
      for (const auto& a : keys) list += (list.empty() ? "" : ", ") + a;
      throw InputError(at(v, deck) + ": " + what + "." + std::string(k.str()) + ": unknown key (expected one of: " + list + ")");
    }
}

double positive(const toml::table& t, const std::string& key, const std::string& deck, const std::string& what) {
  const auto* n = t.get(key);
  if (!n) throw InputError(at(t, deck) + ": " + what + ": missing required key '" + key + "'");
  const auto v = n->value<double>();
  if (!v) throw InputError(at(*n, deck) + ": " + what + "." + key + ": expected a number");
  if (!(*v > 0)) throw InputError(at(*n, deck) + ": " + what + "." + key + ": must be > 0, found " + fmt(*v));
  return *v;
}

// interval = cycles over which a law averages the sliding speed (default 100, Sec. 3.3.2).
int interval_key(const toml::table& t, const std::string& deck) {
  const auto* n = t.get("interval");
  if (!n) return 100;
  const auto v = n->value<int64_t>();
  if (!v || *v < 1) throw InputError(at(*n, deck) + ": contact.friction.interval: expected a whole number of cycles >= 1");
  return static_cast<int>(*v);
}
}  // namespace

std::shared_ptr<const material::Material> make_material(const toml::table& t, const std::string& deck,
                                                        const std::string& dir) {
  const auto* type = t.get("type");
  const std::string ty = type && type->value<std::string>() ? *type->value<std::string>() : "";
  if (ty != "elastic" && ty != "j2")
    throw InputError(at(type ? *type : static_cast<const toml::node&>(t), deck) +
                     ": material.type: expected \"elastic\" or \"j2\"");
  const double E = positive(t, "E", deck, "material"), rho = positive(t, "density", deck, "material");
  const auto* nun = t.get("nu");
  if (!nun || !nun->value<double>()) throw InputError(at(t, deck) + ": material: missing number 'nu'");
  const double nu = *nun->value<double>();
  if (!(nu > -1.0 && nu < 0.5)) throw InputError(at(*nun, deck) + ": material.nu: must lie in (-1, 0.5), found " + fmt(nu));
  if (ty == "elastic") {
    check_keys(t, deck, "material", {"type", "E", "nu", "density"});
    return std::make_shared<material::LinearElastic>(E, nu, rho);
  }
  check_keys(t, deck, "material", {"type", "E", "nu", "density", "hardening", "yield", "tangent"});
  if (const auto* h = t.get("hardening")) {
    const auto file = h->value<std::string>();
    if (!file) throw InputError(at(*h, deck) + ": material.hardening: expected a file name");
    std::filesystem::path p(*file);
    if (p.is_relative()) p = std::filesystem::path(dir) / p;
    return std::make_shared<material::J2Isotropic>(E, nu, rho, material::HardeningCurve::load(p.string()));
  }
  const double sy = positive(t, "yield", deck, "material");
  double H = 0;
  if (const auto* tn = t.get("tangent")) {
    if (!tn->value<double>() || *tn->value<double>() < 0)
      throw InputError(at(*tn, deck) + ": material.tangent: expected a hardening modulus >= 0 MPa");
    H = *tn->value<double>();
  }
  // Linear hardening as a two-point table (constant extrapolation of the slope).
  return std::make_shared<material::J2Isotropic>(E, nu, rho,
                                                 material::HardeningCurve({0.0, 1.0}, {sy, sy + H}, at(t, deck)));
}

// friction = { law = "surface", nodes = "table_6_1.csv" | lines = "table_5_16.csv",
//              p_min, p_max, v_min, v_max (nodes only; default Sec. 6.3), interval = 100 }
static std::shared_ptr<friction::FrictionLaw> make_surface_friction(const toml::table& t, const std::string& deck,
                                                                    const std::string& dir) {
  check_keys(t, deck, "contact.friction", {"law", "nodes", "lines", "interval", "p_min", "p_max", "v_min", "v_max"});
  const int interval = interval_key(t, deck);
  friction::SurfaceDomain d;
  for (const auto& [key, ptr] : {std::pair{"p_min", &d.p_min}, std::pair{"p_max", &d.p_max},
                                 std::pair{"v_min", &d.v_min}, std::pair{"v_max", &d.v_max}})
    if (const auto* n = t.get(key)) {
      if (!n->value<double>()) throw InputError(at(*n, deck) + ": contact.friction." + key + ": expected a number");
      *ptr = *n->value<double>();
    }
  if (!(d.p_min >= 0 && d.p_min < d.p_max))
    throw InputError(at(t, deck) + ": contact.friction: need 0 <= p_min < p_max [MPa]");
  if (!(d.v_min >= 0 && d.v_min < d.v_max))
    throw InputError(at(t, deck) + ": contact.friction: need 0 <= v_min < v_max [mm/s]");
  const auto* nodes = t.get("nodes");
  const auto* lines = t.get("lines");
  if (!nodes == !lines)
    throw InputError(at(t, deck) + ": contact.friction: give exactly one of 'nodes' (Table 6.1 format) or 'lines' "
                     "(Table 5.16 format)");
  const auto* src = nodes ? nodes : lines;
  const auto file = src->value<std::string>();
  if (!file) throw InputError(at(*src, deck) + ": contact.friction." + (nodes ? "nodes" : "lines") + ": expected a file name");
  if (lines && (t.get("v_min") || t.get("v_max")))
    throw InputError(at(t, deck) + ": contact.friction: with 'lines' the speed range is that of the outer lines; "
                     "remove v_min/v_max");
  std::filesystem::path fp(*file);
  if (fp.is_relative()) fp = std::filesystem::path(dir) / fp;
  const std::string where = at(*src, deck) + ": contact.friction." + (nodes ? "nodes" : "lines") + ": ";
  try {
    const auto [rd, td] = nodes ? friction::load_surface_nodes(fp.string(), d)
                                : friction::load_surface_lines(fp.string(), d.p_min, d.p_max);
    return std::make_shared<friction::SurfaceLaw>(rd, td, interval);
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(where + fp.string() + ": " + e.what());
  }
}

std::shared_ptr<friction::FrictionLaw> make_friction(const toml::table& t, const std::string& deck,
                                                     const std::string& dir) {
  const auto* law = t.get("law");
  const std::string l = law && law->value<std::string>() ? *law->value<std::string>() : "";
  if (l == "coulomb") {
    check_keys(t, deck, "contact.friction", {"law", "mu"});
    const auto* mu = t.get("mu");
    if (!mu || !mu->value<double>()) throw InputError(at(t, deck) + ": contact.friction: missing number 'mu'");
    if (*mu->value<double>() < 0) throw InputError(at(*mu, deck) + ": contact.friction.mu: must be >= 0");
    return std::make_shared<friction::Coulomb>(*mu->value<double>());
  }
  if (l == "stribeck") {
    check_keys(t, deck, "contact.friction",
               {"law", "table", "interval", "mu_BL", "mu_EHL", "L_BL", "L_EHL", "Ra_um", "eta_Pa_s"});
    const int interval = interval_key(t, deck);
    analysis::StribeckParams p;
    if (const auto* tab = t.get("table")) {
      const auto file = tab->value<std::string>();
      if (!file) throw InputError(at(*tab, deck) + ": contact.friction.table: expected a file name");
      std::filesystem::path fp(*file);
      if (fp.is_relative()) fp = std::filesystem::path(dir) / fp;
      p = study::load_stribeck(fp.string());
    } else {
      p.mu_BL = positive(t, "mu_BL", deck, "contact.friction");
      p.mu_EHL = positive(t, "mu_EHL", deck, "contact.friction");
      p.L_BL = positive(t, "L_BL", deck, "contact.friction");
      p.L_EHL = positive(t, "L_EHL", deck, "contact.friction");
      p.Ra_um = positive(t, "Ra_um", deck, "contact.friction");
      p.eta_Pa_s = positive(t, "eta_Pa_s", deck, "contact.friction");
    }
    try {
      return std::make_shared<friction::Stribeck>(p, interval);
    } catch (const std::invalid_argument& e) {
      throw InputError(at(t, deck) + ": contact.friction: " + e.what());
    }
  }
  if (l == "surface") return make_surface_friction(t, deck, dir);
  throw InputError(at(law ? *law : static_cast<const toml::node&>(t), deck) +
                   ": contact.friction.law: expected \"coulomb\", \"stribeck\" or \"surface\" (found \"" + l + "\")");
}

fe::Mesh make_quarter_disk(const toml::table& t, const std::string& deck) {
  check_keys(t, deck, "mesh", {"kind", "radius", "thickness", "core_fraction", "core", "ring", "through"});
  fe::QuarterDiskSpec s;
  s.radius = positive(t, "radius", deck, "mesh");
  s.thickness = positive(t, "thickness", deck, "mesh");
  if (t.get("core_fraction")) s.core_fraction = positive(t, "core_fraction", deck, "mesh");
  for (const auto& [key, ptr] : {std::pair{"core", &s.core}, std::pair{"ring", &s.ring}, std::pair{"through", &s.through}})
    if (const auto* n = t.get(key)) {
      const auto v = n->value<int64_t>();
      if (!v || *v < 1) throw InputError(at(*n, deck) + ": mesh." + key + ": expected a whole number of elements >= 1");
      *ptr = static_cast<int>(*v);
    }
  try {
    return fe::quarter_disk(s);
  } catch (const std::invalid_argument& e) {
    throw InputError(at(t, deck) + ": mesh: " + e.what());
  }
}

}  // namespace drawbend::io
