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
//  - AllEdits: every edit (removals of the four kinds, reconnections, deformations onto random
//    smooth targets) on fields from random constraints and from the boundary curvature of the
//    solids of RandomRemovals (pebble.obj a surface mesh), and designed two-loop fields (round
//    the hole of two solid tori; concentric in the box and the ball); targets picked
//    automatically. Counts per kind attempts, verified, refused (no
//    valid region or segment) and failed (the check named); every verified result is checked
//    again here (outside unchanged bitwise, a fresh extraction's curve count, the paired ends
//    joined, the target followed), a mismatch counted as a silent failure.
//  - RemoveTwoLoopsBox1M: two-loop removal (a reconnection, then a one-loop removal) of a
//    wedge and a trisector circle, concentric in the 1M-tet box (paper Fig. 17d).
//  - RemoveTwoLoops1M: the same for two circles round the hole of a ~1M-tet TetGen solid torus
//    (a worst case: the merged loop bounds a band all round the torus).
// Commands and figures: bench/RESULTS.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bench/process_measures.h"
#include "core/design/propagate.h"
#include "core/edit/deform_curve.h"
#include "core/edit/reconnect_curves.h"
#include "core/edit/remove_curves.h"
#include "core/point_locator.h"
#include "core/structured_mesh.h"
#include "core/surface/primitives.h"
#include "core/topology/extract_degenerate_curves.h"
#include "io/mesh/surface_readers.h"
#include "io/tetgen/tetgen_mesher.h"
#include "tests/core/design/curve_test_meshes.h"
#include "tests/core/edit/reconnect_test_fields.h"
#include "tests/core/edit/removal_test_fields.h"
#include "tests/support/random_vec3.h"

