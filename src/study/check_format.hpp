#pragma once
// How the report shows a checks.csv: numbers rounded to the digits their
// tolerance resolves, real units ("1" for a dimensionless number), yes/no
// for the thesis's claims, and the kind of each check.
//
// checks.csv is read by column name.  The column `kind` (rederived,
// simulated, measured, fitted, selected, verification, health, software) may be absent in
// outputs written before checks had kinds: such checks count as
// "unclassified", so the report still builds.
#include <string>

#include "core/csv.hpp"

namespace drawbend::study {

/// A claim (yes/no statement tested on numbers) is stored as 1/0 with unit "true=1".
bool is_boolean_unit(const std::string& unit);

/// The unit as shown: "1" for a dimensionless number ("-" or empty), "" for a claim.
std::string display_unit(const std::string& unit);

/// `v` rounded to the decimal place of the tolerance's leading digit, with at
/// least 3 and at most 6 significant digits (tol <= 0: 6 significant digits).
/// Examples: (74.105281, 5) -> "74.1"; (118.647, 0.005) -> "118.647";
/// (168.29819, 20) -> "168".
std::string round_for_display(double v, double tol);

/// A checks.csv cell (thesis or ours) as shown: yes/no for a claim, else rounded.
/// Text that is not a number is returned unchanged.
std::string display_value(const std::string& cell, const std::string& unit, const std::string& tolerance);

/// The tolerance as shown ("-" for a claim, whose tolerance is exact).
std::string display_tolerance(const std::string& tolerance, const std::string& unit);

/// The kind of a check row, "unclassified" when checks.csv has no `kind` column.
std::string kind_of(const CsvTable& t, const CsvRow& r);

/// What a kind compares, for the report's tables ("our simulations against the thesis's ...").
std::string kind_label(const std::string& kind);

/// Kinds in the order the report lists them.
const std::vector<std::string>& kind_order();

/// Escape &, <, > and " for HTML.
std::string html_escape(const std::string& s);
/// Escaped text that may break after each character of `after` (<wbr>): a
/// check id at '.' and '_', a quantity or a note at '/' and '_', so that one
/// long name does not set the width of a checks table and push its note
/// column out of view (report/check_html.py measures the narrowest layout).
std::string html_breakable(const std::string& s, const std::string& after);
/// HTML text (already escaped) with each provenance marker of a note,
/// "[161.6 N]{.src-thesis}" (tests/docs/notes_audit.cpp), as a span that the
/// style sheet tags with its source: <span class="src src-thesis">161.6 N</span>.
std::string html_provenance(const std::string& html);

/// A chapter's checks as an HTML table (raw HTML inside the Markdown, so the
/// report controls its classes): check, kind, quantity, thesis, ours,
/// tolerance, unit, status (coloured), note.
std::string checks_html_table(const CsvTable& t, const std::string& caption);

}  // namespace drawbend::study
