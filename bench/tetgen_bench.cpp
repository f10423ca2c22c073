// TetGen adapter benchmark: spheres of about 150K, 500K and 1M tets.
// Reports per size: tet count reached, surface build time, TetGen time, TetMesh topology
// build time (the constructor: validation, edges, faces, boundary, incidence, volumes), each
// as wall-clock and as process CPU time (std::clock, all threads: robust on a busy machine),
// and the peak resident memory of the run (VmHWM, reset before each size).
// Run: build-<dir>/bench/tetgen_bench --benchmark_counters_tabular=true
// Results and machine notes: bench/RESULTS.md.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>
#include <ctime>
#include <string>

#include "bench/process_measures.h"
#include "core/surface/primitives.h"
#include "io/tetgen/tetgen_mesher.h"

namespace {

using Clock = std::chrono::steady_clock;

using tfd::bench::peakMegabytes;  // since the last resetPeakMemory()
using tfd::bench::resetPeakMemory;

void BM_TetgenSphere(benchmark::State& state) {
  const double target = double(state.range(0));
  tfd::core::PrimitiveSpec spec;  // unit sphere
  double surfaceSeconds = 0, tetgenSeconds = 0, topologySeconds = 0, peak = 0;
  double tetgenCpu = 0, topologyCpu = 0;
  std::size_t tets = 0, boundaryTriangles = 0;
  for (auto _ : state) {
    resetPeakMemory();
    const auto t0 = Clock::now();
    const tfd::core::SurfaceMesh surface = tfd::core::makePrimitiveForTets(spec, target);
    const auto t1 = Clock::now();
    // The adapter reports the stage "building the tet mesh topology" right after TetGen.
    Clock::time_point tetgenDone = t1;
    const std::clock_t c1 = std::clock();
    std::clock_t cTetgenDone = c1;
    tfd::core::Progress progress(
        [&](double, std::string_view stage) {
          if (stage == "building the tet mesh topology") {
            tetgenDone = Clock::now();
            cTetgenDone = std::clock();
          }
        },
        nullptr);
    tfd::io::TetgenOptions options;
    options.targetTets = target;
    const auto mesh = tfd::io::tetrahedralize(surface, options, progress);
    const auto t2 = Clock::now();
    const std::clock_t c2 = std::clock();
    tetgenCpu = double(cTetgenDone - c1) / CLOCKS_PER_SEC;
    topologyCpu = double(c2 - cTetgenDone) / CLOCKS_PER_SEC;
    surfaceSeconds = std::chrono::duration<double>(t1 - t0).count();
    tetgenSeconds = std::chrono::duration<double>(tetgenDone - t1).count();
    topologySeconds = std::chrono::duration<double>(t2 - tetgenDone).count();
    peak = peakMegabytes();
    tets = mesh->tetCount();
    boundaryTriangles = surface.triangles.size();
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["tets"] = double(tets);
  state.counters["tets/target"] = double(tets) / target;
  state.counters["surface_tris"] = double(boundaryTriangles);
  state.counters["surface_s"] = surfaceSeconds;
  state.counters["tetgen_s"] = tetgenSeconds;
  state.counters["topology_s"] = topologySeconds;
  state.counters["tetgen_cpu_s"] = tetgenCpu;
  state.counters["topology_cpu_s"] = topologyCpu;
  state.counters["peak_MB"] = peak;
}

/// The TetMesh constructor alone (validation, incidence, edges, faces, boundary, volumes) on
/// TetGen's 1M-tet sphere, 1 and 2 threads; the copy of the input arrays is not timed.
const std::shared_ptr<const tfd::core::TetMesh>& sphere1M() {
  static const auto sphere = [] {
    tfd::io::TetgenOptions options;
    options.targetTets = 1e6;
    return tfd::io::tetrahedralize(tfd::core::makePrimitiveForTets(tfd::core::PrimitiveSpec{}, 1e6),
                                   options);
  }();
  return sphere;
}

void BM_TetMeshTopology(benchmark::State& state) {
  const auto& sphere = sphere1M();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  std::size_t faces = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto positions = sphere->positions();
    auto tets = sphere->tets();
    state.ResumeTiming();
    const tfd::core::TetMesh mesh(std::move(positions), std::move(tets));
    faces = mesh.faces().size();
    benchmark::DoNotOptimize(&mesh);
  }
  state.counters["tets"] = double(sphere->tetCount());
  state.counters["faces"] = double(faces);
}

/// The restoring constructor (stored topology ids, as the on-disk cook cache keeps them;
/// core/tet_mesh_restore.cpp) on the same mesh, 1 and 2 threads; the copies are not timed.
void BM_TetMeshRestore(benchmark::State& state) {
  const auto& sphere = sphere1M();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    auto positions = sphere->positions();
    auto tets = sphere->tets();
    tfd::core::TetMesh::StoredTopology stored{sphere->tetEdges(), sphere->tetFaces(),
                                              sphere->faceTets()};
    state.ResumeTiming();
    const tfd::core::TetMesh mesh(std::move(positions), std::move(tets), std::move(stored));
    benchmark::DoNotOptimize(&mesh);
  }
  state.counters["tets"] = double(sphere->tetCount());
}

BENCHMARK(BM_TetMeshRestore)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_TetMeshTopology)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_TetgenSphere)
    ->Arg(150'000)
    ->Arg(500'000)
    ->Arg(1'000'000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
