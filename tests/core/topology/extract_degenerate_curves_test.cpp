// Extraction on analytic fields with known curves (algorithms note §11), including the
// non-generic block-diagonal fields of the paper's default design elements, on structured
// meshes where the curve runs along edges and through vertices and on jittered meshes;
// completeness against a brute-force search; determinism and robustness.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/error.h"
#include "core/topology/extract_degenerate_curves.h"
#include "tests/core/topology/topology_test_support.h"

namespace tfd::core::topology {
namespace {

using testing::TensorFunction;

/// F1 (paper Eq. 2–3 default L wedge) and relatives: the straight line x = y = 0.
Tensor f1Wedge(const Vec3& p) { return {p.x() - 1, -p.x() - 1, 2, p.y(), 0, 0}; }
Tensor f1Trisector(const Vec3& p) { return {p.x() - 1, -p.x() - 1, 2, -p.y(), 0, 0}; }
Tensor f3Wedge(const Vec3& p) { return {1 + p.x(), 1 - p.x(), -2, p.y(), 0, 0}; }
Tensor f3Trisector(const Vec3& p) { return {1 + p.x(), 1 - p.x(), -2, -p.y(), 0, 0}; }
/// Oster's SingleTopoLine: a straight L line through the origin along (1, 1, 1), a wedge.
Tensor singleTopoLine(const Vec3& p) {
  const double x = p.x(), y = p.y(), z = p.z();
  const double a = 1.6 * x - 0.8 * y + 0.2 * z + 1, b = 2 * x - 0.6 * y - 0.4 * z + 1;
  const double c = -0.2 * x - 0.5 * y + 0.7 * z;
  return {a, b, 4, c, 0, 0};
}

struct AnalyticCase {
  const char* name;
  TensorFunction field;
  Vec3 point, direction;  // the exact straight curve
  DegenerateType type;
  DegeneratePattern pattern;
  double half;  // mesh box [−half, half]³
};

double distanceToLine(const Vec3& p, const Vec3& a, const Vec3& d) {
  const Vec3 u = d.normalized();
  return (p - a - (p - a).dot(u) * u).norm();
}

void checkStraightCurve(const AnalyticCase& c, std::shared_ptr<const TetMesh> mesh,
                        const char* meshName) {
  SCOPED_TRACE(std::string(c.name) + " on " + meshName);
  const DegenerateCurves curves = extractDegenerateCurves(testing::sampleField(mesh, c.field));
  ASSERT_EQ(curves.size(), 1u) << curves.summary();
  const DegenerateCurve& curve = curves.curve(0);
  EXPECT_FALSE(curve.closed);
  EXPECT_EQ(curve.type, c.type);
  const double h = mesh->meanEdgeLength();
  int matching = 0;
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    EXPECT_LT(distanceToLine(curve.points[i], c.point, c.direction), h);
    EXPECT_NE(curve.patterns[i], c.pattern == DegeneratePattern::Wedge
                                     ? DegeneratePattern::Trisector
                                     : DegeneratePattern::Wedge);
    matching += curve.patterns[i] == c.pattern;
  }
  EXPECT_GT(matching, int(curve.points.size()) * 9 / 10);
  // The curve crosses the whole box: its length is that of the line inside the box.
  const Vec3 u = c.direction.normalized();
  const double extent = 2 * c.half / u.cwiseAbs().maxCoeff();
  EXPECT_NEAR(curve.length(), extent, 2 * h);
  EXPECT_TRUE(curves.warnings().empty()) << curves.warnings()[0];
}

const std::vector<AnalyticCase>& analyticCases() {
  static const std::vector<AnalyticCase> cases = {
      {"F1 L-wedge", f1Wedge, Vec3::Zero(), Vec3::UnitZ(), DegenerateType::Linear,
       DegeneratePattern::Wedge, 1},
      {"F1 L-trisector", f1Trisector, Vec3::Zero(), Vec3::UnitZ(), DegenerateType::Linear,
       DegeneratePattern::Trisector, 1},
      {"F3 P-wedge", f3Wedge, Vec3::Zero(), Vec3::UnitZ(), DegenerateType::Planar,
       DegeneratePattern::Wedge, 1},
      {"F3 P-trisector", f3Trisector, Vec3::Zero(), Vec3::UnitZ(), DegenerateType::Planar,
       DegeneratePattern::Trisector, 1},
      {"SingleTopoLine", singleTopoLine, Vec3::Zero(), Vec3(1, 1, 1), DegenerateType::Linear,
       DegeneratePattern::Wedge, 0.5},
  };
  return cases;
}

TEST(TopologyExtract, StraightLinesAlongMeshEdgesAndThroughVertices) {
  // The lines lie on grid lines (F1, F3) or on the Kuhn cubes' shared diagonals
  // (SingleTopoLine): every curve point is on an edge or a vertex, and the fields are block
  // diagonal, so only the non-generic fallback can find them.
  for (const AnalyticCase& c : analyticCases()) {
    checkStraightCurve(c, makeBoxMesh(8, 8, 8, Vec3::Constant(-c.half), Vec3::Constant(c.half)),
                       "structured box");
  }
}

TEST(TopologyExtract, StraightLinesOnJitteredMeshes) {
  for (const AnalyticCase& c : analyticCases()) {
    checkStraightCurve(c, testing::jitteredBox(7, -c.half, c.half, 0.15, 11), "jittered box");
  }
}

TEST(TopologyExtract, TiltedCircleIsOneLoopWithTwoTransitions) {
  // α = x² + y² − ¼, β = z − 0.3x in the block: the degenerate set is the ellipse where the
  // cylinder meets the tilted plane. With e = ẑ, δ = 0.6 y: wedge for y > 0, trisector for
  // y < 0, transitions at (±½, 0, ±0.15).
  const TensorFunction circle = [](const Vec3& p) {
    const double a = p.x() * p.x() + p.y() * p.y() - 0.25, b = p.z() - 0.3 * p.x();
    return Tensor{-1 + a, -1 - a, 2, b, 0, 0};
  };
  const auto mesh = testing::jitteredBox(12, -1, 1, 0.15, 5);
  const DegenerateCurves curves = extractDegenerateCurves(testing::sampleField(mesh, circle));
  ASSERT_EQ(curves.size(), 1u) << curves.summary();
  const DegenerateCurve& c = curves.curve(0);
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.type, DegenerateType::Linear);
  const double h = mesh->meanEdgeLength();
  std::vector<Vec3> transitions;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const Vec3& p = c.points[i];
    EXPECT_NEAR(std::hypot(p.x(), p.y()), 0.5, h);
    EXPECT_NEAR(p.z(), 0.3 * p.x(), h);
    if (p.y() > h) {
      EXPECT_EQ(c.patterns[i], DegeneratePattern::Wedge) << p.transpose();
    }
    if (p.y() < -h) {
      EXPECT_EQ(c.patterns[i], DegeneratePattern::Trisector) << p.transpose();
    }
    if (c.patterns[i] == DegeneratePattern::Transition) transitions.push_back(p);
  }
  ASSERT_GE(transitions.size(), 2u);
  for (const Vec3& t : transitions) {
    const double d = std::min((t - Vec3(0.5, 0, 0.15)).norm(), (t - Vec3(-0.5, 0, -0.15)).norm());
    EXPECT_LT(d, 2 * h) << t.transpose();
  }
  EXPECT_EQ(curves.statistics().closed, 1);
}

