// End to end: curve constraints -> propagate -> degenerate-curve extraction (paper §5 "Design",
// "Parameterization"; §3-4 for the extracted topology).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/design/curve_element_builder.h"
#include "core/design/propagate.h"
#include "core/edit/local_smooth.h"
#include "core/topology/extract_degenerate_curves.h"
#include "tests/support/solid_meshes.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

const std::shared_ptr<const TetMesh>& ball() {
  static const auto mesh = test::mappedBall(22);  // 63888 tets
  return mesh;
}

double distanceToPolyline(const Vec3& p, const std::vector<Vec3>& poly, bool closed) {
  double best = 1e300;
  const std::size_t n = poly.size();
  if (n == 1) return (p - poly[0]).norm();
  for (std::size_t s = 0; s < (closed ? n : n - 1); ++s) {
    const Vec3 a = poly[s], b = poly[(s + 1) % n];
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p - (a + t * (b - a))).norm());
  }
  return best;
}

/// Symmetric Hausdorff distance between two polylines, measured at their points and at
/// points every `step` along their segments.
double hausdorff(const std::vector<Vec3>& a, bool aClosed, const std::vector<Vec3>& b, bool bClosed,
                 double step) {
  const auto oneSided = [&](const std::vector<Vec3>& from, bool closed, const std::vector<Vec3>& to,
                            bool toClosed) {
    double worst = 0;
    const std::size_t n = from.size();
    for (std::size_t s = 0; s < (closed ? n : n - 1); ++s) {
      const Vec3 p = from[s], q = from[(s + 1) % n];
      const int k = std::max(1, static_cast<int>(std::ceil((q - p).norm() / step)));
      for (int i = 0; i <= k; ++i) {
        worst = std::max(worst, distanceToPolyline(p + (q - p) * (double(i) / k), to, toClosed));
      }
    }
    return worst;
  };
  return std::max(oneSided(a, aClosed, b, bClosed), oneSided(b, bClosed, a, aClosed));
}

struct DesignCase {
  bool closed;
  DegenerateType type;
  DegeneratePattern pattern;
};

std::string caseName(const ::testing::TestParamInfo<DesignCase>& info) {
  return std::string(info.param.closed ? "Closed" : "Open") +
         (info.param.type == DegenerateType::Linear ? "Linear" : "Planar") +
         (info.param.pattern == DegeneratePattern::Wedge ? "Wedge" : "Trisector");
}

CurveOptions designCurve(bool closed) {
  CurveOptions o;
  if (closed) {
    for (int i = 0; i < 9; ++i) {
      const double s = 2 * kPi * i / 9;
      o.points.push_back(Vec3(0.1, -0.05, 0.05) +
                         Vec3(0.45 * std::cos(s), 0.45 * std::sin(s), 0.12 * std::sin(2 * s)));
    }
  } else {
    o.points = {{-0.96, 0.1, 0.05},
                {-0.4, 0.25, 0.15},
                {0.2, 0.05, -0.1},
                {0.6, -0.15, 0.1},
                {0.95, -0.1, 0.0}};
  }
  o.closed = closed;
  return o;
}

class CurveDesign : public ::testing::TestWithParam<DesignCase> {};

TEST_P(CurveDesign, ExtractedCurveFollowsTheDesignedOneWithItsTypeAndPattern) {
  const auto& mesh = ball();
  const double h = mesh->meanEdgeLength();
  const DesignCase c = GetParam();
  CurveOptions o = designCurve(c.closed);
  o.type = c.type;
  o.pattern = c.pattern;
  o.spacing = 0.5 * h;
  o.radius = 2.5 * h;
  ConstraintSet constraints;
  constraints.curves.push_back(buildCurveElement(o));
  std::vector<Vec3> designed;
  for (const auto& s : constraints.curves[0].samples) designed.push_back(s.origin);

  const PropagateResult result = propagate(mesh, constraints);
  const DegenerateCurves curves = extractDegenerateCurves(result.field);
  ASSERT_FALSE(curves.empty());
  int best = -1;
  double bestDistance = 1e300;
  for (const DegenerateCurve& e : curves.curves()) {
    const double d = hausdorff(e.points, e.closed, designed, c.closed, 0.25 * h);
    if (d < bestDistance) bestDistance = d, best = e.id;
  }
  const DegenerateCurve& e = curves.curve(best);
  EXPECT_LE(bestDistance, h) << curves.summary();
  EXPECT_EQ(e.closed, c.closed);
  EXPECT_EQ(e.type, c.type);
  const DegeneratePattern expected = c.pattern;
  int agree = 0, disagree = 0, transitions = 0;
  for (std::size_t i = 0; i < e.points.size(); ++i) {
    if (e.patterns[i] == DegeneratePattern::Transition) {
      ++transitions;
      continue;
    }
    (e.patterns[i] == expected ? agree : disagree)++;
  }
  // With the non-degenerate eigenvector along the tangent the designed curve has no transition
  // point; allow a few stray classifications where the curve runs out to the boundary.
  EXPECT_GT(agree, 50);
  EXPECT_GE(agree, 0.95 * (agree + disagree)) << disagree << " points disagree";
  EXPECT_LE(transitions, 2);
}

