#include "core/topology/face_prefilter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/topology/zheng_pang.h"

namespace tfd::core::topology {

double degeneracyDistanceLowerBound(const Tensor& t) {
  const Tensor a = t.deviator();
  const double norm = a.norm();
  if (norm == 0) return 0;
  // Eigenvalues 2p cos(φ + 2πk/3) of the traceless A with p = ‖A‖/√6, cos 3φ = det(A/p)/2.
  const double p = norm / std::sqrt(6.0);
  const Mat3 b = a.matrix() / p;
  const double halfDet = std::clamp(b.determinant() / 2, -1.0, 1.0);
  const double phi = std::acos(halfDet) / 3;
  const double l1 = 2 * p * std::cos(phi);
  const double l3 = 2 * p * std::cos(phi + 2 * std::numbers::pi / 3);
  const double l2 = -l1 - l3;
  const double gap = std::min(l1 - l2, l2 - l3) / std::numbers::sqrt2;
  // acos loses about half the digits next to cos 3φ = ±1: a margin of 1e-7 ‖A‖ keeps the bound
  // below the true distance.
  return std::max(0.0, gap - 1e-7 * norm);
}

namespace {

double squaredDistance(const Tensor& a, const Tensor& b) {
  const double dxx = a.xx - b.xx, dyy = a.yy - b.yy, dzz = a.zz - b.zz;
  const double dxy = a.xy - b.xy, dyz = a.yz - b.yz, dxz = a.xz - b.xz;
  return dxx * dxx + dyy * dyy + dzz * dzz + 2 * (dxy * dxy + dyz * dyz + dxz * dxz);
}

}  // namespace

namespace {

/// True when the balls B(P_k, r_k) around the corners of the planar triangle P0 P1 P2 cover it.
/// F(x) = min_k (|x − P_k|² − r_k²) is a minimum of convex paraboloids, so its maximum over the
/// triangle lies at a corner, at an edge point where two of the power functions are equal, or
/// at the interior point where all three are (power-diagram vertices); cover iff F < 0 there.
bool ballsCoverTriangle(const double px[3], const double py[3], const double r2[3], double margin) {
  const auto power = [&](double x, double y) {
    double f = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const double dx = x - px[k], dy = y - py[k];
      f = std::min(f, dx * dx + dy * dy - r2[k]);
    }
    return f;
  };
  const auto h = [&](int k, double x, double y) {  // |x|² dropped: power up to a common term
    return -2 * (x * px[k] + y * py[k]) + px[k] * px[k] + py[k] * py[k] - r2[k];
  };
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = (e + 1) % 3;
    const double ex = px[j] - px[i], ey = py[j] - py[i];
    for (int p = 0; p < 3; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        // h_p − h_q is affine along the edge: solve for t ∈ [0, 1].
        const double v0 = h(p, px[i], py[i]) - h(q, px[i], py[i]);
        const double v1 = h(p, px[j], py[j]) - h(q, px[j], py[j]);
        if (v0 == v1) continue;
        const double t = v0 / (v0 - v1);
        if (t < 0 || t > 1) continue;
        if (power(px[i] + t * ex, py[i] + t * ey) >= -margin) return false;
      }
    }
  }
  // Radical centre: h_0 = h_1 = h_2 (2x2 linear system).
  const double a11 = 2 * (px[1] - px[0]), a12 = 2 * (py[1] - py[0]);
  const double a21 = 2 * (px[2] - px[0]), a22 = 2 * (py[2] - py[0]);
  const double b1 =
      (px[1] * px[1] + py[1] * py[1] - r2[1]) - (px[0] * px[0] + py[0] * py[0] - r2[0]);
  const double b2 =
      (px[2] * px[2] + py[2] * py[2] - r2[2]) - (px[0] * px[0] + py[0] * py[0] - r2[0]);
  const double det = a11 * a22 - a12 * a21;
  if (det != 0) {
    const double cx = (b1 * a22 - b2 * a12) / det, cy = (a11 * b2 - a21 * b1) / det;
    // Inside the triangle? Barycentric signs by cross products.
    const auto cross = [&](int k, double x, double y) {
      const int l = (k + 1) % 3;
      return (px[l] - px[k]) * (y - py[k]) - (py[l] - py[k]) * (x - px[k]);
    };
    const double c0 = cross(0, cx, cy), c1 = cross(1, cx, cy), c2 = cross(2, cx, cy);
    const bool inside = (c0 >= 0 && c1 >= 0 && c2 >= 0) || (c0 <= 0 && c1 <= 0 && c2 <= 0);
    if (inside && power(cx, cy) >= -margin) return false;
  }
  return true;
}

}  // namespace

