#pragma once
// The degenerate curves of a tensor field (paper §3–4) as an immutable value: polylines with
// their L/P type and per-point wedge / trisector / transition pattern, summary statistics,
// warnings of the extraction, and a pick query that finds the curve nearest a point in space
// (edit nodes name their target curve by a picked point, never by an index).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/degeneracy.h"
#include "core/tensor.h"

namespace tfd::core {

/// Where a curve point came from: a mesh face (the usual case), an edge or a vertex (points
/// canonicalised so that all cells around them share them), or the inside of a tet (transition
/// points and arc samples).
struct PointSource {
  enum class Kind : std::uint8_t { Face, Edge, Vertex, Tet };
  Kind kind = Kind::Face;
  int id = -1;
  friend bool operator==(const PointSource&, const PointSource&) = default;
};

struct DegenerateCurve {
  int id = 0;  ///< index in DegenerateCurves::curves(); stable for a given field
  DegenerateType type = DegenerateType::Linear;
  bool closed = false;  ///< a loop; the first point is not repeated at the end
  std::vector<Vec3> points;
  std::vector<DegeneratePattern> patterns;  ///< one per point
  std::vector<Vec3> tangents;               ///< unit, pointing along increasing point index
  std::vector<Vec3> eigenvectors;           ///< unit non-degenerate eigenvector (sign arbitrary)
  std::vector<PointSource> sources;         ///< one per point
  double length() const;
  std::size_t segmentCount() const {
    return points.size() < 2 ? 0 : (closed ? points.size() : points.size() - 1);
  }
};

/// Result of DegenerateCurves::pick: the nearest point of the nearest curve.
struct CurvePick {
  int curveId = -1;
  int segment = -1;              ///< segment from point `segment` to the next (wrapping on loops)
  double t = 0;                  ///< position along that segment in [0, 1]
  int pointIndex = -1;           ///< the curve point nearest to the picked position
  double arcLength = 0;          ///< distance along the curve from its first point
  double distance = 0;           ///< from the query point to the curve
  Vec3 position = Vec3::Zero();  ///< nearest position on the curve
};

struct CurveStatistics {
  int curves = 0, linear = 0, planar = 0, closed = 0, open = 0;
  int points = 0, wedgePoints = 0, trisectorPoints = 0, transitionPoints = 0;
};

/// Counters of the extraction (for profiling, tests and the CLI's verbose output).
struct ExtractionDiagnostics {
  std::int64_t faces = 0;                   ///< unique faces of the mesh
  std::int64_t facesCulledByGap = 0;        ///< proved clean by the eigen-gap test
  std::int64_t facesCulledByBernstein = 0;  ///< proved clean by the Bernstein test
  std::int64_t facesSolved = 0;             ///< faces given to the exact solver (all rounds)
  std::int64_t facePoints = 0;              ///< degenerate points on faces (final)
  std::int64_t perturbedVertices = 0;       ///< vertices moved by the non-generic fallback
  int rounds = 0;                           ///< fallback rounds used (0: field was generic)
  std::int64_t unresolvedFaces = 0;         ///< still non-generic after the last round
  std::int64_t oddTets = 0;                 ///< tets whose points could not all be paired
  std::int64_t heuristicTets = 0;           ///< tets connected by nearest pairs, not the conic
  std::int64_t danglingEnds = 0;            ///< open-curve ends not on the boundary
  std::int64_t junctions = 0;               ///< points where more than two segments meet
};

/// Immutable set of degenerate curves. The constructor puts curves in a canonical order
/// (each open curve runs from its lexicographically smaller end; a loop starts at its smallest
/// point and runs towards its smaller neighbour; curves sorted by first point) and numbers
/// them, so ids depend only on the geometry, not on how the curves were produced.
class DegenerateCurves {
 public:
  DegenerateCurves() = default;
  /// Throws core::Error when a curve's per-point arrays do not match its point count (empty
  /// tangents / eigenvectors / sources are filled with defaults).
  explicit DegenerateCurves(std::vector<DegenerateCurve> curves,
                            std::vector<std::string> warnings = {},
                            ExtractionDiagnostics diagnostics = {});

  const std::vector<DegenerateCurve>& curves() const { return curves_; }
  std::size_t size() const { return curves_.size(); }
  bool empty() const { return curves_.empty(); }
  const DegenerateCurve& curve(int id) const;  ///< throws core::Error for a bad id

  /// Human-readable warnings, e.g. "the field is zero everywhere: no degenerate curves".
  const std::vector<std::string>& warnings() const { return warnings_; }
  const CurveStatistics& statistics() const { return statistics_; }
  const ExtractionDiagnostics& diagnostics() const { return diagnostics_; }

  /// The curve nearest to p (ties: the lower id), or nothing when there are no curves.
  std::optional<CurvePick> pick(const Vec3& p) const;

  /// One line, e.g. "5 degenerate curves (3 linear, 2 planar; 1 loop), 412 points,
  /// 4 transition points".
  std::string summary() const;
  /// Approximate memory use, for cache accounting.
  std::size_t byteSize() const;

 private:
  std::vector<DegenerateCurve> curves_;
  std::vector<std::string> warnings_;
  CurveStatistics statistics_;
  ExtractionDiagnostics diagnostics_;
};

}  // namespace tfd::core
