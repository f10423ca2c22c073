#include "core/edit/remove_two_loops.h"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <limits>
#include <optional>

#include "core/edit/edit_driver.h"
#include "core/edit/reconnect_curves.h"

namespace tfd::core {

RemoveCurvesResult removeTwoLoops(const TensorField& field, const RemoveCurvesOptions& o,
                                  const DegenerateCurves& all, const DegenerateCurve& a,
                                  const DegenerateCurve& b, RemoveCurvesReport report,
                                  const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  // Step 1: reconnect where the loops come closest.
  std::size_t ia = 0, ib = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.points.size(); ++i)
    for (std::size_t j = 0; j < b.points.size(); ++j)
      if (const double d = (a.points[i] - b.points[j]).squaredNorm(); d < best)
        best = d, ia = i, ib = j;
  ReconnectCurvesOptions ro;
  ro.picks = {a.points[ia], b.points[ib]};
  ro.regionDistance = o.regionDistance;
  ro.retries = o.retries;
  ro.growFactor = o.growFactor;
  ro.extract = o.extract;
  ro.extracted = &all;
  const std::string step1 = "two-loop removal, step 1 (reconnecting the loops into one): ";
  std::optional<ReconnectCurvesResult> joined;
  try {
    joined = reconnectCurves(field, ro, progress);
  } catch (const Cancelled&) {
    throw;
  } catch (const ReconnectionFailed& e) {
    throw RemovalFailed(step1 + e.what());
  } catch (const Error& e) {
    throw RemovalRefused(step1 + e.what());
  }
  if (joined->curves.size() + 1 != report.curvesBefore)
    throw RemovalFailed(step1 + "the loops did not merge (" + std::to_string(report.curvesBefore) +
                        " curves -> " + std::to_string(joined->curves.size()) + ")");
  // Step 2: remove the merged loop, named by the point of the first loop farthest along it
  // from the reconnection.
  RemoveCurvesOptions lo = o;
  lo.picks = {a.points[(ia + a.points.size() / 2) % a.points.size()]};
  lo.curves = &joined->curves;
  lo.extracted = &joined->curves;  // extracted from joined->field with o.extract
  const std::string step2 = "two-loop removal, step 2 (removing the merged loop): ";
  std::optional<RemoveCurvesResult> removed;
  try {
    removed = removeCurves(joined->field, lo, progress);
  } catch (const Cancelled&) {
    throw;
  } catch (const RemovalFailed& e) {
    throw RemovalFailed(step2 + e.what());
  } catch (const Error& e) {
    throw RemovalRefused(step2 + e.what());
  }
  if (removed->report.scenario != RemovalScenario::OneLoop)
    throw RemovalFailed(step2 + "the merged curve was not a mixed loop");
  RemoveCurvesResult r = std::move(*removed);
  const std::size_t curvesBefore = report.curvesBefore;
  const RemovalScenario scenario = report.scenario;
  auto targets = std::move(report.targets);
  auto distances = std::move(report.pickDistances);
  report = std::move(r.report);
  report.scenario = scenario, report.targets = std::move(targets);
  report.pickDistances = std::move(distances);
  report.curvesBefore = curvesBefore;
  report.reconnection = joined->report.lines();
  report.seconds = secondsSince(start);
  r.report = std::move(report);
  std::vector<int> region;
  std::set_union(joined->regionTets.begin(), joined->regionTets.end(), r.regionTets.begin(),
                 r.regionTets.end(), std::back_inserter(region));
  r.regionTets = std::move(region);
  return r;
}

}  // namespace tfd::core
