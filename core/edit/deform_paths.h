#pragma once
// The two curves of a degenerate curve deformation (paper §6.1): the original segment γ1 of the
// picked curve and its new course γ2, sampled with the same number of points so that sample i
// of γ2 corresponds to sample i of γ1 (the paper's bijection γ2 → γ1).
//
// Which part of the curve moves: the paper lets the user give γ1 ⊂ γ together with γ2 (Fig. 10).
// Here the target polyline names both: its two ends are projected onto the picked curve, and γ1
// is the arc of the curve between those two projections (on a loop, the one of the two arcs
// that holds the pick). γ2 is the target joined to the curve at those two projections, so γ1
// and γ2 share their ends and the deformed curve stays one curve. The rest of the curve (outside
// γ1) does not move.
#include <span>
#include <vector>

#include "core/tensor.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

struct DeformPaths {
  std::vector<Vec3> gamma1, gamma2;  ///< resampled, the same number of points, γ1[i] ↔ γ2[i]
  std::vector<Vec3> target;          ///< γ2 as given (joined to the curve), before resampling
  /// The curve's points strictly inside γ1 (one flag per curve point): the part that moves.
  std::vector<char> inGamma1;
  /// The rest of the curve, outside γ1, as polylines (the course that must not change).
  std::vector<std::vector<Vec3>> rest;
  double length1 = 0, length2 = 0;
};

/// `pick`: the picked position on `curve` (a CurvePick of this curve); `target`: at least two
/// finite points; `spacing`: the largest sample spacing (e.g. a quarter of the edge length).
/// Throws core::Error naming the parameter when the target is degenerate (fewer than two
/// points, a non-finite point, zero length) or its ends meet the curve at the same place.
DeformPaths deformPaths(const DegenerateCurve& curve, const CurvePick& pick,
                        std::span<const Vec3> target, double spacing);

/// `n` points along a polyline at equal arc-length steps (its ends included).
std::vector<Vec3> resamplePolyline(std::span<const Vec3> polyline, int n);

/// Distance from p to a polyline (one point: the distance to it); the closest segment and its
/// parameter are returned when asked.
double distanceToPolyline(const Vec3& p, std::span<const Vec3> polyline, int* segment = nullptr,
                          double* t = nullptr);

}  // namespace tfd::core
