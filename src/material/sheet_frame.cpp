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

}  // namespace drawbend::material
