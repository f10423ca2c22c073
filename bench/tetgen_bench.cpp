// TetGen adapter benchmark: spheres of about 150K, 500K and 1M tets.
// Reports per size: tet count reached, surface build time, TetGen time, TetMesh topology
// build time (the constructor: validation, edges, faces, boundary, incidence, volumes), each
// as wall-clock and as process CPU time (std::clock, all threads: robust on a busy machine),
// and the peak resident memory of the run (VmHWM, reset before each size).
// BM_SurfacePreparation: what TetMesh does to a surface file before TetGen (weld, orient,
// check, find voids) on a sphere of ~1M triangles read as a soup (every corner repeated).
// Run: build-<dir>/bench/tetgen_bench --benchmark_counters_tabular=true
// Results and machine notes: bench/RESULTS.md.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <chrono>
#include <ctime>
#include <string>

#include "bench/process_measures.h"
#include "core/surface/primitives.h"
#include "core/surface/surface_cavities.h"
#include "core/surface/surface_check.h"
#include "core/surface/surface_orient.h"
#include "core/surface/surface_weld.h"
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

void BM_SurfacePreparation(benchmark::State& state) {
  using namespace tfd::core;
  const SurfaceMesh sphere = makeSphere(1.0, 0.0054);  // ~1M triangles
  SurfaceMesh soup;
  for (const auto& t : sphere.triangles) {
    const int first = int(soup.positions.size());
    for (int v : t) soup.positions.push_back(sphere.positions[v]);
    soup.triangles.push_back({first, first + 1, first + 2});
  }
  double weldS = 0, orientS = 0, checkS = 0;
  for (auto _ : state) {
    SurfaceMesh s = soup;
    auto t0 = Clock::now();
    weldCloseVertices(s, 1e-3 * medianEdgeLength(s));
    auto t1 = Clock::now();
    orientConsistently(s);
    auto t2 = Clock::now();
    benchmark::DoNotOptimize(closedSurfaceProblems(s));
    benchmark::DoNotOptimize(cavityPoints(s));
    auto t3 = Clock::now();
    weldS += std::chrono::duration<double>(t1 - t0).count();
    orientS += std::chrono::duration<double>(t2 - t1).count();
    checkS += std::chrono::duration<double>(t3 - t2).count();
    if (s.positions.size() != sphere.positions.size()) state.SkipWithError("weld missed corners");
  }
  const double n = double(state.iterations());
  state.counters["triangles"] = double(soup.triangles.size());
  state.counters["weld_ms"] = 1e3 * weldS / n;
  state.counters["orient_ms"] = 1e3 * orientS / n;
  state.counters["check_ms"] = 1e3 * checkS / n;
}

BENCHMARK(BM_SurfacePreparation)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();
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
