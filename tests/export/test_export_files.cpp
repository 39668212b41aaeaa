// The friction-model exports read back by independent readers (readers.hpp,
// written from each target's documented layout, no code shared with the
// writer) and compared with the law of friction_model.toml as drawbend's
// solver evaluates it (friction::SurfaceLaw: nine-node surfaces, p and v
// clamped to the domain, mu >= 0).
//
// Usage: test_export_files -- DIR SHEET TOOL, DIR the output of
//   drawbend loop ... --out DIR --parts SHEET,TOOL   (its default exports).
//
// Expected answers, fixed before the run:
//  * tables (LS-DYNA FS = 2 and ORTHO_FRICTION, Abaqus Standard and Explicit):
//    |mu_file - mu_law| <= 1e-4 at 400 random (p, v) per direction, half inside
//    the domain and half outside it up to 10 p_max, 10 v_max (the law holds the
//    edge value there; 1e-4: the bound for tables; the writer aims at 2e-5);
//  * OpenRadioss polynomial: inside the fitted range relative error <= the
//    error the file states + 1e-4 (the statement is the max on a 161 x 161 grid
//    per band, rounded up to 0.001 %; between grid points a smooth quadratic's
//    error can exceed it by O(h^2), far below 1e-4); outside, |error| <= the
//    stated outside error on the stated box;
//  * layout: Ifric 1, Iform 2, the pair's part IDs = SHEET, TOOL, Idir 0 (1 for
//    --direction ortho), /FRIC_ORIENT on SHEET along (1, 0, 0); LS-DYNA FS = 2
//    with FD a table, no "FS = -2"; Abaqus ANISOTROPIC for Standard;
//  * a model without TD data says "COPY" in every file that carries TD;
//  * round trip through our solver: the block of Chapter 6 sliding on a floor
//    whose nine-node surface is sampled from each READER's mu at the nine nodes
//    gives F_T/F_N within 1 % of the law at three (p, v) along RD (and one along
//    TD through Abaqus): 1 %, the Chapter 6 block's own agreement with its input
//    (steady sliding, explicit dynamics, penalty contact).  For OpenRadioss the
//    bound against the law is 1 % + the file's stated fit error, and 1 %
//    against the polynomial itself.
#define BOOST_TEST_MODULE export_files
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <regex>

#include "friction/surface_law.hpp"
#include "loop/export.hpp"
#include "readers.hpp"
#include "sim/block_case.hpp"

namespace fs = std::filesystem;
using namespace drawbend;
namespace er = export_readers;

namespace {

struct Args {
  std::string dir;
  int sheet = 0, tool = 0;
};
Args args() {
  auto& m = boost::unit_test::framework::master_test_suite();
  if (m.argc < 4) throw std::runtime_error("usage: test_export_files -- DIR SHEET TOOL");
  return {m.argv[1], std::stoi(m.argv[2]), std::stoi(m.argv[3])};
}

// The law of a friction_model.toml, read as a deck's [friction] table.
struct Model {
  std::string toml, suffix;
  friction::SurfaceDomain d;
  std::unique_ptr<friction::SurfaceLaw> law;
  double mu(int dir, double p, double v) const { return dir == 1 ? law->at(p, v).mu1 : law->at(p, v).mu2; }
};
Model load_model(const std::string& toml) {
  Model m;
  m.toml = toml;
  const std::string stem = fs::path(toml).stem().string();
  m.suffix = stem.substr(std::string("friction_model").size());
  std::ifstream f(toml);
  std::string nodes, section;
  for (std::string l; std::getline(f, l);) {
    if (l.rfind("[", 0) == 0) section = l;
    if (section != "[friction]") continue;
    const auto eq = l.find(" = ");
    if (eq == std::string::npos) continue;
    const std::string k = l.substr(0, eq), v = l.substr(eq + 3);
    if (k == "nodes") nodes = v.substr(1, v.size() - 2);
    if (k == "p_min") m.d.p_min = std::stod(v);
    if (k == "p_max") m.d.p_max = std::stod(v);
    if (k == "v_min") m.d.v_min = std::stod(v);
    if (k == "v_max") m.d.v_max = std::stod(v);
  }
  const auto [rd, td] = friction::load_surface_nodes((fs::path(toml).parent_path() / nodes).string(), m.d);
  m.law = std::make_unique<friction::SurfaceLaw>(rd, td, 1);
  return m;
}

std::vector<Model> models() {
  std::vector<Model> v;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(args().dir)) {
    const std::string n = e.path().filename().string();
    if (n.rfind("friction_model", 0) == 0 && e.path().extension() == ".toml") names.push_back(e.path().string());
  }
  std::sort(names.begin(), names.end());
  for (const auto& n : names) v.push_back(load_model(n));
  BOOST_REQUIRE(!v.empty());
  return v;
}

