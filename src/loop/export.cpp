// Friction-model export: the model file, the options, LS-DYNA and Abaqus; see
// export.hpp.  The OpenRadioss writer is export_radioss.cpp.
//
// Layouts followed (each file's header names its keyword):
//  * LS-DYNA Keyword User's Manual Vol. I: *CONTACT (card 1 SSID MSID SSTYP
//    MSTYP ..., card 2 FS FD DC VC VDC PENCHK BT DT, card 3 SFS SFM SST MST
//    SFST SFMT FSF VSF; 8 fields of 10 characters); FS = 2: FD is the ID of a
//    *DEFINE_TABLE giving mu from the contact pressure (the table's values) and
//    the relative sliding speed (each curve's abscissa), read by the
//    SURFACE_TO_SURFACE and ONE_WAY_SURFACE_TO_SURFACE contacts with the shell
//    thickness offset.  _ORTHO_FRICTION: four more cards right after card 3
//    (before the optional cards A-G): FS1_S FD1_S DC1_S VC1_S LC1_S OACS_S LCFS
//    LCPS (direction 1, SURFA = slave side), FS2_S FD2_S DC2_S VC2_S LC2_S
//    (direction 2), then the same two for SURFB (_M); LC1/LC2: a table giving mu
//    in that direction "as a function of the relative velocity and interface
//    pressure ... each curve in the table definition defines the coefficient of
//    friction versus the interface pressure corresponding to a particular value
//    of the relative velocity"; OACS (integer) = 0: directions of the segment
//    slid on, 1: directions of the sliding node; LCFS (mu against the angle of
//    sliding from direction 1; when given, FS, FD, DC, VC and LC are ignored) and
//    LCPS (a pressure scale on LCFS) left blank.  Sources: the card layout of
//    OpenRadioss's LS-DYNA reader, hm_cfg_files/config/CFG/Keyword971_R14.1/
//    CONTACT/OneWaySurfToSurf.cfg (commit bd4557b), and the field texts of the
//    Keyword User's Manual as carried by ansys/pydyna, keyword class
//    ContactFormingOneWaySurfaceToSurfaceOrthoFriction (auto/contact/
//    contact_forming_one_way_surface_to_surface_ortho_friction.py).
//    FS = 2, which variable the table's values are: CONFIRMED from the
//    manual's text as carried by ansys/pydyna (commit baa7279,
//    src/ansys/dyna/core/keywords/keyword_classes/auto/
//    contact_automatic_single_surface.py, card 2 common to *CONTACT): FS
//    "EQ.2: For a subset of SURFACE_TO_SURFACE type contacts, FD is a table ID
//    (see *DEFINE_TABLE). That table specifies two or more values of contact
//    pressure, with each pressure value in the table corresponding to a curve
//    of friction coefficient as a function of relative velocity", and FD
//    "FS.EQ.2: Table ID for table that specifies two or more values of contact
//    pressure, with each pressure value in the table corresponding to a curve
//    of friction coefficient as a function of relative velocity".  So values:
//    pressure, curves: mu against speed (written so).  The older text of the
//    same field (e.g. pydyna's ContactSurfaceToSurfaceThermalFriction) names
//    the contacts:
//    "For contact types SURFACE_TO_SURFACE and ONE_WAY_SURFACE_TO_SURFACE ...
//    This option must be used in combination with the thickness offset
//    option"; the shell thickness option is THKOPT/SHLTHK (SHLTHK = 1 or 2:
//    "Shell thickness considered in type surface to surface and node to
//    surface type contact options"), on the contact's optional card or in
//    *CONTROL_CONTACT.  Hence the isotropic card written is
//    *CONTACT_ONE_WAY_SURFACE_TO_SURFACE, a type the text names; not checked
//    in an LS-DYNA run here.
//    *DEFINE_TABLE:
//    card TBID SFA OFFA (10 characters each), then one value per line (20
//    characters); *DEFINE_CURVE: LCID SIDR SFA SFO OFFA OFFO DATTYP, then
//    abscissa and ordinate in 20-character fields.
//  * Abaqus Keywords Reference, *FRICTION: ANISOTROPIC with DEPENDENCIES = 0
//    data lines mu_1, mu_2, slip-rate, contact pressure (then temperature and
//    field variables); isotropic: mu, slip rate, contact pressure.  Outside the
//    tabulated range of an independent variable Abaqus holds the end value
//    (piecewise-linear, constant beyond the ends).  Anisotropic friction is an
//    Abaqus/Standard feature for this form; Abaqus/Explicit takes the isotropic
//    table (or a VFRIC/VFRICTION user subroutine, not written here).
#include "loop/export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

