// The held-out gain of one probe of the screen (screen_probe.hpp).
#include <cstddef>
#include <vector>

#include "loop/screen_probe.hpp"

namespace drawbend::loop::detail {

double probe_cv(const ProbeDef& p, const std::vector<int>& rows, const std::vector<double>& z,
                const std::vector<int>& l, const std::vector<double>& w, const std::vector<double>& r,
                const Folds& f, int cell) {
  // pooled index of stratum s: itself, or 0 for the strata of the cell (-1: outside it)
  auto pool = [&](int s) { return cell < 0 ? s : s % p.ngroups == cell ? 0 : -1; };
  double sse0 = 0, sse1 = 0;
  const int S = p.nstrata, L = p.nlev;
  for (int k = 0; k < f.k; ++k) {
    std::vector<double> sm(S, 0), sn(S, 0), sx(S, 0), sxx(S, 0), sxr(S, 0), lm(static_cast<size_t>(S) * L, 0),
        ln(static_cast<size_t>(S) * L, 0);
    double q11 = 0, q12 = 0, q22 = 0, b1 = 0, b2 = 0;
    for (int i : rows)
      if (f.fold[i] != k) sm[p.row_stratum[i]] += r[i], sn[p.row_stratum[i]] += 1;
    for (int s = 0; s < S; ++s) sm[s] = sn[s] > 0 ? sm[s] / sn[s] : 0;
    std::vector<double> mz(S, 0), mz2(S, 0);
    for (int i : rows)
      if (f.fold[i] != k) mz[p.row_stratum[i]] += z[i] / sn[p.row_stratum[i]], mz2[p.row_stratum[i]] += z[i] * z[i] / sn[p.row_stratum[i]];
    for (int i : rows) {
      if (f.fold[i] == k) continue;
      const int s = p.row_stratum[i], ps = pool(s);
      if (ps < 0) continue;
      const double rc = r[i] - sm[s];
      const size_t li = static_cast<size_t>(ps) * L + l[i];
      switch (p.shape) {
        case Shape::levels: lm[li] += rc, ln[li] += 1; break;
        case Shape::wlevels: lm[li] += w[i] * rc, ln[li] += w[i] * w[i]; break;
        case Shape::slopes: sx[ps] += (z[i] - mz[s]) * (z[i] - mz[s]), sxr[ps] += (z[i] - mz[s]) * rc; break;
        case Shape::wslope: q11 += z[i] * z[i] * w[i] * w[i], b1 += z[i] * w[i] * rc; break;
        case Shape::quad: {
          const double f1 = z[i] - mz[s], f2 = z[i] * z[i] - mz2[s];
          q11 += f1 * f1, q12 += f1 * f2, q22 += f2 * f2, b1 += f1 * rc, b2 += f2 * rc;
          break;
        }
      }
    }
    double c1 = 0, c2 = 0;
    if (p.shape == Shape::quad) {
      const double det = q11 * q22 - q12 * q12;
      if (p.dof[0] == 2 && det > 1e-12 * std::max(1.0, q11 * q22)) c1 = (q22 * b1 - q12 * b2) / det, c2 = (q11 * b2 - q12 * b1) / det;
      else if (q11 > 1e-12) c1 = b1 / q11;
    }
    if (p.shape == Shape::wslope && q11 > 1e-12) c1 = b1 / q11;
    for (int i : rows) {
      if (f.fold[i] != k) continue;
      const int s = p.row_stratum[i], ps = pool(s);
      if (sn[s] <= 0) continue;
      double pr = sm[s];
      const size_t li = static_cast<size_t>(std::max(ps, 0)) * L + l[i];
      if (ps >= 0) switch (p.shape) {
        case Shape::levels: pr += ln[li] > 0 ? lm[li] / ln[li] : 0; break;
        case Shape::wlevels: pr += ln[li] > 0 ? w[i] * lm[li] / ln[li] : 0; break;
        case Shape::slopes: pr += sx[ps] > 1e-12 ? sxr[ps] / sx[ps] * (z[i] - mz[s]) : 0; break;
        case Shape::wslope: pr += c1 * z[i] * w[i]; break;
        case Shape::quad: pr += c1 * (z[i] - mz[s]) + c2 * (z[i] * z[i] - mz2[s]); break;
      }
      sse0 += (r[i] - sm[s]) * (r[i] - sm[s]);
      sse1 += (r[i] - pr) * (r[i] - pr);
    }
  }
  return sse0 > 0 ? 1 - sse1 / sse0 : 0.0;
}

}  // namespace drawbend::loop::detail
