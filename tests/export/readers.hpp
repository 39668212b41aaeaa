#pragma once
// Independent readers of the three friction exports, written from each
// target's documented layout, NOT from drawbend's writer (src/loop/export*.cpp
// is not included here and no code is shared with it).  Each reader reads the
// file the way its solver does and gives mu(p, v) the way its solver evaluates
// it.  A layout error (a number across a field boundary, a card missing, a
// field out of place) throws std::runtime_error naming the line.
//
//  OpenRadioss (hm_cfg_files/config/CFG/radioss2020/FRICTION/friction.cfg;
//  engine int07/i7for3.F): '#' lines are comments; /FRICTION/ID, a title line,
//  then fixed columns: Ifric 1-10, Ifiltr 11-20, Xfreq 21-40, Iform 41-50; C1..C5
//  in five 20-column fields; C6, Fric, VIS_F in three; then per pair
//  grpart_ID1 1-10, grpart_ID2 11-20, part_ID1 21-30, part_ID2 31-40, Idir 51-60
//  (41-50 blank), its C1..C5 and C6 Fric VIS_F, and a second pair of cards when
//  Idir = 1.  mu = Fric + (C1 + C4 P) P + (C2 + C3 P) V + C5 V^2, at least 1e-30.
//  /FRIC_ORIENT/ID, title, "%10d%10d" (grpart, part), VX VY VZ (3 x 20) skew (10)
//  phi (20) Iorth (10).
//
//  LS-DYNA (Keyword User's Manual): '$' lines are comments, '*' starts a
//  keyword; cards of 8 fields of 10 columns; *DEFINE_TABLE: TBID (1-10), then one
//  VALUE per line in columns 1-20, followed by one *DEFINE_CURVE per value in
//  order; *DEFINE_CURVE: LCID SIDR SFA SFO ... (10 columns each), then points
//  A (1-20) O (21-40).  Between curves of a table: linear in the value; outside
//  the values: the end curve.  Curves: linear, extrapolated from the end segment.
//  *CONTACT_..._ID: card CID; card 1 SSID MSID SSTYP MSTYP ...; card 2 FS FD ...;
//  card 3.  FS = 2 (the manual's FS/FD text, as carried by ansys/pydyna commit
//  baa7279, contact_automatic_single_surface.py): "FD is a table ID (see
//  *DEFINE_TABLE). That table specifies two or more values of contact pressure,
//  with each pressure value in the table corresponding to a curve of friction
//  coefficient as a function of relative velocity", read by the
//  SURFACE_TO_SURFACE and ONE_WAY_SURFACE_TO_SURFACE contacts; so this reader
//  evaluates FD's table at (value = pressure, abscissa = speed).  _ORTHO_FRICTION: four more cards right after card 3, FS1_S FD1_S DC1_S
//  VC1_S LC1_S OACS_S LCFS LCPS / FS2_S FD2_S DC2_S VC2_S LC2_S / the same two for
//  SURFB (_M).  OACS integer (0: directions of the segment slid on, 1: of the
//  sliding node); LCFS, when given, replaces FS FD DC VC LC (mu against the angle
//  from direction 1), LCPS scales it with pressure.  Layout from OpenRadioss's
//  LS-DYNA reader (hm_cfg_files/config/CFG/Keyword971_R14.1/CONTACT/
//  OneWaySurfToSurf.cfg) and the manual's field texts as carried by ansys/pydyna
//  (ContactFormingOneWaySurfaceToSurfaceOrthoFriction).
//
//  Abaqus (Keywords Reference, *FRICTION): '**' comments; data lines separated
//  by commas.  ANISOTROPIC: mu1, mu2, slip rate, pressure; isotropic: mu, slip
//  rate, pressure.  The first independent variable (slip rate) varies fastest;
//  linear interpolation, constant beyond the tabulated range.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace export_readers {

inline std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot open");
  std::vector<std::string> v;
  for (std::string l; std::getline(f, l);) v.push_back(l);
  return v;
}

