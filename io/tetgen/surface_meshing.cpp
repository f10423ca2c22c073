#include "io/tetgen/surface_meshing.h"

#include <cmath>

#include "core/surface/primitives.h"
#include "core/surface/surface_check.h"
#include "core/surface/surface_weld.h"
#include "io/tetgen/tetgen_mesher.h"

namespace tfd::io {

std::shared_ptr<const core::TetMesh> meshSurface(core::SurfaceMesh surface,
                                                 const SurfaceMeshingRequest& request,
                                                 SurfaceMeshingReport* report,
                                                 const core::Progress& progress) {
  SurfaceMeshingReport r;
  if (!request.procedural) {
    const core::WeldReport weld = core::weldCoincidentVertices(surface);
    r.weldedVertices = weld.mergedVertices;
    r.droppedTriangles = weld.droppedTriangles;
    // Before anything uses its volume: an open or flat surface is named as such.
    requireClosedSurface(surface, request.source.empty() ? "the surface" : request.source);
  }
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