#include "core/file_gate.hpp"
#include "core/csv.hpp"
#include "core/list_option.hpp"
#include "core/input_problems.hpp"
#include "core/toml_read.hpp"
#include "io/deck_context.hpp"
#include "friction/surface_law.hpp"
#include "loop/export_detail.hpp"

namespace drawbend::loop {

namespace detail {

std::string num(double v, int prec) {
  char b[512];
  std::snprintf(b, sizeof b, "%.*g", prec, v);
  return b;
}

std::string field(double v, int width, int max_digits) {
  for (int prec = std::min(width - 1, max_digits); prec >= 1; --prec) {
    const std::string s = num(v, prec);
    if (static_cast<int>(s.size()) < width) return std::string(width - s.size(), ' ') + s;
  }
  throw std::runtime_error("number " + num(v, 6) + " does not fit in a field of " + std::to_string(width));
}

std::string ifield(long v, int width) {
  const std::string s = std::to_string(v);
  if (static_cast<int>(s.size()) > width) throw std::invalid_argument("ID " + s + " is wider than its field");
  return std::string(width - s.size(), ' ') + s;
}

double as_printed(double v, int width, int max_digits) { return std::stod(field(v, width, max_digits)); }

std::vector<double> grid(double a, double b, int n, int width) {
  std::vector<double> g(n);
  for (int k = 0; k < n; ++k) g[k] = as_printed(n > 1 ? a + (b - a) * k / (n - 1) : a, width, 8);
  g.front() = a;  // the domain's ends exactly (they are printed with all their digits below)
  g.back() = b;
  return g;
}

double bilinear(const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<std::vector<double>>& f,
                double x, double y) {
  auto locate = [](const std::vector<double>& g, double t, size_t& i, double& w) {
    t = std::clamp(t, g.front(), g.back());
    i = 0;
    while (i + 2 < g.size() && t > g[i + 1]) ++i;
    w = (t - g[i]) / (g[i + 1] - g[i]);
  };
  size_t i, j;
  double a, b;
  locate(xs, x, i, a);
  locate(ys, y, j, b);
  return (1 - a) * ((1 - b) * f[i][j] + b * f[i][j + 1]) + a * ((1 - b) * f[i + 1][j] + b * f[i + 1][j + 1]);
}

Table make_table_n(const analysis::FrictionSurface& s, int width, int n) {
  Table t;
  {
    t.ps = grid(s.p_min, s.p_max, n, width);
    t.vs = grid(s.v_min, s.v_max, n, width);
    t.mu.assign(n, std::vector<double>(n));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) t.mu[i][j] = as_printed(law_mu(s, t.ps[i], t.vs[j]), width, 8);
    t.max_error = 0;
    const int fine = 4 * (n - 1) + 1;
    for (int a = 0; a < fine; ++a)
      for (int b = 0; b < fine; ++b) {
        const double p = s.p_min + (s.p_max - s.p_min) * a / (fine - 1), v = s.v_min + (s.v_max - s.v_min) * b / (fine - 1);
        t.max_error = std::max(t.max_error, std::abs(bilinear(t.ps, t.vs, t.mu, p, v) - law_mu(s, p, v)));
      }
  }
  return t;
}

Table make_table(const analysis::FrictionSurface& s, int width, double tol) {
  Table t;
  for (int n = 11; n <= 201; n += 10)
    if ((t = make_table_n(s, width, n)).max_error <= tol) break;
  return t;
}

std::string range_text(const analysis::FrictionSurface& s) {
  return "p " + fmt_shortest(s.p_min) + " to " + fmt_shortest(s.p_max) + " MPa, v " + fmt_shortest(s.v_min) + " to " +
         fmt_shortest(s.v_max) + " mm/s";
}

std::string provenance(const ExportModel& m, const std::string& c, const std::string& direction) {
  std::ostringstream h;
  h << c << " friction model: " << m.source;
  if (!m.data.empty()) h << ", identified by `drawbend loop` from " << m.data;
  if (!m.lubricant.empty()) h << ", lubricant " << m.lubricant;
  h << "\n" << c << " units: N, mm, s, MPa (pressure MPa, sliding speed mm/s); declare them in your deck.\n"
    << c << " data range (the law's domain): " << range_text(m.rd) << ".\n"
    << c << " the law (drawbend's surface law): mu_RD(p, v), mu_TD(p, v) nine-node surfaces, p and v CLAMPED to\n"
    << c << "   that domain (the edge value outside it), mu >= 0.\n";
  if (m.td_copied && direction != "rd")
    h << c << " NOTE: the data had no TD rows: TD is a COPY of RD here, not a measurement.\n";
  if (m.rd_copied && direction != "td")
    h << c << " NOTE: the data had no RD rows: RD is a COPY of TD here, not a measurement.\n";
  return h.str();
}

}  // namespace detail