/// Columns [a, b] (1-based, inclusive) of a line as a number; blank = 0 (the
/// Fortran reading of an empty field).  Anything else in the field than one
/// number (with blanks) is a layout error.
inline double col(const std::string& line, int a, int b, const std::string& where) {
  std::string f = static_cast<int>(line.size()) >= a ? line.substr(a - 1, b - a + 1) : "";
  const auto first = f.find_first_not_of(' ');
  if (first == std::string::npos) return 0.0;
  const auto last = f.find_last_not_of(' ');
  const std::string t = f.substr(first, last - first + 1);
  char* end = nullptr;
  const double x = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size() || t.find(' ') != std::string::npos)
    throw std::runtime_error(where + ": columns " + std::to_string(a) + "-" + std::to_string(b) + " hold '" + f +
                             "', not one number");
  return x;
}

/// Linear interpolation in a sorted abscissa, extrapolation from the end segments.
inline double lin_extrap(const std::vector<double>& x, const std::vector<double>& y, double t) {
  if (x.size() == 1) return y[0];
  size_t i = 0;
  while (i + 2 < x.size() && t > x[i + 1]) ++i;
  return y[i] + (y[i + 1] - y[i]) * (t - x[i]) / (x[i + 1] - x[i]);
}

// ---------------------------------------------------------------- OpenRadioss
struct RadLaw {
  double c[6] = {0, 0, 0, 0, 0, 0};  // C1..C6
  double fric = 0, visf = 0;
  double mu(double p, double v) const {
    return std::max(1e-30, fric + (c[0] + c[3] * p) * p + (c[1] + c[2] * p) * v + c[4] * v * v);
  }
};
struct RadPair {
  int grpart1 = 0, grpart2 = 0, part1 = 0, part2 = 0, idir = 0;
  RadLaw dir1, dir2;
};
struct RadFriction {
  int id = 0, ifric = 0, ifiltr = 0, iform = 0;
  double xfreq = 0;
  RadLaw deflt;
  std::vector<RadPair> pairs;
};
struct RadOrient {
  int id = 0, grpart = 0, part = 0, skew = 0, iorth = 0;
  double vx = 0, vy = 0, vz = 0, phi = 0;
};
struct RadFile {
  std::vector<RadFriction> frictions;
  std::vector<RadOrient> orients;
  std::vector<std::string> comments;
};