/// A smooth random field: constant + a few low-frequency sines per component.
TensorFunction randomSmoothField(unsigned seed) {
  std::mt19937_64 rng(seed);
  struct Wave {
    Tensor amplitude;
    Vec3 frequency;
    double phase;
  };
  std::vector<Wave> waves;
  std::normal_distribution<double> n(0, 1);
  const Tensor constant = testing::randomTraceless(rng, 0.3);
  for (int k = 0; k < 4; ++k) {
    waves.push_back({testing::randomTraceless(rng), Vec3(n(rng), n(rng), n(rng)) * 1.2,
                     std::uniform_real_distribution<double>(0, 6.28)(rng)});
  }
  return [constant, waves](const Vec3& p) {
    Tensor t = constant;
    for (const Wave& w : waves) t += w.amplitude * std::sin(w.frequency.dot(p) + w.phase);
    return t;
  };
}

TEST(TopologyExtract, RandomSmoothFieldsMissNothingABruteForceSearchFinds) {
  int bruteForcePoints = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const auto mesh = testing::jitteredBox(4, -1, 1, 0.15, seed);
    const TensorField field = testing::sampleField(mesh, randomSmoothField(seed));
    const DegenerateCurves curves = extractDegenerateCurves(field);
    std::vector<Vec3> reported;
    for (const DegenerateCurve& c : curves.curves()) {
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        reported.push_back(c.points[i]);
        const auto t = field.sample(c.points[i]);
        ASSERT_TRUE(t.has_value());
        EXPECT_LE(normalizedDiscriminant(*t), 1e-10) << "seed " << seed;
      }
    }
    const double h = mesh->meanEdgeLength();
    for (std::size_t f = 0; f < mesh->faces().size(); ++f) {
      const auto& fv = mesh->faces()[f];
      const auto found =
          testing::bruteForceFacePoints(field.at(fv[0]), field.at(fv[1]), field.at(fv[2]), 14);
      for (const Vec3& b : found) {
        const Vec3 p = b[0] * mesh->positions()[fv[0]] + b[1] * mesh->positions()[fv[1]] +
                       b[2] * mesh->positions()[fv[2]];
        double best = 1e300;
        for (const Vec3& q : reported) best = std::min(best, (p - q).norm());
        EXPECT_LT(best, 1e-6 * h) << "seed " << seed << " face " << f << " missed point "
                                  << p.transpose();
        ++bruteForcePoints;
      }
    }
    // The pre-filter only saves time.
    ExtractOptions noFilter;
    noFilter.prefilter = false;
    const DegenerateCurves unfiltered = extractDegenerateCurves(field, noFilter);
    ASSERT_EQ(unfiltered.size(), curves.size());
    for (std::size_t i = 0; i < curves.size(); ++i)
      EXPECT_EQ(unfiltered.curves()[i].points, curves.curves()[i].points);
  }
  EXPECT_GT(bruteForcePoints, 20);
}

