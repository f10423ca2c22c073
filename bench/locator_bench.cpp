// Point location on a TetGen sphere of about 1M tets: building the uniform-grid locator
// (core/point_locator.h), then locating a million random points of the bounding box
// (about half fall inside the ball) with PointLocator::locateAll on 1 and 2 threads.
//
//   build/bench/locator_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <random>

#include "core/point_locator.h"
#include "io/tetgen/tetgen_mesher.h"
#include "tests/support/random_vec3.h"

namespace {

using namespace tfd;

const std::shared_ptr<const core::TetMesh>& sphere() {
  static const auto mesh = io::meshPrimitive(core::PrimitiveShape::Sphere, 1'000'000);
  return mesh;
}

std::vector<core::Vec3> randomPoints(std::size_t n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<core::Vec3> points(n);
  for (auto& p : points) p = tfd::test::drawVec3(u, rng);
  return points;
}

void BM_LocatorBuild(benchmark::State& state) {
  const auto& mesh = sphere();
  for (auto _ : state) {
    core::PointLocator locator(*mesh);
    benchmark::DoNotOptimize(&locator);
  }
  state.counters["tets"] = double(mesh->tetCount());
}

void BM_LocateMillion(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  const auto& mesh = sphere();
  const core::PointLocator& locator = mesh->locator();
  const std::vector<core::Vec3> points = randomPoints(1'000'000);
  std::size_t inside = 0;
  for (auto _ : state) {
    const auto hits = locator.locateAll(points);
    inside = 0;
    for (const auto& h : hits) inside += h.has_value();
  }
  state.counters["inside"] = double(inside);
}

/// A few points without the grid (core::locateByScan): one pass over the tets per call.
/// Compare with BM_LocatorBuild + the grid's per-point cost to find the break-even count.
void BM_LocateByScan(benchmark::State& state) {
  const auto& mesh = sphere();
  const std::vector<core::Vec3> points = randomPoints(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    const auto hits = core::locateByScan(*mesh, points);
    benchmark::DoNotOptimize(hits.data());
  }
  state.counters["points"] = double(points.size());
}

BENCHMARK(BM_LocateByScan)
    ->Arg(1)
    ->Arg(4)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5)
    ->UseRealTime();
BENCHMARK(BM_LocatorBuild)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_LocateMillion)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