inline RadFile read_openradioss(const std::string& path) {
  const auto all = lines_of(path);
  RadFile f;
  std::vector<std::pair<int, std::string>> cards;  // (line number, text) without comments
  for (size_t k = 0; k < all.size(); ++k) {
    if (!all[k].empty() && all[k][0] == '#') f.comments.push_back(all[k]);
    else if (!all[k].empty()) cards.push_back({static_cast<int>(k + 1), all[k]});
  }
  size_t i = 0;
  auto where = [&](size_t j) { return path + ":" + std::to_string(cards[j].first); };
  auto need = [&](size_t j) {
    if (j >= cards.size()) throw std::runtime_error(path + ": card missing at the end");
    return cards[j].second;
  };
  auto law = [&](size_t j, RadLaw& l) {
    const std::string a = need(j), b = need(j + 1);
    if (!a.empty() && a[0] == '/') throw std::runtime_error(where(j) + ": expected C1..C5, found a keyword");
    for (int k = 0; k < 5; ++k) l.c[k] = col(a, 1 + 20 * k, 20 + 20 * k, where(j));
    l.c[5] = col(b, 1, 20, where(j + 1));
    l.fric = col(b, 21, 40, where(j + 1));
    l.visf = col(b, 41, 60, where(j + 1));
  };
  while (i < cards.size()) {
    const std::string& head = cards[i].second;
    if (head.rfind("/FRICTION/", 0) == 0) {
      RadFriction r;
      r.id = std::stoi(head.substr(10));
      const std::string c1 = need(i + 2);
      r.ifric = static_cast<int>(col(c1, 1, 10, where(i + 2)));
      r.ifiltr = static_cast<int>(col(c1, 11, 20, where(i + 2)));
      r.xfreq = col(c1, 21, 40, where(i + 2));
      r.iform = static_cast<int>(col(c1, 41, 50, where(i + 2)));
      law(i + 3, r.deflt);
      i += 5;
      while (i < cards.size() && cards[i].second[0] != '/') {
        RadPair p;
        const std::string& pc = cards[i].second;
        p.grpart1 = static_cast<int>(col(pc, 1, 10, where(i)));
        p.grpart2 = static_cast<int>(col(pc, 11, 20, where(i)));
        p.part1 = static_cast<int>(col(pc, 21, 30, where(i)));
        p.part2 = static_cast<int>(col(pc, 31, 40, where(i)));
        if (col(pc, 41, 50, where(i)) != 0) throw std::runtime_error(where(i) + ": columns 41-50 must be blank");
        p.idir = static_cast<int>(col(pc, 51, 60, where(i)));
        law(i + 1, p.dir1);
        i += 3;
        if (p.idir == 1) law(i, p.dir2), i += 2;
        r.pairs.push_back(p);
      }
      f.frictions.push_back(r);
    } else if (head.rfind("/FRIC_ORIENT/", 0) == 0) {
      RadOrient o;
      o.id = std::stoi(head.substr(13));
      const std::string a = need(i + 2), b = need(i + 3);
      o.grpart = static_cast<int>(col(a, 1, 10, where(i + 2)));
      o.part = static_cast<int>(col(a, 11, 20, where(i + 2)));
      o.vx = col(b, 1, 20, where(i + 3));
      o.vy = col(b, 21, 40, where(i + 3));
      o.vz = col(b, 41, 60, where(i + 3));
      o.skew = static_cast<int>(col(b, 61, 70, where(i + 3)));
      o.phi = col(b, 71, 90, where(i + 3));
      o.iorth = static_cast<int>(col(b, 91, 100, where(i + 3)));
      f.orients.push_back(o);
      i += 4;
    } else {
      throw std::runtime_error(where(i) + ": unexpected card '" + head + "'");
    }
  }
  return f;
}

// ---------------------------------------------------------------- LS-DYNA
struct DynaCurve {
  std::vector<double> a, o;
};
struct DynaTable {
  std::vector<double> values;
  std::vector<DynaCurve> curves;
  /// mu at (table value t, curve abscissa x).
  double at(double t, double x) const {
    std::vector<double> y(values.size());
    for (size_t k = 0; k < values.size(); ++k) y[k] = lin_extrap(curves[k].a, curves[k].o, x);
    if (t <= values.front()) return y.front();
    if (t >= values.back()) return y.back();
    return lin_extrap(values, y, t);
  }
};
struct DynaContact {
  std::string keyword;
  int cid = 0, ssid = 0, msid = 0, sstyp = 0, mstyp = 0;
  double fs = 0, fd = 0;
  int lc1_s = 0, lc2_s = 0, lc1_m = 0, lc2_m = 0;
  int oacs_s = 0, oacs_m = 0, lcfs = 0, lcps = 0, lcfm = 0, lcpm = 0;
};
struct DynaFile {
  std::map<int, DynaTable> tables;
  std::vector<DynaContact> contacts;
  std::vector<std::string> comments;
  bool keyword = false, end = false;
};

