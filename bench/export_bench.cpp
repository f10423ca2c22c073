// Export timings on a ~1M-tet box mesh (55³ cubes × 6 = 998,250 tets): OpenVDB at a voxel
// size giving 128³ voxels, the voxel sampling alone, EXR slices and VTU. The argument is the
// thread count. Results and the command line: bench/RESULTS.md.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/point_locator.h"
#include "core/structured_mesh.h"
#include "io/volume/exr_writer.h"
#include "io/volume/field_resample.h"
#include "io/volume/vdb_writer.h"
#include "io/vtk/vtu_writer.h"

namespace {

using namespace tfd;

const core::TensorField& benchField() {
  static const core::TensorField field = [] {
    auto mesh = core::makeBoxMesh(55, 55, 55, core::Vec3(0, 0, 0), core::Vec3(1, 1, 1));
    std::vector<core::Tensor> values;
    values.reserve(mesh->vertexCount());
    for (const auto& p : mesh->positions()) {
      values.push_back(core::Tensor{std::sin(3 * p.x()), p.y() - 0.5, -std::sin(3 * p.x()),
                                    p.x() * p.z(), std::cos(2 * p.y()), 0.3 * p.z()});
    }
    core::TensorField f(std::move(mesh), std::move(values));
    f.mesh().locator();  // built once, outside the timings
    return f;
  }();
  return field;
}

constexpr double kVoxelSize = 1.0 / 127;  // centres 0 … 1: 128³ = 2,097,152 voxels

std::filesystem::path outDir() {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tfd-export-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

void BM_VdbExport(benchmark::State& state, bool everything) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, state.range(0));
  const auto& field = benchField();
  io::VdbExportOptions options;
  options.voxelSize = kVoxelSize;
  if (everything) {
    options.quantities = io::VoxelQuantities{true, true, true, {}};
  }
  const auto path = outDir() / "bench.vdb";
  std::size_t active = 0;
  for (auto _ : state) active = io::writeFieldVdb(path, field, options).activeVoxels;
  state.counters["voxels"] = double(active);
  state.counters["MB"] = double(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove_all(path.parent_path());
}
BENCHMARK_CAPTURE(BM_VdbExport, tensor, false)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_VdbExport, tensor_eigen, true)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Locating and interpolating at every voxel centre, the lower bound of any VDB fill strategy.
void BM_SampleVoxels(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, state.range(0));
  const auto& field = benchField();
  const auto lattice = io::latticeForMesh(field.mesh(), kVoxelSize);
  for (auto _ : state) {
    auto samples = io::sampleVoxels(field, lattice, lattice.min, lattice.max);
    benchmark::DoNotOptimize(samples.data());
  }
}
BENCHMARK(BM_SampleVoxels)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ExrSlices(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, state.range(0));
  const auto& field = benchField();
  io::ExrExportOptions options;
  options.voxelSize = kVoxelSize;
  const auto dir = outDir();
  for (auto _ : state) io::writeFieldExrSlices((dir / "s.%04d.exr").string(), field, options);
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_ExrSlices)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_VtuExport(benchmark::State& state) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, state.range(0));
  const auto& field = benchField();
  const auto path = outDir() / "bench.vtu";
  for (auto _ : state) io::writeFieldVtu(path, field);
  state.counters["MB"] = double(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove_all(path.parent_path());
}
BENCHMARK(BM_VtuExport)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