// 2n points: n inside the domain, n outside it (up to fp x p_max, fv x v_max).
std::vector<std::pair<double, double>> points(const friction::SurfaceDomain& d, int n, double fp, double fv,
                                              unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<double, double>> pts;
  for (int k = 0; k < n; ++k) pts.push_back({d.p_min + (d.p_max - d.p_min) * u(g), d.v_min + (d.v_max - d.v_min) * u(g)});
  while (static_cast<int>(pts.size()) < 2 * n) {
    const double p = fp * d.p_max * u(g), v = fv * d.v_max * u(g);
    if (p < d.p_min || p > d.p_max || v < d.v_min || v > d.v_max) pts.push_back({p, v});
  }
  return pts;
}

bool any_comment(const std::vector<std::string>& c, const std::string& s) {
  for (const auto& l : c)
    if (l.find(s) != std::string::npos) return true;
  return false;
}

// The numbers an OpenRadioss file states in its header.
struct RadStated {
  double rel = -1, outside = -1, p_box = 0, v_box = 0;
  std::vector<std::tuple<int, double, double>> bands;  // friction ID, v from, v to
  std::string direction;
};
RadStated rad_stated(const er::RadFile& f) {
  RadStated s;
  std::smatch m;
  for (const auto& l : f.comments) {
    if (std::regex_search(l, m, std::regex("max relative error inside the fitted range: ([0-9.eE+-]+) %")))
      s.rel = std::stod(m[1]) / 100;
    if (std::regex_search(l, m, std::regex("over p 0 to ([0-9.eE+-]+) MPa, v 0 to ([0-9.eE+-]+) mm/s: ([0-9.eE+-]+)")))
      s.p_box = std::stod(m[1]), s.v_box = std::stod(m[2]), s.outside = std::stod(m[3]);
    if (std::regex_search(l, m, std::regex("# band [0-9]+: /FRICTION/([0-9]+) for v ([0-9.eE+-]+) to ([0-9.eE+-]+) mm/s")))
      s.bands.push_back({std::stoi(m[1]), std::stod(m[2]), std::stod(m[3])});
    if (std::regex_search(l, m, std::regex("isotropic pair law for (rd|td|mean)"))) s.direction = m[1];
    if (l.find("Idir = 1 (direction 1 = RD") != std::string::npos) s.direction = "ortho";
  }
  BOOST_REQUIRE(s.rel >= 0 && s.outside >= 0 && !s.bands.empty() && !s.direction.empty());
  return s;
}
// mu of the pair law as OpenRadioss evaluates it, in the band that holds v.
double rad_mu(const er::RadFile& f, const RadStated& s, int dir, double p, double v) {
  size_t k = 0;
  while (k + 1 < s.bands.size() && v > std::get<2>(s.bands[k])) ++k;
  for (const auto& fr : f.frictions)
    if (fr.id == std::get<0>(s.bands[k])) return (dir == 2 && fr.pairs[0].idir == 1 ? fr.pairs[0].dir2 : fr.pairs[0].dir1).mu(p, v);
  throw std::runtime_error("band's /FRICTION not found");
}

double law_dir(const Model& m, const std::string& direction, int dir, double p, double v) {
  if (direction == "td") return m.mu(2, p, v);
  if (direction == "mean") {
    // the mean of the two surfaces, clamped like the law (mean of nodes = mean of surfaces)
    return std::max(0.0, 0.5 * (m.law->rd()(std::clamp(p, m.d.p_min, m.d.p_max), std::clamp(v, m.d.v_min, m.d.v_max)) +
                                m.law->td()(std::clamp(p, m.d.p_min, m.d.p_max), std::clamp(v, m.d.v_min, m.d.v_max))));
  }
  return m.mu(direction == "ortho" ? dir : 1, p, v);
}