namespace {

using namespace tfd::core;
using tfd::bench::CookCounters;
using tfd::bench::peakMegabytes;
namespace io = tfd::io;

/// FNV-1a over the bytes of the edited field, the region's tets and the curves' points: the
/// label of a verified 1M result, so that two builds can be checked to give bit-for-bit the
/// same result (bench/RESULTS.md, branch ballspeed).
std::string resultHash(const TensorField& field, const std::vector<int>& regionTets,
                       const DegenerateCurves& curves) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  mix(field.values().data(), field.values().size() * sizeof(Tensor));
  mix(regionTets.data(), regionTets.size() * sizeof(int));
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const DegenerateCurve& curve = curves.curve(int(c));
    mix(curve.points.data(), curve.points.size() * sizeof(Vec3));
  }
  char text[32];
  std::snprintf(text, sizeof text, "hash %016llx", static_cast<unsigned long long>(h));
  return text;
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
  CookCounters cooks;
  for (auto _ : state) {
    const CookCounters::Cook cook(cooks);
    try {
      last = removeCurves(field, o);
    } catch (const RemovalFailed& e) {  // reported, not hidden: counted as verified = 0
      verified = false;
      const std::string m = e.what();
      const auto at = m.find("last region ");
      if (at != std::string::npos) failedRegion = std::stoul(m.substr(at + 12));
    }
  }
  cooks.report(state);
  state.counters["verified"] = verified;
  if (verified) state.SetLabel(resultHash(last.field, last.regionTets, last.curves));
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
  CookCounters cooks;
  for (auto _ : state) {
    const CookCounters::Cook cook(cooks);
    try {
      last = removeCurves(field, o);
    } catch (const RemovalFailed& e) {  // reported, not hidden: counted as verified = 0
      verified = false;
      state.SetLabel(e.what());
    }
  }
  cooks.report(state);
  state.counters["verified"] = verified;
  if (verified) state.SetLabel(resultHash(last.field, last.regionTets, last.curves));
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
  CookCounters cooks;
  for (auto _ : state) {
    const CookCounters::Cook cook(cooks);
    try {
      last = deformCurve(field, o);
    } catch (const DeformationFailed& e) {  // reported, not hidden
      verified = false;
      state.SetLabel(e.what());
    }
  }
  cooks.report(state);
  state.counters["verified"] = verified;
  if (verified) state.SetLabel(resultHash(last.field, last.regionTets, last.curves));
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
    const Mat3 frame = rotationFromEulerDegrees(tfd::test::drawVec3(angle, rng));
    const Vec3 at = tfd::test::drawVec3(u, rng);
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
  CookCounters cooks;
  for (auto _ : state) {
    const CookCounters::Cook cook(cooks);
    try {
      last = reconnectCurves(field, o);
    } catch (const ReconnectionFailed& e) {  // reported, not hidden
      verified = false;
      state.SetLabel(e.what());
    }
  }
  cooks.report(state);
  state.counters["verified"] = verified;
  if (verified) state.SetLabel(resultHash(last.field, last.regionTets, last.curves));
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
        std::fprintf(stderr,
                     "FAILED #%d (%s; picks (%.4g %.4g %.4g) (%.4g %.4g %.4g), segment %.4g, "
                     "distance %.4g): %s\n",
                     i, scenarios[k].name, o.picks[0].x(), o.picks[0].y(), o.picks[0].z(),
                     o.picks[1].x(), o.picks[1].y(), o.picks[1].z(), o.segmentLength,
                     o.regionDistance, m.c_str());
      } catch (const Error& e) {
        ++refused;
        ++reasons["refused: " + std::string(e.what()).substr(0, 60)];
        std::fprintf(stderr,
                     "REFUSED #%d (%s; picks (%.4g %.4g %.4g) (%.4g %.4g %.4g), segment %.4g, "
                     "distance %.4g): %s\n",
                     i, scenarios[k].name, o.picks[0].x(), o.picks[0].y(), o.picks[0].z(),
                     o.picks[1].x(), o.picks[1].y(), o.picks[1].z(), o.segmentLength,
                     o.regionDistance, e.what());
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

// ---------------------------------------------------------------------------------------------
// AllEdits (issue 11): the randomized success benchmark of every edit.

/// A verified edit checked again by the benchmark, independently of the edit's own
/// verification: every vertex outside the returned region keeps its tensor bitwise, and a
/// fresh extraction of the returned field finds the curves the result claims, as many as the
/// edit must leave. Returns the problem, empty when none.
std::string recheck(const TensorField& before, const TensorField& after,
                    const std::vector<int>& regionTets, const DegenerateCurves& claimed,
                    const DegenerateCurves& again, std::size_t expected) {
  const TetMesh& mesh = before.mesh();
  std::vector<char> inRegion(mesh.vertexCount(), 0);
  for (int t : regionTets)
    for (int v : mesh.tets()[t]) inRegion[v] = 1;
  for (int v = 0; v < int(mesh.vertexCount()); ++v)
    if (!inRegion[v] && std::memcmp(&before.at(v), &after.at(v), sizeof(Tensor)) != 0)
      return "vertex " + std::to_string(v) + " outside the region changed";
  if (again.size() != claimed.size())
    return "re-extraction finds " + std::to_string(again.size()) + " curves, the result claims " +
           std::to_string(claimed.size());
  if (again.size() != expected)
    return std::to_string(again.size()) + " curves after the edit, " + std::to_string(expected) +
           " expected";
  return {};
}

/// Whether one curve holds both points (within 1e-6 mean edge lengths).
bool oneCurveHolds(const DegenerateCurves& curves, const Vec3& a, const Vec3& b, double h) {
  for (const DegenerateCurve& c : curves.curves()) {
    bool ha = false, hb = false;
    for (const Vec3& p : c.points) {
      ha = ha || (p - a).norm() < 1e-6 * h;
      hb = hb || (p - b).norm() < 1e-6 * h;
    }
    if (ha && hb) return true;
  }
  return false;
}

/// Point indices of the middle half of an open curve, or all of a loop's.
std::vector<std::size_t> middleIndices(const DegenerateCurve& c) {
  std::vector<std::size_t> out;
  const std::size_t n = c.points.size();
  for (std::size_t i = 0; i < n; ++i)
    if (c.closed || (4 * i >= n && 4 * i < 3 * n)) out.push_back(i);
  return out;
}

/// Reconnection picks for two distinct curves of one type: where their middle parts come
/// closest (a user reconnects two segments that pass near each other).
std::array<Vec3, 2> closestMiddlePoints(const DegenerateCurve& a, const DegenerateCurve& b) {
  double best = std::numeric_limits<double>::infinity();
  std::array<Vec3, 2> out{a.points[0], b.points[0]};
  for (std::size_t i : middleIndices(a))
    for (std::size_t j : middleIndices(b))
      if (const double d = (a.points[i] - b.points[j]).squaredNorm(); d < best)
        best = d, out = {a.points[i], b.points[j]};
  return out;
}

/// A random smooth deformation target for the curve: an arc of length `length` around a random
/// point of its middle half, pushed sideways by amplitude · sin²(π s) (s ∈ [0, 1] along the arc)
/// in a random direction across the arc's chord; the ends stay on the curve. Empty when the arc
/// would reach an open curve's end or a target point leaves the mesh.
std::vector<Vec3> smoothTarget(const TetMesh& mesh, const DegenerateCurve& c, double length,
                               double amplitude, std::mt19937& rng, Vec3& pick) {
  const std::vector<std::size_t> middle = middleIndices(c);
  if (middle.empty()) return {};
  const int n = int(c.points.size());
  const int centre = int(middle[rng() % middle.size()]);
  pick = c.points[centre];
  std::vector<int> idx{centre};
  for (int dir : {-1, 1}) {
    double s = 0;
    for (int j = centre; s < 0.5 * length;) {
      int next = j + dir;
      if (c.closed) next = (next + n) % n;
      if (next < 0 || next >= n || next == centre || int(idx.size()) >= n) return {};
      s += (c.points[next] - c.points[j]).norm();
      j = next;
      if (dir < 0)
        idx.insert(idx.begin(), j);
      else
        idx.push_back(j);
    }
  }
  std::vector<double> s(idx.size(), 0);
  for (std::size_t i = 1; i < idx.size(); ++i)
    s[i] = s[i - 1] + (c.points[idx[i]] - c.points[idx[i - 1]]).norm();
  const Vec3 chord = (c.points[idx.back()] - c.points[idx.front()]).normalized();
  std::normal_distribution<double> g;
  Vec3 dir = tfd::test::drawVec3(g, rng);
  dir -= dir.dot(chord) * chord;
  if (!(dir.norm() > 1e-6)) return {};
  dir.normalize();
  std::vector<Vec3> target;
  for (std::size_t i = 0; i < idx.size(); ++i) {
    const double w = std::sin(3.14159265358979 * s[i] / s.back());
    target.push_back(c.points[idx[i]] + amplitude * w * w * dir);
    if (!mesh.locator().locate(target.back())) return {};
  }
  return target;
}

struct EditTally {
  int attempts = 0, verified = 0, refused = 0, failed = 0, silent = 0;
  void add(const EditTally& o) {
    attempts += o.attempts, verified += o.verified, refused += o.refused;
    failed += o.failed, silent += o.silent;
  }
};

/// The failed check a *Failed message names ("check '…'"), or what it says.
std::string failedCheckOf(const std::string& m) {
  const auto a = m.find("check '");
  if (a == std::string::npos) return "(no check named) " + m.substr(0, 70);
  const auto b = m.find('\'', a + 7);
  std::string prefix;
  if (m.rfind("two-loop removal, step 1", 0) == 0) prefix = "step 1: ";
  if (m.rfind("two-loop removal, step 2", 0) == 0) prefix = "step 2: ";
  return prefix + m.substr(a + 7, b - a - 7);
}

/// What a refusal says, in a few words (its message names the curves and places).
std::string refusalKind(const std::string& m) {
  const std::pair<const char*, const char*> kinds[] = {
      {"no ball region", "no ball region without another curve"},
      {"ends on the domain surface", "segment reaches the curve's end on the surface"},
      {"reach where a picked curve ends", "segment reaches the curve's end on the surface"},
      {"is too short for segments", "loop too short for the segments"},
      {"is outside the mesh", "target outside the mesh"},
      {"different L/P types", "curves of different types"}};
  for (const auto& [needle, kind] : kinds)
    if (m.find(needle) != std::string::npos) return kind;
  return m.substr(0, 60);
}

void AllEdits(benchmark::State& state) {
  auto solids = randomSolids();
  PrimitiveSpec torusSpec;
  torusSpec.shape = PrimitiveShape::Torus;
  torusSpec.majorRadius = 0.6, torusSpec.minorRadius = 0.36;
  // Designed two-loop fields: circles round the hole of two solid tori (turning frame) and
  // concentric circles in the box and the ball (swirl frame), Fig. 17d.
  const std::vector<std::pair<std::string, std::shared_ptr<const TetMesh>>> twoLoopSolids = {
      solids[2], {"torus (TetGen)", io::meshPrimitive(torusSpec, 25'000)}, solids[0], solids[1]};
  const int wanted = int(state.range(0));
  // At most this many possible edits (region found) per kind, so that no kind fills the quota
  // alone; the rare kinds (removals of curves of random fields) take what the fields give.
  const std::map<std::string, int> cap = {
      {"deformation", wanted / 3}, {"reconnection", wanted / 3}, {"two-loop", wanted / 8}};
  const int maxFields = 4 * wanted;
  std::map<std::string, EditTally> byKind, bySolid, bySource;
  std::map<std::string, int> failedChecks, refusals;
  EditTally total;
  int fields = 0;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  for (auto _ : state) {
    while (total.verified + total.failed < wanted && fields < maxFields) {
      const bool twoLoops = fields % 6 == 5;
      const std::size_t twoLoopSolid = std::size_t(fields / 6) % twoLoopSolids.size();
      const auto& [name, mesh] =
          twoLoops ? twoLoopSolids[twoLoopSolid] : solids[fields % solids.size()];
      const bool curvature = !twoLoops && fields % 4 == 3;
      const std::string source = twoLoops    ? "designed two loops"
                                 : curvature ? "curvature"
                                             : "random constraints";
      ++fields;
      TensorField field = [&] {
        if (twoLoops) {
          const bool torus = twoLoopSolid < 2;
          const double r1 = (torus ? 0.40 : 0.25) + 0.08 * unit(rng);
          const double r2 = (torus ? 0.72 : 0.50) + 0.08 * unit(rng);
          const double z0 = 0.1 * (unit(rng) - 0.5);
          const bool inner = rng() % 2;
          return testing::designedField(
              mesh, [=](const Vec3& p) { return testing::twoCirclesW(p, r1, r2, z0, inner); },
              [=](const Vec3& p) {
                return torus ? testing::turningFrame(p) : testing::swirlFrame(p);
              });
        }
        try {
          return randomDesign(mesh, rng, curvature);
        } catch (const Error&) {
          return TensorField(mesh, std::vector<Tensor>(mesh->vertexCount()));
        }
      }();
      const DegenerateCurves curves = extractDegenerateCurves(field);
      const double h = mesh->meanEdgeLength();
      const double radius = 0.5 * (mesh->boundsMax() - mesh->boundsMin()).norm();
      struct Edit {
        std::string kind;
        std::function<std::string()> run;  ///< throws; returns the recheck's problem
        std::string note = {};             ///< printed with a failure
      };
      std::vector<Edit> edits;
      // Removals: the targets whose scenario applies, picked at their middle points.
      auto targets = removableTargets(curves);
      std::shuffle(targets.begin(), targets.end(), rng);
      if (targets.size() > 2) targets.resize(2);
      for (const auto& target : targets) {
        const RemovalScenario scenario = removalScenario(target);
        RemoveCurvesOptions o;
        for (const DegenerateCurve* c : target) o.picks.push_back(c->points[c->points.size() / 2]);
        const std::size_t expected =
            curves.size() -
            (scenario == RemovalScenario::TwoCurve || scenario == RemovalScenario::TwoLoop ? 2 : 1);
        edits.push_back({toString(scenario), [&field, o, expected] {
                           const RemoveCurvesResult r = removeCurves(field, o);
                           return recheck(field, r.field, r.regionTets, r.curves,
                                          extractDegenerateCurves(r.field), expected);
                         }});
      }
      // Reconnections: pairs of distinct curves of one type, picked where they come closest.
      std::vector<std::array<int, 2>> pairs;
      for (const DegenerateCurve& a : curves.curves())
        for (const DegenerateCurve& b : curves.curves())
          if (a.id < b.id && a.type == b.type) pairs.push_back({a.id, b.id});
      std::shuffle(pairs.begin(), pairs.end(), rng);
      if (pairs.size() > 2) pairs.resize(2);
      for (const auto& [ia, ib] : pairs) {
        const DegenerateCurve &a = curves.curve(ia), &b = curves.curve(ib);
        ReconnectCurvesOptions o;
        const std::array<Vec3, 2> picks = closestMiddlePoints(a, b);
        o.picks = {picks[0], picks[1]};
        o.curves = &curves;
        // Two open curves keep their number; a loop joins the other curve.
        const std::size_t expected = curves.size() - (a.closed || b.closed ? 1 : 0);
        edits.push_back({"reconnection", [&field, o, expected, h] {
                           const ReconnectCurvesResult r = reconnectCurves(field, o);
                           const DegenerateCurves again = extractDegenerateCurves(r.field);
                           std::string problem =
                               recheck(field, r.field, r.regionTets, r.curves, again, expected);
                           for (int i = 0; problem.empty() && i < 4; ++i)
                             if (!oneCurveHolds(again, r.report.ends[i].position,
                                                r.report.ends[r.report.partner[i]].position, h))
                               problem = std::string("no curve joins end ") + endpointName(i) +
                                         " to its partner";
                           return problem;
                         }});
      }
      // Deformations: a random arc of a random curve onto a random smooth target.
      std::vector<int> ids(curves.size());
      for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = int(i);
      std::shuffle(ids.begin(), ids.end(), rng);
      int deforms = 0;
      for (int id : ids) {
        if (deforms == 2) break;
        DeformCurveOptions o;
        // An arc of 15–35 % of the bounding radius pushed by 1–3 edge lengths, at most 30 %
        // of the arc's length (a smooth bump, not a spike).
        const double length = (0.15 + 0.2 * unit(rng)) * radius;
        const double amplitude = std::min((1 + 2 * unit(rng)) * h, 0.3 * length);
        o.target = smoothTarget(*mesh, curves.curve(id), length, amplitude, rng, o.pick);
        if (o.target.empty()) continue;
        o.curves = &curves;
        ++deforms;
        const std::size_t expected = curves.size();
        edits.push_back(
            {"deformation",
             [&field, o, expected] {
               const DeformCurveResult r = deformCurve(field, o);
               const DegenerateCurves again = extractDegenerateCurves(r.field);
               std::string problem =
                   recheck(field, r.field, r.regionTets, r.curves, again, expected);
               for (const Vec3& p : o.target)
                 if (problem.empty() && again.pick(p)->distance > 1.001 * r.report.tolerance)
                   problem = "the new curve is " + std::to_string(again.pick(p)->distance) +
                             " from the target (bound " + std::to_string(r.report.tolerance) + ")";
               return problem;
             },
             // The bump's bend radius at its top, L² / (2π² A), against the mean edge length.
             "arc " + std::to_string(length) + ", push " + std::to_string(amplitude / h) +
                 " h, bend radius " +
                 std::to_string(length * length / (2 * 9.8696 * amplitude) / h) + " h"});
      }
      for (const Edit& edit : edits) {
        EditTally& kind = byKind[edit.kind];
        const auto capped = cap.find(edit.kind);
        if ((capped != cap.end() && kind.verified + kind.failed >= capped->second) ||
            total.verified + total.failed >= wanted)
          continue;
        EditTally one;
        one.attempts = 1;
        try {
          const std::string problem = edit.run();
          one.verified = 1;
          if (!problem.empty()) {
            one.silent = 1;
            std::fprintf(stderr, "SILENT (field %d, %s, %s, %s): %s\n", fields, name.c_str(),
                         source.c_str(), edit.kind.c_str(), problem.c_str());
          }
        } catch (const RemovalFailed& e) {
          one.failed = 1, ++failedChecks[edit.kind + ": " + failedCheckOf(e.what())];
          std::fprintf(stderr, "FAILED (field %d, %s, %s, %s): %s\n", fields, name.c_str(),
                       source.c_str(), edit.kind.c_str(), e.what());
        } catch (const ReconnectionFailed& e) {
          one.failed = 1, ++failedChecks[edit.kind + ": " + failedCheckOf(e.what())];
          std::fprintf(stderr, "FAILED (field %d, %s, %s, %s): %s\n", fields, name.c_str(),
                       source.c_str(), edit.kind.c_str(), e.what());
        } catch (const DeformationFailed& e) {
          one.failed = 1, ++failedChecks[edit.kind + ": " + failedCheckOf(e.what())];
          std::fprintf(stderr, "FAILED (field %d, %s, %s, %s; %s): %s\n", fields, name.c_str(),
                       source.c_str(), edit.kind.c_str(), edit.note.c_str(), e.what());
        } catch (const Error& e) {  // RemovalRefused and the edits' set-up errors
          one.refused = 1;
          ++refusals[edit.kind + ": " + refusalKind(e.what())];
        }
        total.add(one), kind.add(one), bySolid[name].add(one), bySource[source].add(one);
        if (total.attempts % 20 == 0)
          std::fprintf(stderr, "... %d fields, %d attempts, %d verified, %d failed\n", fields,
                       total.attempts, total.verified, total.failed);
      }
    }
  }
  std::fprintf(stderr, "%-24s %8s %8s %8s %8s %6s\n", "", "attempts", "verified", "refused",
               "failed", "silent");
  for (const auto* table : {&byKind, &bySolid, &bySource})
    for (const auto& [key, t] : *table)
      std::fprintf(stderr, "%-24s %8d %8d %8d %8d %6d\n", key.c_str(), t.attempts, t.verified,
                   t.refused, t.failed, t.silent);
  std::fprintf(stderr, "%-24s %8d %8d %8d %8d %6d\n", "total", total.attempts, total.verified,
               total.refused, total.failed, total.silent);
  for (const auto& [check, n] : failedChecks)
    std::fprintf(stderr, "  failed %3d  %s\n", n, check.c_str());
  for (const auto& [why, n] : refusals) std::fprintf(stderr, "  refused %3d  %s\n", n, why.c_str());
  state.counters["fields"] = fields;
  state.counters["attempts"] = total.attempts;
  state.counters["verified"] = total.verified;
  state.counters["refused"] = total.refused;
  state.counters["failed"] = total.failed;
  state.counters["silent"] = total.silent;
  state.counters["success_of_possible"] =
      total.verified + total.failed > 0 ? double(total.verified) / (total.verified + total.failed)
                                        : 0;
}
BENCHMARK(AllEdits)->Arg(210)->Iterations(1)->Unit(benchmark::kSecond);

/// Runs the two-loop removal of `field` picked at `picks`, one iteration per repetition, and
/// reports its counters (a failure is reported, not hidden).
void runTwoLoops(benchmark::State& state, const TensorField& field, std::vector<Vec3> picks) {
  RemoveCurvesOptions o;
  o.picks = std::move(picks);
  o.regionDistance = state.range(0) < 0 ? -1 : state.range(0) / 100.0;
  RemoveCurvesResult last{field, {}, {}, {}};
  bool verified = true;
  CookCounters cooks;  // fresh pages: what a first cook pays the host for (RESULTS, session 11)
  for (auto _ : state) {
    const CookCounters::Cook cook(cooks);
    try {
      last = removeCurves(field, o);
    } catch (const RemovalFailed& e) {  // reported, not hidden
      verified = false;
      state.SetLabel(e.what());
    }
  }
  cooks.report(state);
  if (verified)  // the report (both steps' regions and times) on stderr
    for (const std::string& line : last.report.lines())
      std::fprintf(stderr, "  %s\n", line.c_str());
  state.counters["verified"] = verified;
  if (verified) state.SetLabel(resultHash(last.field, last.regionTets, last.curves));
  state.counters["tets"] = double(field.mesh().tetCount());
  state.counters["region_tets"] = double(last.regionTets.size());
  state.counters["step2_region_tets"] = double(last.report.regionTets);
  state.counters["curves_after"] = double(last.curves.size());
  state.counters["peak_MB"] = peakMegabytes();
}

/// Fig. 17d as the paper draws it: a wedge circle ρ = 0.3 and a trisector circle ρ = 0.5 around
/// the z axis in the 998,250-tet box of RemoveLoop1M, under testing::swirlFrame (pure loops
/// without an axis to avoid). The merged loop of step 1 bounds the band between the circles.
void RemoveTwoLoopsBox1M(benchmark::State& state) {
  static const TensorField field = testing::designedField(
      makeBoxMesh(55, 55, 55, Vec3(-1, -1, -1), Vec3(1, 1, 1)),
      [](const Vec3& p) { return testing::twoCirclesW(p, 0.3, 0.5); },
      [](const Vec3& p) { return testing::swirlFrame(p); });
  runTwoLoops(state, field, {Vec3(0.3, 0, 0), Vec3(-0.5, 0, 0)});
}
BENCHMARK(RemoveTwoLoopsBox1M)
    ->Arg(10)
    ->Arg(20)
    ->Arg(-1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(2)
    ->ReportAggregatesOnly(false);

/// The two circles of remove_two_loops_test.cpp (ρ = 0.45 wedge, ρ = 0.75 trisector) on a
/// TetGen solid torus (R = 0.6, r = 0.36) of about 1M tets. Both circles run round the torus's
/// hole, so the only ball the merged loop bounds is the band between them all round the torus
/// (cut at the reconnection): a worst case, whose step-2 region is half the mesh or more at
/// any distance.
void RemoveTwoLoops1M(benchmark::State& state) {
  static const TensorField field = [] {
    PrimitiveSpec spec;
    spec.shape = PrimitiveShape::Torus;
    spec.majorRadius = 0.6, spec.minorRadius = 0.36;
    return testing::designedField(
        io::meshPrimitive(spec, 1'000'000),
        [](const Vec3& p) { return testing::twoCirclesW(p, 0.45, 0.75); }, testing::turningFrame);
  }();
  runTwoLoops(state, field, {Vec3(0.45, 0, 0), Vec3(-0.75, 0, 0)});
}
BENCHMARK(RemoveTwoLoops1M)
    ->Arg(15)
    ->Arg(25)
    ->Arg(-1)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(2)
    ->ReportAggregatesOnly(false);

}  // namespace

BENCHMARK_MAIN();
