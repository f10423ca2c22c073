// Element synthesis (core/synth/element_synthesis.h) of about 10,000 sticks and leaves in a
// TetGen ball of about 200K tets with the affine two-region field of the tests (linear for
// x > 0.1, planar below): placement (sequential Bridson sampling with exact box collision
// tests), then instancing the built-in meshes into one mesh on 1 and 2 threads.
//
//   build/bench/elements_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "core/design/field_expression.h"
#include "core/synth/element_synthesis.h"
#include "io/tetgen/tetgen_mesher.h"

namespace {

using namespace tfd;

const core::TensorField& ballField() {
  static const core::TensorField field = [] {
    auto mesh = io::meshPrimitive(core::PrimitiveShape::Sphere, 200'000);
    core::TensorExpressions e;
    e.components = {"2*x", "-x+0.3", "-x-0.3", "0.4*y+0.1", "0.3*z", "0.2+0.2*x"};
    return core::evaluateFieldExpression(mesh, e);
  }();
  return field;
}

// Size chosen so the ball fills with about 10,000 elements (no element limit reached).
core::ElementSynthesisOptions options() {
  core::ElementSynthesisOptions o;
  o.size = 0.064;
  o.maxElements = 1'000'000;
  return o;
}

void BM_PlaceElements(benchmark::State& state) {
  const core::TensorField& field = ballField();
  const core::ElementShapes shapes;
  core::ElementPlacement placed;
  for (auto _ : state) placed = core::placeElements(field, shapes, options());
  state.counters["elements"] = double(placed.points.points.size());
  state.counters["sticks"] = double(placed.report.lines);
  state.counters["leaves"] = double(placed.report.boxes);
  state.counters["collisions"] = double(placed.report.overlapRejected);
  state.counters["elements/s"] = benchmark::Counter(double(placed.points.points.size()),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}

void BM_InstanceElements(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(state.range(0)));
  const core::ElementShapes shapes;
  const core::ElementPlacement placed = core::placeElements(ballField(), shapes, options());
  std::size_t triangles = 0;
  for (auto _ : state) {
    const core::SurfaceMesh mesh = core::instanceElements(placed.points, shapes);
    triangles = mesh.triangles.size();
  }
  state.counters["triangles"] = double(triangles);
}

BENCHMARK(BM_PlaceElements)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_InstanceElements)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
