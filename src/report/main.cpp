// drawbend-report: assemble the chapters into build/report/study.md and run
// Pandoc to write one self-contained HTML file (math as MathML, figures as
// embedded SVG).
//
// 1. Read options.  2. Find the chapters.  3. Expand their Markdown.
// 4. Run Pandoc (--columns=100000: a pipe table never gets fixed relative
//    column widths, so the browser sizes its columns and a wide table scrolls).
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

namespace {

// The thesis as its source text names it: the title page of
// /work/shared/seed/000_9db729c8f9049a50.txt prints the title and an empty
// "By" line, so the author, university and year are not stated there.
const char* thesis_citation =
    "*A Draw-Bend Friction Test Applied to Measurement and Modeling of Anisotropic Friction on Sheet Metal*, "
    "PhD thesis (its source text names no author, university or year; its cup-drawing experiments, Sec. 6.6, "
    "were run at McMaster University).";

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
  opt.add(out, "out", "HTML file to write (the Markdown is written beside it)");
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
    const std::string md = std::filesystem::path(out).replace_extension(".md").string();
    write_file_atomic(md, study::assemble_report(chapters, title, front));
    const std::string tmp = out + ".tmp.html";
    const std::string cmd = pandoc + " '" + md + "' --from markdown --to html5 --standalone --self-contained" +
                            " --mathml --toc --toc-depth=2 --columns=100000 --css '" + css + "' -o '" + tmp + "'";
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("pandoc failed: " + cmd);
    std::filesystem::rename(tmp, out);
    std::cout << "report: " << out << " (" << chapters.size() << " chapters)\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "drawbend-report: " << e.what() << "\n";
    return 2;
  }
}
