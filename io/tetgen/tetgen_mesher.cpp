#include "io/tetgen/tetgen_mesher.h"

#include <tetgen.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/memory_budget.h"
#include "core/spatial_order.h"
#include "core/surface/surface_cavities.h"
#include "core/surface/surface_check.h"
#include "io/tet_mesh_build.h"
#include "io/tetgen/tetgen_process.h"

namespace tfd::io {
namespace detail {
extern const int kTetgenTerminateInterposed;  // io/tetgen/tetgen_terminate.cpp
}
namespace {

std::string tetgenFailure(int code) {
  switch (code) {
    case 1:
      return "TetGen ran out of memory (code 1); ask for fewer tets";
    case 2:
      return "TetGen hit an internal error (code 2); the input surface may be degenerate";
    case 3:
      return "the input surface intersects itself (TetGen code 3); repair it (remove the "
             "self-intersections) and try again";
    case 4:
      return "the input surface has a very small feature compared to its size (TetGen code 4); "
             "simplify or clean up the surface";
    case 5:
      return "the input surface has two very close facets (TetGen code 5); repair the surface";
    case 10:
      return "TetGen rejected the input (code 10, input error)";
    default:
      return "TetGen failed with code " + std::to_string(code);
  }
}

/// Throws when two referenced vertices have exactly the same position.
void checkCoincidentVertices(const core::SurfaceMesh& s, const std::string& source) {
  std::vector<int> order(s.positions.size());
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const auto &p = s.positions[a], &q = s.positions[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (s.positions[order[i]] == s.positions[order[i - 1]]) {
      throw core::Error(source + ": vertices " + std::to_string(order[i - 1]) + " and " +
                        std::to_string(order[i]) +
                        " have the same position; weld duplicate vertices first");
    }
  }
}

}  // namespace

double defaultTetgenTimeLimit(double targetTets) {
  return 30.0 + 40e-6 * std::max(0.0, targetTets);
}

double tetgenMemoryEstimate(double tets, std::size_t surfaceVertices) {
  return kTetgenBaseBytes + kTetgenBytesPerTet * tets + 200.0 * double(surfaceVertices);
}

std::string tetgenSwitches(double surfaceVolume, const TetgenOptions& o) {
  std::ostringstream s;
  s << "pzQ";
  if (o.keepBoundary) s << 'Y';
  if (o.quality > 0) s << 'q' << o.quality;
  if (o.targetTets > 0) {
    const double a = std::abs(surfaceVolume) / o.targetTets * o.volumeFactor;
    // Fixed notation: TetGen parses the number itself; keep ~12 significant digits.
    const int digits = std::clamp(12 - int(std::floor(std::log10(a))), 1, 40);
    s << 'a' << std::fixed;
    s.precision(digits);
    s << a;
  }
  return s.str();
}

void requireClosedSurface(const core::SurfaceMesh& surface, const std::string& source) {
  if (const auto problems = core::closedSurfaceProblems(surface); !problems.empty()) {
    std::string message =
        source + " is not a closed, manifold, consistently oriented surface (TetGen needs one): ";
    for (std::size_t i = 0; i < problems.size(); ++i) message += (i ? "; " : "") + problems[i];
    throw core::Error(message);
  }
}

std::shared_ptr<const core::TetMesh> tetrahedralize(const core::SurfaceMesh& input,
                                                    const TetgenOptions& options,
                                                    const core::Progress& progress) {
  if (!(options.targetTets >= 0) || !std::isfinite(options.targetTets)) {
    throw core::Error("TetGen: target tet count must be a non-negative number");
  }
  if (options.quality != 0 && !(options.quality >= 1.05)) {
    throw core::Error("TetGen: quality (radius-edge ratio) must be 0 (off) or at least 1.05");
  }
  if (!(options.volumeFactor > 0)) throw core::Error("TetGen: volume factor must be positive");
  const std::string source = options.source.empty() ? "the surface" : options.source;
  progress.throwIfCancelled();
  progress.report(0, "checking the surface");

  core::SurfaceMesh surface = input;
  requireClosedSurface(surface, source);
  core::removeUnreferencedVertices(surface);
  checkCoincidentVertices(surface, source);
  const double volume = core::enclosedVolume(surface);
  std::string switches = tetgenSwitches(volume, options);

  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = int(surface.positions.size());
  in.pointlist = new REAL[3 * surface.positions.size()];
  for (std::size_t v = 0; v < surface.positions.size(); ++v) {
    for (int i = 0; i < 3; ++i) in.pointlist[3 * v + i] = surface.positions[v][i];
  }
  in.numberoffacets = int(surface.triangles.size());
  in.facetlist = new tetgenio::facet[surface.triangles.size()];
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for (int i = 0; i < 3; ++i) f.polygonlist[0].vertexlist[i] = surface.triangles[t][i];
  }

