#pragma once
// The seven cubic constraint functions of Zheng & Pang (Vis 2004) for double degeneracy of a
// symmetric 3x3 tensor (algorithms note §2.1).
//
// With T = [[x,u,v],[u,y,w],[v,w,z]]: T is degenerate (two equal eigenvalues) iff all seven
// vanish, and the discriminant (λ1−λ2)²(λ2−λ3)²(λ3−λ1)² equals
//   f1² + f2² + f3² + f4² + 15 (f5² + f6² + f7²).
// Every fᵢ is a homogeneous cubic in T and invariant under T → T + μI, so it may be evaluated on
// the tensor or its deviator.
#include <array>

#include "core/tensor.h"

namespace tfd::core::topology {

using ZhengPang = std::array<double, 7>;

/// f1..f7 of t.
inline ZhengPang zhengPangFunctions(const Tensor& t) {
  const double x = t.xx, y = t.yy, z = t.zz, u = t.xy, v = t.xz, w = t.yz;
  const double x2 = x * x, y2 = y * y, z2 = z * z, u2 = u * u, v2 = v * v, w2 = w * w;
  ZhengPang f;
  f[0] = x * ((y2 - z2) + (u2 - v2)) + y * ((z2 - x2) + (w2 - u2)) + z * ((x2 - y2) + (v2 - w2));
  f[1] = w * (2 * (w2 - x2) - (v2 + u2) + 2 * (y * x + z * x - y * z)) + u * v * (2 * x - z - y);
  f[2] = v * (2 * (v2 - y2) - (u2 + w2) + 2 * (z * y + x * y - z * x)) + w * u * (2 * y - x - z);
  f[3] = u * (2 * (u2 - z2) - (w2 + v2) + 2 * (x * z + y * z - x * y)) + v * w * (2 * z - y - x);
  f[4] = w * (v2 - u2) + u * v * (y - z);
  f[5] = v * (u2 - w2) + w * u * (z - x);
  f[6] = u * (w2 - v2) + v * w * (x - y);
  return f;
}

/// f1² + f2² + f3² + f4² + 15 (f5² + f6² + f7²): the discriminant as a sum of squares.
inline double zhengPangDiscriminant(const ZhengPang& f) {
  return f[0] * f[0] + f[1] * f[1] + f[2] * f[2] + f[3] * f[3] +
         15 * (f[4] * f[4] + f[5] * f[5] + f[6] * f[6]);
}

}  // namespace tfd::core::topology
