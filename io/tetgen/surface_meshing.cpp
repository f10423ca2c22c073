#include "io/tetgen/surface_meshing.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/surface/primitives.h"
#include "core/surface/surface_check.h"
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
  const core::OrientReport orient = core::orientConsistently(surface);
  r.flippedTriangles = orient.flippedTriangles;
  // Before anything uses its volume: an open or flat surface is named as such.
  try {
    requireClosedSurface(surface, source);
  } catch (const core::Error& e) {
    throw core::Error(std::string(e.what()) +
                      (orient.oneSided ? ". No reversal of triangles can orient it: the surface "
                                         "is one-sided (a Klein bottle, a projective plane), so "
                                         "it bounds no solid"
                                       : weldHint(surface, r.weldDistance)));
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
