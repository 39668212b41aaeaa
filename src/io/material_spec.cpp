#include "io/material_spec.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <filesystem>
#include <set>
#include <cstdio>

#include "core/quote.hpp"
#include "core/csv.hpp"
#include "core/input_problems.hpp"
#include "core/toml_read.hpp"
#include "material/combined_plasticity.hpp"
#include "material/hill48.hpp"
#include "material/yld2004_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/linear_elastic.hpp"

namespace drawbend::io {

namespace {

// ---- reading ---------------------------------------------------------------

// hardening = "curve.csv" | { plastic_strain = [...], true_stress_MPa = [...] } | yield [+ tangent] | voce = { sigma0, Q, b } | swift = { K, e0, n }.
std::optional<FlowCurve> read_curve(const DeckContext& c, const toml::table& t) {
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
      material::HardeningCurve(col[0], col[1], "the inline curve");  // its checks: start at 0, order, sign
    } catch (const InputError& e) {
      c.bad(*inl, w, e.what());
      return std::nullopt;
    }
    return CurveTable{std::move(col[0]), std::move(col[1])};
  }
  if (t.get("hardening")) {
    const std::string file = c.str(t, "hardening", "material");
    if (c.count() > before) return std::nullopt;
    return CurveFile{file};
  }
  if (t.get("yield")) {
    CurveLinear l;
    l.yield = c.positive(t, "yield", "material");
    const double H = c.in_range(t, "tangent", "material", 0.0, 0.0);
    if (t.get("tangent")) l.tangent = H;
    if (c.count() > before) return std::nullopt;
    return l;
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
  if (voce) return CurveVoce{a, b, d};
  return CurveSwift{a, b, d};
}

// kinematic = { beta = 0.3 } | { C = [MPa, ...], gamma = [...] } (1 to 3 terms).
Kinematic read_kinematic(const DeckContext& c, const toml::table& t) {
  const toml::table* f = c.table(t, "kinematic", "material", true);
  const std::string w = "material.kinematic";
  c.allowed(*f, w, {"beta", "C", "gamma"});
  if (f->get("beta")) {
    if (f->get("C") || f->get("gamma")) c.bad(*f, w, "expected either beta (split form) or C and gamma (Chaboche), not both");
    return KinematicSplit{c.in_range(*f, "beta", w, 0.0, 0.0, 1.0)};
  }
  KinematicChaboche k;
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
    k.C.push_back(Ci.value_or(0.0));
    k.gamma.push_back(gi.value_or(0.0));
  }
  return k;
}

material::Hill48 make_hill(const YieldSurface& s) {
  if (const auto* r = std::get_if<Hill48R>(&s)) return material::Hill48::from_r_values(r->r0, r->r45, r->r90);
  if (const auto* q = std::get_if<Hill48S>(&s)) return material::Hill48::from_stress_ratios(q->s45, q->s90, q->sb);
  return {};
}

// hill48 = { r0, r45, r90 } | { s45, s90, sb } (yield-stress ratios to RD).
YieldSurface read_hill(const DeckContext& c, const toml::table& t) {
  const toml::table* f = c.table(t, "hill48", "material", true);
  const std::string w = "material.hill48";
  c.allowed(*f, w, {"r0", "r45", "r90", "s45", "s90", "sb"});
  const bool r = f->get("r0") || f->get("r45") || f->get("r90");
  const bool s = f->get("s45") || f->get("s90") || f->get("sb");
  if (r == s) {
    c.bad(*f, w, "expected r-values { r0, r45, r90 } or yield-stress ratios to RD { s45, s90, sb }, not both");
    return VonMises{};
  }
  const std::size_t before = c.count();
  const double a = c.positive(*f, r ? "r0" : "s45", w), b = c.positive(*f, r ? "r45" : "s90", w),
               d = c.positive(*f, r ? "r90" : "sb", w);
  if (c.count() > before) return VonMises{};
  const YieldSurface out = r ? YieldSurface(Hill48R{a, b, d}) : YieldSurface(Hill48S{a, b, d});
  try {
    make_hill(out);  // its checks: a positive-definite quadratic form
  } catch (const std::invalid_argument& e) {
    c.bad(*f, w, e.what());
    return VonMises{};
  }
  return out;
}

