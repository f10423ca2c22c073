// Gabor noise (core/synth/gabor_noise.h) on 128³ and 256³ voxel grids over a ball of about
// 1M tets (a 69³ Kuhn box carved to the unit ball: 1,031,856 tets), with a field that has linear
// and planar regions, orientation auto, frequency 8 (a period of 8 voxels at 128³), 16 impulses per
// kernel. Arguments: voxels per side, thread count. Results and the command line:
// bench/RESULTS.md.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>

#include "core/structured_mesh.h"
#include "core/synth/gabor_noise.h"

namespace {

using namespace tfd;

std::shared_ptr<const core::TetMesh> carvedBall(int n) {
  const auto box = core::makeBoxMesh(n, n, n, core::Vec3::Constant(-1), core::Vec3::Constant(1));
  std::vector<int> id(box->vertexCount(), -1);
  std::vector<core::Vec3> positions;
  std::vector<core::TetMesh::Tet> tets;
  for (const auto& t : box->tets()) {
    core::Vec3 c = core::Vec3::Zero();
    for (int v : t) c += box->positions()[v] / 4;
    if (c.norm() >= 1) continue;
    core::TetMesh::Tet out;
    for (int i = 0; i < 4; ++i) {
      if (id[t[i]] < 0) {
        id[t[i]] = int(positions.size());
        positions.push_back(box->positions()[t[i]]);
      }
      out[i] = id[t[i]];
    }
    tets.push_back(out);
  }
  return std::make_shared<const core::TetMesh>(std::move(positions), std::move(tets));
}

const core::TensorField& benchField() {
  static const core::TensorField field = [] {
    auto mesh = carvedBall(69);
    std::vector<core::Tensor> values;
    values.reserve(mesh->vertexCount());
    for (const auto& p : mesh->positions()) {
      values.push_back(core::Tensor{1.0 - p.x(), 0.2 * p.y(), -1.0 + p.x(), 0.4 * p.z(),
                                    0.3 * p.x(), 0.5 * p.y() * p.z()}
                           .deviator());
    }
    core::TensorField f(std::move(mesh), std::move(values));
    f.mesh().locator();  // built once, outside the timings
    return f;
  }();
  return field;
}

core::VoxelGrid gridOf(int perSide) {
  core::VoxelGrid g;
  g.voxelSize = 2.0 / (perSide - 1);
  g.min = {-(perSide - 1) / 2, -(perSide - 1) / 2, -(perSide - 1) / 2};
  g.max = {g.min[0] + perSide - 1, g.min[1] + perSide - 1, g.min[2] + perSide - 1};
  return g;
}

void BM_GaborNoise(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, state.range(1));
  const auto& field = benchField();
  const core::VoxelGrid grid = gridOf(int(state.range(0)));
  core::GaborNoiseOptions o;
  o.frequency = 8;
  core::GaborNoiseStats stats;
  for (auto _ : state) {
    core::ScalarVolume v = core::gaborNoiseVolume(field, grid, o, {}, &stats);
    benchmark::DoNotOptimize(v.values.data());
  }
  state.counters["tets"] = double(field.mesh().tetCount());
  state.counters["voxels"] = double(grid.count());
  state.counters["inside"] = double(stats.insideVoxels);
  state.counters["kernels"] = double(stats.impulses);
  state.counters["evals"] = double(stats.kernelEvaluations);
  state.counters["evals_per_s"] = benchmark::Counter(double(stats.kernelEvaluations),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GaborNoise)
    ->Args({128, 1})
    ->Args({128, 2})
    ->Args({256, 1})
    ->Args({256, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The inside mask alone (boundary crossings per row of voxels).
void BM_InsideMask(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, state.range(1));
  const auto& field = benchField();
  const core::VoxelGrid grid = gridOf(int(state.range(0)));
  for (auto _ : state) {
    auto mask = core::insideMask(field.mesh(), grid);
    benchmark::DoNotOptimize(mask.data());
  }
}
BENCHMARK(BM_InsideMask)->Args({256, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