inline DynaFile read_lsdyna(const std::string& path) {
  const auto all = lines_of(path);
  DynaFile f;
  // blocks: keyword line + its data cards
  std::vector<std::pair<std::string, std::vector<std::pair<int, std::string>>>> blocks;
  for (size_t k = 0; k < all.size(); ++k) {
    const std::string& l = all[k];
    if (l.empty()) continue;
    if (l[0] == '$') {
      f.comments.push_back(l);
      continue;
    }
    if (l[0] == '*') blocks.push_back({l.substr(0, l.find(' ')), {}});
    else if (blocks.empty()) throw std::runtime_error(path + ":" + std::to_string(k + 1) + ": data before any keyword");
    else blocks.back().second.push_back({static_cast<int>(k + 1), l});
  }
  auto where = [&](const std::pair<int, std::string>& c) { return path + ":" + std::to_string(c.first); };
  for (size_t b = 0; b < blocks.size(); ++b) {
    const std::string& kw = blocks[b].first;
    const auto& cards = blocks[b].second;
    if (kw == "*KEYWORD") f.keyword = true;
    else if (kw == "*END") f.end = true;
    else if (kw == "*DEFINE_TABLE") {
      if (cards.empty()) throw std::runtime_error(path + ": *DEFINE_TABLE without cards");
      const int id = static_cast<int>(col(cards[0].second, 1, 10, where(cards[0])));
      DynaTable t;
      for (size_t k = 1; k < cards.size(); ++k) t.values.push_back(col(cards[k].second, 1, 20, where(cards[k])));
      for (size_t k = 0; k < t.values.size(); ++k) {
        const size_t cb = b + 1 + k;
        if (cb >= blocks.size() || blocks[cb].first != "*DEFINE_CURVE")
          throw std::runtime_error(path + ": table " + std::to_string(id) + " needs " + std::to_string(t.values.size()) +
                                   " *DEFINE_CURVE after it");
        const auto& cc = blocks[cb].second;
        DynaCurve c;
        const double sfa = col(cc[0].second, 21, 30, where(cc[0])), sfo = col(cc[0].second, 31, 40, where(cc[0]));
        for (size_t q = 1; q < cc.size(); ++q) {
          c.a.push_back((sfa == 0 ? 1 : sfa) * col(cc[q].second, 1, 20, where(cc[q])));
          c.o.push_back((sfo == 0 ? 1 : sfo) * col(cc[q].second, 21, 40, where(cc[q])));
        }
        t.curves.push_back(c);
      }
      f.tables[id] = t;
    } else if (kw.rfind("*CONTACT_", 0) == 0) {
      DynaContact c;
      c.keyword = kw;
      size_t q = 0;
      const bool has_id = kw.size() > 3 && kw.substr(kw.size() - 3) == "_ID";
      auto card = [&]() -> const std::pair<int, std::string>& {
        if (q >= cards.size()) throw std::runtime_error(path + ": " + kw + ": card missing");
        return cards[q++];
      };
      if (has_id) c.cid = static_cast<int>(col(card().second, 1, 10, where(cards[q - 1])));
      const auto& c1 = card();
      c.ssid = static_cast<int>(col(c1.second, 1, 10, where(c1)));
      c.msid = static_cast<int>(col(c1.second, 11, 20, where(c1)));
      c.sstyp = static_cast<int>(col(c1.second, 21, 30, where(c1)));
      c.mstyp = static_cast<int>(col(c1.second, 31, 40, where(c1)));
      const auto& c2 = card();
      c.fs = col(c2.second, 1, 10, where(c2));
      c.fd = col(c2.second, 11, 20, where(c2));
      card();  // card 3
      if (kw.find("ORTHO_FRICTION") != std::string::npos) {
        // an integer field must hold an integer (LS-DYNA's reader refuses "1.5" there)
        auto icol = [&](const std::pair<int, std::string>& cd, int a0, int b0) {
          const double x = col(cd.second, a0, b0, where(cd));
          if (x != std::floor(x)) throw std::runtime_error(where(cd) + ": columns " + std::to_string(a0) + "-" +
                                                           std::to_string(b0) + " must hold an integer");
          return static_cast<int>(x);
        };
        const auto& a = card();
        c.lc1_s = icol(a, 41, 50);
        c.oacs_s = icol(a, 51, 60);
        c.lcfs = icol(a, 61, 70);
        c.lcps = icol(a, 71, 80);
        const auto& bb = card();
        c.lc2_s = static_cast<int>(col(bb.second, 41, 50, where(bb)));
        const auto& cm = card();
        c.lc1_m = icol(cm, 41, 50);
        c.oacs_m = icol(cm, 51, 60);
        c.lcfm = icol(cm, 61, 70);
        c.lcpm = icol(cm, 71, 80);
        const auto& dm = card();
        c.lc2_m = static_cast<int>(col(dm.second, 41, 50, where(dm)));
      }
      f.contacts.push_back(c);
    }
  }
  return f;
}

