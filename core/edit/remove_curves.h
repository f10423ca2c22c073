#pragma once
// Degenerate curve removal (paper §6.4) for the scenarios whose region is a ball: one-curve,
// two-curve and one-loop (removal_scenario.h), each verified by re-extraction; and two-loop
// removal as the paper's composite of a reconnection and a one-loop removal
// (remove_two_loops.h).
//
// Steps: extract the field's curves; name the targets by the picked points (never by index);
// choose the scenario; forbid every tet holding a point of another curve; seed with the tets
// holding the targets and every tet around their vertices (so the targets' tets have only free
// vertices); grow a ball region (core/region/ball_region.h) out to `regionDistance`; check it
// independently (core/region/ball_check.h); split its vertices into held and free
// (core/region/region_vertices.h); vectorise the non-repeating eigenvector and report the
// incoming / outgoing split (boundary_flow.h) — when the eigenvector cannot be oriented (sign
// conflicts: a degenerate point of the other type that no extracted curve covers, typically
// under-resolved next to the domain surface), forbid the tets around the conflicting edges and
// grow the region again (at most 8 times a try; a seed among them refuses the removal, naming
// the place); likewise around the faces of its boundary where the held angles of §6.3 cannot
// lift continuously (core/edit/angle_defects.h; at most 8 times, and only when no seed is
// among those tets); compute the singularity-free field of §6.3
// (singularity_free_field.h; N smoothed at the free vertices around every edge where it turns
// by more than 30°); re-extract with the same settings and verify
// (edit_verification.h). On a failed verification retry with the distance grown by
// `growFactor`, at most `retries` times; after a new curve or a piece of a target appeared,
// the retry also keeps one more ring of tets from the other curves (unless that ring would
// take a target's tet). Curves cannot end inside the volume, so a region holds
// a loop entirely and an open curve with its ends on the domain surface; when the ball would
// have to cut another curve the removal is refused, naming that curve and how far it is.
#include <string>
#include <vector>

#include "core/edit/boundary_flow.h"
#include "core/edit/removal_scenario.h"
#include "core/progress.h"
#include "core/tensor_field.h"
#include "core/topology/extract_degenerate_curves.h"

namespace tfd::core {

struct RemoveCurvesOptions {
  std::vector<Vec3> picks;  ///< one or two points; each names the curve nearest to it
  /// Grow-out distance of the region (a length); negative: 30 % of the mesh's bounding radius
  /// (half its bounding-box diagonal), the paper's default.
  double regionDistance = -1;
  int retries = 2;          ///< extra tries with a larger region after a failed verification
  double growFactor = 1.5;  ///< distance multiplier per retry
  /// The field's curves when the caller has them (used to resolve the picks, so they name what
  /// the user sees); null: the picks use the extraction below. They must belong to the field.
  const DegenerateCurves* curves = nullptr;
  /// The field's own curves, extracted with `extract`, when the caller has just extracted them
  /// (the two-loop removal between its steps): the edit then skips its first extraction. Not
  /// checked; null: the edit extracts.
  const DegenerateCurves* extracted = nullptr;
  ExtractOptions extract;  ///< settings of the extraction before and after (the same)
};

/// The verification still failed after every retry (the removal itself was possible).
class RemovalFailed : public Error {
 public:
  using Error::Error;
};

struct RemovalTry {
  double distance = 0;
  std::size_t regionTets = 0;
  std::string failedCheck, detail;  ///< empty when it passed
};

struct RemoveCurvesReport {
  RemovalScenario scenario = RemovalScenario::OneLoop;
  std::vector<std::string> targets;  ///< describeCurve() of each target
  std::vector<double> pickDistances;
  std::size_t regionTets = 0, regionVertices = 0, freeVertices = 0, heldVertices = 0;
  std::size_t freeOnSurface = 0, surfaceFaces = 0;
  std::string growStop, shrinkStop, growOutStop;
  BoundaryFlow flow;
  int signConflicts = 0;
  /// Regrowths of the region away from sign conflicts of the non-repeating eigenvector (places
  /// where it repeats that no extracted curve covers), and the conflicting edges avoided.
  int conflictRegrowths = 0, conflictEdges = 0;
  /// Regrowths of the region away from faces of its boundary where the held values of the
  /// angle of §6.3 cannot lift continuously (core/edit/angle_defects.h), and those faces.
  int defectRegrowths = 0, defectFaces = 0;
  /// Retries that kept one more ring of tets away from the other curves (after a new curve or
  /// a piece of a target appeared in the region).
  int widenings = 0;
  std::vector<RemovalTry> tries;
  double seconds = 0;
  std::size_t curvesBefore = 0, curvesAfter = 0;
  /// Two-loop removal only: the info lines of step 1, the reconnection of the two loops into
  /// one (remove_two_loops.h); the other fields then describe step 2, the one-loop removal.
  std::vector<std::string> reconnection;
  /// The node's info lines: scenario and targets, region, region growth, boundary flow,
  /// tries, time, "14 curves -> 13".
  std::vector<std::string> lines() const;
};

struct RemoveCurvesResult {
  TensorField field;
  DegenerateCurves curves;      ///< of `field`, extracted with options.extract
  std::vector<int> regionTets;  ///< the final region, ascending
  RemoveCurvesReport report;
};

/// Throws RemovalRefused when no scenario applies or no ball region avoids the other curves,
/// RemovalFailed when verification failed after the retries (naming the failed check and the
/// last region size), core::Error for bad options (no pick, non-finite pick, a field without
/// curves, curves not of this field), core::Cancelled when cancelled. Never returns a field
/// that did not verify.
RemoveCurvesResult removeCurves(const TensorField& field, const RemoveCurvesOptions& options,
                                const Progress& progress = {});

}  // namespace tfd::core
