#include "study/report_front.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "study/check_format.hpp"
#include "study/list_audit.hpp"

namespace drawbend::study {

namespace fs = std::filesystem;

void StatusCounts::add(const std::string& s) {
  pass += s == "pass";
  fail += s == "fail";
  erratum += s == "erratum";
  disagree += s == "disagree";
}

namespace {

struct ChapterChecks {
  const ChapterSource* ch = nullptr;
  bool present = false;
  CsvTable table;
};

std::vector<ChapterChecks> load_all(const std::vector<ChapterSource>& chapters) {
  std::vector<ChapterChecks> v;
  for (const auto& ch : chapters) {
    ChapterChecks c;
    c.ch = &ch;
    const std::string path = ch.out_dir + "/checks.csv";
    if (fs::exists(path)) {
      c.present = true;
      c.table = read_csv(path);
    }
    v.push_back(std::move(c));
  }
  return v;
}

int count_files(const std::string& dir, const std::string& ext) {
  if (!fs::is_directory(dir)) return 0;
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ext;
  return n;
}

/// Distinct program versions (git describe) recorded in the chapters' provenance.csv.
std::vector<std::string> chapter_versions(const std::vector<ChapterSource>& chapters) {
  std::set<std::string> s;
  for (const auto& ch : chapters) {
    const std::string p = ch.out_dir + "/provenance.csv";
    if (!fs::exists(p)) continue;
    const CsvTable t = read_csv(p);
    for (const auto& r : t.rows)
      if (t.text(r, "kind") == "version") s.insert(t.text(r, "path"));
  }
  return {s.begin(), s.end()};
}

std::string joined(const std::vector<std::string>& v, const std::string& none) {
  if (v.empty()) return none;
  std::string o;
  for (const auto& s : v) o += (o.empty() ? "" : ", ") + s;
  return o;
}

/// The mesh tiers of a mixed report, e.g. "full; quick for ch6-friction-model,
/// ch8-model-loop": the tier most chapters ran, then each other tier with its chapters.
std::string tiers_by_chapter(const std::vector<ChapterSource>& chapters) {
  std::map<std::string, std::vector<std::string>> ids;
  for (const auto& ch : chapters) {
    const std::string t = chapter_tier(ch);
    if (!t.empty()) ids[t].push_back(ch.id);
  }
  if (ids.empty()) return "unknown";
  std::string main_tier;
  std::size_t most = 0;
  for (const auto& [t, v] : ids)
    if (v.size() > most) most = v.size(), main_tier = t;
  std::string o = main_tier;
  for (const auto& [t, v] : ids)
    if (t != main_tier) o += "; " + t + " for " + joined(v, "");
  return o;
}

std::string plural(int n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string status_cells(const StatusCounts& c) {
  std::ostringstream os;
  os << "<td class=\"num\">" << c.total() << "</td><td class=\"num\">" << c.pass << "</td><td class=\"num\">"
     << (c.fail ? "<span class=\"status-fail\">" + std::to_string(c.fail) + "</span>" : "0")
     << "</td><td class=\"num\">" << c.erratum << "</td><td class=\"num\">"
     << (c.disagree ? "<span class=\"status-disagree\">" + std::to_string(c.disagree) + "</span>" : "0")
     << "</td>";
  return os.str();
}

const char* status_head =
    "<th class=\"num\">checks</th><th class=\"num\">pass</th><th class=\"num\">fail</th>"
    "<th class=\"num\">erratum</th><th class=\"num\">disagree</th>";

}  // namespace

std::string chapter_title(const ChapterSource& ch) {
  std::ifstream in(ch.src_dir + "/intro.md");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("# ", 0) == 0) {
      std::string t = line.substr(2);
      if (const auto b = t.find(" {#"); b != std::string::npos) t = t.substr(0, b);
      return t;
    }
  return ch.id;
}

MeasuredCounts measured_counts(const std::vector<ChapterSource>& chapters) {
  MeasuredCounts m;
  for (const auto& c : load_all(chapters)) {
    if (!c.present) continue;
    for (const auto& r : c.table.rows) {
      const std::string k = kind_of(c.table, r), s = c.table.text(r, "status");
      if (k == "measured") {
        const bool claim = is_boolean_unit(c.table.text(r, "unit"));
        (claim ? m.blind_claims : m.blind).add(s);
      }
      m.fitted += k == "fitted";
      m.selected += k == "selected";
    }
  }
  return m;
}

std::string measurement_sentence(const std::vector<ChapterSource>& chapters) {
  const MeasuredCounts m = measured_counts(chapters);
  if (m.blind.total() + m.blind_claims.total() + m.fitted + m.selected == 0) return "";
  std::ostringstream os;
  os << "Agreement with measurement is counted from blind comparisons only (no parameter fitted to the number, no "
        "model chosen on it): " << m.blind.pass << " of " << plural(m.blind.total(), "blind comparison", "blind comparisons")
     << " agree";
  if (m.blind_claims.total() > 0)
    os << ", and " << m.blind_claims.pass << " of " << plural(m.blind_claims.total(), "yes/no claim", "yes/no claims")
       << " tested on measured data hold";
  os << "; " << plural(m.fitted, "measured number was", "measured numbers were") << " fitted to and "
     << plural(m.selected, "was", "were") << " used to choose a model, and are not counted as agreement. ";
  return os.str();
}

std::string abstract_paragraph(const std::vector<ChapterSource>& chapters) {
  const auto all = load_all(chapters);
  std::map<std::string, StatusCounts> by_kind;
  StatusCounts total;
  int tables = 0, figures = 0, ran = 0;
  for (const auto& c : all) {
    tables += count_files(c.ch->out_dir + "/tables", ".csv");
    figures += count_files(c.ch->out_dir + "/figures", ".svg");
    if (!c.present) continue;
    ++ran;
    for (const auto& r : c.table.rows) {
      by_kind[kind_of(c.table, r)].add(c.table.text(r, "status"));
      total.add(c.table.text(r, "status"));
    }
  }
  std::ostringstream os;
  os << "This report rebuilds from source " << plural(tables, "table", "tables") << " and "
     << plural(figures, "figure", "figures") << " of the thesis in " << plural(ran, "chapter", "chapters")
     << " (mesh tier: " << tiers_by_chapter(chapters) << ") and compares "
     << plural(total.total(), "number", "numbers") << " with it. ";
  StatusCounts ours;  // our simulations against the thesis's simulations and measurements
  for (const char* k : {"simulated", "measured"})
    if (by_kind.count(k)) {
      const auto& c = by_kind[k];
      ours.pass += c.pass, ours.fail += c.fail, ours.erratum += c.erratum, ours.disagree += c.disagree;
    }
  if (by_kind.count("unclassified") && by_kind.size() == 1) {
    os << "These outputs do not record the kind of each check, so the counts below mix re-derived arithmetic, "
          "simulations and solver checks: "
       << total.pass << " pass, " << total.disagree << " published values are not reproduced by our simulations, "
       << total.erratum << " are errata of the thesis's own arithmetic";
  } else {
    if (ours.total() > 0) {
      os << "Our own simulations were compared with the thesis's simulated and measured results in "
         << plural(ours.total(), "check", "checks") << ": " << ours.pass << " agree within the tolerance fixed "
         << "beforehand and " << ours.disagree << (ours.disagree == 1 ? " is" : " are")
         << " not reproduced (listed below with what the investigation found). ";
    }
    os << measurement_sentence(chapters);
    if (by_kind.count("rederived")) {
      const auto& c = by_kind["rederived"];
      os << "Re-deriving the thesis's own arithmetic from its printed inputs (" << plural(c.total(), "check", "checks")
         << ") confirms " << plural(c.pass, "value", "values") << " and finds " << plural(c.erratum, "erratum", "errata")
         << ", grouped by cause below. ";
    }
    int solver = 0;
    for (const char* k : {"verification", "health", "software"})
      if (by_kind.count(k)) solver += by_kind[k].total();
    if (solver > 0) {
      const int sv = by_kind.count("verification") ? by_kind["verification"].total() : 0;
      const int sh = by_kind.count("health") ? by_kind["health"].total() : 0;
      const int ss = by_kind.count("software") ? by_kind["software"].total() : 0;
      os << "A further " << solver << " checks test the solver and the pipeline themselves (" << sv
         << " verification, " << sh << " solver health, " << ss << " software)";
    }
    if (by_kind.count("unclassified")) os << "; " << by_kind["unclassified"].total() << " checks are not classified";
  }
  os << ". " << (total.fail == 0 ? "No check fails." : plural(total.fail, "check fails", "checks fail") +
                                                          ": see the chapters' checks tables.");
  std::string s = os.str();
  // The sentence joints above can leave ". ." when an optional clause is absent.
  for (std::size_t p; (p = s.find(". .")) != std::string::npos;) s.erase(p, 2);
  return s;
}

namespace {
/// A YAML single-quoted scalar ('' for a quote; no line breaks).
std::string yaml_quoted(const std::string& s) {
  std::string o = "'";
  for (char c : s) o += c == '\'' ? std::string("''") : c == '\n' ? std::string(" ") : std::string(1, c);
  return o + "'";
}
}  // namespace

std::string front_yaml(const std::vector<ChapterSource>& chapters, const FrontInfo& info, const std::string& title) {
  std::ostringstream os;
  os << "---\ntitle: " << yaml_quoted(title) << "\nlang: en\n"
     << "subtitle: " << yaml_quoted("Reproduces: " + info.citation) << "\n"
     << "date: " << yaml_quoted("Mesh tier: " + tiers_by_chapter(chapters) +
                                " (quick: the test suite's meshes, `make quick`; full: paper fidelity, `make`) \u00b7 "
                                "computed by drawbend " + joined(chapter_versions(chapters), "unknown version") +
                                " \u00b7 report assembled " + info.date)
     << "\nabstract: " << yaml_quoted(abstract_paragraph(chapters)) << "\n---\n\n";
  return os.str();
}

namespace {

/// The checks counted by status: by kind, and by chapter and kind.
struct KindCounts {
  std::map<std::string, StatusCounts> by_kind;
  std::map<std::string, std::map<std::string, StatusCounts>> by_chapter_kind;
};

KindCounts count_kinds(const std::vector<ChapterChecks>& all) {
  KindCounts n;
  for (const auto& c : all)
    if (c.present)
      for (const auto& r : c.table.rows) {
        const std::string k = kind_of(c.table, r), s = c.table.text(r, "status");
        n.by_kind[k].add(s);
        n.by_chapter_kind[c.ch->id][k].add(s);
      }
  return n;
}

/// "Checks by kind": the legend of the statuses and the table of counts by kind, with their total.
void kinds_section(std::ostream& os, const KindCounts& n) {
  os << "## Checks by kind {.unnumbered}\n\n"
     << "*pass*: within the stated tolerance; *fail*: outside it; *erratum*: the thesis disagrees with its own "
        "inputs (explained below and in the chapter); *disagree*: our simulation does not reproduce the published "
        "value, and the investigation's finding is stated (the tolerance is never widened).\n\n";
  os << "<div class=\"table-scroll\">\n<table class=\"summary-table\">\n<caption>Checks counted by what they "
        "compare.</caption>\n<thead><tr><th>kind</th><th>what is compared</th>"
     << status_head << "</tr></thead>\n<tbody>\n";
  StatusCounts total;
  for (const auto& k : kind_order()) {
    const auto it = n.by_kind.find(k);
    if (it == n.by_kind.end()) continue;
    const auto& c = it->second;
    total.pass += c.pass, total.fail += c.fail, total.erratum += c.erratum, total.disagree += c.disagree;
    os << "<tr><td>" << k << "</td><td>" << html_escape(kind_label(k)) << "</td>" << status_cells(c) << "</tr>\n";
  }
  os << "<tr class=\"total\"><td><strong>all</strong></td><td></td>" << status_cells(total)
     << "</tr>\n</tbody>\n</table>\n</div>\n\n";
}

/// Per chapter: status counts and the checks of each kind (not passing in brackets).
void chapters_table(std::ostream& os, const std::vector<ChapterChecks>& all, const KindCounts& n) {
  std::vector<std::string> kinds_present;
  for (const auto& k : kind_order())
    if (n.by_kind.count(k)) kinds_present.push_back(k);
  os << "<div class=\"table-scroll\">\n<table class=\"summary-table\">\n<caption>Checks per chapter (number of "
        "checks of each kind; not passing in brackets).</caption>\n<thead><tr><th>chapter</th><th>tier</th>"
     << status_head;
  for (const auto& k : kinds_present) os << "<th class=\"num\">" << k << "</th>";
  os << "</tr></thead>\n<tbody>\n";
  static const std::map<std::string, StatusCounts> kNone;
  for (const auto& c : all) {
    const std::string tier = chapter_tier(*c.ch);
    os << "<tr><td><a href=\"#checks-" << c.ch->id << "\">" << html_escape(chapter_title(*c.ch)) << "</a></td><td>"
       << html_escape(tier.empty() ? "\u2013" : tier) << "</td>";
    if (!c.present) {
      os << "<td colspan=\"" << 5 + kinds_present.size() << "\">not run</td></tr>\n";
      continue;
    }
    StatusCounts s;
    for (const auto& r : c.table.rows) s.add(c.table.text(r, "status"));
    os << status_cells(s);
    const auto mc = n.by_chapter_kind.find(c.ch->id);
    const auto& m = mc == n.by_chapter_kind.end() ? kNone : mc->second;
    for (const auto& k : kinds_present) {
      const auto it = m.find(k);
      os << "<td class=\"num\">";
      if (it == m.end()) os << "\u2013";
      else {
        os << it->second.total();
        const int off = it->second.total() - it->second.pass;
        if (off) os << " (" << off << ")";
      }
      os << "</td>";
    }
    os << "</tr>\n";
  }
  os << "</tbody>\n</table>\n</div>\n\n";
}

/// One disagreeing check as the cells of its row (all but the note).
std::string disagreement_cells(const ChapterChecks& c, const CsvRow& r) {
  const auto& t = c.table;
  const std::string &unit = t.text(r, "unit"), &tol = t.text(r, "tolerance");
  std::ostringstream row;
  row << "<td class=\"id\"><a href=\"#checks-" << c.ch->id << "\">" << html_breakable(t.text(r, "id"), "._")
      << "</a></td><td class=\"quantity\">" << html_breakable(t.text(r, "quantity"), "/_") << "</td><td class=\"num\">"
      << html_escape(display_value(t.text(r, "thesis"), unit, tol)) << "</td><td class=\"num\">"
      << html_escape(display_value(t.text(r, "ours"), unit, tol)) << "</td><td class=\"num\">"
      << html_escape(display_tolerance(tol, unit)) << "</td><td>" << html_escape(display_unit(unit)) << "</td>";
  return row.str();
}

/// "Not reproduced": every disagreement, rounded, with its tolerance.  Checks
/// that share one explanation (e.g. six lines of one table) are listed
/// together, the explanation shown once beside them (rowspan).  Nothing when there is none.
void not_reproduced_section(std::ostream& os, const std::vector<ChapterChecks>& all) {
  std::vector<std::pair<std::string, std::vector<std::string>>> by_note;  // note -> its rows
  int ndis = 0;
  for (const auto& c : all) {
    if (!c.present) continue;
    for (const auto& r : c.table.rows) {
      if (c.table.text(r, "status") != "disagree") continue;
      ++ndis;
      const std::string& note = c.table.text(r, "note");
      auto it = std::find_if(by_note.begin(), by_note.end(), [&](const auto& x) { return x.first == note; });
      if (it == by_note.end()) it = by_note.insert(by_note.end(), {note, {}});
      it->second.push_back(disagreement_cells(c, r));
    }
  }
  if (ndis == 0) return;
  std::ostringstream nr;
  for (const auto& [note, rows] : by_note)
    for (std::size_t k = 0; k < rows.size(); ++k) {
      nr << "<tr>" << rows[k];
      if (k == 0)
        nr << "<td class=\"note\"" << (rows.size() > 1 ? " rowspan=\"" + std::to_string(rows.size()) + "\"" : "")
           << ">" << (rows.size() > 1 ? "<em>The " + std::to_string(rows.size()) + " checks beside this note:</em> " : "")
           << html_provenance(html_breakable(note, "/_")) << "</td>";
      nr << "</tr>\n";
    }
  os << "## Not reproduced {.unnumbered}\n\n<div class=\"table-scroll\">\n<table class=\"checks-table\">\n"
     << "<caption>Published values our simulations do not reproduce within the stated tolerance ("
     << ndis << "), with what the investigation found.</caption>\n"
     << "<thead><tr><th>check</th><th>quantity</th><th class=\"num\">thesis</th><th class=\"num\">ours</th>"
        "<th class=\"num\">tolerance</th><th>unit</th><th>what the investigation found</th></tr></thead>\n"
        "<tbody>\n"
     << nr.str() << "</tbody>\n</table>\n</div>\n\n";
}

/// "Errata at a glance": grouped by explanation, one row per cause, not per check.  Nothing when there is none.
void errata_section(std::ostream& os, const std::vector<ChapterChecks>& all) {
  std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>> causes;
  for (const auto& c : all) {
    if (!c.present) continue;
    for (const auto& r : c.table.rows) {
      if (c.table.text(r, "status") != "erratum") continue;
      const std::string& note = c.table.text(r, "note");
      auto it = std::find_if(causes.begin(), causes.end(), [&](const auto& x) { return x.first == note; });
      if (it == causes.end()) it = causes.insert(causes.end(), {note, {}});
      it->second.push_back({c.table.text(r, "id"), c.ch->id});
    }
  }
  if (causes.empty()) return;
  os << "## Errata at a glance {.unnumbered}\n\n<div class=\"table-scroll\">\n<table class=\"checks-table\">\n"
     << "<caption>Thesis statements and values that the thesis's own inputs do not reproduce, one row per "
        "cause.</caption>\n<thead><tr><th>checks</th><th>most likely explanation</th></tr></thead>\n<tbody>\n";
  for (const auto& [note, ids] : causes) {
    os << "<tr><td class=\"id\"><a href=\"#checks-" << ids.front().second << "\">" << html_breakable(ids.front().first, "._")
       << "</a>";
    if (ids.size() > 1) os << " and " << ids.size() - 1 << " more";
    os << "</td><td class=\"note\">" << html_breakable(note, "/_") << "</td></tr>\n";
  }
  os << "</tbody>\n</table>\n</div>\n\n";
}

}  // namespace

std::string front_page(const std::vector<ChapterSource>& chapters, const FrontInfo& info) {
  (void)info;
  const auto all = load_all(chapters);
  const KindCounts n = count_kinds(all);
  std::ostringstream os;
  os << "# About this report {#summary .unnumbered}\n\n";
  kinds_section(os, n);
  if (const std::string m = measurement_sentence(chapters); !m.empty()) os << m << "\n\n";
  chapters_table(os, all, n);
  not_reproduced_section(os, all);
  errata_section(os, all);
  return os.str();
}

}  // namespace drawbend::study
