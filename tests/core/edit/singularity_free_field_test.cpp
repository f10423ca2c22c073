// Singularity-free tensor field generation of paper §6.3 (core/edit/singularity_free_field.h),
// checked by re-extracting the degenerate curves (core/topology).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "core/derived_cache.h"
#include "core/edit/region_complex.h"
#include "core/edit/singularity_free_field.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/error.h"
#include "core/structured_mesh.h"
#include "core/topology/curve_tets.h"
#include "core/topology/extract_degenerate_curves.h"

namespace tfd::core {
namespace {

/// An L-type degenerate arch: in the frame R(p), the tensor is [[−1+u, v, 0], [v, −1−u, 0],
/// [0, 0, 2]] with u = (y − y0)/2, v = (z − 1 + (x − x0)²)/2, degenerate (λ2 = λ3) exactly on
/// the parabola y = y0, z = 1 − (x − x0)², which rises from the bottom face z = 0, turns over
/// (a transition point where the tangent is ⊥ the major eigenvector) and comes back down: a
/// curve with a wedge and a trisector end, both on the same face (paper Fig. 17a). R(p) turns
/// the frame smoothly (the degenerate set does not change) so that the major eigenvector is not
/// constant. The offsets keep the curve off grid planes.
constexpr double kX0 = 0.037, kY0 = 0.013;
Tensor arch(const Vec3& p) {
  const double u = (p.y() - kY0) / 2, v = (p.z() - 1 + (p.x() - kX0) * (p.x() - kX0)) / 2;
  Mat3 m;
  m << -1 + u, v, 0, v, -1 - u, 0, 0, 0, 2;
  const Mat3 r = (Eigen::AngleAxisd(0.5 * p.x(), Vec3::UnitY()) *
                  Eigen::AngleAxisd(0.35 * p.y() + 0.2 * p.z(), Vec3::UnitX()))
                     .toRotationMatrix();
  return Tensor::fromMatrix(r * m * r.transpose());
}

struct ArchCase {
  std::shared_ptr<const TetMesh> mesh;
  TensorField field;
  std::vector<int> region;  ///< tets with every vertex in a half-ellipsoid on the bottom face
  static std::shared_ptr<const TetMesh> makeMesh(int scale) {
    return makeBoxMesh(8 * scale, 5 * scale, 5 * scale, Vec3(-1.6, -1, 0), Vec3(1.6, 1, 2));
  }
  explicit ArchCase(int scale = 2) : mesh(makeMesh(scale)), field(sample(mesh)) {
    for (std::size_t t = 0; t < mesh->tetCount(); ++t) {
      bool inside = true;
      for (int v : mesh->tets()[t]) {
        const Vec3& p = mesh->positions()[v];
        const Vec3 q((p.x() - kX0) / 1.55, (p.y() - kY0) / 0.75, p.z() / 1.55);
        inside = inside && q.squaredNorm() < 1;
      }
      if (inside) region.push_back(static_cast<int>(t));
    }
  }
  static TensorField sample(std::shared_ptr<const TetMesh> mesh) {
    std::vector<Tensor> values;
    for (const Vec3& p : mesh->positions()) values.push_back(arch(p));
    return TensorField(mesh, values);
  }
  std::vector<char> noHeld() const { return std::vector<char>(mesh->vertexCount(), 0); }
};

bool bitwiseEqual(const Tensor& a, const Tensor& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Whether some point of some curve comes from a region tet (or a face / edge / vertex of one).
int curvePointsInRegion(const TetMesh& mesh, const DegenerateCurves& curves,
                        const std::vector<int>& region) {
  int count = 0;
  for (const DegenerateCurve& c : curves.curves())
    for (const PointSource& s : c.sources)
      for (int t : tetsOfSource(mesh, s))
        if (std::binary_search(region.begin(), region.end(), t)) {
          ++count;
          break;
        }
  return count;
}

TEST(SingularityFreeField, RemovesTheWedgeTrisectorArchAndNothingElseMoves) {
  const ArchCase c;
  const DegenerateCurves before = extractDegenerateCurves(c.field);
  ASSERT_EQ(before.size(), 1u) << before.summary();
  const DegenerateCurve& archCurve = before.curves()[0];
  EXPECT_EQ(archCurve.type, DegenerateType::Linear);
  EXPECT_GT(before.statistics().transitionPoints, 0) << before.summary();
  EXPECT_GT(curvePointsInRegion(*c.mesh, before, c.region), 20);

  SingularityFreeReport report;
  const TensorField after =
      singularityFreeField(c.field, c.region, c.noHeld(), DegenerateType::Linear, {}, &report);
  EXPECT_EQ(report.nonBallSteps, 0) << report.summary();
  EXPECT_LT(report.maxHolonomyDefect, 1e-12);
  EXPECT_GT(report.freeVertices, 100u);
  const DegenerateCurves curves = extractDegenerateCurves(after);
  EXPECT_TRUE(curves.empty()) << curves.summary();
  EXPECT_EQ(curvePointsInRegion(*c.mesh, curves, c.region), 0);

  // Everything outside the region and every held vertex: bitwise the input.
  std::vector<char> inRegion(c.mesh->vertexCount(), 0), touchesOutside(c.mesh->vertexCount(), 0);
  for (std::size_t t = 0; t < c.mesh->tetCount(); ++t) {
    const bool in = std::binary_search(c.region.begin(), c.region.end(), static_cast<int>(t));
    for (int v : c.mesh->tets()[t]) (in ? inRegion : touchesOutside)[v] = 1;
  }
  std::size_t changed = 0;
  for (std::size_t v = 0; v < c.mesh->vertexCount(); ++v) {
    const bool same = bitwiseEqual(after.at(int(v)), c.field.at(int(v)));
    if (!inRegion[v] || touchesOutside[v]) {
      EXPECT_TRUE(same) << "vertex " << v;
    }
    changed += !same;
  }
  EXPECT_EQ(changed, report.freeVertices);
}

/// A field without degenerate points (constant, distinct eigenvalues) whose frame turns so
/// much that its major eigenvector covers most of the sphere over the region: some jumps exceed
/// π, and an angle field solved without them gets degenerate points.
TEST(SingularityFreeField, StronglyTurningFieldNeedsTheJumps) {
  const auto mesh = makeBoxMesh(14, 14, 14, Vec3::Constant(-1), Vec3::Constant(1));
  std::vector<Tensor> values;
  for (const Vec3& p : mesh->positions()) {
    const Mat3 r = (Eigen::AngleAxisd(4.4 * p.x(), Vec3::UnitY()) *
                    Eigen::AngleAxisd(3.6 * p.y() + 0.5 * p.z(), Vec3::UnitX()) *
                    Eigen::AngleAxisd(3.0 * p.z(), Vec3::UnitZ()))
                       .toRotationMatrix();
    values.push_back(Tensor::fromMatrix(r * Vec3(2.0, -0.6, -1.4).asDiagonal() * r.transpose()));
  }
  const TensorField field(mesh, values);
  std::vector<int> region;
  for (std::size_t t = 0; t < mesh->tetCount(); ++t) {
    Vec3 m = Vec3::Zero();
    for (int v : mesh->tets()[t]) m += mesh->positions()[v] / 4;
    if ((m - Vec3(0.03, -0.02, 0.01)).norm() < 0.85) region.push_back(static_cast<int>(t));
  }
  ASSERT_TRUE(extractDegenerateCurves(field).empty());
  SingularityFreeReport report;
  const TensorField after =
      singularityFreeField(field, region, std::vector<char>(mesh->vertexCount(), 0),
                           DegenerateType::Linear, {}, &report);
  EXPECT_EQ(report.nonBallSteps, 0);
  EXPECT_LT(report.maxHolonomyDefect, 1e-12);
  // (Solved with zero jumps instead, this region gets 16 degenerate loops.)
  const DegenerateCurves curves = extractDegenerateCurves(after);
  EXPECT_TRUE(curves.empty()) << curves.summary();
}

// The same property on an unstructured TetGen sphere is an io-layer test:
// tests/io/tetgen/singularity_free_field_tetgen_test.cpp.

TEST(SingularityFreeField, KeepsTheNonRepeatingEigenvectorAndPositiveGapsInside) {
  const ArchCase c;
  SingularityFreeReport report;
  const TensorField after =
      singularityFreeField(c.field, c.region, c.noHeld(), DegenerateType::Linear, {}, &report);
  const RegionComplex region = regionComplex(*c.mesh, c.region);
  double heldMin12 = 1e300, heldMin23 = 1e300, freeMin12 = 1e300, freeMin23 = 1e300;
  int solved = 0;
  for (int v : region.vertices) {
    const EigenDecomposition in = eigenDecompose(c.field.at(v).deviator());
    const EigenDecomposition out = eigenDecompose(after.at(v).deviator());
    EXPECT_NEAR(after.at(v).trace(), 0, 1e-13);
    const bool isSolved = !bitwiseEqual(after.at(v), c.field.at(v));
    solved += isSolved;
    const Vec3& l = (isSolved ? out : in).values;
    double& m12 = isSolved ? freeMin12 : heldMin12;
    double& m23 = isSolved ? freeMin23 : heldMin23;
    m12 = std::min(m12, l[0] - l[1]);
    m23 = std::min(m23, l[1] - l[2]);
    if (isSolved) {  // the major (non-repeating) eigenvector is not changed (paper §6.3)
      EXPECT_GT(std::abs(in.vectors.col(0).dot(out.vectors.col(0))), 1 - 1e-9) << "vertex " << v;
    }
  }
  ASSERT_GT(solved, 100);
  // The gaps are harmonic: positive inside, never below their smallest held value (discrete
  // maximum principle; the box mesh's cotangent weights are non-negative).
  EXPECT_GT(heldMin12, 0);
  EXPECT_GT(heldMin23, 0);
  EXPECT_GE(freeMin12, heldMin12 - 1e-9);
  EXPECT_GE(freeMin23, heldMin23 - 1e-9);
  EXPECT_NEAR(report.freeMinGap12, freeMin12, 1e-9);
  EXPECT_NEAR(report.freeMinGap23, freeMin23, 1e-9);
  // The solve's own figures reach the report (a lost assignment once left them at 0).
  EXPECT_GT(report.iterations, 0);
  EXPECT_GT(report.relativeResidual, 0);
  EXPECT_LE(report.relativeResidual, 1e-7);
  EXPECT_NE(report.summary().find(" in " + std::to_string(report.iterations) + " iterations"),
            std::string::npos);
  // The input's gap λ2 − λ3 vanishes on the arch inside the region; the new one does not.
  double inputMin23 = 1e300;
  for (int v : region.vertices) {
    const Vec3 l = eigenDecompose(c.field.at(v).deviator()).values;
    inputMin23 = std::min(inputMin23, l[1] - l[2]);
  }
  EXPECT_LT(inputMin23, 0.5 * freeMin23);
}

// A designed isotropic part is spread harmonically from the held vertices (a linear trace
// exactly, to the solver's tolerance); a trace at rounding level is not a design: it is left
// out of the solve (one column less, whose tolerance relative to it would cost iterations)
// and the solved tensors are traceless.
TEST(SingularityFreeField, SolvesADesignedTraceAndLeavesRoundingOut) {
  const ArchCase c;
  auto withTrace = [&](auto&& trace) {
    std::vector<Tensor> values = c.field.values();
    for (std::size_t v = 0; v < values.size(); ++v) {
      const double t = trace(c.mesh->positions()[v], v) / 3;
      values[v].xx += t, values[v].yy += t, values[v].zz += t;
    }
    return TensorField(c.mesh, values);
  };
  // Linear and constant across the region's one stretch of domain surface (z = 0), where the
  // solve has the natural boundary condition: exactly harmonic there too.
  auto linear = [](const Vec3& p) { return 0.3 * p.x() - 0.2 * p.y() + 0.1; };
  SingularityFreeReport designed;
  const TensorField solved =
      singularityFreeField(withTrace([&](const Vec3& p, std::size_t) { return linear(p); }),
                           c.region, c.noHeld(), DegenerateType::Linear, {}, &designed);
  EXPECT_TRUE(designed.traceSolved);
  EXPECT_GT(designed.freeVertices, 100u);
  for (std::size_t v = 0; v < c.mesh->vertexCount(); ++v)
    EXPECT_NEAR(solved.at(int(v)).trace(), linear(c.mesh->positions()[v]), 1e-8) << v;

  SingularityFreeReport rounding;  // traces of a few ulps, as sums of rotated tensors leave
  const TensorField noisy =
      withTrace([](const Vec3&, std::size_t v) { return (int(v % 7) - 3) * 2e-16; });
  const TensorField traceless =
      singularityFreeField(noisy, c.region, c.noHeld(), DegenerateType::Linear, {}, &rounding);
  EXPECT_FALSE(rounding.traceSolved);
  EXPECT_EQ(rounding.freeVertices, designed.freeVertices);
  const RegionComplex region = regionComplex(*c.mesh, c.region);
  for (int v : region.vertices) {
    if (!bitwiseEqual(traceless.at(v), noisy.at(v))) {  // solved
      EXPECT_NEAR(traceless.at(v).trace(), 0, 1e-14) << v;
    }
  }
}

TEST(SingularityFreeField, HeldInteriorVerticesKeepTheirValues) {
  const ArchCase c;
  std::vector<char> held = c.noHeld();
  const RegionComplex region = regionComplex(*c.mesh, c.region);
  // Hold a few interior vertices away from the arch (their values carry no degenerate point).
  int asked = 0;
  for (int v : region.vertices) {
    const Vec3& p = c.mesh->positions()[v];
    if (!c.mesh->isBoundaryVertex(v) && p.z() > 1.15 && v % 3 == 0) held[v] = 1, ++asked;
  }
  ASSERT_GT(asked, 3);
  SingularityFreeReport report;
  const TensorField after =
      singularityFreeField(c.field, c.region, held, DegenerateType::Linear, {}, &report);
  for (std::size_t v = 0; v < held.size(); ++v) {
    if (held[v]) {
      EXPECT_TRUE(bitwiseEqual(after.at(int(v)), c.field.at(int(v))));
    }
  }
  EXPECT_TRUE(extractDegenerateCurves(after).empty());
}

TEST(SingularityFreeField, SameResultForOneAndTwoThreads) {
  const ArchCase c;
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    derivedCache().clear();  // each run builds its own solver set-up
    return singularityFreeField(c.field, c.region, c.noHeld(), DegenerateType::Linear);
  };
  const TensorField a = run(1), b = run(2);
  for (std::size_t v = 0; v < c.mesh->vertexCount(); ++v)
    EXPECT_TRUE(bitwiseEqual(a.at(int(v)), b.at(int(v)))) << "vertex " << v;
}

TEST(SingularityFreeField, SameResultWithOrWithoutTheVectorisationsDecompositions) {
  const ArchCase c;
  const RegionComplex region = regionComplex(*c.mesh, c.region);
  VectorisedEigenvector n = vectoriseEigenvector(c.field, region, DegenerateType::Linear);
  ASSERT_EQ(n.eigen.size(), n.vertices.size());
  const TensorField kept =
      singularityFreeField(c.field, region, n, c.noHeld(), DegenerateType::Linear, {}, nullptr);
  n.eigen.clear();  // decomposed again by the singularity-free field
  const TensorField again =
      singularityFreeField(c.field, region, n, c.noHeld(), DegenerateType::Linear, {}, nullptr);
  for (std::size_t v = 0; v < c.mesh->vertexCount(); ++v)
    ASSERT_TRUE(bitwiseEqual(kept.at(int(v)), again.at(int(v)))) << "vertex " << v;
}

TEST(SingularityFreeField, RefusesBadInput) {
  const ArchCase c;
  EXPECT_THROW(
      singularityFreeField(c.field, c.region, std::vector<char>(3, 0), DegenerateType::Linear),
      Error);
  EXPECT_THROW(singularityFreeField(c.field, {}, c.noHeld(), DegenerateType::Linear), Error);
  // The whole mesh: no vertex is held.
  std::vector<int> all(c.mesh->tetCount());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
  EXPECT_THROW(singularityFreeField(c.field, all, c.noHeld(), DegenerateType::Linear), Error);
  // The minor eigenvector repeats on the L-type arch: it cannot be oriented around it.
  try {
    singularityFreeField(c.field, c.region, c.noHeld(), DegenerateType::Planar);
    FAIL() << "a region where the eigenvector cannot be oriented was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be oriented"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tfd::core