DegenerateCurves extractWithThreads(const TensorField& field, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return extractDegenerateCurves(field);
}

TEST(TopologyExtract, IdenticalCurvesForOneAndTwoThreads) {
  const auto mesh = testing::jitteredBox(14, -1, 1, 0.15, 3);
  for (const TensorFunction& f : {randomSmoothField(9), TensorFunction(f1Trisector)}) {
    const TensorField field = testing::sampleField(mesh, f);
    const DegenerateCurves one = extractWithThreads(field, 1);
    const DegenerateCurves two = extractWithThreads(field, 2);
    ASSERT_EQ(one.size(), two.size());
    ASSERT_GT(one.size(), 0u);
    for (std::size_t i = 0; i < one.size(); ++i) {
      const DegenerateCurve &a = one.curves()[i], &b = two.curves()[i];
      EXPECT_EQ(a.points, b.points);  // bitwise
      EXPECT_EQ(a.patterns, b.patterns);
      EXPECT_EQ(a.tangents, b.tangents);
      EXPECT_EQ(a.sources, b.sources);
      EXPECT_EQ(a.type, b.type);
      EXPECT_EQ(a.closed, b.closed);
    }
    EXPECT_EQ(one.warnings(), two.warnings());
  }
}

TEST(TopologyExtract, TinyJitterKeepsTheTopologyOfAGenericField) {
  const auto mesh = testing::jitteredBox(10, -1, 1, 0.15, 4);
  for (unsigned seed = 30; seed < 33; ++seed) {
    const TensorField field = testing::sampleField(mesh, randomSmoothField(seed));
    std::mt19937_64 rng(seed);
    std::vector<Tensor> jittered = field.values();
    for (Tensor& t : jittered) t += testing::randomTraceless(rng, 1e-9 * t.norm());
    const DegenerateCurves a = extractDegenerateCurves(field);
    const DegenerateCurves b =
        extractDegenerateCurves(TensorField(field.meshPtr(), std::move(jittered)));
    ASSERT_EQ(a.size(), b.size()) << "seed " << seed;
    EXPECT_GT(a.size(), 0u);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a.curves()[i].type, b.curves()[i].type);
      EXPECT_EQ(a.curves()[i].closed, b.curves()[i].closed);
      EXPECT_EQ(a.curves()[i].points.size(), b.curves()[i].points.size());
    }
  }
}

TEST(TopologyExtract, ZeroAndConstantFieldsWarnInsteadOfFailing) {
  const auto mesh = makeBoxMesh(3, 3, 3, Vec3::Zero(), Vec3::Ones());
  const DegenerateCurves zero =
      extractDegenerateCurves(TensorField(mesh, std::vector<Tensor>(mesh->vertexCount())));
  EXPECT_TRUE(zero.empty());
  ASSERT_EQ(zero.warnings().size(), 1u);
  EXPECT_NE(zero.warnings()[0].find("zero everywhere"), std::string::npos);

  const Tensor generic{1, -0.3, -0.7, 0.2, 0.1, -0.4};
  const DegenerateCurves constant =
      extractDegenerateCurves(TensorField(mesh, std::vector<Tensor>(mesh->vertexCount(), generic)));
  EXPECT_TRUE(constant.empty());
  ASSERT_EQ(constant.warnings().size(), 1u);
  EXPECT_NE(constant.warnings()[0].find("constant"), std::string::npos);

  const Tensor degenerate{2, -1, -1, 0, 0, 0};
  const DegenerateCurves everywhere = extractDegenerateCurves(
      TensorField(mesh, std::vector<Tensor>(mesh->vertexCount(), degenerate)));
  EXPECT_TRUE(everywhere.empty());
  EXPECT_NE(everywhere.warnings()[0].find("degenerate everywhere"), std::string::npos);
}

