#pragma once
// Degenerate curve deformation (paper §6.1), verified by re-extraction.
//
// Steps: extract the field's curves; name the curve by the picked point; γ1 and γ2 from the
// target (deform_paths.h: the target's ends, projected onto the curve, bound the segment γ1
// that moves); forbid every tet holding a point of another curve (and the tets around their
// vertices, as for removal); seed with the tets holding γ1 and γ2, every tet around their
// vertices and every tet around a vertex of the thick envelope (within D + h of γ2,
// deformation_map.h), so that all the vertices φ holds are inside the region; grow a ball region
// (core/region/ball_region.h) out to `regionDistance` and check it independently; build φ and the
// deformed field (deformation_map.h); a fold-over on a tet holding γ2 fails the try. Verification:
// every vertex outside the region's free vertices keeps its tensor bitwise and every other curve is
// unchanged (edit_verification.h, checks 1–2); inside, exactly one curve, which follows the new
// course (γ2, and the rest of the curve where it passes through the region) within the mean edge
// length of the region (Hausdorff distance over the region). A failed try retries with the distance
// grown by `growFactor`.
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/tensor_field.h"
#include "core/topology/extract_degenerate_curves.h"

namespace tfd::core {

struct DeformCurveOptions {
  Vec3 pick = Vec3::Zero();  ///< names the curve nearest to it (and, on a loop, the arc)
  std::vector<Vec3> target;  ///< the new course: at least two points; ends meet the curve
  /// Grow-out distance of the region; negative: 30 % of the mesh's bounding radius (the paper).
  double regionDistance = -1;
  int retries = 2;          ///< extra tries with a larger region after a failed try
  double growFactor = 1.5;  ///< distance multiplier per retry
  /// The field's curves when the caller has them (the pick names what the user sees); they
  /// must belong to the field. Null: the extraction below.
  const DegenerateCurves* curves = nullptr;
  ExtractOptions extract;  ///< settings of the extraction before and after (the same)
};

/// No try verified (the deformation itself could be set up).
class DeformationFailed : public Error {
 public:
  using Error::Error;
};

struct DeformTry {
  double distance = 0;
  std::size_t regionTets = 0;
  std::size_t foldOvers = 0, foldOversOnCurve = 0;
  double hausdorff = -1;            ///< −1: not measured (an earlier check failed)
  std::string failedCheck, detail;  ///< empty when it passed
};

struct DeformCurveReport {
  std::string curve;  ///< describeCurve() of the picked curve
  double pickDistance = 0;
  double length1 = 0, length2 = 0;  ///< of γ1 and γ2
  int samples = 0;                  ///< points of each resampled curve
  std::size_t regionTets = 0, regionVertices = 0;
  std::size_t envelopeVertices = 0, solvedVertices = 0, identityVertices = 0;
  std::size_t foldOvers = 0, foldOversOnCurve = 0, outsidePreimages = 0;
  double hausdorff = 0, tolerance = 0;  ///< the distance and its bound (mean edge length)
  std::vector<DeformTry> tries;
  double seconds = 0;
  std::size_t curvesBefore = 0, curvesAfter = 0;
  /// The node's info lines.
  std::vector<std::string> lines() const;
};

struct DeformCurveResult {
  TensorField field;
  DegenerateCurves curves;      ///< of `field`, extracted with options.extract
  std::vector<int> regionTets;  ///< the final region, ascending
  DeformCurveReport report;
};

/// Throws core::Error for bad options (naming `pick`, `target`, `retries`…), when the target
/// leaves the mesh, or when no ball region holds γ1 and γ2 without another curve;
/// DeformationFailed when no try verified (naming the failed check and the last region size);
/// core::Cancelled when cancelled. Never returns a field that did not verify.
DeformCurveResult deformCurve(const TensorField& field, const DeformCurveOptions& options,
                              const Progress& progress = {});

}  // namespace tfd::core