using namespace detail;

double law_mu(const analysis::FrictionSurface& s, double p, double v) {
  return std::max(0.0, s(std::clamp(p, s.p_min, s.p_max), std::clamp(v, s.v_min, s.v_max)));
}

analysis::FrictionSurface direction_surface(const ExportModel& m, const std::string& d) {
  if (d == "rd") return m.rd;
  if (d == "td") return m.td;
  if (d != "mean") throw std::invalid_argument("--direction must be rd, td, mean or ortho, not '" + d + "'");
  analysis::FrictionSurface s = m.rd;
  for (int k = 0; k < 9; ++k) s.mu[k] = 0.5 * (m.rd.mu[k] + m.td.mu[k]);
  return s;
}

void ExportOptions::validate(const std::string& format) const {
  auto bad = [](const std::string& opt, const std::string& what) { throw std::invalid_argument(opt + ": " + what); };
  if (direction != "rd" && direction != "td" && direction != "mean" && direction != "ortho")
    bad("--direction", "expected rd, td, mean or ortho, found '" + direction + "'");
  if (format == "openradioss" && (sheet_part <= 0 || tool_part <= 0))
    bad("--parts", "OpenRadioss needs the part IDs of the sheet and the tool (--parts SHEET,TOOL, positive integers): "
                   "its starter drops a pair with part ID 0 without a word");
  if (sheet_part < 0 || tool_part < 0 || sheet_part > 999999999 || tool_part > 999999999)
    bad("--parts", "expected part IDs from 1 to 999999999");
  if (sheet_part > 0 && sheet_part == tool_part) bad("--parts", "the sheet and the tool need different part IDs");
  if (friction_id < 1 || friction_id > 99999999) bad("--id", "expected an ID from 1 to 99999999, found " + std::to_string(friction_id));
  if (contact_id < 1 || contact_id > 9999999) bad("--id", "expected an ID from 1 to 9999999");
  const double n = std::hypot(rd_vector[0], rd_vector[1], rd_vector[2]);
  if (!(std::isfinite(n) && n > 1e-12 && n < 1e12)) bad("--rd-vector", "expected a finite non-zero vector X,Y,Z");
  if (!(std::isfinite(max_rel_error) && max_rel_error >= 0.001 && max_rel_error <= 0.5))
    bad("--max-rel-error", "expected a fraction from 0.001 to 0.5, found " + fmt_shortest(max_rel_error));
  if (!(std::isfinite(band_v_min) && std::isfinite(band_v_max) && band_v_min >= 0 && band_v_max < 1e7))
    bad("--speed-band", "expected finite speeds from 0 to 1e7 mm/s");
  if ((band_v_min != 0 || band_v_max != 0) && !(band_v_min < band_v_max))
    bad("--speed-band", "expected MIN < MAX, found " + fmt_shortest(band_v_min) + "," + fmt_shortest(band_v_max));
  if (abaqus_product != "standard" && abaqus_product != "explicit")
    bad("--abaqus", "expected standard or explicit, found '" + abaqus_product + "'");
}

namespace {
std::vector<double> numbers(const std::string& text, const std::string& opt, size_t n, bool integers) {
  const std::vector<double> v = list_numbers(text, opt, ',', false);  // empty items, spaces, NaN: named
  if (v.size() != n)
    throw std::invalid_argument(opt + ": expected " + std::to_string(n) + " values separated by commas, found '" + text + "'");
  for (double x : v)
    if (integers && x != std::floor(x))
      throw std::invalid_argument(opt + ": expected " + std::to_string(n) + " integers separated by commas, found '" + text + "'");
  return v;
}
}  // namespace

void set_list_options(ExportOptions& o, const std::string& parts, const std::string& rd_vector,
                      const std::string& speed_band) {
  if (!parts.empty()) {
    const auto v = numbers(parts, "--parts", 2, true);
    if (!(v[0] >= 1 && v[1] >= 1 && v[0] <= 999999999 && v[1] <= 999999999))
      throw std::invalid_argument("--parts: expected part IDs from 1 to 999999999, found '" + parts + "'");
    o.sheet_part = static_cast<int>(v[0]);
    o.tool_part = static_cast<int>(v[1]);
  }
  if (!rd_vector.empty()) {
    const auto v = numbers(rd_vector, "--rd-vector", 3, false);
    o.rd_vector = {v[0], v[1], v[2]};
  }
  if (!speed_band.empty()) {
    const auto v = numbers(speed_band, "--speed-band", 2, false);
    if (!(v[0] > 0 && v[0] < v[1] && v[1] < 1e7))
      throw std::invalid_argument("--speed-band: expected 0 < MIN < MAX < 1e7 mm/s, found '" + speed_band + "'");
    o.band_v_min = v[0];
    o.band_v_max = v[1];
  }
}

