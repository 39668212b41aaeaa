#pragma once
// A local bump of a column as a form (h50-bump, heldout_record.md): a
// Gaussian bump of the column x,
//   b(x) = exp(-((x - c) / w)^2 / 2),
// centre c and width w (the standard deviation of the Gaussian, in the
// column's units) scanned where the bump explains the most of the current
// model's held-out residual.  The forms (form_bumps.cpp) put it on mu
// (generic_smooth with n_basis 1 and Effect::bump_width > 0) and on the
// force channel (force_offset, likewise): one fitted parameter, the bump's
// height, with c and w counted as two searched parameters by the F test
// (f_test's extra_q) and never handed the step by the one-SE rule
// (FormTrial::searched).
#include <optional>
#include <vector>

namespace drawbend::loop {

/// The grid scan_bump searches: 49 centres over the range [lo, hi] of the
/// rows it scans (lo + j (hi - lo) / 48, j = 0..48) and 7 widths geometric
/// from 0.03 to 0.33 of the range (0.03 (0.33 / 0.03)^(k / 6), k = 0..6: a
/// narrow bump and a wide one are equally apart in log width).
constexpr int kBumpCentres = 49;
constexpr int kBumpWidths = 7;
constexpr double kBumpWidthMin = 0.03, kBumpWidthMax = 0.33;
/// A bump counts only with at least kBumpMinValues distinct values of x and
/// max(kBumpMinRows, n / kBumpRowShare) of the n scanned rows within
/// kBumpReach widths of its centre.
constexpr int kBumpMinValues = 5;
constexpr int kBumpMinRows = 10;
constexpr int kBumpRowShare = 20;
constexpr double kBumpReach = 1.5;

/// exp(-((x - c) / w)^2 / 2).
double bump_value(double x, double c, double w);

/// The bump of x at centre c and width w as a basis column: b(x_i), centred
/// and scaled to unit standard deviation over the rows (as the spline basis
/// of model.cpp: the constant stays with mu, the fit is well conditioned);
/// all zeros when the bump does not vary over the rows.
std::vector<double> bump_basis(const std::vector<double>& x, double c, double w);

/// A bump's centre and width (column units), and the sum of squares of the
/// residual its slope explains.
struct Bump {
  double centre = 0, width = 0, explained = 0;
};

/// Over the grid above (the range of x over the rows with use[i] != 0 and
/// x and r finite; use empty: every such row), the supported bump whose
/// slope explains the largest sum of squares of r: (sum (b - b_mean)(r -
/// r_mean))^2 / sum (b - b_mean)^2, from the count and sum of r per distinct
/// value of x (so each grid point costs one pass over the distinct values).
/// Ties: the narrower width, then the lower centre.  Empty with fewer than
/// kBumpMinValues distinct values, no range, or no supported bump that
/// explains anything.
std::optional<Bump> scan_bump(const std::vector<double>& x, const std::vector<double>& r,
                              const std::vector<char>& use = {});

/// A step of a column as a form (h50-step, heldout_record.md): s(x) = [x >
/// c], its threshold c scanned where the step explains the most of the
/// current model's held-out residual, on mu (generic_smooth) or on the force
/// channel (force_offset), overall or in one cell; one fitted parameter, its
/// height, with c counted as one searched parameter by the F test.  The
/// overall step on mu is generic_step (its threshold fitted by forms.cpp).

/// [x > c] as a basis column, centred and scaled to unit standard deviation
/// over the rows (as bump_basis); all zeros when it does not vary.
std::vector<double> step_basis(const std::vector<double>& x, double c);

/// A step's threshold (column units), and the sum of squares of the residual
/// its slope explains.
struct Step1 {
  double at = 0, explained = 0;
};

/// Over the thresholds midway between consecutive distinct values of x (over
/// the rows with use[i] != 0 and x and r finite; use empty: every such row),
/// the step with at least 2 distinct values and max(kBumpMinRows, n /
/// kBumpRowShare) of the n rows on each side whose slope explains the largest
/// sum of squares of r, (S_above - n_above R / n)^2 / (n_above (1 - n_above /
/// n)), from the count and sum of r per distinct value.  Ties: the lower
/// threshold.  Empty with fewer than kBumpMinValues distinct values or no
/// supported step that explains anything.
std::optional<Step1> scan_step(const std::vector<double>& x, const std::vector<double>& r,
                               const std::vector<char>& use = {});

}  // namespace drawbend::loop