  // Pieces of the surface that face the other way bound voids: a hole point in each, or TetGen
  // fills them (it removes only the tets outside the outer boundary by itself).
  const std::vector<core::Vec3> cavities = core::cavityPoints(surface);
  in.numberofholes = int(cavities.size());
  in.holelist = cavities.empty() ? nullptr : new REAL[3 * cavities.size()];
  for (std::size_t h = 0; h < cavities.size(); ++h)
    for (int i = 0; i < 3; ++i) in.holelist[3 * h + i] = cavities[h][i];

  const double expected = options.targetTets > 0 ? options.targetTets : 1000.0 * in.numberofpoints;
  core::checkMemory(
      tetgenMemoryEstimate(expected, surface.positions.size()),
      source + ": TetGen for about " + std::to_string(std::llround(expected)) + " tets");
  TetgenRunLimits limits;
  limits.seconds =
      options.timeLimit > 0 ? options.timeLimit : defaultTetgenTimeLimit(options.targetTets);
  limits.timeLimitName = options.timeLimit > 0 ? "the time limit" : "the automatic time limit";
  limits.memoryBytes = core::memoryBudget();
  limits.source = source;

  progress.report(0.05, "TetGen");
  // Keeps the terminatetetgen work-around linked in (see tetgen_terminate.cpp).
  [[maybe_unused]] volatile int linked = detail::kTetgenTerminateInterposed;
  TetgenRun run = runTetgenInChild(switches, in, limits, progress);
  if (run.failureCode != 0) {
    throw core::Error(source + ": " + tetgenFailure(run.failureCode) +
                      (run.said.empty() ? "" : " [TetGen: " + run.said + "]"));
  }
  progress.throwIfCancelled();
  progress.report(0.8, "building the tet mesh topology");

  if (run.tets.empty()) {
    throw core::Error(source + ": TetGen produced no tetrahedra (switches " + switches + ")");
  }
  std::vector<core::Vec3> positions(run.points.size() / 3);
  for (std::size_t v = 0; v < positions.size(); ++v) {
    positions[v] = core::Vec3(run.points[3 * v], run.points[3 * v + 1], run.points[3 * v + 2]);
  }
  run.points = {};
  std::vector<core::TetMesh::Tet> tets(run.tets.size() / 4);
  for (std::size_t t = 0; t < tets.size(); ++t) {
    for (int i = 0; i < 4; ++i) tets[t][i] = run.tets[4 * t + i];
  }
  run.tets = {};
  // TetGen numbers Steiner points and tets in refinement order (face neighbours ~200K ids
  // apart at 1M tets); along a Hilbert curve every neighbour sweep downstream stays in cache.
  // The input surface's vertices keep their ids.
  core::renumberSpatially(positions, tets, surface.positions.size());
  auto mesh = buildTetMesh(std::move(positions), std::move(tets), "TetGen output", progress);
  progress.report(1.0);
  return mesh;
}

std::shared_ptr<const core::TetMesh> meshPrimitive(const core::PrimitiveSpec& spec,
                                                   double targetTets,
                                                   const core::Progress& progress) {
  progress.report(0, "building the surface");
  const core::SurfaceMesh surface = core::makePrimitiveForTets(spec, targetTets);
  progress.throwIfCancelled();
  TetgenOptions options;
  options.targetTets = targetTets;
  return tetrahedralize(surface, options, progress);
}

std::shared_ptr<const core::TetMesh> meshPrimitive(core::PrimitiveShape shape, double targetTets) {
  core::PrimitiveSpec spec;
  spec.shape = shape;
  return meshPrimitive(spec, targetTets);
}

}  // namespace tfd::io
