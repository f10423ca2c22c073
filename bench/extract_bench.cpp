// Degenerate-curve extraction time on TetGen spheres of ~150K, 500K and 1M tets (paper §7:
// extraction reruns after every edit, so it has to be interactive).
//
// Fields:
//   design  — core::propagate of three degenerate design elements (an L wedge, a P trisector,
//             an L trisector; boundary-conforming, Eq. 1 and 4), the paper's use case;
//   waves   — a smooth analytic field (constant + four tensor-valued plane waves), with more
//             curves and loops.
// Arguments: {target tets, field (0 design, 1 waves), TBB threads}. Meshing and propagation are
// done once per mesh/field outside the timed loop. Counters report the work done.
//
//   build-*/bench/extract_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <map>
#include <memory>

#include "core/design/propagate.h"
#include "core/topology/extract_degenerate_curves.h"
#include "io/tetgen/tetgen_mesher.h"

namespace {

using namespace tfd;

std::shared_ptr<const core::TetMesh> sphere(int tets) {
  static std::map<int, std::shared_ptr<const core::TetMesh>> cache;
  auto& mesh = cache[tets];
  if (!mesh) mesh = io::meshPrimitive(core::PrimitiveShape::Sphere, tets);
  return mesh;
}

core::TensorField designField(const std::shared_ptr<const core::TetMesh>& mesh) {
  using core::DegeneratePattern;
  using core::DegenerateType;
  core::ConstraintSet cs;
  cs.points.push_back(
      {core::makeDegenerateLinearization(core::Vec3(0.3, 0, 0), core::Mat3::Identity(),
                                         DegenerateType::Linear, DegeneratePattern::Wedge),
       true, 0.12});
  cs.points.push_back(
      {core::makeDegenerateLinearization(core::Vec3(-0.35, 0.2, 0.1),
                                         core::rotationFromEulerDegrees(core::Vec3(40, 10, 70)),
                                         DegenerateType::Planar, DegeneratePattern::Trisector),
       true, 0.12});
  cs.points.push_back(
      {core::makeDegenerateLinearization(core::Vec3(0, -0.4, -0.3),
                                         core::rotationFromEulerDegrees(core::Vec3(90, 0, 0)),
                                         DegenerateType::Linear, DegeneratePattern::Trisector),
       true, 0.12});
  return core::propagate(mesh, cs).field;
}

core::TensorField wavesField(const std::shared_ptr<const core::TetMesh>& mesh) {
  const core::Tensor constant = core::Tensor::fromVec5({0.1, -0.05, 0.08, 0.02, -0.1});
  const core::Tensor amplitude[4] = {core::Tensor::fromVec5({0.9, -0.3, 0.4, 0.2, -0.5}),
                                     core::Tensor::fromVec5({-0.2, 0.7, -0.6, 0.3, 0.1}),
                                     core::Tensor::fromVec5({0.5, 0.5, 0.1, -0.8, 0.2}),
                                     core::Tensor::fromVec5({-0.4, 0.1, 0.6, 0.3, 0.9})};
  const core::Vec3 frequency[4] = {
      {4.2, -2.6, 1.4}, {-1.2, 4.8, 3.8}, {3.0, 2.2, -5.2}, {-4.4, -0.8, 2.4}};
  std::vector<core::Tensor> values(mesh->vertexCount());
  for (std::size_t v = 0; v < values.size(); ++v) {
    const core::Vec3& p = mesh->positions()[v];
    core::Tensor t = constant;
    for (int k = 0; k < 4; ++k) t += amplitude[k] * std::sin(frequency[k].dot(p) + k);
    values[v] = t;
  }
  return core::TensorField(mesh, std::move(values));
}

const core::TensorField& field(int tets, int kind) {
  static std::map<std::pair<int, int>, std::unique_ptr<core::TensorField>> cache;
  auto& f = cache[{tets, kind}];
  if (!f) {
    f = std::make_unique<core::TensorField>(kind == 0 ? designField(sphere(tets))
                                                      : wavesField(sphere(tets)));
  }
  return *f;
}

void BM_Extract(benchmark::State& state) {
  const int tets = int(state.range(0)), kind = int(state.range(1)), threads = int(state.range(2));
  const core::TensorField& f = field(tets, kind);
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  core::DegenerateCurves curves;
  for (auto _ : state) {
    curves = core::extractDegenerateCurves(f);
    benchmark::DoNotOptimize(curves);
  }
  const auto& d = curves.diagnostics();
  state.counters["tets"] = double(f.mesh().tetCount());
  state.counters["curves"] = double(curves.size());
  state.counters["loops"] = curves.statistics().closed;
  state.counters["points"] = curves.statistics().points;
  state.counters["solved"] = double(d.facesSolved);
  state.counters["gapCulled%"] = 100.0 * double(d.facesCulledByGap) / double(d.faces);
  state.counters["rounds"] = d.rounds;
  state.counters["warnings"] = double(curves.warnings().size());
  state.SetLabel(kind == 0 ? "design" : "waves");
}

BENCHMARK(BM_Extract)
    ->ArgsProduct({{150'000, 500'000, 1'000'000}, {0, 1}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
