#pragma once
// Loaders for the thesis numbers under data/thesis/ (see data/thesis/README.md).
// Values keep their printed digits (analysis::Printed) so that re-derivation
// tolerances follow from what the thesis actually printed.
#include <optional>
#include <string>
#include <vector>

#include "analysis/linear_fit.hpp"
#include "analysis/printed.hpp"
#include "analysis/stribeck.hpp"
#include "core/csv.hpp"

namespace drawbend::study {

using analysis::Printed;

/// A printed number in a CSV cell; errors name file, line and column.  Its
/// half unit is the finest one printed in that column (trailing zeros dropped
/// by the thesis do not widen a tolerance).
Printed printed(const CsvTable& t, const CsvRow& r, const std::string& col);

/// A row of a force-fit table: Tables 5.3, 5.5-5.12.
struct FitEntry {
  std::string direction;  ///< RD or TD
  double speed_mm_s = 0;  ///< 0 for the rotating-pin bending fits (Table 5.3)
  double pin_mm = 0;
  Printed slope, intercept;
  std::optional<analysis::Range> range;  ///< absent in Tables 5.11/5.12
  std::string source;                    ///< "Table 5.5"

  analysis::LinearFit fit() const;
};

/// Load a fit table; columns direction/speed_mm_s and fback_min_N/fback_max_N
/// are optional (defaults: RD, speed 0, no range).
std::vector<FitEntry> load_fits(const std::string& path, const std::string& source);

/// Find the entry for (direction, speed, pin); throws if absent.
const FitEntry& find_fit(const std::vector<FitEntry>& fits, const std::string& direction, double speed, double pin);

/// Tables 3.1 / 3.3 (parameter,value,unit).
using analysis::load_stribeck;  // analysis/stribeck.hpp

/// A row of a per-case table keyed by direction, speed and pin (Tables 5.14, 5.15, 5.17, 5.18).
struct CaseValue {
  std::string direction;
  double speed_mm_s = 0, pin_mm = 0;
  Printed value;
};
std::vector<CaseValue> load_cases(const std::string& path, const std::string& value_column);
const CaseValue& find_case(const std::vector<CaseValue>& v, const std::string& direction, double speed, double pin);

/// A published scalar from data/thesis/scalars.csv by id; throws if absent.
Printed scalar(const std::string& scalars_csv, const std::string& id);

bool same(double a, double b);  ///< equality of printed keys (speeds, diameters)

}  // namespace drawbend::study
