#include "study/check_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace drawbend::study {

namespace {

bool parse_number(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end && *end == '\0' && std::isfinite(v);
}

}  // namespace

bool is_boolean_unit(const std::string& unit) { return unit == "true=1"; }

std::string display_unit(const std::string& unit) {
  if (is_boolean_unit(unit)) return "";
  if (unit.empty() || unit == "-") return "1";
  return unit;
}

std::string round_for_display(double v, double tol) {
  if (!std::isfinite(v)) return std::isnan(v) ? "NaN" : (v > 0 ? "inf" : "-inf");
  if (v == 0) return "0";
  const int mag = static_cast<int>(std::floor(std::log10(std::abs(v))));  // place of v's leading digit
  int sig = 6;
  if (tol > 0 && std::isfinite(tol)) {
    const int tol_place = static_cast<int>(std::floor(std::log10(tol)));
    sig = std::clamp(mag - tol_place + 1, 3, 6);
  }
  const int decimals = std::max(0, sig - 1 - mag);
  if (mag >= 6 || mag < -4) {  // very large or small: scientific notation with `sig` digits
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*e", sig - 1, v);
    return buf;
  }
  // Round to `sig` significant digits first (so 168.29819 with 3 digits is 168, not 168.3).
  const double scale = std::pow(10.0, sig - 1 - mag);
  const double r = std::round(v * scale) / scale;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, r);
  std::string s = buf;
  if (s == "-0") s = "0";
  return s;
}

std::string display_value(const std::string& cell, const std::string& unit, const std::string& tolerance) {
  double v = 0;
  if (!parse_number(cell, v)) return cell;
  if (is_boolean_unit(unit)) return v != 0 ? "yes" : "no";
  double tol = 0;
  if (!parse_number(tolerance, tol)) tol = 0;
  return round_for_display(v, tol);
}

std::string display_tolerance(const std::string& tolerance, const std::string& unit) {
  if (is_boolean_unit(unit)) return "\u2013";  // a claim holds or not
  double tol = 0;
  if (!parse_number(tolerance, tol)) return tolerance;
  if (tol == 0) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2g", tol);
  return buf;
}

std::string kind_of(const CsvTable& t, const CsvRow& r) {
  if (!t.has_column("kind")) return "unclassified";
  const std::string& k = t.text(r, "kind");
  return k.empty() ? "unclassified" : k;
}

std::string kind_label(const std::string& kind) {
  if (kind == "simulated") return "our simulations vs the thesis's simulations";
  if (kind == "measured") return "our simulations vs the thesis's measurements, blind (nothing fitted or chosen on them)";
  if (kind == "fitted") return "measurements a parameter of our model was fitted to (in-sample, not agreement)";
  if (kind == "selected") return "measurements used to accept or reject a model (not blind, not agreement)";
  if (kind == "rederived") return "the thesis's own arithmetic, re-derived";
  if (kind == "verification") return "solver verification (closed forms, our input laws)";
  if (kind == "health") return "solver health (energy balance, hourglass share)";
  if (kind == "software") return "software (generated files, input hygiene)";
  return "not classified by kind in these outputs";
}

const std::vector<std::string>& kind_order() {
  static const std::vector<std::string> k{"simulated", "measured", "fitted", "selected", "rederived",
                                          "verification", "health", "software", "unclassified"};
  return k;
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string html_breakable(const std::string& s, const std::string& after) {
  std::string o;
  for (char c : s) {
    o += html_escape(std::string(1, c));
    if (after.find(c) != std::string::npos) o += "<wbr>";
  }
  return o;
}

std::string html_provenance(const std::string& html) {
  std::string o;
  std::size_t pos = 0;
  for (;;) {
    const std::size_t mark = html.find("]{.src-", pos);
    if (mark == std::string::npos) break;
    const std::size_t open = html.rfind('[', mark);
    const std::size_t end = html.find('}', mark);
    if (open == std::string::npos || open < pos || end == std::string::npos) {
      o += html.substr(pos, mark + 1 - pos);
      pos = mark + 1;
      continue;
    }
    const std::string kind = html.substr(mark + 7, end - mark - 7);
    o += html.substr(pos, open - pos) + "<span class=\"src src-" + kind + "\" title=\"source: " + kind + "\">" +
         html.substr(open + 1, mark - open - 1) + "</span>";
    pos = end + 1;
  }
  return o + html.substr(pos);
}

std::string checks_html_table(const CsvTable& t, const std::string& caption) {
  std::ostringstream os;
  const bool kinds = t.has_column("kind");
  os << "<div class=\"table-scroll\">\n<table class=\"checks-table\">\n<caption>" << html_escape(caption)
     << "</caption>\n<thead><tr><th>check</th>" << (kinds ? "<th>kind</th>" : "")
     << "<th>quantity</th><th class=\"num\">thesis</th><th class=\"num\">ours</th>"
        "<th class=\"num\">tolerance</th><th>unit</th><th>status</th><th>note</th></tr></thead>\n<tbody>\n";
  for (const auto& r : t.rows) {
    const std::string& unit = t.text(r, "unit");
    const std::string& tol = t.text(r, "tolerance");
    const std::string& status = t.text(r, "status");
    os << "<tr class=\"row-" << html_escape(status) << "\"><td class=\"id\">" << html_breakable(t.text(r, "id"), "._")
       << "</td>";
    if (kinds) os << "<td>" << html_escape(kind_of(t, r)) << "</td>";
    os << "<td class=\"quantity\">" << html_breakable(t.text(r, "quantity"), "/_") << "</td><td class=\"num\">"
       << html_escape(display_value(t.text(r, "thesis"), unit, tol)) << "</td><td class=\"num\">"
       << html_escape(display_value(t.text(r, "ours"), unit, tol)) << "</td><td class=\"num\">"
       << html_escape(display_tolerance(tol, unit)) << "</td><td>" << html_escape(display_unit(unit))
       << "</td><td><span class=\"status-" << html_escape(status) << "\">" << html_escape(status)
       << "</span></td><td class=\"note\">" << html_provenance(html_breakable(t.text(r, "note"), "/_")) << "</td></tr>\n";
  }
  os << "</tbody>\n</table>\n</div>\n";
  return os.str();
}

}  // namespace drawbend::study
