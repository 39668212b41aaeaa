#include "material/sheet_frame.hpp"

#include <cmath>
#include <stdexcept>

namespace drawbend::material {

SheetAxes sheet_axes(const std::array<double, 3>& rd, const std::array<double, 3>& normal) {
  const double nn = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  const double rr = std::sqrt(rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2]);
  if (!(nn > 0) || !(rr > 0) || !std::isfinite(nn) || !std::isfinite(rr))
    throw std::invalid_argument("sheet frame: the rolling direction and the sheet normal must be non-zero vectors");
  SheetAxes a;
  for (int i = 0; i < 3; ++i) a.nd[i] = normal[i] / nn;
  const double d = (rd[0] * a.nd[0] + rd[1] * a.nd[1] + rd[2] * a.nd[2]) / rr;
  double p[3];
  for (int i = 0; i < 3; ++i) p[i] = rd[i] / rr - d * a.nd[i];
  const double pl = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  if (!(pl > 1e-6))
    throw std::invalid_argument("sheet frame: the rolling direction is normal to the sheet");
  for (int i = 0; i < 3; ++i) a.rd[i] = p[i] / pl;
  a.td[0] = a.nd[1] * a.rd[2] - a.nd[2] * a.rd[1];
  a.td[1] = a.nd[2] * a.rd[0] - a.nd[0] * a.rd[2];
  a.td[2] = a.nd[0] * a.rd[1] - a.nd[1] * a.rd[0];
  return a;
}

// Rows of Q are the sheet axes: local = Q A Q^T, global = Q^T A Q.
static void sheet_to_matrix(const double v[6], double A[3][3]) {
  A[0][0] = v[0]; A[1][1] = v[1]; A[2][2] = v[2];
  A[0][1] = A[1][0] = v[3];
  A[1][2] = A[2][1] = v[4];
  A[2][0] = A[0][2] = v[5];
}
// As P (A P^T) with P = Q or Q^T: 45 multiplications where the sum over
// Q_ik A_km Q_jm term by term took 162 (material/lanes/hill48_lanes.hpp's sheet_transform,
// the same arithmetic in the same order).  B is symmetric in exact
// arithmetic, so one entry of each off-diagonal pair gives its shear (B01,
// B12, B20; the term-by-term form averaged both).
void sheet_transform(const double Q[3][3], const double v[6], double out[6], bool to_local) {
  double A[3][3], P[3][3], C[3][3];
  sheet_to_matrix(v, A);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) P[i][k] = to_local ? Q[i][k] : Q[k][i];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) C[k][j] = A[k][0] * P[j][0] + A[k][1] * P[j][1] + A[k][2] * P[j][2];
  constexpr int I[6] = {0, 1, 2, 0, 1, 2}, J[6] = {0, 1, 2, 1, 2, 0};
  for (int n = 0; n < 6; ++n)
    out[n] = P[I[n]][0] * C[0][J[n]] + P[I[n]][1] * C[1][J[n]] + P[I[n]][2] * C[2][J[n]];
}
void cross3(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
// Re-orthonormalise the stored RD and ND after a first-order rotation.
void orthonormalise_axes(double* rd, double* nd) {
  const double lr = std::sqrt(rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2]);
  for (int i = 0; i < 3; ++i) rd[i] /= lr;
  const double d = rd[0] * nd[0] + rd[1] * nd[1] + rd[2] * nd[2];
  for (int i = 0; i < 3; ++i) nd[i] -= d * rd[i];
  const double ln = std::sqrt(nd[0] * nd[0] + nd[1] * nd[1] + nd[2] * nd[2]);
  for (int i = 0; i < 3; ++i) nd[i] /= ln;
}

}  // namespace drawbend::material
