#pragma once
// The report's front page: what was reproduced, from which commit, on which
// mesh tier, with the check counts split by kind and by chapter, the list of
// published values our simulations do not reproduce, and the errata.
//
// Every number on it is counted from the chapters' checks.csv, values.csv,
// tables/ and figures/; nothing is typed by hand.
#include <string>
#include <vector>

#include "study/report_assembler.hpp"

namespace drawbend::study {

struct FrontInfo {
  std::string citation;  ///< Markdown: the thesis reproduced
  std::string date;      ///< when the report was assembled (UTC, YYYY-MM-DD)
};

/// Counts of one set of checks by status.
struct StatusCounts {
  int pass = 0, fail = 0, erratum = 0, disagree = 0;
  int total() const { return pass + fail + erratum + disagree; }
  void add(const std::string& status);
};

/// Checks against measurement by what they are: blind comparisons (kind
/// `measured`, a value; counted by status), blind yes/no claims on measured
/// data (kind `measured`, unit true=1), and the numbers that are not blind:
/// `fitted` (a parameter was fitted to it) and `selected` (used to accept or
/// reject a model).  Only the blind ones count as agreement with measurement.
struct MeasuredCounts {
  StatusCounts blind, blind_claims;
  int fitted = 0, selected = 0;
};
MeasuredCounts measured_counts(const std::vector<ChapterSource>& chapters);

/// One sentence for the abstract and the front page: how many blind
/// comparisons with measurement agree, and how many measured numbers were
/// fitted to or used to choose (empty when there are none of either).
std::string measurement_sentence(const std::vector<ChapterSource>& chapters);

/// The title block (Pandoc YAML metadata, shown before the table of
/// contents): title, the thesis citation (subtitle), the tier, commit and
/// date (date line), and the abstract.
std::string front_yaml(const std::vector<ChapterSource>& chapters, const FrontInfo& info, const std::string& title);

/// The first section (Markdown with raw HTML tables): counts by kind and per
/// chapter, "Not reproduced", "Errata at a glance".
std::string front_page(const std::vector<ChapterSource>& chapters, const FrontInfo& info);

/// The one-paragraph abstract, generated from the checks.
std::string abstract_paragraph(const std::vector<ChapterSource>& chapters);

/// The chapter's title: the first "# " heading of its intro.md, without its {#id}.
std::string chapter_title(const ChapterSource& ch);

}  // namespace drawbend::study
