#pragma once
// Assembles the chapters into one Pandoc Markdown document.
//
// A chapter's intro.md and results.md are plain Pandoc Markdown plus three
// line directives and one inline form, all resolved against the chapter's
// output directory so that the prose never copies a number by hand:
//   @table tables/x.csv | caption     the CSV as a table
//   @figure figures/x.svg | caption   a figure (id fig-<chapter>-<stem>)
//   @checks                            the chapter's checks table (id checks-<chapter>)
//   {{key}}                            a value from the chapter's values.csv
// Unknown keys and missing files are errors: the report never shows a hole.
#include <string>
#include <vector>

#include "core/csv.hpp"

namespace drawbend::study {

struct ChapterSource {
  std::string id;       ///< directory name, e.g. "ch5-measured"
  std::string src_dir;  ///< chapters/<id> (intro.md, results.md)
  std::string out_dir;  ///< build/chapters/<id> (checks.csv, values.csv, tables/, figures/)
};

/// CSV as a Pandoc pipe table (comment lines dropped).  The cells of
/// `status_column` (if >= 0) become styled spans: [pass]{.status-pass}.
std::string markdown_table(const CsvTable& t, const std::string& caption, int status_column = -1);

/// Expand directives and {{key}} values in one chapter's Markdown.
std::string expand_chapter(const std::string& markdown, const ChapterSource& ch);

/// Why a chapter's results are stale: each recorded input or binary
/// (provenance.csv) that is gone or whose hash has changed (empty: up to date).
std::vector<std::string> chapter_staleness(const ChapterSource& ch);

/// The chapter's provenance table, with a loud STALE block when it is stale.
std::string provenance_section(const ChapterSource& ch);

struct FrontInfo;  // study/report_front.hpp

/// The whole report: title block, front page (study/report_front.hpp, with
/// the list of stale chapters), then each chapter followed by its provenance.
std::string assemble_report(const std::vector<ChapterSource>& chapters, const std::string& title,
                            const FrontInfo& info);

/// The parts of that report: the title block and front page (with the list
/// of stale chapters), and one chapter followed by its provenance.  The
/// report is their concatenation; `drawbend-report --pages` renders each as
/// a page of its own (study/report_pages.hpp).
std::string report_front_markdown(const std::vector<ChapterSource>& chapters, const std::string& title,
                                  const FrontInfo& info);
std::string chapter_markdown(const ChapterSource& ch);

/// Chapters found under src_root (directories with intro.md), sorted by name.
std::vector<ChapterSource> discover_chapters(const std::string& src_root, const std::string& out_root);

}  // namespace drawbend::study
