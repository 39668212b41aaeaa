// Notes audit (issue 51 item 5): every number a chapter shows in its prose
// (intro.md, results.md) or in a disagreement note (data/thesis/
// disagreements.csv, the rows this run applied) comes from the run, as
// {{key}} from the run's values.csv, or says where it comes from with a
// provenance marker.  The rules (written before the first audit of a
// chapter; each later refinement, where the audit misread text, is a commit
// of its own with the case that needed it):
//
//  - {{key}}: substituted from the run; the key must be in the run's
//    values.csv (a note that quotes a value the run does not hold fails).
//  - [text]{.src-KIND}: a hand-typed number with its provenance; the report
//    shows the text with a small superscript tag.  KIND is one of
//      thesis  a printed value of the thesis (its tables in data/thesis, or
//              its text and figures, named beside it: "Table 5.3", "Fig. 2.7");
//      input   a definition or an input, not a result: a mesh size, a pin
//              radius, a tolerance, a limit, a deck setting;
//      run     a result of a named diagnostic run or re-analysis outside
//              this chapter's run (dated, documented in docs/ or in the
//              note), or of an earlier version of the code: not reproduced
//              by this run;
//      pub     a published source other than the thesis, cited beside it.
//  - ::: {.src-KIND} ... ::: (a pandoc fenced div, e.g. around a table of
//    published inputs): every number inside has that provenance, unless it
//    carries its own marker; the report labels the block.
//  - A number with a decimal point anywhere else is a finding.
//  - An integer without a decimal point is a finding only when a unit
//    follows it (N, kN, MPa, mm, %, deg, s, ...; also through a range or list:
//    "99-105 N", "+34 / +37 %"); otherwise it is a count, an ordinal or a
//    year ("2 elements", "step 3", "Hill'48"), and is not audited.
//  - Not numbers: references (Table/Fig./Sec./Eq./Chapter/issue/item/step/
//    case/run ... and the list that follows them), dates (2026-12-02),
//    section and version numbers (6.6.2), identifiers (a digit next to a
//    letter or '_': d12.7, T5.16, Yld2004-18p, 2a), code spans `...`,
//    indented code blocks, TeX math $...$ (a formula's constants), HTML
//    comments, link targets.
//  - Case names: the thesis's pins 12.7, 25.4, 38.1 and 42 mm and draw
//    speeds 6.35, 25.4 and 101.6 mm/s name a case when "mm" or "mm/s" follows
//    (through a list: "12.7, 25.4 and 38.1 mm pins").
//
// The prose debt: prose written before this audit still holds hand-typed
// numbers.  --prose-debt FILE (columns chapter,numbers) states, per chapter,
// how many unmarked numbers its prose holds today; the audit fails when the
// count differs either way (a new hand-typed number, or one fixed without
// lowering the debt).  Every finding is printed all the same.  The notes have
// no debt, and a missing key or an unknown provenance kind always fails.
//
// Usage: notes_audit [--count] [--prose-debt FILE] --notes DISAGREEMENTS.csv SRC_DIR OUT_DIR [SRC_DIR OUT_DIR ...]
// Prints one line per finding (file:line: ...), then the count per chapter;
// exits 1 when a finding is not covered by the debt (0 with --count), 2 on bad input.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "core/csv.hpp"

namespace {

using drawbend::CsvTable;
using drawbend::InputError;
using Values = std::map<std::string, std::string>;

struct Finding {
  std::string where, what;
  bool hard = false;  ///< a missing key or an unknown provenance kind: never covered by the prose debt
};

bool ascii_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
/// A UTF-8 lead byte of a letter (Latin-1 and Greek: 0xC3-0xCF; not the
/// punctuation, dashes, minus or superscripts of 0xE2, nor the no-break space).
bool letter_lead(unsigned char c) { return c >= 0xC3 && c <= 0xCF; }
/// Whether the character that starts at byte e is a letter.
bool letter_at(const std::string& s, std::size_t e) {
  return e < s.size() && (ascii_alpha(s[e]) || letter_lead(static_cast<unsigned char>(s[e])));
}
/// Whether the character that ends just before byte i is a letter.
bool letter_before(const std::string& s, std::size_t i) {
  if (i == 0) return false;
  std::size_t b = i - 1;
  while (b > 0 && (static_cast<unsigned char>(s[b]) & 0xC0) == 0x80) --b;
  return letter_at(s, b);
}
bool alpha(char c) { return ascii_alpha(c) || (c & 0x80); }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)); }