void check_openradioss(const Model& m, const std::string& file, int sheet, int tool) {
  const er::RadFile f = er::read_openradioss(file);
  const RadStated s = rad_stated(f);
  BOOST_TEST_MESSAGE(file << ": " << f.frictions.size() << " /FRICTION, stated relative error " << s.rel
                          << ", outside " << s.outside << ", direction " << s.direction);
  BOOST_REQUIRE_EQUAL(f.frictions.size(), s.bands.size());
  for (const auto& fr : f.frictions) {
    const auto& pr = fr.pairs.empty() ? er::RadPair() : fr.pairs[0];
    BOOST_TEST_MESSAGE("  read: /FRICTION/" << fr.id << " Ifric " << fr.ifric << " Ifiltr " << fr.ifiltr << " Xfreq " << fr.xfreq
                       << " Iform " << fr.iform << "; pair parts " << pr.part1 << "," << pr.part2 << " Idir " << pr.idir
                       << ": Fric " << pr.dir1.fric << " C1.." << "C5 " << pr.dir1.c[0] << " " << pr.dir1.c[1] << " "
                       << pr.dir1.c[2] << " " << pr.dir1.c[3] << " " << pr.dir1.c[4] << " VIS_F " << pr.dir1.visf);
    BOOST_TEST(fr.ifric == 1);
    BOOST_TEST(fr.iform == 2);
    BOOST_REQUIRE_EQUAL(fr.pairs.size(), 1u);
    BOOST_TEST(fr.pairs[0].part1 == sheet);
    BOOST_TEST(fr.pairs[0].part2 == tool);
    BOOST_TEST(fr.pairs[0].idir == (s.direction == "ortho" ? 1 : 0));
  }
  BOOST_REQUIRE_EQUAL(f.orients.size(), 1u);
  BOOST_TEST_MESSAGE("  read: /FRIC_ORIENT/" << f.orients[0].id << " part " << f.orients[0].part << " V " << f.orients[0].vx
                     << "," << f.orients[0].vy << "," << f.orients[0].vz << " skew " << f.orients[0].skew << " phi "
                     << f.orients[0].phi << " Iorth " << f.orients[0].iorth);
  BOOST_TEST(f.orients[0].part == sheet);
  BOOST_TEST(f.orients[0].vx == 1.0);
  BOOST_TEST(s.rel < 0.05);
  const bool copied = any_comment(f.comments, "COPY");
  const double v_lo = std::get<1>(s.bands.front()), v_hi = std::get<2>(s.bands.back());
  double worst_in = 0, worst_out = 0;
  for (int dir : {1, 2}) {
    if (dir == 2 && s.direction != "ortho") break;
    for (const auto& [p, v] : points(m.d, 200, s.p_box / m.d.p_max, s.v_box / m.d.v_max, 7 + dir)) {
      const double law = law_dir(m, s.direction, dir, p, v), mu = rad_mu(f, s, dir, p, v);
      const bool inside = p >= m.d.p_min && p <= m.d.p_max && v >= v_lo && v <= v_hi;
      if (inside) worst_in = std::max(worst_in, std::abs(mu - law) / std::max(law, 1e-4));
      else worst_out = std::max(worst_out, std::abs(mu - law));
    }
  }
  BOOST_TEST_MESSAGE("  read back: max relative error inside " << worst_in << ", max |error| outside " << worst_out);
  BOOST_TEST(worst_in <= s.rel + 1e-4);
  BOOST_TEST(worst_out <= s.outside + 1e-9);
  (void)copied;
}

