// Curve constraints and LocalSmooth on a 1M-tet TetGen sphere (bench/RESULTS.md).
//
//   BM_ApplyTenCurves:  build ten CurveConstraint elements (spline, frames, linearisations) and
//                       apply them (tubes covering ~5 % of the vertices) into one accumulator.
//   BM_LocalSmooth10pc: LocalSmooth of a propagated field over a sphere holding 10 % of the
//                       vertices (region set-up, stiffness rows, AMG, solve, new field).
// The mesh, its point locator (built once per mesh and kept with it) and the propagated field
// are made once, outside the timings. TFD_BENCH_TETS overrides the tet count (default 1e6).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "core/design/curve_constraint.h"
#include "core/design/curve_element_builder.h"
#include "core/design/fixed_values.h"
#include "core/design/propagate.h"
#include "core/edit/local_smooth.h"
#include "core/point_locator.h"
#include "io/tetgen/tetgen_mesher.h"

namespace {

using namespace tfd;
using core::Vec3;

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

std::vector<core::CurveOptions> tenCurves() {
  constexpr double kPi = std::numbers::pi;
  std::vector<core::CurveOptions> curves;
  const double radius = 0.072, spacing = 0.02;
  // Five open degenerate curves, chords from near the surface to near the surface.
  const Vec3 ends[5][3] = {{{-0.85, 0.1, 0.2}, {0, 0.25, 0.1}, {0.8, 0.2, 0.3}},
                           {{0.1, -0.85, -0.2}, {0.2, 0, -0.3}, {0.1, 0.8, -0.35}},
                           {{-0.2, -0.3, -0.85}, {-0.3, -0.2, 0}, {-0.25, -0.35, 0.85}},
                           {{-0.6, -0.6, 0.1}, {0, -0.4, 0.45}, {0.55, -0.5, 0.2}},
                           {{-0.5, 0.6, -0.3}, {0.1, 0.55, 0.1}, {0.55, 0.5, -0.4}}};
  for (int c = 0; c < 5; ++c) {
    core::CurveOptions o;
    o.points = {ends[c][0], ends[c][1], ends[c][2]};
    o.spacing = spacing;
    o.radius = radius;
    o.type = c % 2 ? core::DegenerateType::Planar : core::DegenerateType::Linear;
    o.pattern = c % 3 ? core::DegeneratePattern::Wedge : core::DegeneratePattern::Trisector;
    curves.push_back(o);
  }
  // Three closed degenerate loops and two non-degenerate curves.
  const Vec3 centres[5] = {{0.45, 0.1, -0.3},
                           {-0.4, 0.2, 0.45},
                           {0.2, -0.4, 0.5},
                           {-0.5, -0.1, -0.45},
                           {0.45, 0.35, 0.45}};
  for (int c = 0; c < 5; ++c) {
    core::CurveOptions o;
    for (int i = 0; i < 8; ++i) {
      const double s = 2 * kPi * i / 8;
      o.points.push_back(centres[c] + 0.25 * Vec3(std::cos(s), std::sin(s), 0.3 * std::sin(2 * s)));
    }
    o.closed = c < 3;
    if (!o.closed) o.points.resize(5);
    o.spacing = spacing;
    o.radius = radius;
    o.kind = c < 3 ? core::CurveKind::Degenerate : core::CurveKind::Tensor;
    o.type = c == 1 ? core::DegenerateType::Planar : core::DegenerateType::Linear;
    o.rotation = Vec3(0, 0, 30.0 * c);
    curves.push_back(o);
  }
  return curves;
}

struct Scene {
  std::shared_ptr<const core::TetMesh> mesh;
  std::vector<core::CurveOptions> curves = tenCurves();
  std::unique_ptr<core::TensorField> field;
  double smoothRadius = 0;
  Vec3 smoothCentre = Vec3(0.1, 0.05, 0);
};

Scene& scene() {
  static Scene s = [] {
    Scene s;
    const char* env = std::getenv("TFD_BENCH_TETS");
    const double tets = env ? std::atof(env) : 1e6;
    auto t0 = std::chrono::steady_clock::now();
    s.mesh = io::meshPrimitive(core::PrimitiveShape::Sphere, tets);
    std::fprintf(stderr, "mesh: %zu tets, %zu vertices, mean edge %.4f (%.1f s)\n",
                 s.mesh->tetCount(), s.mesh->vertexCount(), s.mesh->meanEdgeLength(), seconds(t0));
    t0 = std::chrono::steady_clock::now();
    s.mesh->locator();
    std::fprintf(stderr, "point locator: %.3f s (once per mesh)\n", seconds(t0));
    core::ConstraintSet constraints;
    for (const auto& o : s.curves) constraints.curves.push_back(core::buildCurveElement(o));
    t0 = std::chrono::steady_clock::now();
    auto propagated = core::propagate(s.mesh, constraints);
    std::fprintf(stderr, "propagate: %.1f s\n", seconds(t0));
    s.field = std::make_unique<core::TensorField>(propagated.field);
    // Radius of the sphere around the centre holding 10 % of the vertices.
    std::vector<double> d;
    for (const Vec3& p : s.mesh->positions()) d.push_back((p - s.smoothCentre).norm());
    std::nth_element(d.begin(), d.begin() + d.size() / 10, d.end());
    s.smoothRadius = d[d.size() / 10];
    return s;
  }();
  return s;
}

void BM_ApplyTenCurves(benchmark::State& state) {
  Scene& s = scene();
  std::size_t fixed = 0;
  for (auto _ : state) {
    core::FixedValueAccumulator accumulator(s.mesh->vertexCount());
    for (const auto& o : s.curves) {
      core::applyCurveElement(*s.mesh, core::buildCurveElement(o), accumulator);
    }
    const core::FixedValues values = accumulator.finish();
    fixed = values.vertices.size();
    benchmark::DoNotOptimize(values.values.data());
  }
  state.counters["tube_vertex_fraction"] = double(fixed) / s.mesh->vertexCount();
  state.counters["tube_vertices"] = double(fixed);
}
BENCHMARK(BM_ApplyTenCurves)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

void BM_LocalSmooth10pc(benchmark::State& state) {
  Scene& s = scene();
  core::LocalSmoothOptions o;
  o.region = core::SmoothRegionShape::Sphere;
  o.center = s.smoothCentre;
  o.radius = s.smoothRadius;
  core::LocalSmoothReport report;
  for (auto _ : state) {
    const core::LocalSmoothResult r = core::localSmooth(*s.field, o);
    report = r.report;
    benchmark::DoNotOptimize(r.field.values().data());
  }
  state.counters["region_fraction"] = double(report.regionVertices) / s.mesh->vertexCount();
  state.counters["free_vertices"] = double(report.freeVertices);
  state.counters["iterations"] = report.iterations;
}
BENCHMARK(BM_LocalSmooth10pc)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
