#include "study/report_assembler.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>

#include "core/provenance.hpp"
#include "study/check_format.hpp"
#include "study/report_front.hpp"

namespace drawbend::study {

namespace fs = std::filesystem;

namespace {

std::string escape_cell(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '|') o += "\\|";
    else if (c == '\n') o += ' ';
    else o += c;
  }
  return o.empty() ? " " : o;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// "path | caption" -> {path, caption}
std::pair<std::string, std::string> split_directive(const std::string& rest) {
  const auto bar = rest.find('|');
  if (bar == std::string::npos) return {trim(rest), ""};
  return {trim(rest.substr(0, bar)), trim(rest.substr(bar + 1))};
}

std::string stem_of(const std::string& path) { return fs::path(path).stem().string(); }

std::string checks_table(const ChapterSource& ch) {
  const CsvTable t = read_csv(ch.out_dir + "/checks.csv");
  return "::: {#checks-" + ch.id + " .checks}\n\n" +
         checks_html_table(t, "Checks of " + ch.id + " against the thesis (" + std::to_string(t.rows.size()) +
                                  " checks; numbers rounded to the digits the tolerance resolves).") +
         "\n:::\n";
}

std::map<std::string, std::string> load_values(const ChapterSource& ch) {
  std::map<std::string, std::string> v;
  const std::string path = ch.out_dir + "/values.csv";
  if (!fs::exists(path)) return v;
  const CsvTable t = read_csv(path);
  for (const auto& r : t.rows) {
    const std::string unit = t.text(r, "unit");
    v[t.text(r, "key")] = t.text(r, "value") + (unit.empty() ? "" : "\u00a0" + unit);
  }
  return v;
}

}  // namespace

std::vector<std::string> chapter_staleness(const ChapterSource& ch) {
  const std::string p = ch.out_dir + "/provenance.csv";
  if (!fs::exists(p)) return {"no provenance.csv: the inputs of these results are unknown (rerun the chapter)"};
  return stale_inputs(p);
}

std::string provenance_section(const ChapterSource& ch) {
  std::ostringstream os;
  const auto stale = chapter_staleness(ch);
  os << "\n## Provenance of these results {.unnumbered .provenance}\n\n";
  if (!stale.empty()) {
    os << "::: {.stale}\n**STALE**: these results do not match the current inputs:\n\n";
    for (const auto& s : stale) os << "- " << escape_cell(s) << "\n";
    os << "\n:::\n\n";
  }
  const std::string p = ch.out_dir + "/provenance.csv";
  if (!fs::exists(p)) return os.str();
  const CsvTable t = read_csv(p);
  os << "| what | file | FNV-1a 64 | bytes |\n|---|---|---|---|\n";
  for (const auto& r : t.rows) {
    const fs::path f(t.text(r, "path"));
    const std::string shown = t.text(r, "kind") == "version" ? f.string() : (f.parent_path().filename() / f.filename()).string();
    os << "| " << escape_cell(t.text(r, "kind")) << " | `" << shown << "` | " << escape_cell(t.text(r, "fnv1a64"))
       << " | " << escape_cell(t.text(r, "bytes")) << " |\n";
  }
  os << "\n: Inputs read by chapter " << ch.id << " and the binary that computed its results"
     << (stale.empty() ? " (all match the current files)." : " (STALE: see above).") << "\n";
  return os.str();
}

std::string markdown_table(const CsvTable& t, const std::string& caption, int status_column) {
  std::ostringstream os;
  os << "| ";
  // A column name may break after each '_' (sets_at_noise_level), so that
  // the names do not set the width of a table of short numbers.
  for (const auto& h : t.header) {
    std::string cell = escape_cell(h);
    for (std::size_t at = cell.find('_'); at != std::string::npos; at = cell.find('_', at + 6))
      cell.insert(at + 1, "<wbr>");
    os << cell << " | ";
  }
  os << "\n|";
  for (std::size_t i = 0; i < t.header.size(); ++i) os << "---|";
  os << "\n";
  for (const auto& r : t.rows) {
    os << "| ";
    for (std::size_t i = 0; i < r.cells.size(); ++i) {
      if (static_cast<int>(i) == status_column)
        os << "[" << r.cells[i] << "]{.status-" << r.cells[i] << "} | ";
      else
        os << escape_cell(r.cells[i]) << " | ";
    }
    os << "\n";
  }
  if (!caption.empty()) os << "\n: " << caption << "\n";
  return os.str();
}

