// Degenerate curve removal (core/edit/remove_curves.h), verification included.
//  - RemoveLoop1M: a mixed loop removed from a field on a 998,250-tet Kuhn box, for several
//    region distances (time against region size; peak memory).
//  - RandomRemovals: removals on fields from random point constraints and from the boundary
//    curvature on several solids; each target picked automatically among the curves whose
//    scenario applies. Counts successes, refusals (no ball region avoids the other curves)
//    and failures (verification failed after the retries).
//  - DeformCurve1M: the straight curve x = y = 0 of a field on the same 1M-tet box bent onto a
//    smooth bump of height 0.3 (paper §6.1), verification included, for several region
//    distances.
//  - ReconnectLines1M: a pure wedge line and a pure trisector line of a field on the same
//    1M-tet box reconnected into two mixed curves (paper §6.2, Fig. 11a), verification
//    included, for several region distances.
//  - RandomReconnections: reconnections on the six designed scenarios of Fig. 11
//    (tests/core/edit/reconnect_test_fields.h) with random picks on the middle half of the two
//    curves, random
//    segment lengths and region distances; counts verified, refused (no region / segments that
//    do not leave it) and failed (no try verified), with the failed checks.
// Commands and figures: bench/RESULTS.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>

#include "core/design/propagate.h"
#include "core/edit/deform_curve.h"
#include "core/edit/reconnect_curves.h"
#include "core/edit/remove_curves.h"
#include "core/structured_mesh.h"
#include "core/surface/primitives.h"
#include "core/topology/extract_degenerate_curves.h"
#include "io/mesh/surface_readers.h"
#include "io/tetgen/tetgen_mesher.h"
#include "tests/core/design/curve_test_meshes.h"
#include "tests/core/edit/reconnect_test_fields.h"
#include "tests/core/edit/removal_test_fields.h"

namespace {

using namespace tfd::core;
namespace io = tfd::io;

double peakMegabytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024;
  return 0;
}

const TensorField& loopField1M() {
  static const TensorField field =
      testing::designedField(makeBoxMesh(55, 55, 55, Vec3(-1, -1, -1), Vec3(1, 1, 1)),
                             [](const Vec3& p) { return testing::loopW(p, 0.3); });
  return field;
}

