// The model loop's candidate catalogue (modelloop/model_loop.hpp,
// named_candidate): one row per kind of candidate, each with its syntax and a
// maker that turns the argument into members that edit a spec.
#include <cmath>
#include <cstdlib>

#include "core/csv.hpp"
#include "core/list_option.hpp"
#include "material/swift_fit.hpp"
#include "modelloop/material_edits.hpp"
#include "modelloop/model_loop.hpp"

namespace drawbend::modelloop {

namespace {

/// "a/b/c" as numbers, each member once (InputError naming the candidate for a bad one).
std::vector<double> values_of(const std::string& name, const std::string& a) {
  try {
    return list_numbers(a, "candidate '" + name + "'", '/');
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

using Maker = void (*)(ModelCandidate& c, const std::string& arg, const std::string& data_dir);

void make_split(ModelCandidate& c, const std::string& arg, const std::string&) {
  c.what = "split combined hardening (kinematic fraction beta fitted on the fit pin)";
  for (double b : values_of(c.name, arg)) {
    if (b < 0 || b > 1) throw InputError("candidate '" + c.name + "': beta must lie in [0, 1]");
    c.members.push_back({"split beta " + fmt(b), [b](DrawBendSpec& s) {
                           // replaces the model's material, and with it a Chaboche back stress; the flow
                           // curve is left unset: the spec's own table (s.hardening) when the deck is built
                           io::MaterialSpec m;
                           m.type = io::MaterialType::j2_combined;
                           m.curve.reset();
                           m.kinematic = io::KinematicSplit{b};
                           set_material(s, m);
                         }});
  }
}

/// Voce or Hill'48 from the published data.  Only the named part changes:
/// Voce replaces the flow curve (yield surface and back stress kept); Hill'48
/// replaces the yield surface (flow curve and back stress kept), so each
/// effect is judged alone.
void make_published(ModelCandidate& c, const std::string& kind, const std::string& data_dir) {
  const bool voce = kind == "voce";
  const std::string f =
      data_dir + (voce ? "/materials/aa5754_o_voce_hou2020.toml" : "/materials/aa5754_o_hill48_hou2020.toml");
  const io::MaterialSpec fm = material_file(f);
  if (voce) {
    c.what = "published Voce flow curve (Hou 2020) instead of the tabulated RD (Swift) curve";
    const auto* v = fm.curve ? std::get_if<io::CurveVoce>(&*fm.curve) : nullptr;
    if (!v) throw InputError(f + ": [material] has no 'voce'");
    const io::FlowCurve curve = *v;
    c.members.push_back({"Voce flow curve", [curve](DrawBendSpec& s) {
                           // Voce on a combined model is carved by its back stress (kept)
                           io::MaterialSpec m = material_of(s);
                           m.curve = carved_curve(m, curve);
                           set_material(s, m);
                         }});
    return;
  }
  c.what = "Hill'48 yield surface, published r-values (Hou 2020), on the same flow curve";
  if (fm.type != io::MaterialType::hill48) throw InputError(f + ": [material] has no 'hill48'");
  const io::YieldSurface surface = fm.surface;
  c.members.push_back({"Hill'48", [surface](DrawBendSpec& s) {
                         // hill48 on a combined model keeps its back stress (hill48 takes `kinematic`).
                         // On a Chaboche model the flow curve is the spec's own table (s.hardening)
                         // carved by the back stress, as before issue 49's typed edit: the current
                         // curve when the back stress was carved from that table.
                         io::MaterialSpec m = material_of(s);
                         m.type = io::MaterialType::hill48;
                         m.surface = surface;
                         if (has_back_stress(m)) m.curve = carved_curve(m, io::CurveFile{s.hardening});
                         set_material(s, m);
                       }});
}
void make_voce(ModelCandidate& c, const std::string&, const std::string& d) { make_published(c, "voce", d); }
void make_hill48(ModelCandidate& c, const std::string&, const std::string& d) { make_published(c, "hill48", d); }

/// The low-strain flow curve: Table 5.1's 0.2 % offset yield stress is the
/// flow stress at eps_p = 0.002.  Since issue 51 the shipped RD table takes
/// it there too (data/materials/aa5754_o_rd.csv, fit condition 1), so on the
/// isotropic model this candidate repeats the table's law as an analytic
/// curve (it differed from the table, which put the YS at eps_p = 0, before
/// then); with a back stress it carves the same law.  Same UTS and n.
void make_offset(ModelCandidate& c, const std::string&, const std::string& data_dir) {
  const std::string f = data_dir + "/thesis/table_5_1.csv";
  const CsvTable t51 = read_csv(f);
  const CsvRow* rd = nullptr;
  for (const auto& r : t51.rows)
    if (t51.text(r, "direction") == "RD") rd = &r;
  if (!rd) throw InputError(f + ": no RD row");
  const material::SwiftLaw law =
      material::fit_swift(t51.number(*rd, "YS02_MPa"), t51.number(*rd, "UTS_MPa"), t51.number(*rd, "n"),
                          material::table_5_1_yield_plastic_strain);
  c.what = "Swift refitted with Table 5.1's 0.2 % offset yield stress at eps_p = 0.002 (K " + fmt(law.K, 5) +
           " MPa, e0 " + fmt(law.eps0, 4) + ", n " + fmt(law.n) + "; initial yield " + fmt(law.stress(0), 4) +
           " MPa): the flow curve below 1 % strain";
  const io::FlowCurve curve = io::CurveSwift{law.K, law.eps0, law.n};
  c.members.push_back({"Swift at 0.2 % offset", [curve](DrawBendSpec& s) {
                         io::MaterialSpec m = material_of(s);
                         m.curve = carved_curve(m, curve);
                         set_material(s, m);
                       }});
}

/// One Armstrong-Frederick back stress carved out of the flow curve: early
/// re-yielding on unbending, which weighs most at small bending strain (large
/// R/t).  chaboche:X1/X2...[@G1/G2...]: every (X_sat, gamma) pair is a member,
/// chosen on the fit pin.  Without @ the rate is gamma = 300 (95 % saturated
/// at eps_p = 1 %), an assumption: no published AA5754-O reverse-loading data
/// (data/materials/README.md).  One point on the fit pin does not identify
/// both parameters: the chosen pair is one of many that fit it (Chapter 8's
/// beam trace shows how far they differ on the other pins).
void make_chaboche(ModelCandidate& c, const std::string& arg, const std::string&) {
  const auto at = arg.find('@');
  const std::vector<double> xs_list = values_of(c.name, arg.substr(0, at));
  const std::vector<double> g_list =
      at == std::string::npos ? std::vector<double>{300.0} : values_of(c.name, arg.substr(at + 1));
  c.what = at == std::string::npos
               ? "Chaboche back stress (gamma 300, X_sat fitted on the fit pin) carved out of the flow curve"
               : "Chaboche back stress (X_sat and gamma fitted on the fit pin) carved out of the flow curve";
  for (double g : g_list) {
    if (!(g > 0)) throw InputError("candidate '" + c.name + "': gamma must be > 0");
    for (double xs : xs_list) {
      if (!(xs > 0)) throw InputError("candidate '" + c.name + "': X_sat must be > 0 MPa");
      const std::string label = "Chaboche X_sat " + fmt(xs) + " MPa" + (at == std::string::npos ? "" : ", gamma " + fmt(g));
      c.members.push_back({label, [xs, g](DrawBendSpec& s) {
                             io::MaterialSpec m = material_of(s);
                             set_back_stress(m, xs, g);
                             set_material(s, m);
                           }});
    }
  }
}

void make_ms(ModelCandidate& c, const std::string& arg, const std::string&) {
  c.what = "mass scaling (numerical: should change nothing when converged)";
  for (double x : values_of(c.name, arg)) {
    if (x < 1) throw InputError("candidate '" + c.name + "': mass scaling must be >= 1");
    c.members.push_back({"mass scaling " + fmt(x), [x](DrawBendSpec& s) { s.mass_scaling = x; }});
  }
}

void make_across(ModelCandidate& c, const std::string& arg, const std::string&) {
  c.what = "elements across the half width (numerical)";
  for (double x : values_of(c.name, arg)) {
    if (x < 1 || x != std::floor(x)) throw InputError("candidate '" + c.name + "': across must be a positive integer");
    const int n = static_cast<int>(x);
    c.members.push_back({std::to_string(n) + " across", [n](DrawBendSpec& s) { s.across = n; }});
  }
}

struct CatalogueRow {
  const char* kind;
  const char* syntax;  ///< as the user writes it (the unknown-candidate message lists them)
  bool takes_values;   ///< kind:values (else the bare kind)
  Maker make;
};

// The catalogue.  A new candidate is one row and one maker.
const CatalogueRow kCatalogue[] = {
    {"split", "split:B1/B2...", true, make_split},
    {"chaboche", "chaboche:X1/X2...[@G1/G2...]", true, make_chaboche},
    {"voce", "voce", false, make_voce},
    {"hill48", "hill48", false, make_hill48},
    {"offset", "offset", false, make_offset},
    {"ms", "ms:X", true, make_ms},
    {"across", "across:N", true, make_across},
};

}  // namespace

ModelCandidate named_candidate(const std::string& name, const std::string& data_dir) {
  const auto colon = name.find(':');
  const std::string kind = name.substr(0, colon);
  const std::string arg = colon == std::string::npos ? "" : name.substr(colon + 1);
  for (const CatalogueRow& row : kCatalogue)
    if (kind == row.kind && (row.takes_values || arg.empty())) {
      ModelCandidate c;
      c.name = name;
      row.make(c, arg, data_dir);
      return c;
    }
  std::string syntax;
  for (const CatalogueRow& row : kCatalogue) syntax += std::string(syntax.empty() ? "" : ", ") + row.syntax;
  throw InputError("unknown candidate '" + name + "' (expected " + syntax + ")");
}

}  // namespace drawbend::modelloop
