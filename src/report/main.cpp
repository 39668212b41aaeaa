// drawbend-report: assemble the chapters into build/report/study.md and run
// Pandoc to write one self-contained HTML file (math as MathML, figures as
// embedded SVG), the archive; with --pages DIR also one page per chapter,
// DIR/index.html the front page (study/report_pages.hpp).
//
// 1. Read options.  2. Find the chapters.  3. Expand their Markdown.
// 4. Run Pandoc (--columns=100000: a pipe table never gets fixed relative
//    column widths, so the browser sizes its columns and a wide table scrolls).
// 5. With --pages: Pandoc on each page's Markdown, then the pages linked.
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <set>
#include <iostream>

#include "core/csv.hpp"
#include "core/options.hpp"
#include "study/checks.hpp"
#include "study/report_assembler.hpp"
#include "study/list_audit.hpp"
#include "study/report_front.hpp"
#include "study/report_pages.hpp"

namespace {

// The thesis as its source text names it: the title page of
// /work/shared/seed/000_9db729c8f9049a50.txt prints the title and an empty
// "By" line, so the author, university and year are not stated there.
const char* thesis_citation =
    "*A Draw-Bend Friction Test Applied to Measurement and Modeling of Anisotropic Friction on Sheet Metal*, "
    "PhD thesis (its source text names no author, university or year; its cup-drawing experiments, Sec. 6.6, "
    "were run at McMaster University).";

/// How the page bar names a chapter: its title up to " — " ("Chapter 5"), or
/// the whole title (without its {#id}) when short, else the chapter's id.
std::string chapter_label(const drawbend::study::ChapterSource& ch) {
  const std::string text = drawbend::read_file(ch.src_dir + "/intro.md");
  if (text.rfind("# ", 0) != 0) return ch.id;
  std::string first = text.substr(2, text.find('\n') - 2);
  first = first.substr(0, first.find(" {"));
  const std::size_t dash = first.find(" \u2014 ");
  if (dash != std::string::npos) first = first.substr(0, dash);
  return first.empty() || first.size() > 40 ? ch.id : first;
}

/// Pandoc: one Markdown file to one self-contained HTML page with its contents.
void run_pandoc(const std::string& pandoc, const std::string& md, const std::string& html, const std::string& css,
                const std::string& extra) {
  const std::string tmp = html + ".tmp.html";
  const std::string cmd = pandoc + " '" + md + "' --from markdown --to html5 --standalone --self-contained" +
                          " --mathml --toc --toc-depth=2 --columns=100000 --css '" + css + "'" + extra + " -o '" + tmp + "'";
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("pandoc failed: " + cmd);
  std::filesystem::rename(tmp, html);
}

/// The date the report is assembled (UTC), or SOURCE_DATE_EPOCH's for reproducible builds.
std::string report_date() {
  std::time_t t = std::time(nullptr);
  if (const char* e = std::getenv("SOURCE_DATE_EPOCH")) t = static_cast<std::time_t>(std::atoll(e));
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&t));
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace drawbend;
  std::string chapters_src = "chapters", chapters_out = "build/chapters", out = "build/report/study.html";
  std::string pandoc = "pandoc", css = "report/style.css", title = "drawbend: a reproduction of the draw-bend friction study";
  Options opt("drawbend-report", "Assemble the chapter pages into one HTML report with Pandoc.");
  opt.add(chapters_src, "chapters-src", "directory with chapters/<id>/{intro,results}.md");
  opt.add(chapters_out, "chapters-out", "directory with the chapters' generated outputs");
  opt.add(out, "out", "the report as one HTML file, for archiving (the Markdown is written beside it; empty: none)");
  std::string pages;
  opt.add(pages, "pages", "folder for the report as pages: index.html (the front page) and one page per chapter "
                          "(their Markdown in md/; empty: none)");
  opt.add(pandoc, "pandoc", "pandoc executable");
  opt.add(css, "css", "style sheet embedded in the HTML");
  opt.add(title, "title", "report title");
  study::FrontInfo front{thesis_citation, report_date()};
  opt.add(front.citation, "citation", "the thesis reproduced, as shown on the front page (Markdown)");
  std::string errata;
  opt.add(errata, "errata", "errata list to audit: every entry must match a check (empty: skip)");
  try {
    if (!opt.parse(argc, argv)) return 0;
    const auto chapters = study::discover_chapters(chapters_src, chapters_out);
    if (chapters.empty()) throw InputError(chapters_src + ": no chapters (directories with intro.md)");
    if (!errata.empty()) {
      // The disagreements list sits beside the errata list and is audited the same way.
      const std::string disagreements =
          (std::filesystem::path(errata).parent_path() / "disagreements.csv").string();
      for (const std::string& list : {errata, disagreements}) {
        if (!std::filesystem::exists(list)) continue;
        // Audited per tier, each entry on the tiers its chapter ran (study/list_audit.hpp).
        const std::vector<std::string> dead = study::unused_list_entries(chapters, list);
        for (const auto& d : dead) std::cerr << list << ": entry '" << d << "' matches no check\n";
        if (!dead.empty()) throw InputError(list + ": " + std::to_string(dead.size()) + " unused entries");
      }
    }
    for (const auto& ch : chapters)
      for (const auto& s : study::chapter_staleness(ch))
        std::cerr << "drawbend-report: warning: chapter " << ch.id << " is STALE: " << s << "\n";
    if (out.empty() && pages.empty()) throw InputError("--out and --pages are both empty: nothing to write");
    if (!out.empty()) {
      const std::string md = std::filesystem::path(out).replace_extension(".md").string();
      write_file_atomic(md, study::assemble_report(chapters, title, front));
      run_pandoc(pandoc, md, out, css, "");
      std::cout << "report: " << out << " (" << chapters.size() << " chapters, one file)\n";
    }
    if (!pages.empty()) {
      namespace fs = std::filesystem;
      fs::create_directories(fs::path(pages) / "md");
      std::vector<study::HtmlPage> html;
      auto render = [&](const std::string& stem, const std::string& label, const std::string& markdown,
                        const std::string& extra) {
        const std::string md = (fs::path(pages) / "md" / (stem + ".md")).string();
        const std::string page = (fs::path(pages) / (stem + ".html")).string();
        write_file_atomic(md, markdown);
        run_pandoc(pandoc, md, page, css, extra);
        html.push_back({stem + ".html", label, read_file(page)});
      };
      render("index", "Front page", study::report_front_markdown(chapters, title, front), "");
      for (const auto& ch : chapters) {
        const std::string label = chapter_label(ch);
        std::string quoted;  // the page title inside the shell's single quotes
        for (char c : label + ": " + ch.id) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
        render(ch.id, label, study::chapter_markdown(ch), " --metadata pagetitle='" + quoted + "'");
      }
      study::link_pages(html);
      for (const auto& p : html) write_file_atomic((fs::path(pages) / p.file).string(), p.html);
      std::cout << "report: " << pages << "/index.html and " << chapters.size() << " chapter pages\n";
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "drawbend-report: " << e.what() << "\n";
    return 2;
  }
}