namespace {
// The domain a friction model may state: contact pressures up to 1e4 MPa (ten
// times the hardest tool steel's yield) and sliding speeds up to 1e4 mm/s (10
// m/s, above any press), the bounds of the builders' options (cli/option_bounds.hpp).
constexpr double kMaxPressureMPa = 1e4;
constexpr double kMaxSpeedMMs = 1e4;
constexpr double kMinSpeedMMs = 1e-3;         ///< 1 um/s, the builders' slowest speed option
constexpr double kMinPressureSpanMPa = 1e-3;  ///< 1 kPa, the builders' smallest pressure option
}  // namespace

ExportModel read_friction_model(const std::string& path) {
  // Every key read as the deck reader reads [contact.friction] (io/deck_context.hpp):
  // file:line: key messages, every problem of the file in one message, a wrong
  // type or an unknown key an error rather than a silent default.
  const toml::table t = parse_toml_file(path);
  InputProblems problems(path);
  const io::DeckContext c(path, problems);
  c.allowed(t, "friction_model", {"friction", "model"});
  const toml::table* f = nullptr;
  problems.attempt([&] { f = c.table(t, "friction", "friction_model", true); });
  if (!f) {
    problems.throw_if_any();
    throw InputError(path + ": no [friction] table (write it with `drawbend loop`)");
  }
  const std::string w = "friction";
  c.allowed(*f, w, {"law", "nodes", "interval", "p_min", "p_max", "v_min", "v_max"});
  const std::string law = c.str(*f, "law", w);
  if (f->get("law") && law != "surface" && c.count() == 0)
    c.bad(*f->get("law"), w + ".law", "expected \"surface\" (the nine-node surface) for export, found \"" + law + "\"");
  c.count_of(*f, "interval", w, 100, 1);
  friction::SurfaceDomain d;
  d.p_min = c.num(*f, "p_min", w, d.p_min);
  d.p_max = c.num(*f, "p_max", w, d.p_max);
  d.v_min = c.num(*f, "v_min", w, d.v_min);
  d.v_max = c.num(*f, "v_max", w, d.v_max);
  const bool read = !std::isnan(d.p_min + d.p_max + d.v_min + d.v_max);  // else the value's problem is recorded
  if (read && !(d.p_min >= 0 && d.p_min < d.p_max && d.p_max <= kMaxPressureMPa))
    c.bad(*f, w, "expected 0 <= p_min < p_max <= " + fmt_shortest(kMaxPressureMPa) + " [MPa], found " +
                     fmt_shortest(d.p_min) + " and " + fmt_shortest(d.p_max));
  if (read && !(d.v_min > 0 && d.v_min < d.v_max && d.v_max <= kMaxSpeedMMs))
    c.bad(*f, w, "expected 0 < v_min < v_max <= " + fmt_shortest(kMaxSpeedMMs) + " [mm/s], found " +
                     fmt_shortest(d.v_min) + " and " + fmt_shortest(d.v_max));
  // A domain narrower than any test measures (v_max 1e-299 mm/s was written to LS-DYNA and
  // Abaqus with exit 0, and OpenRadioss's fit ended in "inf %", 2026-12-04): the speeds from
  // 1 um/s, the pressures over at least 1 kPa, as the builders' options (cli/option_bounds.hpp).
  if (read && d.v_min > 0 && d.v_min < d.v_max && d.v_min < kMinSpeedMMs)
    c.bad(*f->get("v_min"), w + ".v_min", "expected a sliding speed of at least " + fmt_shortest(kMinSpeedMMs) +
                                              " mm/s (1 um/s; a unit error?), found " + fmt_shortest(d.v_min));
  if (read && d.p_min >= 0 && d.p_min < d.p_max && d.p_max - d.p_min < kMinPressureSpanMPa)
    c.bad(*f, w, "expected p_max - p_min of at least " + fmt_shortest(kMinPressureSpanMPa) + " MPa (1 kPa), found " +
                     fmt_shortest(d.p_min) + " and " + fmt_shortest(d.p_max));
  const std::string nodes = c.str(*f, "nodes", w);
  ExportModel m;
  if (const auto* mt = c.table(t, "model", "model", false)) {
    c.allowed(*mt, "model", {"data", "lubricant", "td_copied_from_rd", "rd_copied_from_td"});
    m.data = c.str(*mt, "data", "model", std::string());
    m.lubricant = c.str(*mt, "lubricant", "model", std::string());
    m.td_copied = c.boolean(*mt, "td_copied_from_rd", "model", false);
    m.rd_copied = c.boolean(*mt, "rd_copied_from_td", "model", false);
    // Each direction a copy of the other: no direction measured (exported as "TD copied from RD", exit 0, before 2026-12-05).
    if (m.td_copied && m.rd_copied)
      c.bad(*mt->get("rd_copied_from_td"), "model.rd_copied_from_td",
            "td_copied_from_rd and rd_copied_from_td are both true: one direction must be measured");
  }
  problems.throw_if_any();
  if (nodes.empty()) c.fail(*f->get("nodes"), w + ".nodes", "expected the name of the nodes CSV, found an empty string");
  const std::filesystem::path file = std::filesystem::path(path).parent_path() / nodes;
  const std::string key = c.where(*f->get("nodes"), w + ".nodes");
  name_input(file.string(), key);  // read through the file gate (core/file_gate.hpp)
  try {
    std::tie(m.rd, m.td) = friction::load_surface_nodes(file.string(), d);
    m.rd.validate();
    m.td.validate();
  } catch (const std::invalid_argument& e) {
    throw InputError(key + ": " + e.what());
  } catch (const InputError& e) {  // the CSV's own problems (ragged rows, a header), with the model's line that names it
    throw InputError(key + ": " + e.what());
  }
  // Legal but suspicious: a lubricated sheet slides at mu ~ 0.02 to 0.3, dry
  // metal on metal rarely above 1; a coefficient above 1 is a typing error
  // more often than a measurement, so the export says so (once per direction).
  for (const auto& [dir, s] : {std::pair{"mu_RD", &m.rd}, std::pair{"mu_TD", &m.td}})
    for (std::size_t k = 0; k < s->mu.size(); ++k)
      if (s->mu[k] > 1) {
        std::cerr << "warning: " << file.string() << ": column '" << dir << "': node " << k + 1 << " has mu = "
                  << fmt_shortest(s->mu[k]) << ", above 1 (lubricated sheet metal: 0.02 to 0.3); exported as given\n";
        break;
      }
  m.source = path;
  if (!t.get("model")) m.td_copied = m.rd.mu == m.td.mu;  // no [model] table: identical directions, TD taken as the copy
  return m;
}