bool starts(const std::string& s, std::size_t i, const std::string& w) { return s.compare(i, w.size(), w) == 0; }

/// Spaces, no-break spaces and thin spaces from i on.
std::size_t skip_space(const std::string& s, std::size_t i) {
  for (;;) {
    if (i < s.size() && s[i] == ' ') ++i;
    else if (starts(s, i, "\u00a0") || starts(s, i, "\u2009")) i += 2 + (s[i] == '\xe2');
    else return i;
  }
}

/// End of the number starting at i (digits, a decimal point followed by a
/// digit; "6.6.2", a section or version number, is read whole).
std::size_t number_end(const std::string& s, std::size_t i, bool& decimal, int* dots = nullptr) {
  decimal = false;
  int n = 0;
  while (i < s.size() && digit(s[i])) ++i;
  while (i + 1 < s.size() && s[i] == '.' && digit(s[i + 1])) {
    decimal = true;
    ++n;
    ++i;
    while (i < s.size() && digit(s[i])) ++i;
  }
  if (dots) *dots = n;
  return i;
}

/// After a number ending at i: skip "-105", " / +37", ", 25.4 and 38.1" (a
/// range or list of numbers) and return where the text goes on.
std::size_t skip_chain(const std::string& s, std::size_t i) {
  for (;;) {
    std::size_t j = skip_space(s, i);
    bool sep = false;
    for (const char* w : {"-", "/", ",", "\u2013", "to ", "and ", "or "})
      if (starts(s, j, w)) {
        j += std::string(w).size();
        sep = true;
        break;
      }
    if (!sep) return i;
    j = skip_space(s, j);
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    else if (starts(s, j, "\u2212")) j += 3;
    if (j >= s.size() || !digit(s[j])) return i;
    bool d;
    i = number_end(s, j, d);
  }
}

/// Whether a unit starts at i (after spaces), as a word of its own.
bool unit_at(const std::string& s, std::size_t i) {
  i = skip_space(s, i);
  static const char* units[] = {"%", "\u00b0", "kN", "MPa", "GPa", "mm/s", "m/s", "mm", "micrometres", "\u00b5m",
                                "mJ", "kJ", "J", "min", "ms", "deg", "N/N", "N", "s", "h", "K"};
  for (const char* u : units) {
    const std::string w = u;
    if (!starts(s, i, w)) continue;
    const std::size_t e = i + w.size();
    if (w == "%" || w == "\u00b0" || e >= s.size() || !(alpha(s[e]) || digit(s[e]))) return true;
  }
  return false;
}

/// The word before position i (skipping spaces, '(' and '~').
std::string word_before(const std::string& s, std::size_t i) {
  while (i > 0 && (s[i - 1] == ' ' || s[i - 1] == '(' || s[i - 1] == '~')) --i;
  std::size_t b = i;
  while (b > 0 && (alpha(s[b - 1]) || s[b - 1] == '.')) --b;
  return s.substr(b, i - b);
}

bool reference_word(std::string w) {
  static const std::set<std::string> refs = {
      "Table", "Tables", "table", "tables", "Fig.", "Figs.", "Figure", "Figures", "figure", "Sec.", "Section",
      "Sections", "section", "Sec", "Secs.", "Eq.", "Eqs.", "Equation", "Chapter", "Chapters", "chapter", "chapters", "Ch.",
      "issue", "issues", "item", "items", "step", "steps", "Step", "turn", "demonstration", "Demonstration",
      "Appendix", "page", "p.", "pp.", "row", "rows", "line", "lines", "case", "cases", "Case", "run", "Run",
      "generator", "Generator", "version", "part", "seed", "seeds", "ch", "v"};
  return refs.count(w) > 0;
}

bool case_name(const std::string& num) {
  static const std::set<std::string> names = {"12.7", "25.4", "38.1", "42", "6.35", "101.6"};
  return names.count(num) > 0;
}

const std::set<std::string> kinds = {"thesis", "input", "run", "pub"};

/// The value keys whose printed value is `num` (a hint for the fix).
std::string holders(const Values& v, const std::string& num) {
  std::string out;
  for (const auto& [k, val] : v)
    if (val == num) out += (out.empty() ? "" : ", ") + std::string("{{") + k + "}}";
  return out;
}