TEST(TopologyExtract, FieldVanishingOnARegionDoesNotCrash) {
  // Zero on the half x < 0 (a triple-degenerate region), F1 elsewhere.
  const auto mesh = testing::jitteredBox(6, -1, 1, 0.15, 8);
  const DegenerateCurves curves = extractDegenerateCurves(testing::sampleField(
      mesh, [](const Vec3& p) { return p.x() < 0 ? Tensor{} : f1Wedge(p + Vec3(-0.5, 0, 0)); }));
  bool mentionsZero = false;
  for (const auto& w : curves.warnings())
    mentionsZero = mentionsZero || w.find("vanishes") != std::string::npos;
  EXPECT_TRUE(mentionsZero);
  for (const DegenerateCurve& c : curves.curves()) EXPECT_EQ(c.points.size(), c.patterns.size());
}

TEST(TopologyExtract, InvalidOptionsNameTheOption) {
  const auto mesh = makeBoxMesh(1, 1, 1, Vec3::Zero(), Vec3::Ones());
  const TensorField field = testing::sampleField(mesh, f1Wedge);
  ExtractOptions o;
  o.arcSamples = -1;
  try {
    extractDegenerateCurves(field, o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("arcSamples"), std::string::npos);
  }
}

TEST(TopologyExtract, NonFiniteFieldNamesTheVertex) {
  const auto mesh = makeBoxMesh(2, 2, 2, Vec3::Zero(), Vec3::Ones());
  std::vector<Tensor> values(mesh->vertexCount(), Tensor{1, -1, 0, 0.3, 0, 0});
  values[5].xy = std::nan("");
  try {
    extractDegenerateCurves(TensorField(mesh, values));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 5"), std::string::npos) << e.what();
  }
}

TEST(TopologyExtract, CancellationStopsTheExtraction) {
  const auto mesh = testing::jitteredBox(6, -1, 1, 0.15, 8);
  const TensorField field = testing::sampleField(mesh, f1Wedge);
  std::atomic<bool> cancel{true};
  const Progress progress({}, &cancel);
  EXPECT_THROW(extractDegenerateCurves(field, {}, progress), Cancelled);
}

TEST(TopologyExtract, PickFindsTheNearestCurveAndItsParameter) {
  const auto mesh = makeBoxMesh(8, 8, 8, Vec3::Constant(-1), Vec3::Constant(1));
  // Two F1 lines: x = y = 0 (L wedge) shifted copies would need a sum; use F1 and pick on it.
  const DegenerateCurves curves = extractDegenerateCurves(testing::sampleField(mesh, f1Wedge));
  ASSERT_EQ(curves.size(), 1u);
  const auto pick = curves.pick(Vec3(0.3, 0.1, 0.2));
  ASSERT_TRUE(pick.has_value());
  EXPECT_EQ(pick->curveId, 0);
  EXPECT_NEAR(pick->distance, std::hypot(0.3, 0.1), 1e-5);
  EXPECT_NEAR(pick->position.z(), 0.2, 1e-5);
  // The curve starts at its lexicographically smaller end, z = −1.
  EXPECT_NEAR(pick->arcLength, 1.2, 1e-5);
  const DegenerateCurve& c = curves.curve(0);
  EXPECT_LT((c.points[pick->pointIndex] - pick->position).norm(), 0.25 + 1e-9);
  EXPECT_FALSE(DegenerateCurves().pick(Vec3::Zero()).has_value());
}

TEST(TopologyExtract, CanonicalOrderDoesNotDependOnInputOrder) {
  DegenerateCurve a, b;
  a.points = {{1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  a.patterns.assign(3, DegeneratePattern::Wedge);
  a.tangents.assign(3, Vec3::UnitX());
  b.points = {{0, 1, 0}, {0, 0, 1}, {0, 0, 0}};
  b.closed = true;
  b.patterns = {DegeneratePattern::Wedge, DegeneratePattern::Trisector,
                DegeneratePattern::Transition};
  DegenerateCurve ar = a;
  std::reverse(ar.points.begin(), ar.points.end());
  ar.tangents.assign(3, -Vec3::UnitX());
  const DegenerateCurves one({a, b}), two({b, ar});
  ASSERT_EQ(one.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(one.curves()[i].points, two.curves()[i].points);
    EXPECT_EQ(one.curves()[i].tangents, two.curves()[i].tangents);
    EXPECT_EQ(one.curves()[i].patterns, two.curves()[i].patterns);
  }
  // The loop starts at its smallest point and keeps each point's pattern.
  EXPECT_EQ(one.curve(0).points[0], Vec3(0, 0, 0));
  EXPECT_EQ(one.curve(0).patterns[0], DegeneratePattern::Transition);
  EXPECT_EQ(one.statistics().closed, 1);
  EXPECT_EQ(one.statistics().transitionPoints, 1);
  DegenerateCurve mismatched;
  mismatched.points = {{0, 0, 0}};  // one point, no pattern
  EXPECT_THROW(DegenerateCurves({mismatched}), Error);
}

}  // namespace
}  // namespace tfd::core::topology
