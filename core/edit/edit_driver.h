#pragma once
// What every region edit of §6 shares (RemoveCurves §6.4, DeformCurve §6.1, ReconnectCurves
// §6.2): naming a curve by a picked point, the tets around curves, the tets the region may not
// take (those around every curve the edit does not target), and the try / verify / retry loop:
// a try grows a ball region out to a distance, edits and verifies by re-extraction; a failed
// try retries with the distance grown by a factor, a bounded number of times, and stops early
// when the region did not grow; after the last failure the edit throws, naming the failed check
// and the last region size. Nothing here knows an edit's maths.
#include <chrono>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "core/tet_mesh.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

/// "%.3g" of x, for messages and info lines.
std::string editNumber(double x);

/// The last info lines of every edit: "time 0.12 s" and "14 curves -> 13".
void addEditClosingLines(std::vector<std::string>& out, double seconds, std::size_t curvesBefore,
                         std::size_t curvesAfter);

/// The tets holding the curve's points' sources (with repeats).
std::vector<int> curveSourceTets(const TetMesh& mesh, const DegenerateCurve& curve);

/// `tets` and every tet around one of their vertices; ascending, unique.
std::vector<int> withNeighbourTets(const TetMesh& mesh, std::span<const int> tets);

/// The curve of the field (`all`) nearest to `point`: picked among `given` when the caller has
/// the field's curves (so the pick names what the user sees) and mapped to the same curve of
/// `all`; `distance` is from `point` to the picked curve. Throws core::Error when `given` is
/// empty or does not belong to the field. `point` must be finite and `all` not empty.
CurvePick resolveCurvePick(const TetMesh& mesh, const DegenerateCurves& all,
                           const DegenerateCurves* given, const Vec3& point);

/// Tets an edit's region may not take: those holding a point of a curve not targeted, and every
/// tet around their vertices (then no vertex of such a curve's tets is a region vertex, and
/// neither are their neighbours' values, which the extraction's fallback perturbation looks
/// at). `owner[t]` names the curve (the lowest id when several); −1 where not forbidden.
struct ForbiddenTets {
  std::vector<unsigned char> flag;
  std::vector<int> owner;
  void add(int tet, int who) {
    if (!flag[tet]) flag[tet] = 1, owner[tet] = who;
  }
};
ForbiddenTets forbidOtherCurves(const TetMesh& mesh, const DegenerateCurves& all,
                                std::span<const int> targetIds);

/// The tries of an edit: the first distance (negative `regionDistance`: 30 % of the mesh's
/// bounding radius, the paper's default), the factor and the number of retries. Throws
/// core::Error unless retries ≥ 0, growFactor > 1 and regionDistance finite.
struct EditRetries {
  double distance0 = 0, growFactor = 1.5;
  int retries = 0;
};
EditRetries editRetries(const TetMesh& mesh, double regionDistance, int retries, double growFactor);

/// What one try of an edit came to: verified (stop), failed (record it and retry with a larger
/// region), again (the try changed what the region may take and runs once more at the same
/// distance, unrecorded), or final (failed in a way no larger region changes: record it, no
/// retry).
enum class TryOutcome { Verified, Failed, Again, Final };

/// Runs tries k = 0, 1, … ≤ retries: each gets a fresh `Try` record (a struct with `distance`,
/// `regionTets`, `failedCheck` and `detail`) with its distance set, and `attempt(k, record)`
/// builds the region, edits and verifies. Recorded tries go to `tries`. Returns whether a try
/// verified; stops early after a Final try or when a failed try's region is no larger than the
/// one before.
template <class Try, class Attempt>
bool runEditTries(const EditRetries& plan, std::vector<Try>& tries, const Progress& progress,
                  Attempt&& attempt) {
  for (int k = 0; k <= plan.retries; ++k) {
    Try t;
    t.distance = plan.distance0 * std::pow(plan.growFactor, k);
    progress.report(0.1 + 0.8 * k / (plan.retries + 1), "growing the region");
    const TryOutcome outcome = attempt(k, t);
    if (outcome == TryOutcome::Again) {
      --k;
      continue;
    }
    tries.push_back(std::move(t));
    if (outcome == TryOutcome::Verified) return true;
    if (outcome == TryOutcome::Final) break;
    if (k > 0 && tries[k - 1].regionTets == tries[k].regionTets) break;  // cannot grow
  }
  return false;
}

/// "; #1 distance 0.3, 1200 tets: verified; #2 …": the tries of a report's info line.
template <class Try>
std::string describeTries(const std::vector<Try>& tries) {
  std::string t;
  for (std::size_t i = 0; i < tries.size(); ++i)
    t +=
        "; #" + std::to_string(i + 1) + " distance " + editNumber(tries[i].distance) + ", " +
        std::to_string(tries[i].regionTets) + " tets: " +
        (tries[i].failedCheck.empty() ? std::string("verified")
                                      : tries[i].failedCheck + " failed (" + tries[i].detail + ")");
  return t;
}

/// The edit's final error after every try failed: "<what> failed after N tries: check '…'
/// failed (…); last region … tets (distance …); try 1 (…): …".
template <class Failure, class Try>
[[noreturn]] void failAfterTries(const std::string& what, const std::vector<Try>& tries) {
  const Try& last = tries.back();
  std::string earlier;
  for (std::size_t i = 0; i + 1 < tries.size(); ++i)
    earlier += "; try " + std::to_string(i + 1) + " (" + std::to_string(tries[i].regionTets) +
               " tets): " + tries[i].failedCheck + " (" + tries[i].detail + ")";
  throw Failure(what + " failed after " + std::to_string(tries.size()) +
                (tries.size() == 1 ? " try" : " tries") + ": check '" + last.failedCheck +
                "' failed (" + last.detail + "); last region " + std::to_string(last.regionTets) +
                " tets (distance " + editNumber(last.distance) + ")" + earlier);
}

/// Seconds since `start`.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace tfd::core