namespace {

/// Text with the absolute build and source folders of `ch` written relative
/// ("build/chapters/...", "data/..."): the report shows no machine's paths.
std::string relative_paths(std::string text, const ChapterSource& ch) {
  fs::path src = fs::absolute(ch.src_dir).lexically_normal();
  if (src.has_extension()) src = src.parent_path();  // chapters/<id>/intro.md
  const fs::path repo = src.parent_path().parent_path();
  const fs::path build = fs::absolute(ch.out_dir).lexically_normal().parent_path().parent_path();
  const std::pair<fs::path, std::string> swaps[] = {{build, build.filename().string() + "/"}, {repo, ""}};
  for (const auto& [root, to] : swaps) {
    if (root.empty() || root == root.root_path()) continue;  // never "/": it would eat every "https://"
    const std::string from = root.string() + "/";
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  }
  return text;
}

/// A continuation line of a list item that starts with "N." or "N)" (a
/// wrapped "(22 instead of\n  10) brought", or a {{value}} that expands to a
/// number at the start of a line) would start a numbered list inside the
/// item: escape its marker.  Only indented lines that follow a non-blank line.
void escape_stray_marker(std::string& line, bool prev_blank) {
  if (prev_blank) return;
  std::size_t i = 0;
  while (i < line.size() && line[i] == ' ') ++i;
  if (i == 0) return;
  std::size_t j = i;
  while (j < line.size() && j - i < 9 && std::isdigit(static_cast<unsigned char>(line[j]))) ++j;
  if (j == i || j >= line.size() || (line[j] != '.' && line[j] != ')')) return;
  if (j + 1 < line.size() && line[j + 1] != ' ') return;
  line.insert(j, "\\");
}

}  // namespace

std::string expand_chapter(const std::string& markdown, const ChapterSource& ch) {
  const auto values = load_values(ch);
  std::istringstream in(markdown);
  std::ostringstream out;
  std::string line;
  int lineno = 0;
  bool previous_blank = true, in_code = false;
  const std::string where = ch.src_dir;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string loc = where + ":" + std::to_string(lineno);
    // Inline {{key}} values first, so that captions can quote them too.
    std::string expanded;
    std::size_t pos = 0;
    while (true) {
      const auto open = line.find("{{", pos);
      if (open == std::string::npos) {
        expanded += line.substr(pos);
        break;
      }
      const auto close = line.find("}}", open);
      if (close == std::string::npos) throw InputError(loc + ": unclosed '{{'");
      const std::string key = trim(line.substr(open + 2, close - open - 2));
      const auto it = values.find(key);
      if (it == values.end()) throw InputError(loc + ": unknown value key '" + key + "' (not in values.csv)");
      expanded += line.substr(pos, open - pos) + it->second;
      pos = close + 2;
    }
    line = expanded;
    const bool prev_blank = previous_blank;
    previous_blank = trim(line).empty();
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    if (line.rfind("@table ", 0) == 0) {
      auto [path, caption] = split_directive(line.substr(7));
      out << "\n" << relative_paths(markdown_table(read_csv(ch.out_dir + "/" + path), caption), ch) << "\n";
      continue;
    }
    if (line.rfind("@figure ", 0) == 0) {
      auto [path, caption] = split_directive(line.substr(8));
      const std::string abs = ch.out_dir + "/" + path;
      if (!fs::exists(abs)) throw InputError(loc + ": figure " + abs + " does not exist");
      out << "\n![" << caption << "](" << abs << "){#fig-" << ch.id << "-" << stem_of(path)
          << " width=\"100%\"}\n\n";
      continue;
    }
    if (trim(line) == "@checks") {
      out << "\n" << relative_paths(checks_table(ch), ch) << "\n";
      continue;
    }
    if (!in_code) escape_stray_marker(expanded, prev_blank);
    out << relative_paths(expanded, ch) << "\n";
  }
  return out.str();
}

std::string report_front_markdown(const std::vector<ChapterSource>& chapters, const std::string& title,
                                  const FrontInfo& info) {
  std::ostringstream os;
  os << front_yaml(chapters, info, title) << front_page(chapters, info);
  std::string stale_list;
  for (const auto& ch : chapters)
    if (!chapter_staleness(ch).empty()) stale_list += (stale_list.empty() ? "" : ", ") + ch.id;
  if (!stale_list.empty())
    os << "\n::: {.stale}\n**STALE results**: " << stale_list
       << " were computed from inputs that have changed since; their Provenance sections list which.\n:::\n";
  return os.str();
}

std::string chapter_markdown(const ChapterSource& ch) {
  std::ostringstream os;
  os << "\n";
  for (const char* part : {"intro.md", "results.md"}) {
    const std::string p = ch.src_dir + "/" + part;
    if (!fs::exists(p)) throw InputError(p + ": missing");
    ChapterSource located = ch;
    located.src_dir = p;
    os << expand_chapter(read_file(p), located) << "\n";
  }
  os << provenance_section(ch);
  return os.str();
}

std::string assemble_report(const std::vector<ChapterSource>& chapters, const std::string& title,
                            const FrontInfo& info) {
  std::string md = report_front_markdown(chapters, title, info);
  for (const auto& ch : chapters) md += chapter_markdown(ch);
  return md;
}

std::vector<ChapterSource> discover_chapters(const std::string& src_root, const std::string& out_root) {
  std::vector<ChapterSource> v;
  for (const auto& e : fs::directory_iterator(src_root))
    if (e.is_directory() && fs::exists(e.path() / "intro.md")) {
      const std::string id = e.path().filename().string();
      v.push_back({id, e.path().string(), out_root + "/" + id});
    }
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return v;
}

}  // namespace drawbend::study
