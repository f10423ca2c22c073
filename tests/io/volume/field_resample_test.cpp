// Voxel lattice, field sampling at voxel centres and the per-voxel quantities shared by the
// VDB and EXR exports.
#include "io/volume/field_resample.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>

#include "core/error.h"
#include "core/structured_mesh.h"
#include "io/volume/voxel_quantities.h"
#include "tests/support/carved_ball.h"

namespace tfd {
namespace {

using core::Tensor;
using core::Vec3;

TEST(FieldResample, LatticeCoversTheBoundsOnIntegerMultiplesOfTheVoxelSize) {
  const auto mesh = core::makeBoxMesh(2, 2, 2, Vec3(-0.3, 0.05, 1.0), Vec3(0.7, 0.95, 1.2));
  const io::VoxelLattice l = io::latticeForMesh(*mesh, 0.1);
  // x: −0.3 … 0.7 → indices −3 … 7; y: 0.05 … 0.95 → 1 … 9; z: 1.0 … 1.2 → 10 … 12.
  EXPECT_EQ(l.min, (std::array<int, 3>{-3, 1, 10}));
  EXPECT_EQ(l.max, (std::array<int, 3>{7, 9, 12}));
  EXPECT_EQ(l.dims(), (std::array<int, 3>{11, 9, 3}));
  EXPECT_EQ(l.count(), 11u * 9u * 3u);
  EXPECT_TRUE(l.centre(-3, 1, 10).isApprox(Vec3(-0.3, 0.1, 1.0), 1e-15));

  const io::VoxelLattice shifted = io::latticeForMesh(*mesh, 0.1, Vec3(0.05, 0.05, 0.05));
  EXPECT_EQ(shifted.min, (std::array<int, 3>{-3, 0, 10}));
  EXPECT_EQ(shifted.max, (std::array<int, 3>{6, 9, 11}));
  for (int a = 0; a < 3; ++a) {
    EXPECT_GE(shifted.centre(shifted.min[0], shifted.min[1], shifted.min[2])[a],
              mesh->boundsMin()[a] - 1e-12);
    EXPECT_LE(shifted.centre(shifted.max[0], shifted.max[1], shifted.max[2])[a],
              mesh->boundsMax()[a] + 1e-12);
  }
}

TEST(FieldResample, LatticeRejectsBadVoxelSizes) {
  const auto mesh = core::makeBoxMesh(1, 1, 1, Vec3(0, 0, 0), Vec3(1, 1, 1));
  for (double h : {0.0, -1.0, std::nan(""), double(INFINITY)}) {
    EXPECT_THROW(io::latticeForMesh(*mesh, h), core::Error) << h;
  }
  EXPECT_THROW(io::latticeForMesh(*mesh, 1e-4), core::Error);  // 1e12 voxels
  EXPECT_NO_THROW(io::latticeForMesh(*mesh, 1e-2, Vec3::Zero(), 1.1e6));
  EXPECT_THROW(io::latticeForMesh(*mesh, 1e-2, Vec3::Zero(), 1e6), core::Error);  // 101³
  EXPECT_THROW(io::latticeForMesh(*mesh, 0.1, Vec3(NAN, 0, 0)), core::Error);
  EXPECT_THROW(io::latticeForMesh(*mesh, 1e-300), core::Error);  // index overflow
}

TEST(FieldResample, SamplesAreOrderedXFastestAndMatchPointSampling) {
  const auto mesh = test::carvedBall(6, Vec3(0, 0, 0), 1.0);
  std::vector<Tensor> values;
  for (const auto& p : mesh->positions()) {
    values.push_back(Tensor{p.x(), p.y(), p.z(), p.x() * p.y(), 1.0, -p.z()});
  }
  const core::TensorField field(mesh, std::move(values));
  const io::VoxelLattice l = io::latticeForMesh(*mesh, 0.15, Vec3(0.01, 0.02, 0.03));
  std::vector<std::vector<io::VoxelSample>> runs;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    runs.push_back(io::sampleVoxels(field, l, l.min, l.max));
  }
  ASSERT_EQ(runs[0].size(), l.count());
  std::size_t n = 0, inside = 0;
  for (int k = l.min[2]; k <= l.max[2]; ++k)
    for (int j = l.min[1]; j <= l.max[1]; ++j)
      for (int i = l.min[0]; i <= l.max[0]; ++i, ++n) {
        const Vec3 p = l.centre(i, j, k);
        const auto& s = runs[0][n];
        const auto expected = field.sample(p);
        ASSERT_EQ(s.inside(), expected.has_value());
        if (!s.inside()) {
          EXPECT_EQ(s.value, Tensor{});
          continue;
        }
        ++inside;
        EXPECT_EQ(s.value, *expected);
        // The linear part of the field is reproduced at the voxel centre.
        EXPECT_NEAR(s.value.xx, p.x(), 1e-12);
        EXPECT_NEAR(s.value.zz, p.z(), 1e-12);
        EXPECT_NEAR(s.barycentric.sum(), 1.0, 1e-12);
        EXPECT_EQ(std::memcmp(&s.value, &runs[1][n].value, sizeof(Tensor)), 0);
        EXPECT_EQ(s.tet, runs[1][n].tet);
      }
  EXPECT_GT(inside, l.count() / 3);