/// Audit one text (a note or a paragraph of prose); a finding at offset i
/// gets `where(i)`.
void audit_text(const std::string& s, const std::function<std::string(std::size_t)>& where_at, const Values& values,
                std::vector<Finding>& out, bool covered = false) {
  std::size_t i = 0;
  while (i < s.size()) {
    if (starts(s, i, "{{")) {
      const std::size_t e = s.find("}}", i);
      if (e == std::string::npos) throw InputError(where_at(i) + ": unclosed '{{'");
      std::string key = s.substr(i + 2, e - i - 2);
      key.erase(0, key.find_first_not_of(' '));
      key.erase(key.find_last_not_of(' ') + 1);
      if (!values.count(key))
        out.push_back({where_at(i), "quotes {{" + key + "}}, which this run's values.csv does not hold", true});
      i = e + 2;
    } else if (s[i] == '$') {
      // TeX math: a formula's numbers are its constants and definitions.
      const bool display = starts(s, i, "$$");
      const std::size_t e = s.find(display ? "$$" : "$", i + (display ? 2 : 1));
      i = e == std::string::npos ? s.size() : e + (display ? 2 : 1);
    } else if (s[i] == '`') {
      const std::size_t e = s.find('`', i + 1);
      i = e == std::string::npos ? s.size() : e + 1;
    } else if (starts(s, i, "<!--")) {
      const std::size_t e = s.find("-->", i);
      i = e == std::string::npos ? s.size() : e + 3;
    } else if (starts(s, i, "](") || starts(s, i, "http")) {
      while (i < s.size() && s[i] != ')' && s[i] != ' ') ++i;
    } else if (s[i] == '[') {
      // A provenance marker [text]{.src-KIND}: its text is not audited.
      const std::size_t close = s.find("]{.src-", i);
      const std::size_t next_open = s.find('[', i + 1);
      if (close != std::string::npos && (next_open == std::string::npos || next_open > close)) {
        const std::size_t e = s.find('}', close);
        const std::string kind = s.substr(close + 7, e == std::string::npos ? std::string::npos : e - close - 7);
        if (e == std::string::npos || !kinds.count(kind))
          out.push_back({where_at(i), "provenance marker '{.src-" + kind + "}': expected thesis, input, run or pub", true});
        i = e == std::string::npos ? s.size() : e + 1;
      } else {
        ++i;
      }
    } else if (digit(s[i])) {
      bool decimal;
      int dots = 0;
      const std::size_t e = number_end(s, i, decimal, &dots);
      const std::string num = s.substr(i, e - i);
      if (dots > 1) {  // a section or version number, not a quantity
        i = e;
        continue;
      }
      const bool ident = letter_before(s, i) || (i > 1 && s[i - 1] == '.' && ascii_alpha(s[i - 2])) ||
                         letter_at(s, e) || (e + 1 < s.size() && s[e] == '.' && ascii_alpha(s[e + 1]));
      const bool date = num.size() == 4 && e + 5 < s.size() && s[e] == '-' && digit(s[e + 1]) && digit(s[e + 2]) &&
                        s[e + 3] == '-' && digit(s[e + 4]);
      if (ident || date) {
        i = e;
        while (i < s.size() && (alpha(s[i]) || digit(s[i]) || s[i] == '.' || s[i] == '-' || s[i] == '_')) {
          if (s[i] == '.' && (i + 1 >= s.size() || !(alpha(s[i + 1]) || digit(s[i + 1])))) break;
          ++i;
        }
        continue;
      }
      const std::size_t chain = skip_chain(s, e);
      if (reference_word(word_before(s, i))) {
        // "Table 5.14/5.15", "Eqs. (3.1)-(3.2)", "Secs. 6.6.2-6.6.3", "Figs. 2.11 and 2.12"
        i = e;
        for (;;) {
          std::size_t j = i;
          while (j < s.size() && std::string("()/,-").find(s[j]) != std::string::npos) ++j;
          if (starts(s, j, "\u2013")) j += 3;
          j = skip_space(s, j);
          if (starts(s, j, "and ")) j = skip_space(s, j + 4);
          if (j < s.size() && s[j] == '(') ++j;
          if (j >= s.size() || !digit(s[j]) || j == i) break;
          bool d;
          i = number_end(s, j, d);
        }
        continue;
      }
      const std::size_t after = skip_space(s, chain);
      const bool mm = starts(s, after, "mm") || starts(s, after, "-mm");
      if (case_name(num) && mm) {
        i = e;
        continue;
      }
      if (!covered && (decimal || unit_at(s, chain))) {
        const std::size_t b = i < 30 ? 0 : i - 30;
        std::string ctx = s.substr(b, std::min<std::size_t>(s.size(), e + 30) - b);
        std::string what = "number '" + num + "' is neither {{key}} from values.csv nor marked [..]{.src-KIND} (\u2026" +
                           ctx + "\u2026)";
        if (const std::string h = holders(values, num); !h.empty()) what += "; values.csv holds it as " + h;
        out.push_back({where_at(i), what});
      }
      i = e;
    } else {
      ++i;
    }
  }
}

