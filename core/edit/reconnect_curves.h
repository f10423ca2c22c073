#pragma once
// Degenerate curve reconnection (paper §6.2), verified by re-extraction.
//
// Steps: extract the field's curves; name the two curves by the picked points (they may be the
// same curve, e.g. a loop to break in two; both of one L/P type); the segment of each around
// its pick (`segmentLength` of curve, half on each side) seeds the region, and every tet
// around another curve, or around the picked curves farther than the segments (plus a margin
// of three mean edge lengths, where the region's boundary cuts them; seeds excepted), and
// around an open picked curve's ends on the domain surface, is forbidden
// (edit_driver.h); grow a ball region out to `regionDistance` (core/region/ball_region.h) and
// check it independently (its vertices on the domain surface are held like those on its
// boundary inside the volume: a new curve must not end on the surface); the segments run through it
// to where the curves leave it: their four ends (reconnect_segments.h). Step 2: vectorise the
// non-repeating eigenvector and classify the ends; the pairing follows from Lemma 6.1 / Theorem 6.2
// (reconnect_pairing.h). Step 3: paths between the paired ends, the nearest-path partition and the
// thickened sheet (reconnect_sheet.h, graph distance). Steps 4–5: singularity-free field on the
// sheet, harmonic re-solve of the rest of the region (reconnect_field.h). Verification
// (reconnect_verification.h): outside unchanged; inside, exactly two new curves, joining the ends
// as paired. A failed try retries with the distance grown by `growFactor`, at most `retries` times
// (edit_driver.h); when none verified, the same tries run with segments 0.6 and then 1.5 times
// as long (the report's segmentLength is the one that verified).
#include <array>
#include <string>
#include <vector>

#include "core/edit/boundary_flow.h"
#include "core/edit/reconnect_pairing.h"
#include "core/edit/singularity_free_field.h"
#include "core/progress.h"
#include "core/tensor_field.h"
#include "core/topology/extract_degenerate_curves.h"

namespace tfd::core {

struct ReconnectCurvesOptions {
  std::vector<Vec3> picks;  ///< two points, one on each segment (may be one curve)
  /// Length of curve around each pick that seeds the region; negative: the distance between
  /// the picked points (at least four mean edge lengths).
  double segmentLength = -1;
  /// Grow-out distance of the region; negative: 30 % of the mesh's bounding radius (the paper).
  double regionDistance = -1;
  int retries = 2;          ///< extra tries with a larger region after a failed try
  double growFactor = 1.5;  ///< distance multiplier per retry
  /// The field's curves when the caller has them (the picks name what the user sees); they
  /// must belong to the field. Null: the extraction below.
  const DegenerateCurves* curves = nullptr;
  /// The field's own curves, extracted with `extract`, when the caller has just extracted them
  /// (the two-loop removal between its steps): the edit then skips its first extraction. Not
  /// checked; null: the edit extracts.
  const DegenerateCurves* extracted = nullptr;
  ExtractOptions extract;  ///< settings of the extraction before and after (the same)
};

/// No try verified (the reconnection itself could be set up).
class ReconnectionFailed : public Error {
 public:
  using Error::Error;
};

struct ReconnectTry {
  double distance = 0;
  double segmentLength = 0;  ///< of the segments this try used
  std::size_t regionTets = 0, sheetTets = 0;
  std::string failedCheck, detail;  ///< empty when it passed
};

struct ReconnectCurvesReport {
  std::array<std::string, 2> curves;  ///< describeCurve() of each picked curve
  std::array<double, 2> pickDistances{0, 0};
  double segmentLength = 0;
  /// The four ends where the segments leave the final region (0, 1: segment 1; 2, 3: segment
  /// 2), classified, and the pairing of Theorem 6.2: partner[i] is the end i joins.
  std::array<ReconnectEndpoint, 4> ends;
  std::array<int, 4> partner{-1, -1, -1, -1};
  std::size_t regionTets = 0, regionVertices = 0, freeVertices = 0, heldVertices = 0;
  std::string growStop, shrinkStop, growOutStop;
  BoundaryFlow flow;
  std::array<std::size_t, 2> pathVertices{0, 0};
  std::array<double, 2> pathLengths{0, 0};
  bool pathsAdjusted = false;  ///< the second path was rerouted around the first
  std::size_t sheetTets = 0, sheetVertices = 0, sheetSolved = 0, sidesSolved = 0;
  SingularityFreeReport sheetField;
  std::array<std::string, 2> newCurves;  ///< describeCurve() of the curves through the region
  std::vector<ReconnectTry> tries;
  /// Why the asked segment length had no valid setup (it reached a curve's end on the domain
  /// surface, or another curve), when a shorter or longer one was used instead; else empty.
  std::string askedSegmentProblem;
  double seconds = 0;
  std::size_t curvesBefore = 0, curvesAfter = 0;
  /// The node's info lines: curves, ends and pairing, region, sheet, tries, time, topology.
  std::vector<std::string> lines() const;
};

struct ReconnectCurvesResult {
  TensorField field;
  DegenerateCurves curves;      ///< of `field`, extracted with options.extract
  std::vector<int> regionTets;  ///< the final region, ascending
  ReconnectCurvesReport report;
};

/// Throws core::Error for bad options (naming `picks`, `segment_length`, `retries`…), curves of
/// different L/P types, or when no ball region holds both segments without another curve;
/// ReconnectionFailed when no try verified (naming the failed check and the last region size);
/// core::Cancelled when cancelled. Never returns a field that did not verify.
ReconnectCurvesResult reconnectCurves(const TensorField& field,
                                      const ReconnectCurvesOptions& options,
                                      const Progress& progress = {});

}  // namespace tfd::core
