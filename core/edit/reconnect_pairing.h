#pragma once
// Which endpoint joins which after a degenerate curve reconnection (paper §6.2, Lemma 6.1 and
// Theorem 6.2).
//
// In a ball region where the non-repeating eigenvector is a vector field V (it has been
// vectorised, core/edit/vectorise_eigenvector.h), each end of a curve segment where the curve
// leaves the region is incoming or outgoing, and a wedge or a trisector point. Lemma 6.1: a
// curve inside the region joins two ends in the same part (both incoming or both outgoing)
// exactly when it has an odd number of transition points, i.e. when its ends are one wedge and
// one trisector; ends in different parts have the same pattern. So two ends may be joined only
// when (same part) ≠ (same pattern), i.e. when their charges s = incoming XOR wedge differ.
// The two given segments satisfy this; each end of the first segment has exactly one end of
// the second with the other charge, which is its partner (Theorem 6.2: the reconnection is
// unique).
//
// Incoming / outgoing. The lemma's proof follows the sign of V · t along the curve, which flips
// at each transition point; so an end is classified here by the curve itself: incoming when V
// points along the curve into the region (V · t_in > 0, t_in the curve's tangent into the
// region at that end). This is the paper's picture (Fig. 11: curves crossing the boundary
// where V crosses it the same way) without depending on the angle between the curve and the
// region's boundary; the boundary face's own classification (V · inward face normal > 0) is
// kept in the report for comparison. Equivalently: the curve's canonical orientation (the
// tangent ∇α × ∇β, algorithms-notes §5.2; wedge where it agrees with V) enters the region at an
// end of charge 0 and leaves it at an end of charge 1, and the reconnection keeps it.
// So the charge is the same at every point of a segment (both the pattern and the sign of V · t
// flip at a transition point), and it is read by a vote of the segment's points weighted by
// |V · t| (reconnect_segments.h): one point next to a transition point, where V · t is near
// zero and the pattern unsure, would misclassify an end.
#include <array>
#include <span>
#include <string>

#include "core/degeneracy.h"
#include "core/tensor.h"

namespace tfd::core {

/// One end of a segment to reconnect: where the curve leaves the region.
struct ReconnectEndpoint {
  int curveId = -1;
  int segment = 0;      ///< 0 or 1: which picked segment
  int pointIndex = -1;  ///< the curve point on the region's boundary
  Vec3 position = Vec3::Zero();
  DegeneratePattern pattern = DegeneratePattern::Wedge;  ///< wedge or trisector (never transition)
  bool incoming = false;  ///< V · t_in > 0 (V points along the curve into the region)
  double alignment = 0;   ///< V · t_in, both unit
  int faceIncoming = -1;  ///< by the boundary face: 1 incoming, 0 outgoing, −1 not on a face
  /// The charge voted along the whole segment (reconnect_segments.h), −1 when not voted.
  int votedCharge = -1;
  /// Lemma 6.1's charge: incoming XOR wedge, as voted along the segment when it was (the end's
  /// own point may sit next to a transition point, where both flip). Two ends may be joined
  /// when their charges differ.
  int charge() const {
    return votedCharge >= 0 ? votedCharge
                            : int(incoming) ^ int(pattern == DegeneratePattern::Wedge);
  }
  /// Whether the end's own pattern and V · t agree with the voted charge.
  bool ownAgrees() const {
    return votedCharge < 0 ||
           votedCharge == (int(incoming) ^ int(pattern == DegeneratePattern::Wedge));
  }
};

struct ReconnectPairing {
  std::array<int, 4> partner{-1, -1, -1, -1};  ///< endpoint index → the one it joins
  /// Whether each original segment's two ends satisfy Lemma 6.1 (charges differ); when not,
  /// `problem` says which, and `partner` is left at −1.
  bool consistent = false;
  std::string problem;
};

/// Endpoints 0 and 1 are the two ends of segment 0, endpoints 2 and 3 those of segment 1.
ReconnectPairing pairEndpoints(std::span<const ReconnectEndpoint, 4> ends);

/// Whether a curve inside the region can join the two ends (Lemma 6.1).
bool lemmaAllowsJoin(const ReconnectEndpoint& a, const ReconnectEndpoint& b);

/// "A" … "D" for endpoint 0 … 3.
const char* endpointName(int index);

}  // namespace tfd::core