Values load_values(const std::string& out_dir) {
  Values v;
  const std::string p = out_dir + "/values.csv";
  if (!std::filesystem::exists(p)) throw InputError(p + ": missing (run the chapter first)");
  const CsvTable t = drawbend::read_csv(p);
  for (const auto& r : t.rows) v[t.text(r, "key")] = t.text(r, "value");
  return v;
}

std::vector<std::string> split_ids(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> ids;
  for (std::string id; in >> id;) ids.push_back(id);
  return ids;
}

bool matches(const std::string& entry, const std::string& id) {
  if (!entry.empty() && entry.back() == '*') return id.rfind(entry.substr(0, entry.size() - 1), 0) == 0;
  return entry == id;
}

bool trim_eq(const std::string& line, const std::string& want) {
  const auto b = line.find_first_not_of(" \t"), e = line.find_last_not_of(" \t");
  return b != std::string::npos && line.substr(b, e - b + 1) == want;
}

/// Prose of the chapter: intro.md and results.md, paragraph by paragraph
/// (a number or a case name may wrap onto the next line), outside code
/// blocks; of a directive line only its caption, on its own.
void audit_prose(const std::string& src_dir, const Values& values, std::vector<Finding>& out) {
  for (const char* part : {"intro.md", "results.md"}) {
    const std::string p = src_dir + "/" + part;
    std::ifstream in(p);
    if (!in) throw InputError(p + ": cannot be read");
    std::string para;
    std::string block;  // the KIND of the ::: {.src-KIND} block the text is in
    std::vector<std::pair<std::size_t, int>> starts;  // offset in para -> line
    auto flush = [&] {
      if (!para.empty())
        audit_text(para, [&](std::size_t i) {
          int n = starts.front().second;
          for (const auto& [off, line] : starts)
            if (off <= i) n = line;
          return p + ":" + std::to_string(n);
        }, values, out, !block.empty());
      para.clear();
      starts.clear();
    };
    std::string line;
    int n = 0;
    bool code = false, indented = false;
    while (std::getline(in, line)) {
      ++n;
      const bool fence = line.rfind("```", 0) == 0;
      if (fence) code = !code;
      if (!code && line.rfind(":::", 0) == 0) {  // a fenced div: ::: {.src-KIND} opens a block, ::: closes it
        flush();
        const auto k = line.find("{.src-");
        if (k != std::string::npos) {
          block = line.substr(k + 6, line.find('}', k) - k - 6);
          if (!kinds.count(block))
            out.push_back({p + ":" + std::to_string(n), "provenance block '{.src-" + block + "}': expected thesis, input, run or pub", true});
        } else if (trim_eq(line, ":::")) {
          block.clear();
        }
        continue;
      }
      const bool directive = line.rfind("@", 0) == 0 || line.rfind("#", 0) == 0;
      const bool blank = line.find_first_not_of(" \t") == std::string::npos;
      if (code || fence || directive || blank) flush();
      // An indented code block: a paragraph whose first line is indented by 4.
      if (para.empty() && !blank) indented = line.rfind("    ", 0) == 0 || line.rfind("\t", 0) == 0;
      if (code || fence || blank || indented || line.rfind("@checks", 0) == 0) continue;
      if (line.rfind("@table ", 0) == 0 || line.rfind("@figure ", 0) == 0) {
        const auto bar = line.find('|');
        line = bar == std::string::npos ? "" : line.substr(bar + 1);
      }
      starts.push_back({para.size(), n});
      para += line + " ";
      if (directive) flush();
    }
    flush();
  }
}