INSTANTIATE_TEST_SUITE_P(
    AllKinds, CurveDesign,
    ::testing::Values(DesignCase{false, DegenerateType::Linear, DegeneratePattern::Wedge},
                      DesignCase{false, DegenerateType::Linear, DegeneratePattern::Trisector},
                      DesignCase{false, DegenerateType::Planar, DegeneratePattern::Wedge},
                      DesignCase{false, DegenerateType::Planar, DegeneratePattern::Trisector},
                      DesignCase{true, DegenerateType::Linear, DegeneratePattern::Wedge},
                      DesignCase{true, DegenerateType::Linear, DegeneratePattern::Trisector},
                      DesignCase{true, DegenerateType::Planar, DegeneratePattern::Wedge},
                      DesignCase{true, DegenerateType::Planar, DegeneratePattern::Trisector}),
    caseName);

TEST(CurveDesignTensor, EigenvectorsFollowTheFrameAlongTheCurve) {
  const auto& mesh = ball();
  const double h = mesh->meanEdgeLength();
  // Curves that bend gently at the mesh's resolution (κh ≲ 0.15): the piecewise-linear field
  // cannot follow a frame that turns much within one tet.
  for (bool closed : {false, true}) {
    CurveOptions o;
    o.closed = closed;
    if (closed) {
      for (int i = 0; i < 9; ++i) {
        const double s = 2 * kPi * i / 9;
        o.points.push_back(
            Vec3(0.68 * std::cos(s), 0.68 * std::sin(s), 0.06 * std::sin(2 * s) + 0.05));
      }
    } else {
      o.points = {{-0.95, 0, 0.1}, {-0.3, 0.15, 0.05}, {0.3, 0.1, -0.05}, {0.95, 0, 0}};
    }
    o.kind = CurveKind::Tensor;
    o.eigenvalues = Vec3(0, -1, 1);  // u medium, v minor, tangent major
    o.rotation = Vec3(0, 0, 25);     // about the tangent: u, v turn, the tangent stays
    o.spacing = 0.5 * h;
    o.radius = 2.5 * h;
    ConstraintSet constraints;
    constraints.curves.push_back(buildCurveElement(o));
    const PropagateResult result = propagate(mesh, constraints);
    double worst = 0;
    for (const auto& s : constraints.curves[0].samples) {
      const auto t = result.field.sample(s.origin);
      ASSERT_TRUE(t);
      const EigenDecomposition e = eigenDecompose(*t);
      for (int k = 0; k < 3; ++k) {
        const Vec3 expected = s.frame.col(k == 0 ? 2 : k == 1 ? 0 : 1);
        const double c = std::min(1.0, std::abs(e.vectors.col(k).dot(expected)));
        worst = std::max(worst, std::acos(c) * 180 / kPi);
      }
    }
    EXPECT_LT(worst, 1.0) << (closed ? "closed" : "open");
  }
}

/// Loops whose points all lie within `radius` of `centre`.
int loopsInside(const DegenerateCurves& curves, const Vec3& centre, double radius) {
  int count = 0;
  for (const DegenerateCurve& c : curves.curves()) {
    bool inside = c.closed;
    for (const Vec3& p : c.points) inside = inside && (p - centre).norm() < radius;
    count += inside;
  }
  return count;
}

