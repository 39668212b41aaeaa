#pragma once
// The audit of the errata and disagreement lists (data/thesis/errata.csv,
// disagreements.csv) against the checks the chapters actually ran.
//
// Every entry must name at least one check, or the list could hide a check
// that was renamed or removed.  Entries are per mesh tier (a disagreement seen
// on the quick mesh only), and `make` may run one chapter on the quick tier
// beside full-tier others.  So an entry is audited only on the tiers its own
// chapter ran (its chapter is the check id's first segment, e.g. "ch8" of
// "ch8.fb.d42"), and an entry whose chapter ran on no tier at all (a misspelt
// id) is unused outright.
#include <string>
#include <vector>

#include "study/report_assembler.hpp"

namespace drawbend::study {

/// The chapter segment of a check id or list entry: "ch8" for "ch8.fb.d42".
std::string chapter_of(const std::string& check_id);

/// The tier a chapter's values.csv states ("" when it states none or has no values.csv).
std::string chapter_tier(const ChapterSource& ch);

/// The entries of `list_csv` (an errata or disagreements list with an
/// optional `tier` column) that match no check of the chapters' checks.csv,
/// audited as described above.  A chapter that states no tier counts as quick.
std::vector<std::string> unused_list_entries(const std::vector<ChapterSource>& chapters, const std::string& list_csv);

}  // namespace drawbend::study