  std::atomic<bool> cancel{true};
  EXPECT_THROW(io::sampleVoxels(field, l, l.min, l.max, core::Progress({}, &cancel)),
               core::Cancelled);
}

TEST(FieldResample, RowSamplerGivesExactlyThePointLocatorsAnswer) {
  const auto mesh = test::carvedBall(7, Vec3(0.1, 0, 0), 1.0);
  std::vector<Tensor> values;
  for (const auto& p : mesh->positions()) {
    values.push_back(Tensor{std::sin(p.x()), p.y(), p.z() * p.z(), 0.1, p.x() - p.y(), 2.0});
  }
  const core::TensorField field(mesh, std::move(values));
  std::size_t inside = 0, points = 0;
  for (int line = 0; line < 40; ++line) {
    // Lines in varied directions, through and out of the ball, sampled with small steps, some
    // exactly through mesh vertices (line 0 runs along edges of the carved box mesh, hitting a
    // vertex every fourth step).
    const Vec3 start = line == 0 ? Vec3(-0.9, -1 + 6.0 / 7, -1 + 6.0 / 7)
                                 : Vec3(-1.2 + 0.01 * line, -0.9 + 0.045 * line, 0.7 - 0.03 * line);
    const Vec3 dir = line == 0 ? Vec3(1, 0, 0)
                               : Vec3(1, 0.3 * std::sin(line), 0.2 * std::cos(line)).normalized();
    io::RowSampler sampler(field);
    for (int step = 0; step < 160; ++step, ++points) {
      const Vec3 p = start + (line == 0 ? 2.0 / 7.0 / 4.0 : 0.015) * step * dir;
      const io::VoxelSample a = sampler(p);
      const io::VoxelSample b = io::sampleField(field, p);
      ASSERT_EQ(a.tet, b.tet) << line << " " << step;
      ASSERT_EQ(std::memcmp(a.barycentric.data(), b.barycentric.data(), 4 * sizeof(double)), 0);
      ASSERT_EQ(std::memcmp(&a.value, &b.value, sizeof(Tensor)), 0);
      inside += a.inside();
    }
  }
  EXPECT_GT(inside, points / 3);
  EXPECT_LT(inside, points);
}

TEST(VoxelQuantities, NamesOrderAndValues) {
  const auto mesh = core::makeBoxMesh(1, 1, 1, Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::vector<double> density(mesh->vertexCount());
  for (std::size_t v = 0; v < density.size(); ++v) density[v] = mesh->positions()[v].sum();
  const auto q = io::VoxelQuantities{true, true, true, io::interpolateVertexScalars(mesh, density)};
  EXPECT_EQ(q.channelCount(), 19);
  const auto names = q.channelNames("S");
  ASSERT_EQ(names.size(), 19u);
  EXPECT_EQ(names[0], "S.xx");
  EXPECT_EQ(names[5], "S.xz");
  EXPECT_EQ(names[6], "S.eigval.x");
  EXPECT_EQ(names[9], "S.e1.x");
  EXPECT_EQ(names[17], "S.e3.z");
  EXPECT_EQ(names[18], "density");

  io::VoxelSample s;
  s.tet = 0;
  s.barycentric = Eigen::Vector4d(0.1, 0.2, 0.3, 0.4);
  s.value = Tensor{3, 2, 1, 0, 0, 0};
  float out[19];
  q.evaluate(Vec3::Zero(), s, out);
  EXPECT_EQ(out[0], 3.0f);
  EXPECT_EQ(out[6], 3.0f);                     // λ1
  EXPECT_EQ(out[8], 1.0f);                     // λ3
  EXPECT_NEAR(std::abs(out[9]), 1.0f, 1e-7);   // e1 = ±x
  EXPECT_NEAR(std::abs(out[13]), 1.0f, 1e-7);  // e2 = ±y
  EXPECT_NEAR(std::abs(out[17]), 1.0f, 1e-7);  // e3 = ±z
  const auto& t = mesh->tets()[0];
  double expected = 0;
  for (int i = 0; i < 4; ++i) expected += s.barycentric[i] * density[t[i]];
  EXPECT_NEAR(out[18], expected, 1e-6);
  EXPECT_THROW(io::interpolateVertexScalars(mesh, {1.0}), core::Error);
}

}  // namespace
}  // namespace tfd