/// A field with three small designed degenerate loops around the centre of the ball.
const TensorField& loopyField() {
  static const TensorField field = [] {
    const auto& mesh = ball();
    const double h = mesh->meanEdgeLength();
    ConstraintSet constraints;
    const Vec3 centres[3] = {{0.33, 0, 0}, {-0.33, 0.05, 0}, {0, 0.3, 0.25}};
    for (int k = 0; k < 3; ++k) {
      CurveOptions o;
      for (int i = 0; i < 6; ++i) {
        const double s = 2 * kPi * i / 6;
        o.points.push_back(centres[k] + 0.16 * Vec3(std::cos(s), std::sin(s) * std::cos(k),
                                                    std::sin(s) * std::sin(k)));
      }
      o.closed = true;
      o.type = k == 1 ? DegenerateType::Planar : DegenerateType::Linear;
      o.spacing = 0.5 * h;
      o.radius = 1.2 * h;
      constraints.curves.push_back(buildCurveElement(o));
    }
    return propagate(mesh, constraints).field;
  }();
  return field;
}

TEST(CurveDesignLocalSmooth, SmoothingARegionRemovesTheLoopsInside) {
  const TensorField& field = loopyField();
  const DegenerateCurves before = extractDegenerateCurves(field);
  const Vec3 centre = Vec3::Zero();
  const int loopsBefore = loopsInside(before, centre, 0.7);
  ASSERT_GE(loopsBefore, 3) << before.summary();
  LocalSmoothOptions o;
  o.region = SmoothRegionShape::Sphere;
  o.center = centre;
  o.radius = 0.7;
  const LocalSmoothResult smoothed = localSmooth(field, o);
  const DegenerateCurves after = extractDegenerateCurves(smoothed.field);
  EXPECT_LT(loopsInside(after, centre, 0.7), loopsBefore) << after.summary();
  // Outside the region the field, and so its topology far from the region, is unchanged.
  for (int v = 0; v < static_cast<int>(field.mesh().vertexCount()); ++v) {
    if ((field.mesh().positions()[v] - centre).norm() > o.radius) {
      ASSERT_EQ(smoothed.field.at(v), field.at(v));
    }
  }
}

TEST(CurveDesignLocalSmooth, CurveRegionIsTheTubeAroundThePickedCurve) {
  const TensorField& field = loopyField();
  const DegenerateCurves curves = extractDegenerateCurves(field);
  const double h = field.mesh().meanEdgeLength();
  LocalSmoothOptions o;
  o.region = SmoothRegionShape::Curve;
  o.pick = Vec3(0.33 + 0.16, 0.02, 0.01);  // next to the first designed loop
  o.radius = 1.5 * h;
  const auto picked = curves.pick(o.pick);
  ASSERT_TRUE(picked);
  const DegenerateCurve& target = curves.curve(picked->curveId);
  EXPECT_LT(picked->distance, h);
  double pickDistance = -1;
  const std::vector<int> region = smoothRegionVertices(field, o, &pickDistance);
  EXPECT_NEAR(pickDistance, picked->distance, 1e-12);
  ASSERT_GT(region.size(), 20u);
  std::vector<char> inRegion(field.mesh().vertexCount(), 0);
  for (int v : region) {
    inRegion[v] = 1;
    EXPECT_LE(distanceToPolyline(field.mesh().positions()[v], target.points, target.closed),
              o.radius + 1e-12);
  }
  const LocalSmoothResult r = localSmooth(field, o);
  EXPECT_EQ(r.report.regionVertices, region.size());
  EXPECT_GT(r.report.freeVertices, 0u);
  int changed = 0;
  for (int v = 0; v < static_cast<int>(field.mesh().vertexCount()); ++v) {
    if (!inRegion[v]) {
      ASSERT_EQ(r.field.at(v), field.at(v));
    } else {
      changed += !(r.field.at(v) == field.at(v));
    }
  }
  EXPECT_GT(changed, 0);
  // Passing the curves the caller already has gives the same result without re-extracting.
  o.curves = &curves;
  EXPECT_EQ(localSmooth(field, o).field.values(), r.field.values());
}

}  // namespace
}  // namespace tfd::core
