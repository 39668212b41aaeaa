#pragma once
// Columns computed from the measured forces (issue 50, new kinds of data).
//
// A lab may send, beside the forces, what it computed from them: its own mu,
// the friction force, the force ratio.  Such a column carries the outlet
// force's own noise, so it "explains" the residual of any model, whatever the
// physics: screened, it would be named on data with no undeclared effect.
//
// The check (per numeric extra column that varies within tests; rows with a
// value; per pin, at least 20 rows): least squares of the column on a fixed
// smooth basis of the forces,
//   without F_out: 1, F_back, ln F_back, F_back^2
//   with F_out:    the above and F_out, ln F_out, ln(F_out / F_back)^2,
//                  F_out^2, F_out F_back
// summed over the pins.  The column is the measured forces' when the basis
// with F_out leaves less than `kResponseFraction` of the variance the basis
// without it leaves, and the latter is not itself almost nothing (a column
// the back tension alone determines is not the response's).
// Why 1e-3: a physical variable x acting on the outlet force with an effect
// of k noise sd can be read back from F_out at best to a fraction 1 / (1 +
// k^2) of its variance (the noise is independent of x), so 1e-3 takes k > 31
// noise sd in a single cell, far beyond any effect the loop is built for;
// mu = ln(F_out / F_back) / (pi / 2) written to 4 decimals leaves about 1e-6.
// Not caught: a test-level summary (one value per test), or a column rounded
// so coarsely that the rounding is as large as the noise it carries.
#include <string>
#include <vector>

#include "loop/measured.hpp"

namespace drawbend::loop {

inline constexpr double kResponseFraction = 1e-3;

struct ResponseColumn {
  std::string name;
  double fraction = 0;  ///< residual variance with F_out / without it
};

/// The extra columns that the measured forces determine, in column order.
std::vector<ResponseColumn> response_columns(const Dataset& data);

}  // namespace drawbend::loop
