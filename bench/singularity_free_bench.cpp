// Singularity-free field of §6.3 (core/edit/singularity_free_field.h) on a Kuhn box mesh of
// about 1M tets (55³ cubes × 6), for ball regions of growing size: the cost should follow the
// region, not the mesh. The field turns its frame smoothly (its major eigenvector covers a
// large part of the sphere) so that the jumps are not trivial. Reports region tets, free
// vertices and CG iterations; vectorisation alone is timed separately.
//   build/bench/singularity_free_bench
// (commands and figures in bench/RESULTS.md).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <memory>

#include "core/edit/singularity_free_field.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/structured_mesh.h"

namespace {

using namespace tfd::core;

const TensorField& field() {
  static const TensorField f = [] {
    const auto mesh = makeBoxMesh(55, 55, 55, Vec3::Constant(-1), Vec3::Constant(1));
    std::vector<Tensor> values;
    values.reserve(mesh->vertexCount());
    for (const Vec3& p : mesh->positions()) {
      const Mat3 r = (Eigen::AngleAxisd(2.2 * p.x(), Vec3::UnitY()) *
                      Eigen::AngleAxisd(1.8 * p.y() + 0.5 * p.z(), Vec3::UnitX()))
                         .toRotationMatrix();
      values.push_back(Tensor::fromMatrix(r * Vec3(2.0, -0.6, -1.4).asDiagonal() * r.transpose()));
    }
    return TensorField(mesh, std::move(values));
  }();
  return f;
}

/// Tets whose centroid lies within `radius` of a point near the centre.
std::vector<int> ball(const TetMesh& mesh, double radius) {
  std::vector<int> out;
  for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
    Vec3 c = Vec3::Zero();
    for (int v : mesh.tets()[t]) c += mesh.positions()[v] / 4;
    if ((c - Vec3(0.03, -0.02, 0.01)).norm() < radius) out.push_back(static_cast<int>(t));
  }
  return out;
}

/// Argument: region radius in percent of the box's half-width.
void SingularityFree(benchmark::State& state) {
  const TensorField& f = field();
  const std::vector<int> region = ball(f.mesh(), state.range(0) / 100.0);
  const std::vector<char> held(f.mesh().vertexCount(), 0);
  SingularityFreeReport report;
  for (auto _ : state) {
    const TensorField out =
        singularityFreeField(f, region, held, DegenerateType::Linear, {}, &report);
    benchmark::DoNotOptimize(out.values().data());
  }
  state.counters["mesh_tets"] = static_cast<double>(f.mesh().tetCount());
  state.counters["region_tets"] = static_cast<double>(report.regionTets);
  state.counters["free_vertices"] = static_cast<double>(report.freeVertices);
  state.counters["cg_iterations"] = report.iterations;
  state.counters["non_ball_steps"] = report.nonBallSteps;
}
BENCHMARK(SingularityFree)->Arg(20)->Arg(40)->Arg(60)->Unit(benchmark::kMillisecond);

void Vectorise(benchmark::State& state) {
  const TensorField& f = field();
  const std::vector<int> region = ball(f.mesh(), state.range(0) / 100.0);
  for (auto _ : state) {
    const VectorisedEigenvector v = vectoriseEigenvector(f, region, DegenerateType::Linear);
    benchmark::DoNotOptimize(v.directions.data());
  }
  state.counters["region_tets"] = static_cast<double>(region.size());
}
BENCHMARK(Vectorise)->Arg(20)->Arg(40)->Arg(60)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
