#include "io/tetgen/surface_meshing.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/surface/primitives.h"
#include "core/surface/surface_check.h"
#include "core/surface/surface_holes.h"
#include "core/surface/surface_orient.h"
#include "core/surface/surface_weld.h"
#include "io/tetgen/tetgen_mesher.h"

namespace tfd::io {
namespace {

/// When every open edge of a surface has a twin close by (a seam written a little apart), the
/// weld tolerance that would pair them, as advice; else "".
std::string weldHint(const core::SurfaceMesh& surface, double used) {
  const double edge = core::medianEdgeLength(surface);
  const double gap = core::openEdgeWeldDistance(surface, 0.1 * edge);
  if (!(gap > used) || !(gap <= 0.1 * edge)) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                ". Every open edge has a twin within %.3g (%.3g of the median edge): if these "
                "are seams written a little apart, a weld_tolerance above %.3g welds them",
                gap, gap / edge, gap / edge);
  return text;
}

/// When the surface's only openings are holes (loops of open edges), how many and how long,
/// and the fill_holes that closes them; else "".
std::string holeHint(const core::SurfaceMesh& surface) {
  const auto loops = core::holeLoops(surface);
  if (loops.empty()) return "";
  std::size_t shortest = loops.front().size(), longest = shortest;
  for (const auto& loop : loops)
    shortest = std::min(shortest, loop.size()), longest = std::max(longest, loop.size());
  const std::string fill = "fill_holes ≥ " + std::to_string(longest);
  if (loops.size() == 1)
    return ". It has 1 hole (a loop of " + std::to_string(longest) + " open edges): " + fill +
           " closes it with a fan of triangles";
  const std::string sizes = shortest == longest
                                ? std::to_string(longest)
                                : std::to_string(shortest) + "–" + std::to_string(longest);
  return ". It has " + std::to_string(loops.size()) + " holes (loops of " + sizes +
         " open edges): " + fill + " closes them with a fan of triangles each";
}

}  // namespace

void prepareFileSurface(core::SurfaceMesh& surface, const SurfaceMeshingRequest& request,
                        SurfaceMeshingReport& r) {
  const std::string source = request.source.empty() ? "the surface" : request.source;
  if (!(request.weldTolerance >= 0) || !std::isfinite(request.weldTolerance))
    throw core::Error("the weld tolerance must be a finite number ≥ 0");
  r.weldDistance = request.weldTolerance * core::medianEdgeLength(surface);
  const core::WeldReport weld = core::weldCloseVertices(surface, r.weldDistance);
  r.weldedVertices = weld.mergedVertices;
  r.droppedTriangles = weld.droppedTriangles;
  r.repeatedTriangles = core::removeRepeatedTriangles(surface);
  if (surface.triangles.empty() && r.repeatedTriangles > 0)
    throw core::Error(source +
                      " encloses no volume: every triangle has a copy facing the other way "
                      "(a flat or doubled surface)");
  if (request.fillHoles > 0) {
    const core::HoleFilling filling = core::fillHoles(surface, std::size_t(request.fillHoles));
    r.filledHoles = filling.filled;
    r.holeTriangles = filling.triangles;
  }
  const core::OrientReport orient = core::orientConsistently(surface);
  r.flippedTriangles = orient.flippedTriangles;
  // Before anything uses its volume: an open or flat surface is named as such.
  try {
    requireClosedSurface(surface, source);
  } catch (const core::Error& e) {
    // Advice, most specific first (a seam's open edges are no holes to fill).
    std::string advice = orient.oneSided ? ". No reversal of triangles can orient it: the "
                                           "surface is one-sided (a Klein bottle, a projective "
                                           "plane), so it bounds no solid"
                                         : weldHint(surface, r.weldDistance);
    if (advice.empty()) advice = holeHint(surface);
    throw core::Error(std::string(e.what()) + advice);
  }
}

std::shared_ptr<const core::TetMesh> meshSurface(core::SurfaceMesh surface,
                                                 const SurfaceMeshingRequest& request,
                                                 SurfaceMeshingReport* report,
                                                 const core::Progress& progress) {
  SurfaceMeshingReport r;
  if (!request.procedural) prepareFileSurface(surface, request, r);
  TetgenOptions o;
  o.targetTets = request.targetTets;
  o.quality = request.quality;
  o.keepBoundary = request.boundary == BoundaryMode::Keep;
  if (request.boundary == BoundaryMode::Auto) {
    const double wanted =
        core::edgeLengthForTargetTets(std::abs(core::enclosedVolume(surface)), o.targetTets);
    o.keepBoundary =
        request.procedural || core::meanEdgeLength(surface) <= kKeepableEdgeRatio * wanted;
  }
  if (!o.keepBoundary) o.volumeFactor = kRefineVolumeFactor;
  o.timeLimit = request.timeLimit;
  o.source = request.source;
  r.boundaryKept = o.keepBoundary;
  if (report) *report = r;
  return tetrahedralize(surface, o, progress);
}

}  // namespace tfd::io
