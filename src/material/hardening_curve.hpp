#pragma once
// Isotropic hardening curve: flow (true) stress as a piecewise-linear function
// of the equivalent plastic strain, from a table of points (eps_p_i, sigma_i).
//
//  - Between table points: linear interpolation.
//  - Beyond the last point: LINEAR extrapolation with the slope of the last
//    segment (a constant hardening modulus), i.e. the table's last slope is
//    continued indefinitely.  A one-point table is perfectly plastic.
//  - Requirements (checked): at least one point; plastic strain starts at 0
//    and strictly increases; stress is positive and non-decreasing (so every
//    slope H >= 0, which makes the radial return unique).
//
// Segment k (k = 0 .. size()-1) is [eps_p_k, eps_p_{k+1}) with slope H_k; the
// last segment is the extrapolation [eps_p_{n-1}, inf).  Finding the segment
// of a strain is O(1): a uniform bin table maps a strain to a nearby segment.
#include <string>
#include <vector>

namespace drawbend::material {

class HardeningCurve {
 public:
  /// Points (plastic strain, true stress in MPa).  Throws drawbend::InputError
  /// naming `source` and the point index when a requirement above fails.
  HardeningCurve(std::vector<double> plastic_strain, std::vector<double> stress,
                 const std::string& source = "hardening curve");
  /// Reads a CSV with columns `plastic_strain,true_stress_MPa` ('#' comment
  /// lines allowed).  Throws drawbend::InputError with file:line on bad data.
  static HardeningCurve load(const std::string& csv_path);
  /// Voce sigma = sigma0 + Q (1 - exp(-b eps_p)) [MPa] and Swift
  /// sigma = K (e0 + eps_p)^n [MPa], tabulated at 401 points on [0, 1.5] spaced
  /// as (i/400)^2 (dense where the curve bends most; the interpolation error is
  /// below 0.01 MPa for AA5754-O- and AA6016-like constants), the last slope
  /// continued beyond.  Throw std::invalid_argument for non-physical constants
  /// (sigma0, K, e0 <= 0, Q, b, n < 0).
  static HardeningCurve voce(double sigma0, double Q, double b);
  static HardeningCurve swift(double K, double e0, double n);

  std::size_t size() const { return x_.size(); }
  const std::vector<double>& plastic_strains() const { return x_; }
  const std::vector<double>& stresses() const { return y_; }
  double initial_yield() const { return y_.front(); }
  /// The flow stress at 100 % plastic strain, beyond any sheet's necking strain in
  /// tension: a generous bound of the stress a strip carries, so its section times it
  /// bounds a force on the strip (drawbend-deck's --back-tension, model-loop's points).
  double tension_bound() const { return stress(1.0); }

  /// Segment containing ep (0 for ep <= 0, size()-1 for ep >= the last point).
  int segment(double ep) const noexcept {
    const int last = static_cast<int>(x_.size()) - 1;
    if (ep >= x_[last]) return last;
    if (ep <= 0.0) return 0;
    double b = ep * inv_bin_width_;
    int k = bins_[b < max_bin_ ? static_cast<int>(b) : static_cast<int>(max_bin_)];
    while (ep >= x_[k + 1]) ++k;  // ep < x_[last], so this stops at last-1 at most
    while (k > 0 && ep < x_[k]) --k;
    return k;
  }
  /// Flow stress on segment k at plastic strain ep (no search).
  double stress_on(int k, double ep) const noexcept { return y_[k] + h_[k] * (ep - x_[k]); }
  /// Start strain, start stress and slope of segment k.
  double segment_start(int k) const noexcept { return x_[k]; }
  double segment_stress(int k) const noexcept { return y_[k]; }
  double segment_slope(int k) const noexcept { return h_[k]; }
  /// End strain of segment k (+infinity for the last, extrapolated segment).
  double segment_end(int k) const noexcept;

  /// The arrays behind segment() and stress_on(), for code that must compute
  /// their bits in another form (the element kernel's lanes: material/lanes/j2_lanes.hpp).
  struct Table {
    const double *x, *y, *h;  ///< points and slopes
    const int* bins;          ///< bins[b]: segment containing b * bin width
    double inv_bin_width, max_bin;
    int last;                 ///< size() - 1
  };
  Table table() const noexcept {
    return {x_.data(), y_.data(), h_.data(), bins_.data(), inv_bin_width_, max_bin_, static_cast<int>(x_.size()) - 1};
  }

  /// Flow stress sigma_y(ep) in MPa.
  double stress(double ep) const noexcept { return stress_on(segment(ep), ep); }
  /// Hardening modulus d sigma_y / d ep (right derivative) in MPa.
  double slope(double ep) const noexcept { return h_[segment(ep)]; }

 private:
  std::vector<double> x_, y_, h_;  // points and segment slopes (h_.back() = extrapolation slope)
  std::vector<int> bins_;          // bins_[b]: segment containing b * bin width
  double inv_bin_width_ = 0.0;
  double max_bin_ = 0.0;           // index of the last bin, as a double (for the clamp)
};

}  // namespace drawbend::material
