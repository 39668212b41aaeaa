#include "fe/hex8.hpp"

#include "fe/hex8_geometry.hpp"

namespace drawbend::fe {

void volume_derivatives(const double x[8], const double y[8], const double z[8], double dvdx[8], double dvdy[8],
                        double dvdz[8]) {
  baseline::volume_derivatives_t<double>(x, y, z, dvdx, dvdy, dvdz);
}

bool hex_geometry(const double x[8], const double y[8], const double z[8], HexGeometry& g) {
  return baseline::hex_geometry_t<double>(x, y, z, g);
}

}  // namespace drawbend::fe
