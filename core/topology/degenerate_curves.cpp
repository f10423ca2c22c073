#include "core/topology/degenerate_curves.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.h"

namespace tfd::core {
namespace {

/// Lexicographic order on coordinates quantised to `quantum`, so that rounding noise
/// (a boundary point at x = −0.99999999999999989 instead of −1) does not reorder curves.
struct LexLess {
  double quantum = 0;
  bool operator()(const Vec3& a, const Vec3& b) const {
    for (int i = 0; i < 3; ++i) {
      const double qa = quantum > 0 ? std::round(a[i] / quantum) : a[i];
      const double qb = quantum > 0 ? std::round(b[i] / quantum) : b[i];
      if (qa != qb) return qa < qb;
    }
    return false;
  }
};

void reverseCurve(DegenerateCurve& c) {
  std::reverse(c.points.begin(), c.points.end());
  std::reverse(c.patterns.begin(), c.patterns.end());
  std::reverse(c.tangents.begin(), c.tangents.end());
  for (Vec3& t : c.tangents) t = -t;
  std::reverse(c.eigenvectors.begin(), c.eigenvectors.end());
  std::reverse(c.sources.begin(), c.sources.end());
}

template <class T>
void rotateLeft(std::vector<T>& v, std::size_t k) {
  std::rotate(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
}

/// Orientation and start point that depend only on the geometry.
void canonicalise(DegenerateCurve& c, const LexLess& lexLess) {
  const std::size_t n = c.points.size();
  if (n < 2) return;
  if (!c.closed) {
    if (lexLess(c.points.back(), c.points.front())) reverseCurve(c);
    return;
  }
  std::size_t start = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (lexLess(c.points[i], c.points[start])) start = i;
  rotateLeft(c.points, start);
  rotateLeft(c.patterns, start);
  rotateLeft(c.tangents, start);
  rotateLeft(c.eigenvectors, start);
  rotateLeft(c.sources, start);
  if (n > 2 && lexLess(c.points.back(), c.points[1])) {
    reverseCurve(c);  // now ends at the old start
    rotateLeft(c.points, n - 1);
    rotateLeft(c.patterns, n - 1);
    rotateLeft(c.tangents, n - 1);
    rotateLeft(c.eigenvectors, n - 1);
    rotateLeft(c.sources, n - 1);
  }
}

}  // namespace

double DegenerateCurve::length() const {
  double total = 0;
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < segmentCount(); ++i)
    total += (points[(i + 1) % n] - points[i]).norm();
  return total;
}

DegenerateCurves::DegenerateCurves(std::vector<DegenerateCurve> curves,
                                   std::vector<std::string> warnings,
                                   ExtractionDiagnostics diagnostics)
    : curves_(std::move(curves)), warnings_(std::move(warnings)), diagnostics_(diagnostics) {
  for (std::size_t i = 0; i < curves_.size(); ++i) {
    DegenerateCurve& c = curves_[i];
    const std::size_t n = c.points.size();
    if (c.tangents.empty()) c.tangents.assign(n, Vec3::Zero());
    if (c.eigenvectors.empty()) c.eigenvectors.assign(n, Vec3::Zero());
    if (c.sources.empty()) c.sources.assign(n, PointSource{});
    if (c.patterns.size() != n || c.tangents.size() != n || c.eigenvectors.size() != n ||
        c.sources.size() != n) {
      throw Error("degenerate curve " + std::to_string(i) + ": " + std::to_string(n) +
                  " points but " + std::to_string(c.patterns.size()) + " patterns, " +
                  std::to_string(c.tangents.size()) + " tangents, " +
                  std::to_string(c.eigenvectors.size()) + " eigenvectors and " +
                  std::to_string(c.sources.size()) + " sources");
    }
  }
  // Quantum: 1e-9 of the extent of all points.
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const DegenerateCurve& c : curves_)
    for (const Vec3& p : c.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double extent = curves_.empty() ? 0 : (hi - lo).maxCoeff();
  const LexLess lexLess{std::isfinite(extent) && extent > 0 ? 1e-9 * extent : 0};
  for (DegenerateCurve& c : curves_) canonicalise(c, lexLess);
  std::stable_sort(curves_.begin(), curves_.end(),
                   [&](const DegenerateCurve& a, const DegenerateCurve& b) {
                     if (a.points.empty() || b.points.empty())
                       return a.points.size() < b.points.size();
                     if (lexLess(a.points.front(), b.points.front())) return true;
                     if (lexLess(b.points.front(), a.points.front())) return false;
                     if (lexLess(a.points.back(), b.points.back())) return true;
                     if (lexLess(b.points.back(), a.points.back())) return false;
                     return a.points.size() < b.points.size();
                   });
  for (std::size_t i = 0; i < curves_.size(); ++i) {
    const DegenerateCurve& c = curves_[i];
    curves_[i].id = int(i);
    ++statistics_.curves;
    ++(c.type == DegenerateType::Linear ? statistics_.linear : statistics_.planar);
    ++(c.closed ? statistics_.closed : statistics_.open);
    statistics_.points += int(c.points.size());
    for (DegeneratePattern p : c.patterns) {
      if (p == DegeneratePattern::Wedge)
        ++statistics_.wedgePoints;
      else if (p == DegeneratePattern::Trisector)
        ++statistics_.trisectorPoints;
      else
        ++statistics_.transitionPoints;
    }
  }
}

const DegenerateCurve& DegenerateCurves::curve(int id) const {
  if (id < 0 || id >= int(curves_.size()))
    throw Error("degenerate curve id " + std::to_string(id) + " out of range (there are " +
                std::to_string(curves_.size()) + " curves)");
  return curves_[id];
}

std::optional<CurvePick> DegenerateCurves::pick(const Vec3& p) const {
  std::optional<CurvePick> best;
  double bestDistance2 = std::numeric_limits<double>::infinity();
  for (const DegenerateCurve& c : curves_) {
    const std::size_t n = c.points.size();
    if (n == 0) continue;
    if (n == 1) {
      const double d2 = (p - c.points[0]).squaredNorm();
      if (d2 < bestDistance2) {
        bestDistance2 = d2;
        best = CurvePick{c.id, 0, 0, 0, 0, 0, c.points[0]};
      }
      continue;
    }
    double arc = 0;
    for (std::size_t i = 0; i < c.segmentCount(); ++i) {
      const Vec3& a = c.points[i];
      const Vec3& b = c.points[(i + 1) % n];
      const Vec3 d = b - a;
      const double len2 = d.squaredNorm();
      const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
      const Vec3 q = a + t * d;
      const double d2 = (p - q).squaredNorm();
      if (d2 < bestDistance2) {
        bestDistance2 = d2;
        const double len = std::sqrt(len2);
        best =
            CurvePick{c.id, int(i), t, t <= 0.5 ? int(i) : int((i + 1) % n), arc + t * len, 0, q};
      }
      arc += std::sqrt(len2);
    }
  }
  if (best) best->distance = std::sqrt(bestDistance2);
  return best;
}

std::string DegenerateCurves::summary() const {
  std::ostringstream s;
  const CurveStatistics& st = statistics_;
  s << st.curves << " degenerate curve" << (st.curves == 1 ? "" : "s") << " (" << st.linear
    << " linear, " << st.planar << " planar; " << st.closed << " loop"
    << (st.closed == 1 ? "" : "s") << "), " << st.points << " points, " << st.transitionPoints
    << " transition point" << (st.transitionPoints == 1 ? "" : "s");
  if (!warnings_.empty())
    s << ", " << warnings_.size() << " warning" << (warnings_.size() == 1 ? "" : "s");
  return s.str();
}

std::size_t DegenerateCurves::byteSize() const {
  std::size_t bytes = sizeof(*this);
  for (const DegenerateCurve& c : curves_) {
    bytes += sizeof(c) +
             c.points.size() * (3 * sizeof(Vec3) + sizeof(DegeneratePattern) + sizeof(PointSource));
  }
  for (const std::string& w : warnings_) bytes += sizeof(w) + w.size();
  return bytes;
}

}  // namespace tfd::core
