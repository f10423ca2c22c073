// Hyperstreamlines and streamtubes on a TetGen ball of about 1M tets (paper §8, Figure 20):
// evenly spaced major-eigenvector lines at separation 0.05 (test distance 0.025, automatic
// step) in a designed field (core::propagate of three degenerate design elements, as
// extract_bench's "design" field), then circle tubes (8 sides) around them. Meshing and
// propagation happen once outside the timed loops; the locator is built before timing.
// Placement is sequential (Jobard-Lefer), so its time does not depend on the thread count;
// tubes are swept in parallel. Counters: lines, points, total length, RK4 steps per second.
//
//   build/bench/trace_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <memory>

#include "core/design/propagate.h"
#include "core/point_locator.h"
#include "core/trace/hyperstreamlines.h"
#include "core/trace/streamtubes.h"
#include "io/tetgen/tetgen_mesher.h"

namespace {

using namespace tfd;

const core::TensorField& designedBall() {
  static const std::unique_ptr<core::TensorField> field = [] {
    using core::DegeneratePattern;
    using core::DegenerateType;
    const auto mesh = io::meshPrimitive(core::PrimitiveShape::Sphere, 1'000'000);
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
    auto f = std::make_unique<core::TensorField>(core::propagate(mesh, cs).field);
    (void)f->mesh().locator();
    return f;
  }();
  return *field;
}

core::HyperstreamlineOptions options() {
  core::HyperstreamlineOptions o;
  o.family = core::EigenFamily::Major;
  o.separation = 0.05;
  return o;
}

void BM_Hyperstreamlines(benchmark::State& state) {
  const core::TensorField& field = designedBall();
  const core::HyperstreamlineOptions o = options();
  core::Polylines lines;
  for (auto _ : state) lines = core::traceHyperstreamlines(field, o);
  state.counters["tets"] = double(field.mesh().tetCount());
  state.counters["lines"] = double(lines.lines.size());
  state.counters["points"] = double(lines.pointCount());
  state.counters["length"] = lines.totalLength();
  state.counters["step"] = core::hyperstreamlineStep(field, o);
  state.counters["points/s"] =
      benchmark::Counter(double(lines.pointCount()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Streamtubes(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  static const core::Polylines lines = core::traceHyperstreamlines(designedBall(), options());
  core::TubeOptions o;
  o.radius = 0.01;
  o.sides = 8;
  std::size_t triangles = 0;
  for (auto _ : state) triangles = core::sweepTubes(lines, o).triangles.size();
  state.counters["triangles"] = double(triangles);
}

BENCHMARK(BM_Hyperstreamlines)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Streamtubes)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