// ---------------------------------------------------------------- Abaqus
struct AbqFriction {
  bool anisotropic = false;
  std::vector<double> pressures;                 // ascending blocks
  std::vector<std::vector<double>> rates;        // per pressure block
  std::vector<std::vector<double>> mu1, mu2;     // per block (mu2 = mu1 when isotropic)
  std::vector<std::string> comments;
  /// Linear in slip rate within each pressure block, then linear in pressure;
  /// constant beyond the ends.
  double at(int dir, double p, double rate) const {
    std::vector<double> y(pressures.size());
    for (size_t k = 0; k < pressures.size(); ++k) {
      const auto& r = rates[k];
      const auto& m = dir == 1 ? mu1[k] : mu2[k];
      const double t = std::clamp(rate, r.front(), r.back());
      y[k] = lin_extrap(r, m, t);
    }
    return lin_extrap(pressures, y, std::clamp(p, pressures.front(), pressures.back()));
  }
};

inline AbqFriction read_abaqus(const std::string& path) {
  const auto all = lines_of(path);
  AbqFriction f;
  bool in = false;
  for (size_t k = 0; k < all.size(); ++k) {
    const std::string& l = all[k];
    const std::string where = path + ":" + std::to_string(k + 1);
    if (l.rfind("**", 0) == 0) {
      f.comments.push_back(l);
      continue;
    }
    if (l.empty()) continue;
    if (l[0] == '*') {
      std::string u = l;
      std::transform(u.begin(), u.end(), u.begin(), ::toupper);
      u.erase(std::remove(u.begin(), u.end(), ' '), u.end());
      in = u.rfind("*FRICTION", 0) == 0;
      if (in) f.anisotropic = u.find("ANISOTROPIC") != std::string::npos;
      continue;
    }
    if (!in) continue;
    std::vector<double> v;
    std::stringstream ss(l);
    for (std::string item; std::getline(ss, item, ',');) {
      char* end = nullptr;
      const double x = std::strtod(item.c_str(), &end);
      while (*end == ' ') ++end;
      if (*end != '\0' || item.find_first_not_of(' ') == std::string::npos)
        throw std::runtime_error(where + ": '" + item + "' is not a number");
      v.push_back(x);
    }
    const size_t need = f.anisotropic ? 4 : 3;
    if (v.size() != need) throw std::runtime_error(where + ": expected " + std::to_string(need) + " values");
    const double mu1 = v[0], mu2 = f.anisotropic ? v[1] : v[0], rate = v[need - 2], p = v[need - 1];
    if (f.pressures.empty() || p != f.pressures.back()) {
      if (!f.pressures.empty() && p < f.pressures.back()) throw std::runtime_error(where + ": pressure decreases");
      f.pressures.push_back(p);
      f.rates.emplace_back();
      f.mu1.emplace_back();
      f.mu2.emplace_back();
    }
    if (!f.rates.back().empty() && rate <= f.rates.back().back())
      throw std::runtime_error(where + ": slip rate must increase within a pressure");
    f.rates.back().push_back(rate);
    f.mu1.back().push_back(mu1);
    f.mu2.back().push_back(mu2);
  }
  if (f.pressures.empty()) throw std::runtime_error(path + ": no *FRICTION data");
  return f;
}

}  // namespace export_readers