// ---- writing ---------------------------------------------------------------

// A TOML float in its shortest round-trip form: 70000.0, 0.33, 2.7e-9.
std::string number(double v) {
  char buf[64];
  std::string s(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  const std::size_t e = s.find('e');
  if (e == std::string::npos) {
    if (s.find_first_of(".ni") == std::string::npos) s += ".0";  // an integral value stays a float
    return s;
  }
  std::size_t d = e + 1 + (s[e + 1] == '-' || s[e + 1] == '+');  // the exponent without its zero padding
  while (d + 1 < s.size() && s[d] == '0') s.erase(d, 1);
  return s;
}

std::string array(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + number(v[i]);
  return s + "]";
}


std::string curve_lines(const FlowCurve& f) {
  if (const auto* p = std::get_if<CurveFile>(&f)) return "hardening = " + string_literal(p->path) + "\n";
  if (const auto* p = std::get_if<CurveTable>(&f))
    return "hardening = { plastic_strain = " + array(p->plastic_strain) + ", true_stress_MPa = " + array(p->true_stress_MPa) +
           " }\n";
  if (const auto* p = std::get_if<CurveLinear>(&f))
    return "yield = " + number(p->yield) + "\n" + (p->tangent ? "tangent = " + number(*p->tangent) + "\n" : "");
  if (const auto* p = std::get_if<CurveVoce>(&f))
    return "voce = { sigma0 = " + number(p->sigma0) + ", Q = " + number(p->Q) + ", b = " + number(p->b) + " }\n";
  const auto& w = std::get<CurveSwift>(f);
  return "swift = { K = " + number(w.K) + ", e0 = " + number(w.e0) + ", n = " + number(w.n) + " }\n";
}

std::string kinematic_line(const Kinematic& k) {
  if (const auto* s = std::get_if<KinematicSplit>(&k)) return "kinematic = { beta = " + number(s->beta) + " }\n";
  const auto& c = std::get<KinematicChaboche>(k);
  return "kinematic = { C = " + array(c.C) + ", gamma = " + array(c.gamma) + " }\n";
}

// yld2004 = { a = 8, c1 = [c12, c13, c21, c23, c31, c32, c44, c55, c66], c2 = [...] } (Yld2004-18p, C' and C'').
YieldSurface read_yld2004(const DeckContext& c, const toml::table& t) {
  Yld2004Surface y;
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

std::string surface_line(const YieldSurface& s) {
  if (const auto* y = std::get_if<Yld2004Surface>(&s))
    return "yld2004 = { a = " + number(y->a) + ", c1 = " + array(std::vector<double>(y->c1.begin(), y->c1.end())) +
           ", c2 = " + array(std::vector<double>(y->c2.begin(), y->c2.end())) + " }\n";
  if (const auto* r = std::get_if<Hill48R>(&s))
    return "hill48 = { r0 = " + number(r->r0) + ", r45 = " + number(r->r45) + ", r90 = " + number(r->r90) + " }\n";
  if (const auto* q = std::get_if<Hill48S>(&s))
    return "hill48 = { s45 = " + number(q->s45) + ", s90 = " + number(q->s90) + ", sb = " + number(q->sb) + " }\n";
  return "";
}

}  // namespace

const char* type_name(MaterialType t) {
  switch (t) {
    case MaterialType::elastic: return "elastic";
    case MaterialType::j2: return "j2";
    case MaterialType::j2_combined: return "j2_combined";
    case MaterialType::hill48: return "hill48";
    case MaterialType::yld2004: return "yld2004";
  }
  return "?";
}

MaterialSpec from_toml(const DeckContext& c, const toml::table& t) {
  MaterialSpec m;
  const std::string ty = c.str(t, "type", "material");
  const MaterialType types[] = {MaterialType::elastic, MaterialType::j2, MaterialType::j2_combined, MaterialType::hill48,
                                MaterialType::yld2004};
  bool known = false;
  for (const MaterialType k : types)
    if (ty == type_name(k)) m.type = k, known = true;
  if (!known)
    c.fail(t.get("type") ? *t.get("type") : static_cast<const toml::node&>(t), "material.type",
           "expected \"elastic\", \"j2\", \"j2_combined\", \"hill48\" or \"yld2004\", found \"" + ty + "\"");
  const bool elastic = m.type == MaterialType::elastic, hill = m.type == MaterialType::hill48;
  const bool combined = m.type == MaterialType::j2_combined, yld = m.type == MaterialType::yld2004;
  std::set<std::string> keys = {"type", "E", "nu", "density"};
  if (!elastic) keys.insert(std::begin(kFlowCurveKeys), std::end(kFlowCurveKeys));
  if (combined || hill || yld) keys.insert("kinematic");
  if (hill) keys.insert("hill48");
  if (yld) keys.insert("yld2004");
  c.allowed(t, "material", keys);
  m.E = c.positive(t, "E", "material");
  m.density = c.positive(t, "density", "material");
  m.nu = c.num(t, "nu", "material");
  if (!std::isnan(m.nu) && !(m.nu > -1.0 && m.nu < 0.5))
    c.bad(*t.get("nu"), "material.nu", "expected Poisson's ratio in (-1, 0.5), found " + fmt_shortest(m.nu));
  if (elastic) return m;
  m.curve = read_curve(c, t);
  if (combined || ((hill || yld) && t.get("kinematic"))) m.kinematic = read_kinematic(c, t);
  if (hill) m.surface = read_hill(c, t);
  if (yld) m.surface = read_yld2004(c, t);
  return m;
}

const char* key_of(const FlowCurve& f) {
  if (std::holds_alternative<CurveLinear>(f)) return "yield";
  if (std::holds_alternative<CurveVoce>(f)) return "voce";
  if (std::holds_alternative<CurveSwift>(f)) return "swift";
  return "hardening";
}

const char* key_of(const YieldSurface& s) {
  if (std::holds_alternative<Hill48R>(s) || std::holds_alternative<Hill48S>(s)) return "hill48";
  if (std::holds_alternative<Yld2004Surface>(s)) return "yld2004";
  return "";
}

bool has_flow_curve(const toml::table& t) {
  for (const char* k : kFlowCurveKeys)
    if (t.contains(k)) return true;
  return false;
}

MaterialSpec read_material(const toml::table& t, const std::string& where) {
  InputProblems problems(where);
  const DeckContext c(where, problems);
  MaterialSpec m;
  problems.attempt([&] { m = from_toml(c, t); });
  problems.throw_if_any();
  return m;
}

std::string to_toml(const MaterialSpec& m) {
  std::string s = "[material]\ntype = \"" + std::string(type_name(m.type)) + "\"\nE = " + number(m.E) +
                  "\nnu = " + number(m.nu) + "\ndensity = " + number(m.density) + "\n";
  if (m.curve) s += curve_lines(*m.curve);
  if (m.kinematic) s += kinematic_line(*m.kinematic);
  return s + surface_line(m.surface);
}

std::string to_toml_inline(const MaterialSpec& m) {
  const std::string s = to_toml(m);
  std::string keys;
  std::size_t p = s.find('\n') + 1;  // after "[material]"
  for (std::size_t e; (e = s.find('\n', p)) != std::string::npos; p = e + 1)
    keys += (keys.empty() ? "" : ", ") + s.substr(p, e - p);
  return "{ " + keys + " }";
}

material::HardeningCurve make_flow_curve(const FlowCurve& f, const std::string& dir) {
  if (const auto* p = std::get_if<CurveFile>(&f)) {
    std::filesystem::path file(p->path);
    if (file.is_relative() && !dir.empty()) file = std::filesystem::path(dir) / file;
    return material::HardeningCurve::load(file.string());
  }
  if (const auto* p = std::get_if<CurveTable>(&f))
    return material::HardeningCurve(p->plastic_strain, p->true_stress_MPa, "the inline curve");
  if (const auto* p = std::get_if<CurveLinear>(&f)) {
    // Linear hardening as a two-point table (constant extrapolation of the slope).
    const double H = p->tangent.value_or(0.0);
    return material::HardeningCurve({0.0, 1.0}, {p->yield, p->yield + H}, "material.yield");
  }
  if (const auto* p = std::get_if<CurveVoce>(&f)) return material::HardeningCurve::voce(p->sigma0, p->Q, p->b);
  const auto& w = std::get<CurveSwift>(f);
  return material::HardeningCurve::swift(w.K, w.e0, w.n);
}

std::shared_ptr<const material::Material> make_material(const MaterialSpec& m, const std::string& dir) {
  if (m.type == MaterialType::elastic) return std::make_shared<material::LinearElastic>(m.E, m.nu, m.density);
  material::HardeningCurve curve = make_flow_curve(m.curve.value(), dir);
  if (m.type == MaterialType::j2) return std::make_shared<material::J2Isotropic>(m.E, m.nu, m.density, std::move(curve));
  material::KinematicHardening kin;
  if (m.kinematic) {
    if (const auto* s = std::get_if<KinematicSplit>(&*m.kinematic)) kin.beta = s->beta;
    if (const auto* c = std::get_if<KinematicChaboche>(&*m.kinematic))
      for (std::size_t i = 0; i < c->C.size(); ++i) kin.chaboche.push_back({c->C[i], c->gamma[i]});
  }
  if (const auto* y = std::get_if<Yld2004Surface>(&m.surface)) {
    material::Yld2004 yf;
    yf.a = y->a;
    yf.c1 = y->c1;
    yf.c2 = y->c2;
    return std::make_shared<material::Yld2004Plasticity>(m.E, m.nu, m.density, std::move(curve), kin, yf);
  }
  return std::make_shared<material::CombinedPlasticity>(m.E, m.nu, m.density, std::move(curve), kin, make_hill(m.surface));
}

MaterialSpec read_partial_material(toml::table& t, const std::string& default_curve,
                                   const std::optional<std::string>& curve_dir, const std::string& where) {
  if (auto* h = t.get_as<std::string>("hardening"); h && curve_dir && std::filesystem::path(h->get()).is_relative())
    *h = std::filesystem::absolute(std::filesystem::path(*curve_dir) / h->get()).lexically_normal().string();
  const MaterialSpec d;
  if (!t.contains("type")) t.insert("type", type_name(d.type));
  if (!t.contains("E")) t.insert("E", d.E);
  if (!t.contains("nu")) t.insert("nu", d.nu);
  if (!t.contains("density")) t.insert("density", d.density);
  const std::string type = t["type"].value_or(std::string());
  if (type != type_name(MaterialType::elastic) && !has_flow_curve(t)) t.insert("hardening", default_curve);
  return read_material(t, where);
}

std::shared_ptr<const material::Material> make_material(const DeckContext& c, const toml::table& t,
                                                        const std::string& dir, std::string* type) {
  const std::size_t before = c.count();
  const MaterialSpec spec = from_toml(c, t);
  if (c.count() > before) return nullptr;
  if (type) *type = type_name(spec.type);
  if (const auto* f = spec.curve ? std::get_if<CurveFile>(&*spec.curve) : nullptr;
      f && !readable_file(deck_relative(dir, f->path))) {  // a missing file is named with the deck line that asked for it
    c.bad(*t.get("hardening"), "material.hardening", missing_file(f->path, dir));
    return nullptr;
  }
  try {
    try {
      return make_material(spec, dir);
    } catch (const std::invalid_argument& e) {
      if (spec.type == MaterialType::yld2004 && t.get("yld2004"))  // the yield function's own checks (convexity)
        c.fail(*t.get("yld2004"), "material.yld2004", e.what());
      throw;
    }
  } catch (const std::invalid_argument& e) {
    c.fail(t, "material", e.what());
  } catch (const InputError& e) {  // the curve file's own problem (file:line), with the deck line that named it
    if (!t.get("hardening")) throw;  // (before 2026-12-05 "curve.csv: missing required column" without the deck)
    c.fail(*t.get("hardening"), "material.hardening", e.what());
  }
}

void material_warnings(const DeckContext& c, const toml::table& t, std::vector<std::string>& warnings) {
  // The range of real solids: a soft rubber (E ~ 1 MPa; 0.1 MPa leaves a
  // margin) to diamond (1.05e6 MPa); aerogel (~1 kg/m^3 = 1e-12 t/mm^3) to
  // osmium (22.6e3 kg/m^3 = 2.26e-8 t/mm^3).  Outside it a value is most
  // likely in other units (GPa, kg/m^3).
  struct Range {
    const char* key;
    double lo, hi;
    const char* unit;
    const char* why;
  };
  const Range ranges[] = {
      {"E", 0.1, 1.2e6, "MPa", "a soft rubber to diamond"},
      {"density", 1e-12, 2.3e-8, "t/mm^3", "an aerogel to osmium"},
  };
  for (const auto& r : ranges) {
    const toml::node* n = t.get(r.key);
    if (!n) continue;
    const auto v = n->value<double>();
    if (!v || !(*v > 0) || !std::isfinite(*v)) continue;  // reported as an input error
    if (*v < r.lo || *v > r.hi)
      warnings.push_back(c.where(*n, std::string("material.") + r.key) + ": " + fmt_shortest(*v) + " " + r.unit +
                         " is outside the range of real materials (" + fmt_shortest(r.lo) + " to " +
                         fmt_shortest(r.hi) + " " + r.unit + ", " + r.why + "); check the units (mm, N, MPa, s, t/mm^3)");
  }
}

material::Yld2004 load_yld2004_toml(const std::string& path) {
  const toml::table root = parse_toml_file(path);
  // A material file ([material] yld2004 = {...}, as `drawbend calibrate` writes it) or a published
  // yield-function set alone (yld2004 = {...} at the top: no elasticity or flow curve, so no material).
  const bool in_material = root["material"]["yld2004"].as_table() != nullptr;
  const auto* y = in_material ? root["material"]["yld2004"].as_table() : root["yld2004"].as_table();
  if (!y) {  // a yld2004 key of another type is named at its line (the file alone before 2026-12-05)
    const toml::node* n = root["material"]["yld2004"].node();
    const bool nested = n != nullptr;
    if (!n) n = root["yld2004"].node();
    if (n)
      throw InputError(path + ":" + std::to_string(n->source().begin.line) + (nested ? ": material.yld2004" : ": yld2004") +
                       ": expected a table { a, c1 = [9 numbers], c2 = [9 numbers] }, found " +
                       (n->is_array() ? "an array" : n->is_string() ? "a string" : "a " + std::string(n->is_boolean() ? "boolean" : "number")));
    throw InputError(path + ": expected yld2004 = { a, c1 = [9 numbers], c2 = [9 numbers] }, at the top or in [material]");
  }
  const std::string at = path + ":" + std::to_string(y->source().begin.line) + (in_material ? ": material.yld2004" : ": yld2004");
  material::Yld2004 out;
  out.a = (*y)["a"].value_or(std::numeric_limits<double>::quiet_NaN());  // a double default: NAN is a float
  for (const char* key : {"c1", "c2"}) {
    const auto* arr = (*y)[key].as_array();
    if (!arr || arr->size() != 9)
      throw InputError(at + "." + key + ": expected 9 numbers c12, c13, c21, c23, c31, c32, c44, c55, c66");
    for (std::size_t i = 0; i < 9; ++i) (key[1] == '1' ? out.c1 : out.c2)[i] =
          (*arr)[i].value_or(std::numeric_limits<double>::quiet_NaN());
  }
  try {
    out.validate();
  } catch (const std::invalid_argument& e) {
    throw InputError(at + ": " + e.what());
  }
  return out;
}

}  // namespace drawbend::io