namespace {

// The LS-DYNA *DEFINE_TABLEs of an export, written one after the other: table
// IDs base+1.., curve IDs base+101.., and the largest |mu - law| of their grids.
struct LsdynaTables {
  explicit LsdynaTables(int base_id) : base(base_id), curve(base_id + 101) {}
  int base, curve;
  std::vector<int> ids;
  double max_error = 0;
  std::ostringstream body;

  // Flat ends: the first and last rows/columns repeated at 0 and 10x the
  // domain's upper end, so that any interpolation or extrapolation rule gives
  // the clamped law up to there (stated in the header).
  static std::vector<double> extend(std::vector<double> g, double hi) {
    if (g.front() > 0) g.insert(g.begin(), 0.0);
    g.push_back(hi);
    return g;
  }
  void write(const analysis::FrictionSurface& s, bool values_are_pressure, const std::string& what) {
    const Table t = make_table(s, 20, 2e-5);
    max_error = std::max(max_error, t.max_error);
    const auto ps = extend(t.ps, 10 * s.p_max), vs = extend(t.vs, 10 * s.v_max);
    const int id = base + 1 + static_cast<int>(ids.size());
    ids.push_back(id);
    const auto& outer = values_are_pressure ? ps : vs;
    const auto& inner = values_are_pressure ? vs : ps;
    body << "$ table " << id << ": " << what << "; values = "
         << (values_are_pressure ? "contact pressure [MPa], curves = mu against sliding speed [mm/s]"
                                 : "sliding speed [mm/s], curves = mu against contact pressure [MPa]")
         << "\n*DEFINE_TABLE\n$     TBID\n" << ifield(id, 10) << "\n";
    for (double x : outer) body << field(x, 20) << "\n";
    for (double x : outer) {
      body << "*DEFINE_CURVE\n$     LCID      SIDR       SFA       SFO\n" << ifield(curve++, 10) << ifield(0, 10)
           << field(1, 10) << field(1, 10) << "\n$                 A1                  O1\n";
      for (double y : inner) {
        const double p = values_are_pressure ? x : y, v = values_are_pressure ? y : x;
        body << field(y, 20) << field(law_mu(s, p, v), 20, 8) << "\n";
      }
    }
  }
};

// The isotropic contact: *CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID with FS = 2
// and FD = the table; `ids` is card 1's SSID MSID SSTYP MSTYP.
void lsdyna_isotropic_contact(std::ostream& h, const ExportOptions& o, int table, const std::string& ids) {
  h << "$ isotropic, direction " << o.direction << " (--direction rd|td|mean; ortho for the orthotropic form).\n"
    << "$ FS = 2, FD = table " << table << ": the manual's FS field, \"FD is a table ID (see *DEFINE_TABLE). That\n"
    << "$ table specifies two or more values of contact pressure, with each pressure value in the table\n"
    << "$ corresponding to a curve of friction coefficient as a function of relative velocity\", for\n"
    << "$ *CONTACT_SURFACE_TO_SURFACE and *CONTACT_ONE_WAY_SURFACE_TO_SURFACE \"in combination with the\n"
    << "$ thickness offset option\"; other contact types do not read the table.  Not run in LS-DYNA here.\n"
    << "$ SSID/MSID = sheet/tool part IDs (--parts, SSTYP = MSTYP = 3).\n"
    << "$ SET BY HAND: the shell thickness offset (SHLTHK = 1 or 2: THKOPT = 1 on the contact's optional card D,\n"
    << "$   or *CONTROL_CONTACT SHLTHK); the deck's units N, mm, s.\n"
    << "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID\n$      CID\n" << ifield(o.contact_id, 10) << "\n"
    << "$     SSID      MSID     SSTYP     MSTYP    SBOXID    MBOXID       SPR       MPR\n" << ids << "\n"
    << "$       FS        FD        DC        VC       VDC    PENCHK        BT        DT\n"
    << field(2, 10) << ifield(table, 10) << field(0, 10) << field(0, 10) << field(0, 10) << "\n"
    << "$      SFS       SFM       SST       MST      SFST      SFMT       FSF       VSF\n"
    << field(1, 10) << field(1, 10) << "\n";
}

// The orthotropic contact: *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ORTHO_FRICTION_ID
// with LC1 = table rd (RD) and LC2 = table td (TD) on both sides.
void lsdyna_ortho_contact(std::ostream& h, const ExportOptions& o, int rd, int td, const std::string& ids) {
  h << "$ orthotropic: *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ORTHO_FRICTION, LC1 = table " << rd
    << " (RD), LC2 = table " << td << " (TD),\n"
    << "$ on the slave (sheet, SURFA) side.  OACS_S = 1: the directions are those of the sliding node, i.e.\n"
    << "$ the sheet's (0 would take the directions of the tool segment slid on): set the sheet elements'\n"
    << "$ material axes with direction 1 along RD.  LCFS/LCPS blank (an LCFS curve would replace LC1/LC2).\n"
    << "$ FS/FD of card 2 are not used for the sheet.  The SURFB cards (FS1_M ...) repeat the tables; a\n"
    << "$ one-way contact checks only SURFA nodes.  Not run in LS-DYNA here: check on a block slide first.\n"
    << "$ SET BY HAND: the sheet elements' material axes (direction 1 = RD); the deck's units N, mm, s.\n"
    << "*CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ORTHO_FRICTION_ID\n$      CID\n" << ifield(o.contact_id, 10)
    << "\n$     SSID      MSID     SSTYP     MSTYP    SBOXID    MBOXID       SPR       MPR\n" << ids << "\n"
    << "$       FS        FD        DC        VC       VDC    PENCHK        BT        DT\n"
    << field(0, 10) << field(0, 10) << "\n"
    << "$      SFS       SFM       SST       MST      SFST      SFMT       FSF       VSF\n"
    << field(1, 10) << field(1, 10) << "\n"
    << "$    FS1_S     FD1_S     DC1_S     VC1_S     LC1_S    OACS_S      LCFS      LCPS\n"
    << field(0, 10) << field(0, 10) << field(0, 10) << field(0, 10) << ifield(rd, 10) << ifield(1, 10) << "\n"
    << "$    FS2_S     FD2_S     DC2_S     VC2_S     LC2_S\n"
    << field(0, 10) << field(0, 10) << field(0, 10) << field(0, 10) << ifield(td, 10) << "\n"
    << "$    FS1_M     FD1_M     DC1_M     VC1_M     LC1_M    OACS_M      LCFM      LCPM\n"
    << field(0, 10) << field(0, 10) << field(0, 10) << field(0, 10) << ifield(rd, 10) << ifield(1, 10) << "\n"
    << "$    FS2_M     FD2_M     DC2_M     VC2_M     LC2_M\n"
    << field(0, 10) << field(0, 10) << field(0, 10) << field(0, 10) << ifield(td, 10) << "\n";
}

}  // namespace

