#include "analysis/printed.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <stdexcept>

namespace drawbend::analysis {

Printed parse_printed(const std::string& raw) {
  // Thousands separators only in the form 1,450 or 12,345,678; any other comma
  // (a decimal comma, a stray one) is an error rather than a silent 100x.
  static const std::regex thousands(R"(^[+-]?\d{1,3}(,\d{3})+(\.\d*)?$)");
  std::string s;
  for (char c : raw)
    if (c != ' ') s += c;
  if (s.find(',') != std::string::npos) {
    if (!std::regex_match(s, thousands)) throw std::invalid_argument("not a number: '" + raw + "'");
    s.erase(std::remove(s.begin(), s.end(), ','), s.end());
  }
  if (s.empty()) throw std::invalid_argument("empty number");
  std::size_t used = 0;
  const double v = std::stod(s, &used);
  if (used != s.size() || !std::isfinite(v)) throw std::invalid_argument("not a number: '" + raw + "'");
  // Decimals printed in the mantissa, shifted by the exponent if any.
  const auto epos = s.find_first_of("eE");
  const std::string mant = s.substr(0, epos);
  const int exponent = epos == std::string::npos ? 0 : std::stoi(s.substr(epos + 1));
  const auto dot = mant.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mant.size() - dot - 1);
  return {v, 0.5 * std::pow(10.0, -(decimals - exponent)), raw};
}

double rounding_tolerance(const std::function<double(const std::vector<double>&)>& f,
                          const std::vector<Printed>& inputs, double output_half_ulp) {
  std::vector<double> x;
  for (const auto& p : inputs) x.push_back(p.value);
  double tol = output_half_ulp;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double h = inputs[i].half_ulp;
    if (h == 0.0) continue;
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    tol += std::abs(f(xp) - f(xm)) / 2.0;  // |df/dx| * h
  }
  return tol;
}

}  // namespace drawbend::analysis
