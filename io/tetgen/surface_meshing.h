#pragma once
// Meshing a surface as the TetMesh node asks for it: the boundary rule (keep the surface
// triangles or let TetGen refine them) and the welding of vertices repeated at one position
// (UV seams, per-face exports), on top of io/tetgen/tetgen_mesher.h.
#include <memory>
#include <string>

#include "core/progress.h"
#include "core/surface/surface_mesh.h"
#include "core/tet_mesh.h"

namespace tfd::io {

/// keep: the surface triangles are the mesh boundary (TetGen -Y; the tet count then follows the
/// surface's resolution); refine: TetGen may split them for quality and size; auto: keep for
/// procedural solids and for surfaces already as fine as the target needs (mean edge at most
/// kKeepableEdgeRatio times the edge length the target asks for), refine coarser ones.
enum class BoundaryMode { Auto, Keep, Refine };

/// Surface edges up to this factor above the target edge length count as fine enough to keep.
inline constexpr double kKeepableEdgeRatio = 1.5;
/// TetGen's volume-bound calibration without -Y (boundary refined too; see bench/RESULTS.md).
inline constexpr double kRefineVolumeFactor = 2.5;

/// The default weld tolerance, relative to the median edge length: far above the rounding of
/// float32 files (6e-8 of a coordinate, so 6e-5 of an edge a thousandth of the model) and far
/// below any edge TetGen could mesh well. The median, unlike the bounding box, does not grow
/// with one outlying vertex.
inline constexpr double kDefaultWeldTolerance = 1e-3;

struct SurfaceMeshingRequest {
  double targetTets = 20'000;
  double quality = 1.414;  ///< TetGen radius-edge bound (0: no quality refinement)
  BoundaryMode boundary = BoundaryMode::Auto;
  double timeLimit = 0;  ///< seconds TetGen may run (TetgenOptions::timeLimit; 0: automatic)
  /// Vertices closer than this fraction of the surface's median edge length are welded
  /// (core::weldCloseVertices); 0: only those at exactly one position.
  double weldTolerance = kDefaultWeldTolerance;
  /// Holes of at most this many edges are closed (core::fillHoles); 0: none.
  int fillHoles = 0;
  /// A procedural solid (core/surface/primitives.h): its surface already matches the target, so
  /// auto keeps it, and it has no repeated vertices to weld.
  bool procedural = false;
  std::string source;  ///< names the surface in messages, e.g. "file 'part.stl'"
};

struct SurfaceMeshingReport {
  std::size_t weldedVertices = 0;     ///< vertices merged into an earlier one (same place or close)
  double weldDistance = 0;            ///< the absolute weld tolerance used (0: exact positions)
  std::size_t repeatedTriangles = 0;  ///< removed: copies of a face, or a face between solids
  std::size_t filledHoles = 0;        ///< holes closed with a fan
  std::size_t holeTriangles = 0;      ///< triangles that closed them
  std::size_t flippedTriangles = 0;   ///< reversed to agree with their neighbours
  std::size_t droppedTriangles = 0;   ///< triangles that lost a corner in the welding
  bool boundaryKept = true;           ///< the surface triangles are the mesh boundary
};

/// A surface read from a file, made ready for TetGen as meshSurface() does: welded
/// (request.weldTolerance), its repeated triangles removed (core::removeRepeatedTriangles), its
/// holes up to request.fillHoles edges closed (core::fillHoles), its triangles oriented alike
/// (core::orientConsistently), then checked (closed, manifold, two-sided). Fills the weld, repeat
/// and flip counts of `report`. Throws core::Error naming request.source, with advice where a weld
/// tolerance or one-sidedness explains the problem.
void prepareFileSurface(core::SurfaceMesh& surface, const SurfaceMeshingRequest& request,
                        SurfaceMeshingReport& report);

/// Welds, removes repeated triangles (core::removeRepeatedTriangles) and orients the triangles
/// consistently (core::orientConsistently) unless procedural,
/// applies the boundary rule and tetrahedralises (tetrahedralize's errors and guarantees).
/// `report` may be null.
std::shared_ptr<const core::TetMesh> meshSurface(core::SurfaceMesh surface,
                                                 const SurfaceMeshingRequest& request,
                                                 SurfaceMeshingReport* report,
                                                 const core::Progress& progress = {});

}  // namespace tfd::io
