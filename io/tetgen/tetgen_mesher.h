#pragma once
// TetGen adapter: a closed triangle surface to a quality tetrahedral mesh (paper section 4
// works on such meshes; the paper used TetGen too).
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "core/progress.h"
#include "core/surface/primitives.h"
#include "core/surface/surface_mesh.h"
#include "core/tet_mesh.h"

namespace tfd::io {

struct TetgenOptions {
  /// Wanted number of tets; 0 puts no volume bound (only quality refinement). The volume
  /// bound is `a` = |enclosed volume| / targetTets · volumeFactor. With keepBoundary the count
  /// also depends on the surface resolution: give a surface whose edge length is
  /// core::edgeLengthForTargetTets(volume, targetTets) (the procedural solids do) to land
  /// within about ±25 % of the target.
  double targetTets = 100'000;
  /// Radius-edge ratio bound (TetGen `q`); 0 switches quality refinement off. TetGen needs
  /// a bound above about 1.1 to terminate; 1.414 is its default.
  double quality = 1.414;
  /// Keep the input surface triangles as the boundary (TetGen `Y`): no Steiner points on the
  /// surface, so boundary resolution is exactly the input's. Without it, quality refinement
  /// splits boundary triangles freely.
  bool keepBoundary = true;
  /// Calibration of the volume bound: TetGen's mean tet volume ends up well below the bound,
  /// 1.8 lands the count on the target (see bench/RESULTS.md).
  double volumeFactor = 1.8;
  /// Wall-clock limit in seconds for TetGen itself; 0: defaultTetgenTimeLimit(targetTets).
  double timeLimit = 0;
  /// Names the surface in error messages, e.g. "file 'part.stl'"; empty: "the surface".
  std::string source = {};
};

/// The automatic time limit: 30 s plus 40 s per million target tets (TetGen makes about a
/// million tets in 7 s on one core of the 2-core machine of bench/RESULTS.md, so this leaves
/// room for a busy machine; a refinement that never ends is stopped).
double defaultTetgenTimeLimit(double targetTets);

/// Peak memory of meshing `tets` tets: TetGen in its child process (measured about 190 bytes
/// per tet), then the TetMesh built from its output in this process (about 320 bytes per
/// tet, measured at 1M and 3M tets, see bench/RESULTS.md), with some margin.
inline constexpr double kTetgenBaseBytes = 48.0 * 1024 * 1024;
inline constexpr double kTetgenBytesPerTet = 400;
double tetgenMemoryEstimate(double tets, std::size_t surfaceVertices);

/// The TetGen switch string used for `surface` (its volume) and `options`; always PLC mode
/// (`p`), zero-based numbering (`z`) and quiet (`Q`), e.g. "pzQYq1.414a0.000012".
std::string tetgenSwitches(double surfaceVolume, const TetgenOptions& options);

/// Throws core::Error "<source> is not a closed, manifold, consistently oriented surface
/// (TetGen needs one): <problems>" unless `surface` is one that encloses a volume.
void requireClosedSurface(const core::SurfaceMesh& surface, const std::string& source);

/// Tetrahedralises the solid bounded by `surface`.
/// Messages start with options.source (or "the surface"). The surface is checked first: it must be
/// closed, manifold and consistently oriented (either orientation), without coincident vertices,
/// and enclose a non-zero volume; otherwise a core::Error lists the problems. Unreferenced vertices
/// are ignored. TetGen failures become core::Error messages (1 out of memory, 2 internal error, 3
/// self-intersecting surface, 4 very small input feature, 5 two very close facets, 10 input error).
/// The result has positively oriented tets and keeps every surface vertex (with
/// keepBoundary, the boundary faces are exactly the input triangles). Deterministic: the same
/// input and options give the identical mesh. TetGen runs in a child process
/// (tetgen_process.h): a cancelled `progress` stops it within about 50 ms (core::Cancelled);
/// beyond options.timeLimit, or beyond the memory budget (core/memory_budget.h), it is stopped
/// with a core::Error. A request whose estimated memory (tetgenMemoryEstimate) exceeds the
/// budget is refused before TetGen starts.
std::shared_ptr<const core::TetMesh> tetrahedralize(const core::SurfaceMesh& surface,
                                                    const TetgenOptions& options,
                                                    const core::Progress& progress = {});

/// One call for examples and benchmarks: the procedural solid `spec` with a surface resolution
/// matched to `targetTets`, tetrahedralised with default quality and the boundary kept.
std::shared_ptr<const core::TetMesh> meshPrimitive(const core::PrimitiveSpec& spec,
                                                   double targetTets,
                                                   const core::Progress& progress = {});
/// The same with default dimensions: a sphere of radius 1, a 2 × 2 × 2 box, tori with R = 1,
/// r = 0.4; e.g. meshPrimitive(core::PrimitiveShape::Sphere, 500'000).
std::shared_ptr<const core::TetMesh> meshPrimitive(core::PrimitiveShape shape, double targetTets);

}  // namespace tfd::io
