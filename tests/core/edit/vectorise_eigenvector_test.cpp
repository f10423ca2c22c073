// Vectorising the non-repeating eigenvector in a region (core/edit/vectorise_eigenvector.h).
#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>

#include <Eigen/Geometry>

#include "core/edit/vectorise_eigenvector.h"
#include "core/error.h"
#include "core/structured_mesh.h"

namespace tfd::core {
namespace {

/// R(p) diag(λ) R(p)ᵀ with a rotation that turns the frame by up to ~170° across the box: the
/// major eigenvector R(p) x̂ changes the sign of every coordinate somewhere, so no fixed
/// reference direction orients it, yet it is a smooth vector field.
Mat3 frameAt(const Vec3& p) {
  return (Eigen::AngleAxisd(1.4 * p.x() + 0.3 * p.z(), Vec3::UnitZ()) *
          Eigen::AngleAxisd(0.9 * p.y(), Vec3::UnitX()))
      .toRotationMatrix();
}

TensorField rotatingField(std::shared_ptr<const TetMesh> mesh, const Vec3& lambda) {
  std::vector<Tensor> values;
  for (const Vec3& p : mesh->positions()) {
    const Mat3 r = frameAt(p);
    values.push_back(Tensor::fromMatrix(r * lambda.asDiagonal() * r.transpose()));
  }
  return TensorField(mesh, values);
}

std::vector<int> allTets(const TetMesh& mesh) {
  std::vector<int> tets(mesh.tetCount());
  for (std::size_t t = 0; t < tets.size(); ++t) tets[t] = static_cast<int>(t);
  return tets;
}

/// Tets whose centroid lies within `radius` of the z axis.
std::vector<int> tetsNearZAxis(const TetMesh& mesh, double radius) {
  std::vector<int> out;
  for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
    Vec3 c = Vec3::Zero();
    for (int v : mesh.tets()[t]) c += mesh.positions()[v] / 4;
    if (std::hypot(c.x(), c.y()) < radius) out.push_back(static_cast<int>(t));
  }
  return out;
}

TEST(VectoriseEigenvector, SmoothFieldHasNoConflictAndFollowsTheEigenvectorUpToSign) {
  const auto mesh = makeBoxMesh(8, 8, 8, Vec3::Constant(-1.5), Vec3::Constant(1.5));
  for (DegenerateType type : {DegenerateType::Linear, DegenerateType::Planar}) {
    const TensorField field = rotatingField(mesh, Vec3(2.0, -0.5, -1.5));
    const VectorisedEigenvector v = vectoriseEigenvector(field, allTets(*mesh), type);
    ASSERT_EQ(v.vertices.size(), mesh->vertexCount());
    EXPECT_EQ(v.signConflicts, 0);
    int positiveX = 0;
    for (std::size_t i = 0; i < v.vertices.size(); ++i) {
      EXPECT_EQ(v.vertices[i], static_cast<int>(i));
      const Vec3 truth = frameAt(mesh->positions()[i]).col(type == DegenerateType::Linear ? 0 : 2);
      EXPECT_NEAR(v.directions[i].norm(), 1, 1e-14);
      EXPECT_GT(std::abs(v.directions[i].dot(truth)), 1 - 1e-12);
      positiveX += v.directions[i].x() > 0;
    }
    // The field really turns: a fixed reference direction would have conflicts.
    EXPECT_GT(positiveX, 0);
    EXPECT_LT(positiveX, static_cast<int>(mesh->vertexCount()));
    // The orientation is the truth's up to one global sign: every edge agrees with it.
    const double s =
        v.directions[0].dot(frameAt(mesh->positions()[0]).col(nonRepeatingColumn(type)));
    for (std::size_t i = 0; i < v.vertices.size(); ++i) {
      const Vec3 truth = frameAt(mesh->positions()[i]).col(nonRepeatingColumn(type));
      EXPECT_GT(s * v.directions[i].dot(truth), 0) << "vertex " << i;
    }
  }
}

/// F3 of the algorithms note: a P-type wedge along the z axis, A = [[1+x, y, 0], [y, 1−x, 0],
/// [0, 0, −2]]. Its major eigenvector turns by π around the axis (index ½); its minor one is ẑ.
TensorField planarWedge(std::shared_ptr<const TetMesh> mesh) {
  std::vector<Tensor> values;
  for (const Vec3& p : mesh->positions()) {
    values.push_back(Tensor{1 + p.x(), 1 - p.x(), -2, p.y(), 0, 0});
  }
  return TensorField(mesh, values);
}

TEST(VectoriseEigenvector, RegionAroundADegenerateCurveHasConflictsOnlyForTheRepeatedVector) {
  // Offset so that no vertex lies on the curve x = y = 0.
  const auto mesh = makeBoxMesh(10, 10, 4, Vec3(-1.03, -0.97, -1), Vec3(0.97, 1.03, 1));
  const TensorField field = planarWedge(mesh);
  const std::vector<int> region = tetsNearZAxis(*mesh, 0.7);
  const VectorisedEigenvector major = vectoriseEigenvector(field, region, DegenerateType::Linear);
  EXPECT_GT(major.signConflicts, 0) << "the major eigenvector cannot be oriented around a wedge";
  // The conflicting edges are listed and disagree in sign; they form the cut where the tree's
  // signs flip, which reaches the curve x = y = 0 (the removal forbids the tets around them).
  ASSERT_EQ(major.conflictEdges.size(), std::size_t(major.signConflicts));
  double nearest = 1e9;
  for (int e : major.conflictEdges) {
    const auto& ends = mesh->edges()[e];
    const auto at = [&](int v) {
      return major.directions[std::lower_bound(major.vertices.begin(), major.vertices.end(), v) -
                              major.vertices.begin()];
    };
    EXPECT_LT(at(ends[0]).dot(at(ends[1])), 0);
    const Vec3 mid = 0.5 * (mesh->positions()[ends[0]] + mesh->positions()[ends[1]]);
    nearest = std::min(nearest, std::hypot(mid.x(), mid.y()));
  }
  EXPECT_LT(nearest, 0.2 * std::sqrt(2.0)) << "the cut reaches the cell of the curve";
  const VectorisedEigenvector minor = vectoriseEigenvector(field, region, DegenerateType::Planar);
  EXPECT_EQ(minor.signConflicts, 0) << "the non-repeating (minor) eigenvector can";
  EXPECT_TRUE(minor.conflictEdges.empty());
  for (const Vec3& d : minor.directions) EXPECT_GT(std::abs(d.z()), 1 - 1e-12);
  // A region beside the curve, not around it: the major eigenvector orients fine there.
  std::vector<int> beside;
  for (int t : tetsNearZAxis(*mesh, 10)) {
    bool right = true;
    for (int v : mesh->tets()[t]) right = right && mesh->positions()[v].x() > 0.2;
    if (right) beside.push_back(t);
  }
  ASSERT_FALSE(beside.empty());
  EXPECT_EQ(vectoriseEigenvector(field, beside, DegenerateType::Linear).signConflicts, 0);
}

/// Reference: the orientation of the maximum spanning tree of |e_u·e_v| from the seed (Prim's
/// order with std::priority_queue, ties by vertex id), on the raw eigenvectors.
std::vector<Vec3> primOrientation(const TensorField& field, const VectorisedEigenvector& v,
                                  DegenerateType type) {
  const TetMesh& mesh = field.mesh();
  const int n = static_cast<int>(v.vertices.size());
  auto local = [&](int vertex) {
    return int(std::lower_bound(v.vertices.begin(), v.vertices.end(), vertex) - v.vertices.begin());
  };
  std::vector<std::vector<int>> adjacent(n);
  for (const auto& e : mesh.edges()) {
    const int a = local(e[0]), b = local(e[1]);
    if (a < n && b < n && v.vertices[a] == e[0] && v.vertices[b] == e[1])
      adjacent[a].push_back(b), adjacent[b].push_back(a);
  }
  std::vector<Vec3> dirs(n);
  for (int i = 0; i < n; ++i)
    dirs[i] = eigenDecompose(field.at(v.vertices[i]).deviator())
                  .vectors.col(nonRepeatingColumn(type))
                  .normalized();
  const int seed = local(v.seed);
  int axis = 0;
  dirs[seed].cwiseAbs().maxCoeff(&axis);
  if (dirs[seed][axis] < 0) dirs[seed] = -dirs[seed];  // the seed's largest component positive
  std::vector<char> done(n, 0);
  std::priority_queue<std::tuple<double, int, int>> queue;
  auto push = [&](int from) {
    for (int to : adjacent[from])
      if (!done[to]) queue.emplace(std::abs(dirs[from].dot(dirs[to])), -to, from);
  };
  done[seed] = 1;
  push(seed);
  while (!queue.empty()) {
    const auto [weight, negTo, from] = queue.top();
    queue.pop();
    if (done[-negTo]) continue;
    done[-negTo] = 1;
    if (dirs[from].dot(dirs[-negTo]) < 0) dirs[-negTo] = -dirs[-negTo];
    push(-negTo);
  }
  return dirs;
}

TEST(VectoriseEigenvector, OrientationIsThatOfTheMaximumSpanningTreeWithOrWithoutConflicts) {
  const auto mesh = makeBoxMesh(10, 10, 4, Vec3(-1.03, -0.97, -1), Vec3(0.97, 1.03, 1));
  const std::vector<int> aroundAxis = tetsNearZAxis(*mesh, 0.7);
  struct Case {
    TensorField field;
    std::vector<int> region;
    DegenerateType type;
    bool conflicts;
  };
  const std::vector<Case> cases = {
      {rotatingField(mesh, Vec3(2.0, -0.5, -1.5)), allTets(*mesh), DegenerateType::Linear, false},
      {planarWedge(mesh), aroundAxis, DegenerateType::Planar, false},
      {planarWedge(mesh), aroundAxis, DegenerateType::Linear, true}};  // around the wedge
  for (const Case& c : cases) {
    const VectorisedEigenvector v = vectoriseEigenvector(c.field, c.region, c.type);
    EXPECT_EQ(v.signConflicts > 0, c.conflicts);
    const std::vector<Vec3> reference = primOrientation(c.field, v, c.type);
    ASSERT_EQ(reference.size(), v.directions.size());
    for (std::size_t i = 0; i < reference.size(); ++i)
      ASSERT_EQ(reference[i], v.directions[i]) << "vertex " << v.vertices[i];
  }
}

TEST(VectoriseEigenvector, RefusesDisconnectedOrInvalidRegions) {
  const auto mesh = makeBoxMesh(4, 1, 1, Vec3(0, 0, 0), Vec3(4, 1, 1));
  const TensorField field = rotatingField(mesh, Vec3(2.0, -0.5, -1.5));
  // Tets of the first and the last cube share no vertex.
  const std::vector<int> split = {0, 1, 2, 18, 19};
  try {
    vectoriseEigenvector(field, split, DegenerateType::Linear);
    FAIL() << "a disconnected region was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not connected"), std::string::npos) << e.what();
  }
  EXPECT_THROW(vectoriseEigenvector(field, std::vector<int>{}, DegenerateType::Linear), Error);
  EXPECT_THROW(vectoriseEigenvector(field, {0, 24}, DegenerateType::Linear), Error);
}

TEST(VectoriseEigenvector, SameResultForOneAndTwoThreads) {
  const auto mesh = makeBoxMesh(10, 10, 10, Vec3::Constant(-1), Vec3::Constant(1));
  const TensorField field = rotatingField(mesh, Vec3(1.0, 0.7, -1.7));
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return vectoriseEigenvector(field, allTets(*mesh), DegenerateType::Linear);
  };
  const VectorisedEigenvector a = run(1), b = run(2);
  ASSERT_EQ(a.directions.size(), b.directions.size());
  for (std::size_t i = 0; i < a.directions.size(); ++i) EXPECT_EQ(a.directions[i], b.directions[i]);
  EXPECT_EQ(a.signConflicts, b.signConflicts);
}

}  // namespace
}  // namespace tfd::core