/// The disagreement notes this run applied: rows whose tier fits the run's
/// and whose id (or one of its space-separated ids) matches a check it ran.
void audit_notes(const CsvTable& notes, const std::string& out_dir, const Values& values, std::vector<Finding>& out) {
  const CsvTable checks = drawbend::read_csv(out_dir + "/checks.csv");
  std::string tier = values.count("tier") ? values.at("tier") : "quick";
  for (const auto& r : notes.rows) {
    const std::string rt = notes.has_column("tier") ? notes.text(r, "tier") : "";
    if (!rt.empty() && rt != "all" && rt != tier) continue;
    bool applied = false;
    for (const auto& entry : split_ids(notes.text(r, "id")))
      for (const auto& c : checks.rows) applied = applied || matches(entry, checks.text(c, "id"));
    if (!applied) continue;
    const std::string where = notes.where(r, "explanation") + " (" + notes.text(r, "id") + ")";
    audit_text(notes.text(r, "explanation"), [&](std::size_t) { return where; }, values, out);
  }
}

}  // namespace

int main(int argc, char** argv) {
  bool count_only = false;
  std::string notes_path, debt_path;
  std::vector<std::string> dirs;
  for (int a = 1; a < argc; ++a) {
    const std::string s = argv[a];
    if (s == "--count") count_only = true;
    else if (s == "--notes" && a + 1 < argc) notes_path = argv[++a];
    else if (s == "--prose-debt" && a + 1 < argc) debt_path = argv[++a];
    else dirs.push_back(s);
  }
  if (notes_path.empty() || dirs.empty() || dirs.size() % 2) {
    std::cerr << "usage: notes_audit [--count] [--prose-debt FILE] --notes DISAGREEMENTS.csv SRC_DIR OUT_DIR [SRC_DIR OUT_DIR ...]\n";
    return 2;
  }
  try {
    const CsvTable notes = drawbend::read_csv(notes_path);
    std::map<std::string, int> debt;
    if (!debt_path.empty()) {
      const CsvTable d = drawbend::read_csv(debt_path);
      for (const auto& r : d.rows) debt[d.text(r, "chapter")] = static_cast<int>(d.number(r, "numbers"));
    }
    int total = 0, failing = 0;
    std::ostringstream summary;
    for (std::size_t k = 0; k < dirs.size(); k += 2) {
      const Values values = load_values(dirs[k + 1]);
      std::vector<Finding> prose, note;
      audit_prose(dirs[k], values, prose);
      audit_notes(notes, dirs[k + 1], values, note);
      for (const auto* list : {&prose, &note})
        for (const auto& f : *list) std::cout << f.where << ": " << f.what << "\n";
      const std::string id = std::filesystem::path(dirs[k]).filename().string();
      auto hard_in = [](const std::vector<Finding>& l) {
        return static_cast<int>(std::count_if(l.begin(), l.end(), [](const Finding& f) { return f.hard; }));
      };
      const int hard = hard_in(prose) + hard_in(note);
      const int soft_prose = static_cast<int>(prose.size()) - hard_in(prose);
      const int unmarked_notes = static_cast<int>(note.size()) - hard_in(note);
      const int owed = debt.count(id) ? debt[id] : 0;
      summary << "notes audit: " << id << ": " << prose.size() << " in prose, " << note.size() << " in notes";
      if (!debt_path.empty()) summary << " (prose debt " << owed << ")";
      summary << "\n";
      if (soft_prose != owed && !debt_path.empty())
        summary << "notes audit: " << id << ": " << soft_prose << " unmarked numbers in the prose where the debt ("
                << debt_path << ") says " << owed << (soft_prose < owed ? ": lower the debt" : ": mark or substitute them")
                << "\n";
      failing += hard + unmarked_notes + (debt_path.empty() ? soft_prose : (soft_prose != owed ? 1 : 0));
      total += static_cast<int>(prose.size() + note.size());
    }
    std::cout << summary.str() << "notes audit: " << total << " numbers neither from the run nor marked\n";
    return failing > 0 && !count_only ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "input error: " << e.what() << "\n";
    return 2;
  }
}