void check_lsdyna(const Model& m, const std::string& file, const std::string& direction) {
  const er::DynaFile f = er::read_lsdyna(file);
  BOOST_TEST(f.keyword);
  BOOST_TEST(f.end);
  BOOST_REQUIRE_EQUAL(f.contacts.size(), 1u);
  BOOST_TEST(!any_comment(f.comments, "FS = -2"));
  const auto& c = f.contacts[0];
  double worst = 0, worst_in = 0, worst_out = 0;
  auto note = [&](double p, double v, double err) {
    worst = std::max(worst, err);
    const bool inside = p >= m.d.p_min && p <= m.d.p_max && v >= m.d.v_min && v <= m.d.v_max;
    (inside ? worst_in : worst_out) = std::max(inside ? worst_in : worst_out, err);
  };
  auto describe = [&](int id) {
    const auto& t = f.tables.at(id);
    BOOST_TEST_MESSAGE("  read: table " << id << ": " << t.values.size() << " values " << t.values.front() << " .. "
                       << t.values.back() << ", curve 1: " << t.curves[0].a.size() << " points (" << t.curves[0].a.front()
                       << ", " << t.curves[0].o.front() << ") .. (" << t.curves[0].a.back() << ", " << t.curves[0].o.back() << ")");
  };
  BOOST_TEST_MESSAGE("  read: " << c.keyword << " CID " << c.cid << " SSID " << c.ssid << " MSID " << c.msid << " SSTYP "
                     << c.sstyp << " MSTYP " << c.mstyp << " FS " << c.fs << " FD " << c.fd << " LC1_S " << c.lc1_s
                     << " LC2_S " << c.lc2_s << " OACS_S " << c.oacs_s << " LCFS " << c.lcfs << " LCPS " << c.lcps);
  if (direction != "ortho") {
    BOOST_TEST(c.fs == 2.0);
    // the contact types the manual's FS = 2 text names (readers.hpp)
    BOOST_TEST((c.keyword == "*CONTACT_SURFACE_TO_SURFACE_ID" || c.keyword == "*CONTACT_ONE_WAY_SURFACE_TO_SURFACE_ID"),
               c.keyword);
    BOOST_REQUIRE(f.tables.count(static_cast<int>(c.fd)));
    const auto& t = f.tables.at(static_cast<int>(c.fd));
    describe(static_cast<int>(c.fd));
    for (const auto& [p, v] : points(m.d, 200, 10, 10, 11)) note(p, v, std::abs(t.at(p, v) - law_dir(m, direction, 1, p, v)));
  } else {
    BOOST_TEST(c.keyword.find("ORTHO_FRICTION") != std::string::npos);
    BOOST_REQUIRE(f.tables.count(c.lc1_s) && f.tables.count(c.lc2_s));
    // the sheet's directions (OACS = 1: the sliding SURFA node's), and no LCFS curve that would replace LC1/LC2
    BOOST_TEST(c.oacs_s == 1);
    BOOST_TEST((c.lcfs == 0 && c.lcps == 0 && c.lcfm == 0 && c.lcpm == 0));
    for (int dir : {1, 2}) {
      const auto& t = f.tables.at(dir == 1 ? c.lc1_s : c.lc2_s);  // values: speed; curves: mu against pressure
      describe(dir == 1 ? c.lc1_s : c.lc2_s);
      for (const auto& [p, v] : points(m.d, 200, 10, 10, 13 + dir)) note(p, v, std::abs(t.at(v, p) - m.mu(dir, p, v)));
    }
  }
  BOOST_TEST_MESSAGE(file << ": contact " << c.keyword << " FS " << c.fs << " FD " << c.fd << ", max |mu - law| inside "
                          << worst_in << ", outside (to 10 p_max, 10 v_max) " << worst_out);
  BOOST_TEST(worst <= 1e-4);
}

void check_abaqus(const Model& m, const std::string& file, const std::string& direction) {
  const er::AbqFriction f = er::read_abaqus(file);
  double worst = 0, worst_in = 0, worst_out = 0;
  for (int dir : {1, 2}) {
    if (dir == 2 && !f.anisotropic) break;
    for (const auto& [p, v] : points(m.d, 200, 10, 10, 17 + dir)) {
      const double err = std::abs(f.at(dir, p, v) - (f.anisotropic ? m.mu(dir, p, v) : law_dir(m, direction, 1, p, v)));
      const bool inside = p >= m.d.p_min && p <= m.d.p_max && v >= m.d.v_min && v <= m.d.v_max;
      worst = std::max(worst, err);
      (inside ? worst_in : worst_out) = std::max(inside ? worst_in : worst_out, err);
    }
  }
  BOOST_TEST_MESSAGE(file << ": " << (f.anisotropic ? "anisotropic" : "isotropic") << ", " << f.pressures.size()
                          << " pressures x " << f.rates.front().size() << " slip rates (first line: " << f.mu1[0][0] << ", "
                          << f.mu2[0][0] << ", " << f.rates[0][0] << ", " << f.pressures[0] << "), max |mu - law| inside "
                          << worst_in << ", outside (to 10 p_max, 10 v_max) " << worst_out);
  BOOST_TEST(worst <= 1e-4);
}

bool td_copied(const Model& m) { return m.law->rd().mu == m.law->td().mu; }

}  // namespace