ExportResult export_lsdyna(const ExportModel& m, const ExportOptions& o) {
  o.validate("lsdyna");
  ExportResult r;
  r.format = "lsdyna";
  const bool ortho = o.direction == "ortho";
  LsdynaTables tables(o.contact_id * 1000);
  if (ortho) {
    tables.write(m.rd, false, "LC1, mu along direction 1 (RD)");
    tables.write(m.td, false, std::string("LC2, mu along direction 2 (TD)") + (m.td_copied ? ", COPIED from RD (no TD data)" : ""));
  } else {
    tables.write(direction_surface(m, o.direction), true,
                 "mu(p, v) for FS = 2, direction " + o.direction + (m.td_copied && o.direction != "rd" ? " (TD copied from RD)" : ""));
  }
  r.max_error = std::max(r.max_error, tables.max_error);
  std::ostringstream h;
  h << "*KEYWORD\n$ drawbend export to LS-DYNA (keyword format, 10-character fields; tables 20-character)\n"
    << provenance(m, "$", o.direction)
    << "$ tables: mu at the printed grid points, linear between them; max |mu - law| over the domain "
    << num(r.max_error, 3) << ".\n"
    << "$ outside the domain the tables hold the edge values (flat end points at p = 0 and 10 p_max, v = 0 and\n"
    << "$ 10 v_max) = the law's clamp; beyond 10 p_max or 10 v_max LS-DYNA's own end rule applies.\n";
  const std::string ids = ifield(o.sheet_part, 10) + ifield(o.tool_part, 10) + ifield(3, 10) + ifield(3, 10);
  if (!ortho) lsdyna_isotropic_contact(h, o, tables.ids[0], ids);
  else lsdyna_ortho_contact(h, o, tables.ids[0], tables.ids[1], ids);
  if (o.sheet_part == 0 || o.tool_part == 0)
    h << "$ SET BY HAND: SSID and MSID are 0 (no --parts given): put your sheet and tool part IDs.\n";
  else if (o.parts_placeholder)
    h << "$ SET BY HAND: SSID " << o.sheet_part << " and MSID " << o.tool_part
      << " are drawbend loop's PLACEHOLDERS: put your sheet and tool part IDs\n$   (or drawbend export --parts SHEET,TOOL).\n";
  r.text = h.str() + tables.body.str() + "*END\n";
  return r;
}