void RemoveLoop1M(benchmark::State& state) {
  const TensorField& field = loopField1M();
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.3, 0, 0)};
  o.regionDistance = state.range(0) < 0 ? -1 : state.range(0) / 100.0;
  RemoveCurvesResult last{field, {}, {}, {}};
  bool verified = true;
  std::size_t failedRegion = 0;
  for (auto _ : state) {
    try {
      last = removeCurves(field, o);
    } catch (const RemovalFailed& e) {  // reported, not hidden: counted as verified = 0
      verified = false;
      const std::string m = e.what();
      const auto at = m.find("last region ");
      if (at != std::string::npos) failedRegion = std::stoul(m.substr(at + 12));
    }
  }
  state.counters["verified"] = verified;
  if (!verified) state.counters["failed_region_tets"] = double(failedRegion);
  state.counters["tets"] = double(field.mesh().tetCount());
  state.counters["region_tets"] = double(last.report.regionTets);
  state.counters["free_vertices"] = double(last.report.freeVertices);
  state.counters["tries"] = double(last.report.tries.size());
  state.counters["curves_after"] = double(last.curves.size());
  state.counters["peak_MB"] = peakMegabytes();
}
BENCHMARK(RemoveLoop1M)
    ->Arg(5)
    ->Arg(10)
    ->Arg(20)
    ->Arg(-1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(2)
    ->ReportAggregatesOnly(false);

/// The same loop on a TetGen ball of radius 1 and ~1M tets (the mesh of
/// examples/remove_loop.tfd.json at ball.target_tets=1000000): an unstructured mesh packs about
/// twice the box's tets into the same distance.
const TensorField& loopFieldBall1M() {
  static const TensorField field =
      testing::designedField(io::meshPrimitive(PrimitiveShape::Sphere, 1'000'000),
                             [](const Vec3& p) { return testing::loopW(p, 0.3); });
  return field;
}

void RemoveLoopBall1M(benchmark::State& state) {
  const TensorField& field = loopFieldBall1M();
  RemoveCurvesOptions o;
  o.picks = {Vec3(0.3, 0, 0)};
  o.regionDistance = state.range(0) < 0 ? -1 : state.range(0) / 100.0;
  RemoveCurvesResult last{field, {}, {}, {}};
  bool verified = true;
  for (auto _ : state) {
    try {
      last = removeCurves(field, o);
    } catch (const RemovalFailed& e) {  // reported, not hidden: counted as verified = 0
      verified = false;
      state.SetLabel(e.what());
    }
  }
  state.counters["verified"] = verified;
  state.counters["tets"] = double(field.mesh().tetCount());
  state.counters["region_tets"] = double(last.report.regionTets);
  state.counters["free_vertices"] = double(last.report.freeVertices);
  state.counters["tries"] = double(last.report.tries.size());
  state.counters["curves_after"] = double(last.curves.size());
  state.counters["peak_MB"] = peakMegabytes();
}
BENCHMARK(RemoveLoopBall1M)
    ->Arg(5)
    ->Arg(10)
    ->Arg(20)
    ->Arg(30)
    ->Arg(-1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(2)
    ->ReportAggregatesOnly(false);

void DeformCurve1M(benchmark::State& state) {
  static const TensorField field =
      testing::designedField(makeBoxMesh(55, 55, 55, Vec3(-1, -1, -1), Vec3(1, 1, 1)),
                             [](const Vec3& p) { return testing::Complex(p.x(), p.y()); });
  DeformCurveOptions o;
  o.pick = Vec3(0, 0, 0.05);
  const Vec3 d = Vec3(1, 0.4, 0).normalized();
  for (int i = 0; i <= 12; ++i) {  // the bump of tests/core/edit/deform_curve_test.cpp
    const double z = -0.45 + 0.9 * i / 12, c = std::cos(3.14159265358979 * z / 0.9);
    o.target.push_back(0.3 * c * c * d + Vec3(0, 0, z));
  }
  o.regionDistance = state.range(0) < 0 ? -1 : state.range(0) / 100.0;
  DeformCurveResult last{field, {}, {}, {}};
  bool verified = true;
  for (auto _ : state) {
    try {
      last = deformCurve(field, o);
    } catch (const DeformationFailed& e) {  // reported, not hidden
      verified = false;
      state.SetLabel(e.what());
    }
  }
  state.counters["verified"] = verified;
  state.counters["tets"] = double(field.mesh().tetCount());
  state.counters["region_tets"] = double(last.report.regionTets);
  state.counters["solved_vertices"] = double(last.report.solvedVertices);
  state.counters["fold_overs"] = double(last.report.foldOvers);
  state.counters["hausdorff"] = last.report.hausdorff;
  state.counters["bound"] = last.report.tolerance;
  state.counters["tries"] = double(last.report.tries.size());
  state.counters["peak_MB"] = peakMegabytes();
}
BENCHMARK(DeformCurve1M)
    ->Arg(10)
    ->Arg(20)
    ->Arg(-1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(2)
    ->ReportAggregatesOnly(false);

/// A field from random point constraints (degenerate and not) on the mesh.
TensorField randomDesign(std::shared_ptr<const TetMesh> mesh, std::mt19937& rng, bool curvature) {
  std::uniform_real_distribution<double> u(-0.5, 0.5), angle(0, 360);
  ConstraintSet set;
  const int n = curvature ? 1 : 3 + int(rng() % 3);
  for (int i = 0; i < n; ++i) {
    PointElement e;
    const Mat3 frame = rotationFromEulerDegrees(Vec3(angle(rng), angle(rng), angle(rng)));
    const Vec3 at(u(rng), u(rng), u(rng));
    if (rng() % 2) {
      e.field = makeDegenerateLinearization(
          at, frame, rng() % 2 ? DegenerateType::Linear : DegenerateType::Planar,
          rng() % 2 ? DegeneratePattern::Wedge : DegeneratePattern::Trisector);
      e.degenerate = true;
    } else {
      e.field = makeTensorLinearization(at, frame, Vec3(1, 0.2 * u(rng), -1));
    }
    set.points.push_back(e);
  }
  PropagateOptions po;
  po.curvatureBoundary = curvature;
  po.boundaryConforming = !curvature;
  return propagate(std::move(mesh), set, po).field;
}

/// The solids of RandomRemovals: three made here and two tetrahedralised by TetGen, one of
/// them from a surface file (examples/pebble.obj) and one of genus 2.
std::vector<std::pair<std::string, std::shared_ptr<const TetMesh>>> randomSolids() {
  io::TetgenOptions to;
  to.targetTets = 25'000;
  to.source = "examples/pebble.obj";
  const auto pebble =
      io::tetrahedralize(io::readObj(std::string(TFD_SOURCE_DIR) + "/examples/pebble.obj"), to);
  PrimitiveSpec twoHoles;
  twoHoles.shape = PrimitiveShape::DoubleTorus;
  return {{"box", testing::jitteredBox(14, 0.15)},
          {"ball", testing::carvedBall(18)},
          {"torus", testing::keepTets(*testing::jitteredBox(20, 0.15),
                                      [](const Vec3& c) {
                                        return std::hypot(std::hypot(c.x(), c.y()) - 0.6, c.z()) <
                                               0.33;
                                      })},
          {"pebble.obj", pebble},
          {"double torus", io::meshPrimitive(twoHoles, 25'000)}};
}

/// Targets whose scenario applies: each curve alone (one-curve, one-loop) and each pair of an
/// open pure wedge and an open pure trisector curve of the same type (two-curve). Each target
/// is picked at the middle point of its curves.
std::vector<std::vector<const DegenerateCurve*>> removableTargets(const DegenerateCurves& curves) {
  std::vector<std::vector<const DegenerateCurve*>> out;
  const auto& all = curves.curves();
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = i; j < all.size(); ++j) {
      std::vector<const DegenerateCurve*> t{&all[i]};
      if (j != i) t.push_back(&all[j]);
      try {
        removalScenario(t);
        out.push_back(std::move(t));
      } catch (const RemovalRefused&) {
      }
    }
  }
  return out;
}

struct Tally {
  int attempts = 0, successes = 0, refusals = 0, failures = 0;
  void add(const Tally& o) {
    attempts += o.attempts, successes += o.successes;
    refusals += o.refusals, failures += o.failures;
  }
};

void ReconnectLines1M(benchmark::State& state) {
  static const TensorField field =
      testing::designedField(makeBoxMesh(55, 55, 55, Vec3(-1, -1, -1), Vec3(1, 1, 1)),
                             [](const Vec3& p) { return testing::twoLinesW(p, 0.3); });
  ReconnectCurvesOptions o;
  o.picks = {Vec3(0.3, 0, 0), Vec3(-0.3, 0, 0)};
  o.regionDistance = state.range(0) < 0 ? -1 : state.range(0) / 100.0;
  ReconnectCurvesResult last{field, {}, {}, {}};
  bool verified = true;
  for (auto _ : state) {
    try {
      last = reconnectCurves(field, o);
    } catch (const ReconnectionFailed& e) {  // reported, not hidden
      verified = false;
      state.SetLabel(e.what());
    }
  }
  state.counters["verified"] = verified;
  state.counters["tets"] = double(field.mesh().tetCount());
  state.counters["region_tets"] = double(last.report.regionTets);
  state.counters["sheet_tets"] = double(last.report.sheetTets);
  state.counters["solved"] = double(last.report.sheetSolved + last.report.sidesSolved);
  state.counters["tries"] = double(last.report.tries.size());
  state.counters["curves_after"] = double(last.curves.size());
  state.counters["peak_MB"] = peakMegabytes();
}
BENCHMARK(ReconnectLines1M)
    ->Arg(10)
    ->Arg(20)
    ->Arg(-1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(2)
    ->ReportAggregatesOnly(false);

void RandomReconnections(benchmark::State& state) {
  const auto mesh = testing::jitteredBox(18, 0.15);
  const auto& scenarios = testing::scenarios();
  std::vector<TensorField> fields;
  std::vector<DegenerateCurves> curves;
  for (const auto& s : scenarios) {
    fields.push_back(
        testing::designedField(mesh, s.W, [](const Vec3&) { return testing::upFrame(); }));
    curves.push_back(extractDegenerateCurves(fields.back()));
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  int verified = 0, refused = 0, failed = 0, retried = 0;
  std::map<std::string, int> reasons;
  for (auto _ : state) {
    for (int i = 0; i < state.range(0); ++i) {
      const std::size_t k = std::size_t(i) % scenarios.size();
      ReconnectCurvesOptions o;
      for (const Vec3& p : scenarios[k].picks) {
        const DegenerateCurve& c = curves[k].curve(curves[k].pick(p)->curveId);
        // Anywhere on the middle half of the curve (a user picks away from its ends).
        const double at = 0.25 + 0.5 * unit(rng);
        o.picks.push_back(c.points[std::size_t(at * double(c.points.size() - 1))]);
      }
      o.segmentLength = 0.3 + 0.5 * unit(rng);
      o.regionDistance = 0.15 + 0.25 * unit(rng);
      o.curves = &curves[k];
      try {
        const ReconnectCurvesResult r = reconnectCurves(fields[k], o);
        ++verified;
        retried += r.report.tries.size() > 1;
      } catch (const ReconnectionFailed& e) {
        ++failed;
        const std::string m = e.what();
        const auto a = m.find("check '"), b = m.find('\'', a + 7);
        ++reasons["failed: " + m.substr(a + 7, b - a - 7)];
      } catch (const Error& e) {
        ++refused;
        ++reasons["refused: " + std::string(e.what()).substr(0, 60)];
      }
    }
  }
  for (const auto& [reason, count] : reasons) std::printf("  %4d  %s\n", count, reason.c_str());
  state.counters["attempts"] = double(state.range(0));
  state.counters["verified"] = verified;
  state.counters["verified_after_retry"] = retried;
  state.counters["refused"] = refused;
  state.counters["failed"] = failed;
  state.counters["success_of_possible"] =
      verified + failed > 0 ? double(verified) / double(verified + failed) : 0.0;
}
BENCHMARK(RandomReconnections)->Arg(120)->Iterations(1)->Unit(benchmark::kSecond);

void RandomRemovals(benchmark::State& state) {
  const auto solids = randomSolids();
  Tally total;
  std::map<std::string, Tally> bySolid, byScenario, bySource;
  std::map<std::string, int> failedChecks;
  int fields = 0;
  for (auto _ : state) {
    std::mt19937 rng(11);
    // Until `wanted` attempts found a region (success or failure), within bounds.
    const int wanted = int(state.range(0));
    while (total.successes + total.failures < wanted && total.attempts < 10 * wanted &&
           fields < 40 * wanted) {
      const auto& [name, mesh] = solids[fields % solids.size()];
      const bool curvature = fields % 4 == 3;
      ++fields;
      TensorField field = [&] {
        try {
          return randomDesign(mesh, rng, curvature);
        } catch (const Error&) {
          return TensorField(mesh, std::vector<Tensor>(mesh->vertexCount()));
        }
      }();
      const DegenerateCurves curves = extractDegenerateCurves(field);
      auto targets = removableTargets(curves);
      std::shuffle(targets.begin(), targets.end(), rng);
      if (targets.size() > 3) targets.resize(3);
      for (const auto& target : targets) {
        if (total.successes + total.failures >= wanted) break;
        Tally one;
        one.attempts = 1;
        RemoveCurvesOptions o;
        for (const DegenerateCurve* c : target) o.picks.push_back(c->points[c->points.size() / 2]);
        const std::string scenario = toString(removalScenario(target));
        try {
          removeCurves(field, o);
          one.successes = 1;
        } catch (const RemovalRefused&) {
          one.refusals = 1;
        } catch (const RemovalFailed& e) {
          one.failures = 1;
          const std::string m = e.what();
          const auto a = m.find("check '"), b = m.find("'", a + 7);
          ++failedChecks[m.substr(a + 7, b - a - 7)];
          std::fprintf(stderr, "FAILED (field %d, %s, %s, %s): %s\n", fields, name.c_str(),
                       curvature ? "curvature" : "random constraints", scenario.c_str(), e.what());
        }
        total.add(one), bySolid[name].add(one), byScenario[scenario].add(one);
        bySource[curvature ? "curvature" : "random constraints"].add(one);
      }
    }
  }
  std::fprintf(stderr, "%-20s %8s %9s %8s %8s\n", "", "attempts", "successes", "refusals",
               "failures");
  for (const auto* table : {&bySolid, &byScenario, &bySource})
    for (const auto& [key, t] : *table)
      std::fprintf(stderr, "%-20s %8d %9d %8d %8d\n", key.c_str(), t.attempts, t.successes,
                   t.refusals, t.failures);
  state.counters["fields"] = fields;
  state.counters["attempts"] = total.attempts;
  state.counters["successes"] = total.successes;
  state.counters["refusals"] = total.refusals;
  state.counters["failures"] = total.failures;
  state.counters["success_of_possible"] =
      total.successes + total.failures > 0
          ? double(total.successes) / (total.successes + total.failures)
          : 0;
  for (const auto& [check, n] : failedChecks) state.counters["failed:" + check] = n;
}
BENCHMARK(RandomRemovals)->Arg(100)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