BOOST_AUTO_TEST_CASE(loop_exports_read_back) {
  const Args a = args();
  for (const Model& m : models()) {
    const std::string base = (fs::path(m.toml).parent_path() / "friction_").string();
    check_openradioss(m, base + "openradioss" + m.suffix + ".rad", a.sheet, a.tool);
    check_lsdyna(m, base + "lsdyna" + m.suffix + ".k", "rd");
    check_abaqus(m, base + "abaqus" + m.suffix + ".inp", "ortho");
    BOOST_TEST(er::read_abaqus(base + "abaqus" + m.suffix + ".inp").anisotropic);
    // every file says what the user must still set by hand
    BOOST_TEST(any_comment(er::read_openradioss(base + "openradioss" + m.suffix + ".rad").comments, "SET BY HAND"));
    BOOST_TEST(any_comment(er::read_lsdyna(base + "lsdyna" + m.suffix + ".k").comments, "SET BY HAND"));
    BOOST_TEST(any_comment(er::read_abaqus(base + "abaqus" + m.suffix + ".inp").comments, "SET BY HAND"));
    if (td_copied(m)) BOOST_TEST(any_comment(er::read_abaqus(base + "abaqus" + m.suffix + ".inp").comments, "COPY"));
  }
}

BOOST_AUTO_TEST_CASE(other_forms_read_back) {
  const Args a = args();
  const fs::path tmp = fs::path(a.dir) / "forms";
  fs::create_directories(tmp);
  for (const Model& m : models()) {
    const loop::ExportModel em = loop::read_friction_model(m.toml);
    loop::ExportOptions o;
    o.sheet_part = a.sheet;
    o.tool_part = a.tool;
    for (const std::string d : {"td", "mean", "ortho"}) {
      o.direction = d;
      const std::string rad = (tmp / ("or_" + d + m.suffix + ".rad")).string(), k = (tmp / ("ls_" + d + m.suffix + ".k")).string();
      std::ofstream(rad) << loop::export_openradioss(em, o).text;
      std::ofstream(k) << loop::export_lsdyna(em, o).text;
      check_openradioss(m, rad, a.sheet, a.tool);
      check_lsdyna(m, k, d);
      if (td_copied(m)) BOOST_TEST(any_comment(er::read_openradioss(rad).comments, "COPY"));
    }
    // part IDs that are `drawbend loop`'s placeholders (no --parts) are said to be so
    {
      loop::ExportOptions q = o;
      q.direction = "rd";
      q.parts_placeholder = true;
      const std::string rad = (tmp / ("or_placeholder" + m.suffix + ".rad")).string(),
                        k = (tmp / ("ls_placeholder" + m.suffix + ".k")).string();
      std::ofstream(rad) << loop::export_openradioss(em, q).text;
      std::ofstream(k) << loop::export_lsdyna(em, q).text;
      BOOST_TEST(any_comment(er::read_openradioss(rad).comments, "PLACEHOLDERS"));
      BOOST_TEST(any_comment(er::read_lsdyna(k).comments, "PLACEHOLDERS"));
    }
    o.direction = "td";
    o.abaqus_product = "explicit";
    const std::string inp = (tmp / ("abq_explicit" + m.suffix + ".inp")).string();
    std::ofstream(inp) << loop::export_abaqus(em, o).text;
    BOOST_TEST(!er::read_abaqus(inp).anisotropic);
    check_abaqus(m, inp, "td");
    // a speed band beyond the data (faster tools): the polynomial fits the clamped law there
    o.direction = "rd";
    o.band_v_min = m.d.v_min;
    o.band_v_max = 5 * m.d.v_max;
    const std::string band = (tmp / ("or_band" + m.suffix + ".rad")).string();
    std::ofstream(band) << loop::export_openradioss(em, o).text;
    check_openradioss(m, band, a.sheet, a.tool);
  }
}