ExportResult export_abaqus(const ExportModel& m, const ExportOptions& o) {
  o.validate("abaqus");
  ExportResult r;
  r.format = "abaqus";
  const bool explicit_ = o.abaqus_product == "explicit";
  std::string dir = o.direction;
  if (!explicit_) dir = "ortho";
  else if (dir == "ortho") throw std::invalid_argument("--direction: Abaqus/Explicit takes an isotropic table here (rd, td or mean)");
  std::ostringstream h, b;
  h << "** drawbend export to Abaqus/" << (explicit_ ? "Explicit" : "Standard") << " (--abaqus standard|explicit)\n"
    << provenance(m, "**", dir);
  if (!explicit_) {
    // one grid for both columns: the finer of the two directions' grids
    const int n = static_cast<int>(std::max(make_table(m.rd, 20, 2e-5).ps.size(), make_table(m.td, 20, 2e-5).ps.size()));
    const Table trd = make_table_n(m.rd, 20, n), ttd = make_table_n(m.td, 20, n);
    const Table& g = trd;
    for (size_t i = 0; i < g.ps.size(); ++i)
      for (size_t j = 0; j < g.vs.size(); ++j) {
        const double mu1 = as_printed(law_mu(m.rd, g.ps[i], g.vs[j]), 20, 8);
        const double mu2 = as_printed(law_mu(m.td, g.ps[i], g.vs[j]), 20, 8);
        b << num(mu1, 8) << ", " << num(mu2, 8) << ", " << num(g.vs[j], 10) << ", " << num(g.ps[i], 10) << "\n";
      }
    r.max_error = std::max(trd.max_error, ttd.max_error);
    h << "** *FRICTION, ANISOTROPIC (Abaqus/Standard): data lines mu_1 (along the first local slip direction =\n"
      << "**   RD), mu_2 (TD), slip rate [mm/s], contact pressure [MPa]; " << g.ps.size() << " pressures x "
      << g.vs.size() << " slip rates.\n"
      << "** linear between points, the end value beyond the table (= the law's clamp); max |mu - law| "
      << num(r.max_error, 3) << ".\n"
      << "** SET BY HAND: put it under your *SURFACE INTERACTION and orient the contact's first local\n"
      << "**   direction along RD (*ORIENTATION on the slave surface).  Abaqus/Explicit: --abaqus explicit.\n"
      << "*FRICTION, ANISOTROPIC\n";
  } else {
    const auto s = direction_surface(m, dir);
    const Table t = make_table(s, 20, 2e-5);
    r.max_error = t.max_error;
    for (size_t i = 0; i < t.ps.size(); ++i)
      for (size_t j = 0; j < t.vs.size(); ++j)
        b << num(t.mu[i][j], 8) << ", " << num(t.vs[j], 10) << ", " << num(t.ps[i], 10) << "\n";
    h << "** *FRICTION isotropic, direction " << dir << " (--direction rd|td|mean): data lines mu, slip rate [mm/s],\n"
      << "**   contact pressure [MPa]; " << t.ps.size() << " pressures x " << t.vs.size() << " slip rates.\n"
      << "** linear between points, the end value beyond the table (= the law's clamp); max |mu - law| "
      << num(r.max_error, 3) << ".\n"
      << "** Anisotropic friction in Abaqus/Explicit needs a VFRIC/VFRICTION user subroutine (not written).\n"
      << "** SET BY HAND: put it under your *SURFACE INTERACTION.\n"
      << "*FRICTION\n";
  }
  r.text = h.str() + b.str();
  return r;
}

