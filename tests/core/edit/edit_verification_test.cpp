// Verification of an edit (core/edit/edit_verification.h): each of the four checks fails on
// the one kind of result it exists for, and passes a correct one.
#include <gtest/gtest.h>

#include <cmath>

#include "core/edit/edit_verification.h"
#include "core/point_locator.h"
#include "core/region/ball_region.h"
#include "core/region/region_vertices.h"
#include "tests/core/design/curve_test_meshes.h"

namespace tfd::core {
namespace {

/// A synthetic curve through the given tets (points at their centroids).
DegenerateCurve curveThrough(const TetMesh& m, const std::vector<int>& tets,
                             const Vec3& shift = Vec3::Zero()) {
  DegenerateCurve c;
  for (int t : tets) {
    const auto& v = m.tets()[t];
    c.points.push_back(0.25 * (m.positions()[v[0]] + m.positions()[v[1]] + m.positions()[v[2]] +
                               m.positions()[v[3]]) +
                       shift);
    c.patterns.push_back(DegeneratePattern::Wedge);
    c.sources.push_back({PointSource::Kind::Tet, t});
  }
  return c;
}

class Verification : public ::testing::Test {
 protected:
  void SetUp() override {
    mesh = testing::jitteredBox(8, 0.1);
    std::vector<Tensor> values(mesh->vertexCount());
    for (std::size_t v = 0; v < values.size(); ++v)
      values[v] = Tensor{1.0 + double(v % 7), -1, 0, 0.1 * double(v % 3), 0, 0}.deviator();
    field = std::make_shared<TensorField>(mesh, values);
    // Region: a ball around tet near the centre; the target inside, the other far outside.
    const auto located = mesh->locator().locate(Vec3(0.05, 0.02, 0.01));
    ASSERT_TRUE(located.has_value());
    const int centre = located->tet;
    region = growBallRegion(*mesh, std::vector<int>{centre},
                            std::vector<unsigned char>(mesh->tetCount(), 0), {0.4})
                 .tets;
    free = regionVertices(*mesh, region).free;
    const auto in = tetFlags(*mesh, region);
    std::vector<int> inside, outside;
    for (int t = 0; t < int(mesh->tetCount()) && (inside.size() < 3 || outside.size() < 3); ++t) {
      if (in[t] && inside.size() < 3) inside.push_back(t);
      bool near = false;
      for (int v : mesh->tets()[t]) near = near || regionVertices(*mesh, region).held[v];
      if (!in[t] && !near && outside.size() < 3) outside.push_back(t);
    }
    target = curveThrough(*mesh, inside);
    other = curveThrough(*mesh, outside);
  }
  DegenerateCurves set(std::vector<DegenerateCurve> c) { return DegenerateCurves(std::move(c)); }
  int targetId(const DegenerateCurves& s) {
    for (const auto& c : s.curves())
      for (const Vec3& p : c.points)
        if (p == target.points[0]) return c.id;
    ADD_FAILURE() << "no target";
    return 0;
  }

  std::shared_ptr<const TetMesh> mesh;
  std::shared_ptr<TensorField> field;
  std::vector<int> region, free;
  DegenerateCurve target, other;
};

TEST_F(Verification, PassesACorrectEditAndNamesEachFailure) {
  const DegenerateCurves before = set({target, other});
  const std::vector<int> targets{targetId(before)};
  auto verify = [&](const TensorField& after, const DegenerateCurves& curves) {
    return verifyEdit(*field, after, free, region, before, curves, targets);
  };
  EditVerification v = verify(*field, set({other}));
  EXPECT_TRUE(v.passed) << v.failedCheck << ": " << v.detail;
  v = verify(*field, set({other, target}));
  EXPECT_EQ(v.failedCheck, "targets gone");
  DegenerateCurve fresh = curveThrough(*mesh, {target.sources[0].id});
  fresh.points[0] += Vec3(10, 0, 0);  // far from the target, inside the region by its source
  v = verify(*field, set({other, fresh}));
  EXPECT_EQ(v.failedCheck, "nothing new in the region");
  v = verify(*field, set({}));
  EXPECT_EQ(v.failedCheck, "untouched curves unchanged");
  DegenerateCurve moved = other;
  moved.points[1].x() += 1e-9;
  v = verify(*field, set({moved}));
  EXPECT_EQ(v.failedCheck, "untouched curves unchanged");
  moved = other;
  moved.points[1].x() += 1e-13;  // within 1e-12: unchanged
  EXPECT_TRUE(verify(*field, set({moved})).passed);
  // A changed held vertex (not free), and a changed free vertex.
  std::vector<Tensor> values = field->values();
  const auto rv = regionVertices(*mesh, region);
  int heldVertex = -1;
  for (int u : rv.vertices)
    if (rv.held[u]) heldVertex = u;
  ASSERT_GE(heldVertex, 0);
  values[heldVertex].xy = std::nextafter(values[heldVertex].xy, 1e9);
  v = verify(TensorField(mesh, values), set({other}));
  EXPECT_EQ(v.failedCheck, "outside unchanged");
  values = field->values();
  values[free.front()].xy += 1;
  EXPECT_TRUE(verify(TensorField(mesh, values), set({other})).passed);
}

}  // namespace
}  // namespace tfd::core