namespace {
// Slide the Chapter 6 block on a floor whose nine nodes are mu_rd/mu_td
// sampled at the domain's nodes; returns (mu_x, mu_y).
sim::BlockResult slide(const friction::SurfaceDomain& d, const std::function<double(int, double, double)>& mu, double p,
                       double v, double direction_deg, const std::string& tag) {
  const fs::path nodes = fs::path(args().dir) / "forms" / ("roundtrip_" + tag + ".csv");
  fs::create_directories(nodes.parent_path());
  std::ofstream f(nodes);
  f << "node,mu_RD,mu_TD\n";
  const double ps[3] = {d.p_min, 0.5 * (d.p_min + d.p_max), d.p_max}, vs[3] = {d.v_min, 0.5 * (d.v_min + d.v_max), d.v_max};
  char b[512];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      std::snprintf(b, sizeof b, "%d,%.17g,%.17g\n", 3 * i + j + 1, mu(1, ps[i], vs[j]), mu(2, ps[i], vs[j]));
      f << b;
    }
  f.close();
  sim::BlockSpec s = sim::default_block_spec(DRAWBEND_DATA_DIR);
  io::FrictionSpec fr = io::surface_friction(nodes.string(), 100);
  fr.rest.insert_or_assign("p_min", d.p_min);
  fr.rest.insert_or_assign("p_max", d.p_max);
  fr.rest.insert_or_assign("v_min", d.v_min);
  fr.rest.insert_or_assign("v_max", d.v_max);
  s.friction = fr;
  s.pressure = p;
  s.speed = v;
  s.direction_deg = direction_deg;
  return sim::run_block(s);
}
}  // namespace

BOOST_AUTO_TEST_CASE(round_trip_through_our_solver) {
  const Args a = args();
  const Model m = load_model((fs::path(a.dir) / "friction_model.toml").string());
  const std::string base = (fs::path(a.dir) / "friction_").string();
  const er::DynaFile dyna = er::read_lsdyna(base + "lsdyna.k");
  const auto& table = dyna.tables.at(static_cast<int>(dyna.contacts.at(0).fd));
  const er::AbqFriction abq = er::read_abaqus(base + "abaqus.inp");
  const er::RadFile rad = er::read_openradioss(base + "openradioss.rad");
  const RadStated rs = rad_stated(rad);
  const double pts[3][2] = {{0.75 * m.d.p_min + 0.25 * m.d.p_max, m.d.v_min + 0.05 * (m.d.v_max - m.d.v_min)},
                            {0.5 * (m.d.p_min + m.d.p_max), 0.5 * (m.d.v_min + m.d.v_max)},
                            {0.1 * m.d.p_min + 0.9 * m.d.p_max, m.d.v_min + 0.9 * (m.d.v_max - m.d.v_min)}};
  for (int k = 0; k < 3; ++k) {
    const double p = pts[k][0], v = pts[k][1], law = m.mu(1, p, v);
    // OpenRadioss: the nine nodes within the band that holds v
    size_t band = 0;
    while (band + 1 < rs.bands.size() && v > std::get<2>(rs.bands[band])) ++band;
    friction::SurfaceDomain db = m.d;
    db.v_min = std::get<1>(rs.bands[band]);
    db.v_max = std::get<2>(rs.bands[band]);
    const double poly = rad_mu(rad, rs, 1, p, v);
    const auto r_rad = slide(db, [&](int, double pp, double vv) { return rad_mu(rad, rs, 1, pp, vv); }, p, v, 0, "or" + std::to_string(k));
    const auto r_dyn = slide(m.d, [&](int, double pp, double vv) { return table.at(pp, vv); }, p, v, 0, "ls" + std::to_string(k));
    const auto r_abq = slide(m.d, [&](int dir, double pp, double vv) { return abq.at(dir, pp, vv); }, p, v, 0, "ab" + std::to_string(k));
    BOOST_TEST_MESSAGE("p " << p << " MPa, v " << v << " mm/s: law " << law << "; block F_T/F_N: LS-DYNA table "
                            << r_dyn.mu_x << ", Abaqus " << r_abq.mu_x << ", OpenRadioss " << r_rad.mu_x << " (polynomial "
                            << poly << ")");
    BOOST_TEST(std::abs(r_dyn.mu_x - law) <= 0.01 * law);
    BOOST_TEST(std::abs(r_abq.mu_x - law) <= 0.01 * law);
    BOOST_TEST(std::abs(r_rad.mu_x - poly) <= 0.01 * poly);
    BOOST_TEST(std::abs(r_rad.mu_x - law) <= (0.01 + rs.rel) * law);
  }
  // TD through the anisotropic Abaqus table
  const double p = 0.5 * (m.d.p_min + m.d.p_max), v = 0.5 * (m.d.v_min + m.d.v_max), law = m.mu(2, p, v);
  const auto r = slide(m.d, [&](int dir, double pp, double vv) { return abq.at(dir, pp, vv); }, p, v, 90, "abTD");
  BOOST_TEST_MESSAGE("TD p " << p << " v " << v << ": law " << law << ", block F_T/F_N " << r.mu_y);
  BOOST_TEST(std::abs(r.mu_y - law) <= 0.01 * law);
}
