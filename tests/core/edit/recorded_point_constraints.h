#pragma once
// Fields rebuilt from point constraints recorded from a benchmark run (bench/edit_bench.cpp's
// random sequences print them), for tests that pin one benchmark case.
#include <gtest/gtest.h>

#include <span>
#include <vector>

#include "core/design/design_element.h"
#include "core/tensor_field.h"

namespace tfd::core::testing {

/// A point constraint as recorded: its frame row-major, its value and gradient tensors.
struct RecordedPoint {
  bool degenerate;
  Vec3 origin;
  double frame[9];
  Tensor value, jx, jy, jz;
};

inline ConstraintSet recordedConstraints(std::span<const RecordedPoint> points) {
  ConstraintSet set;
  for (const RecordedPoint& r : points) {
    PointElement e;
    e.degenerate = r.degenerate;
    e.field.origin = r.origin;
    for (int i = 0; i < 9; ++i) e.field.frame(i / 3, i % 3) = r.frame[i];
    e.field.value = r.value;
    e.field.jacobian = {r.jx, r.jy, r.jz};
    set.points.push_back(e);
  }
  return set;
}

/// Every vertex of no region tet keeps its tensor bitwise.
inline void expectUnchangedOutside(const TensorField& before, const TensorField& after,
                                   const std::vector<int>& regionTets) {
  std::vector<char> inRegion(before.mesh().vertexCount(), 0);
  for (int t : regionTets)
    for (int v : before.mesh().tets()[t]) inRegion[v] = 1;
  for (std::size_t v = 0; v < inRegion.size(); ++v) {
    if (inRegion[v]) continue;
    const Tensor &a = before.at(static_cast<int>(v)), &b = after.at(static_cast<int>(v));
    ASSERT_TRUE(a.xx == b.xx && a.yy == b.yy && a.zz == b.zz && a.xy == b.xy && a.yz == b.yz &&
                a.xz == b.xz)
        << "vertex " << v;
  }
}

}  // namespace tfd::core::testing