ExportResult export_to(const std::string& format, const ExportModel& m, const ExportOptions& o) {
  if (format == "lsdyna") return export_lsdyna(m, o);
  if (format == "openradioss") return export_openradioss(m, o);
  if (format == "abaqus") return export_abaqus(m, o);
  throw std::invalid_argument("--to: expected lsdyna, openradioss or abaqus, found '" + format + "'");
}

std::string export_path(const std::string& toml_path, const std::string& format) {
  const std::filesystem::path p(toml_path);
  std::string stem = p.stem().string();
  const std::string head = "friction_model";
  const std::string rest = stem.rfind(head, 0) == 0 ? stem.substr(head.size()) : "_" + stem;
  const std::string ext = format == "lsdyna" ? ".k" : format == "openradioss" ? ".rad" : ".inp";
  return (p.parent_path() / ("friction_" + format + rest + ext)).string();
}

std::string write_exports(const std::vector<std::string>& tomls, const std::string& formats, const ExportOptions& o) {
  std::vector<std::string> list;
  if (formats != "none") {
    for (const std::string& f : list_items(formats, "--export")) {
      if (f != "lsdyna" && f != "openradioss" && f != "abaqus")
        throw std::invalid_argument("--export: expected none or a list of lsdyna, openradioss, abaqus; found '" + f + "'");
      list.push_back(f);
    }
  }
  std::ostringstream md;
  md << "\n## Exports to other solvers\n\n";
  if (list.empty()) return md.str() + "None written (--export none); `drawbend export` writes them later.\n";
  md << "Written with `drawbend export` defaults (direction " << o.direction << ", parts " << o.sheet_part << ","
     << o.tool_part << (o.parts_placeholder ? ", PLACEHOLDERS: no --parts given" : "")
     << ": set yours with `drawbend export FILE.toml --to FORMAT --parts SHEET,TOOL`). Each file's "
        "header states the data range, the behaviour outside it, its error against the law and what you must "
        "still set by hand (`SET BY HAND`).\n\n"
     << "| model | file | error against the law |\n|---|---|---|\n";
  for (const auto& t : tomls) {
    const std::string name = std::filesystem::path(t).filename().string();
    ExportModel m;
    try {
      m = read_friction_model(t);
    } catch (const std::exception& e) {  // a model the exports cannot take: said, the loop's other outputs stand
      std::cerr << "warning: no exports of " << name << ": " << e.what() << "\n";
      md << "| `" << name << "` | none written | " << e.what() << " |\n";
      continue;
    }
    for (const auto& f : list) {
      ExportResult r;
      try {
        r = export_to(f, m, o);
      } catch (const std::exception& e) {  // e.g. the polynomial cannot meet its bound: said, nothing written
        std::cerr << "warning: no " << f << " export of " << name << ": " << e.what() << "\n";
        md << "| `" << name << "` | not written (" << f << ") | " << e.what() << " |\n";
        continue;
      }
      const std::string out = export_path(t, f);
      write_file_atomic(out, r.text);
      md << "| `" << name << "` | `" << std::filesystem::path(out).filename().string() << "` | "
         << (f == "openradioss" ? "max relative " + fmt(100 * r.max_error, 3) + " % (" + std::to_string(r.bands) + " speed band(s))"
                                : "max abs(mu - law) " + fmt(r.max_error, 3))
         << (m.td_copied ? "; TD copied from RD (no TD data)" : "") << (m.rd_copied ? "; RD copied from TD (no RD data)" : "")
         << " |\n";
    }
  }
  return md.str();
}

}  // namespace drawbend::loop