bool gapExcludesFace(const Tensor* const t[3], const double gap[3]) {
  const double d01 = squaredDistance(*t[0], *t[1]);
  const double d02 = squaredDistance(*t[0], *t[2]);
  const double d12 = squaredDistance(*t[1], *t[2]);
  const double radius2[3] = {std::max(d01, d02), std::max(d01, d12), std::max(d02, d12)};
  for (int i = 0; i < 3; ++i) {
    if (gap[i] > 0 && gap[i] * gap[i] > radius2[i] * (1 + 1e-12)) return true;
  }
  // Tighter: the three balls of radius gap_i around the corners cover the (flat) triangle of
  // tensors. Coordinates of the corners in the triangle's plane from the side lengths.
  if (d01 == 0) return false;
  const double a = std::sqrt(d01);
  const double x2 = (d01 + d02 - d12) / (2 * a);
  const double y2sq = d02 - x2 * x2;
  if (!(y2sq > 1e-12 * std::max(d01, d02))) return false;
  const double px[3] = {0, a, x2}, py[3] = {0, 0, std::sqrt(y2sq)};
  // Radii shrunk by a relative 1e-9 so that rounding in the planar coordinates cannot matter.
  const double r2[3] = {gap[0] * gap[0] * (1 - 1e-9), gap[1] * gap[1] * (1 - 1e-9),
                        gap[2] * gap[2] * (1 - 1e-9)};
  return ballsCoverTriangle(px, py, r2, 1e-12 * std::max({d01, d02, d12}));
}

bool bernsteinExcludesFace(const Tensor& a0, const Tensor& b0, const Tensor& c0) {
  const Tensor a = a0.deviator(), b = b0.deviator(), c = c0.deviator();
  const double scale = std::max({a.norm(), b.norm(), c.norm()});
  if (scale == 0) return false;  // zero face: everything is (triply) degenerate
  const double inv = 1 / scale;
  const Tensor x = a * inv, y = b * inv, z = c * inv;
  const ZhengPang fa = zhengPangFunctions(x), fb = zhengPangFunctions(y),
                  fc = zhengPangFunctions(z);
  const ZhengPang fabP = zhengPangFunctions(x + y), fabM = zhengPangFunctions(x - y);
  const ZhengPang fbcP = zhengPangFunctions(y + z), fbcM = zhengPangFunctions(y - z);
  const ZhengPang facP = zhengPangFunctions(x + z), facM = zhengPangFunctions(x - z);
  const ZhengPang fabc = zhengPangFunctions(x + y + z);
  // Coefficients are O(1) for unit-scaled corners; rounding stays far below this margin.
  constexpr double kMargin = 1e-12;
  for (int k = 0; k < 7; ++k) {
    // Polar forms C(X,X,Y) = [f(X+Y) − f(X−Y) − 2f(Y)]/6 and
    // C(X,Y,Z) = [f(X+Y+Z) − f(X+Y) − f(Y+Z) − f(X+Z) + f(X) + f(Y) + f(Z)]/6 (times 6 here).
    const double coeff[10] = {
        6 * fa[k],
        6 * fb[k],
        6 * fc[k],
        fabP[k] - fabM[k] - 2 * fb[k],                                  // C(a,a,b)
        fabP[k] + fabM[k] - 2 * fa[k],                                  // C(a,b,b)
        fbcP[k] - fbcM[k] - 2 * fc[k],                                  // C(b,b,c)
        fbcP[k] + fbcM[k] - 2 * fb[k],                                  // C(b,c,c)
        facP[k] - facM[k] - 2 * fc[k],                                  // C(a,a,c)
        facP[k] + facM[k] - 2 * fa[k],                                  // C(a,c,c)
        fabc[k] - fabP[k] - fbcP[k] - facP[k] + fa[k] + fb[k] + fc[k],  // C(a,b,c)
    };
    bool allPositive = true, allNegative = true;
    for (double v : coeff) {
      allPositive = allPositive && v > kMargin;
      allNegative = allNegative && v < -kMargin;
    }
    if (allPositive || allNegative) return true;
  }
  return false;
}

}  // namespace tfd::core::topology
