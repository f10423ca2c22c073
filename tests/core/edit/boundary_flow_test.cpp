// The incoming / outgoing split of a region's boundary (core/edit/boundary_flow.h).
#include "core/edit/boundary_flow.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/structured_mesh.h"

namespace tfd::core {
namespace {

/// A constant field whose major eigenvector is d = (1, 0.3, 0.2) / ‖·‖: it leaves a box through
/// the three faces at the upper x, y, z and enters through the other three.
TensorField tiltedField(std::shared_ptr<const TetMesh> mesh) {
  const Vec3 d = Vec3(1, 0.3, 0.2).normalized();
  const Mat3 m = 3 * d * d.transpose() - Mat3::Identity();
  return TensorField(mesh, std::vector<Tensor>(mesh->vertexCount(), Tensor::fromMatrix(m)));
}

TEST(BoundaryFlow, SplitsABoxByTheSideTheEigenvectorCrosses) {
  const auto mesh = makeBoxMesh(6, 5, 4, Vec3(0, 0, 0), Vec3(1, 2, 3));
  const TensorField field = tiltedField(mesh);
  // The region: tets with every vertex at x ≤ 0.5 (half the box; its boundary at x = 0.5 is
  // inside the mesh).
  std::vector<int> region;
  for (std::size_t t = 0; t < mesh->tetCount(); ++t) {
    bool left = true;
    for (int v : mesh->tets()[t]) left = left && mesh->positions()[v].x() < 0.5 + 1e-9;
    if (left) region.push_back(static_cast<int>(t));
  }
  const VectorisedEigenvector vec = vectoriseEigenvector(field, region, DegenerateType::Linear);
  ASSERT_GT(vec.directions.front().x(), 0) << "the seed's largest component is positive";
  const BoundaryFlow flow = boundaryFlow(*mesh, region, vec);
  // Faces of the half box [0, 0.5] × [0, 2] × [0, 3], two triangles per grid cell: in through
  // x = 0 (5 × 4 cells, area 6), y = 0 (3 × 4, area 1.5), z = 0 (3 × 5, area 1); out through
  // x = 0.5, y = 2, z = 3.
  EXPECT_EQ(flow.incomingFaces, std::size_t(2 * (20 + 12 + 15)));
  EXPECT_EQ(flow.outgoingFaces, std::size_t(2 * (20 + 12 + 15)));
  EXPECT_NEAR(flow.incomingArea, 6 + 1.5 + 1, 1e-12);
  EXPECT_NEAR(flow.outgoingArea, 6 + 1.5 + 1, 1e-12);
  EXPECT_NE(flow.summary().find("50 %"), std::string::npos) << flow.summary();
}

TEST(BoundaryFlow, SameTotalsForOneAndTwoThreads) {
  const auto mesh = makeBoxMesh(40, 30, 30, Vec3(0, 0, 0), Vec3(1, 1, 1));  // > one chunk
  const TensorField field = tiltedField(mesh);
  std::vector<int> region;
  for (std::size_t t = 0; t < mesh->tetCount(); ++t) {  // tets with their centroid in a ball
    Vec3 c = Vec3::Zero();
    for (int v : mesh->tets()[t]) c += mesh->positions()[v] / 4;
    if ((c - Vec3::Constant(0.5)).norm() < 0.45) region.push_back(static_cast<int>(t));
  }
  const VectorisedEigenvector vec = vectoriseEigenvector(field, region, DegenerateType::Linear);
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return boundaryFlow(*mesh, region, vec);
  };
  const BoundaryFlow a = run(1), b = run(2);
  EXPECT_EQ(a.incomingFaces, b.incomingFaces);
  EXPECT_EQ(a.outgoingFaces, b.outgoingFaces);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.incomingArea),
            std::bit_cast<std::uint64_t>(b.incomingArea));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.outgoingArea),
            std::bit_cast<std::uint64_t>(b.outgoingArea));
  EXPECT_GT(a.incomingFaces + a.outgoingFaces, 0u);
}

}  // namespace
}  // namespace tfd::core
