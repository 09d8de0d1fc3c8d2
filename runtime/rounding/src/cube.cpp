// The cube-map face rule (rounding.h, NUMERICS.md cube maps): one definition for the CPU
// device's samplers under both roundings.
#include <cmath>

#include "tierlift/rounding/rounding.h"

namespace tierlift::rounding {

CubeAxes cube_axes(float x, float y, float z) {
  const float ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
  CubeAxes a;
  if (az >= ax && az >= ay) { // ties go to z (NaN components fall through to y)
    a.face = z < 0 ? 5 : 4;
    a.sc = z < 0 ? -x : x;
    a.tc = -y;
    a.ma = az;
  } else if (ax > ay) {
    a.face = x < 0 ? 1 : 0;
    a.sc = x < 0 ? z : -z;
    a.tc = -y;
    a.ma = ax;
  } else {
    a.face = y < 0 ? 3 : 2;
    a.sc = x;
    a.tc = y < 0 ? -z : z;
    a.ma = ay;
  }
  return a;
}

CubeCoord cube_coord_exact(float x, float y, float z) {
  const CubeAxes a = cube_axes(x, y, z);
  const double ma = a.ma;
  return {a.face, static_cast<float>((a.sc / ma + 1.0) / 2.0),
          static_cast<float>((a.tc / ma + 1.0) / 2.0)};
}

CubeCoord cube_coord_llvmpipe(float x, float y, float z) {
  const CubeAxes a = cube_axes(x, y, z);
  const float h = 0.5f / a.ma;
  const float s = flush(a.sc * h) + 0.5f, t = flush(a.tc * h) + 0.5f;
  return {a.face, s, t};
}

} // namespace tierlift::rounding
