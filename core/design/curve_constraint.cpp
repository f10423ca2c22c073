#include "core/design/curve_constraint.h"

#include <cmath>
#include <sstream>

#include "core/design/fixed_values.h"
#include "core/error.h"
#include "core/region/curve_tube.h"

namespace tfd::core {
namespace {

std::string format(const Vec3& p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

void checkSamples(const CurveElement& curve) {
  const std::size_t minimum = curve.closed ? 3 : 2;
  if (curve.samples.size() < minimum) {
    throw Error(std::string("a") + (curve.closed ? " closed" : "n open") +
                " curve needs at least " + std::to_string(minimum) + " samples, got " +
                std::to_string(curve.samples.size()));
  }
  if (!std::isfinite(curve.radius) || curve.radius <= 0) {
    std::ostringstream s;
    s << "the curve's tube radius must be a positive number, got " << curve.radius;
    throw Error(s.str());
  }
  for (std::size_t i = 0; i < curve.samples.size(); ++i) {
    const LocalLinearization& s = curve.samples[i];
    const double defect = (s.frame.transpose() * s.frame - Mat3::Identity()).cwiseAbs().maxCoeff();
    if (!s.origin.allFinite() || !s.frame.allFinite() || !(defect <= 1e-6) ||
        s.frame.determinant() <= 0) {
      throw Error("curve sample " + std::to_string(i) +
                  " has a non-finite position or a frame that is not a rotation");
    }
  }
}

}  // namespace

LocalLinearization interpolateLinearization(const LocalLinearization& a,
                                            const LocalLinearization& b, double t,
                                            const Vec3& origin) {
  LocalLinearization out;
  out.origin = origin;
  const Eigen::AngleAxisd relative(Mat3(a.frame.transpose() * b.frame));
  out.frame = a.frame * Eigen::AngleAxisd(t * relative.angle(), relative.axis()).toRotationMatrix();
  out.value = a.value * (1 - t) + b.value * t;
  for (int i = 0; i < 3; ++i) out.jacobian[i] = a.jacobian[i] * (1 - t) + b.jacobian[i] * t;
  return out;
}

CurveApplyReport applyCurveElement(const TetMesh& mesh, const CurveElement& curve,
                                   FixedValueAccumulator& accumulator) {
  checkSamples(curve);
  if (accumulator.vertexCount() != mesh.vertexCount()) {
    throw Error("curve constraint: the accumulator was made for another mesh");
  }
  std::vector<Vec3> polyline;
  polyline.reserve(curve.samples.size());
  for (const auto& s : curve.samples) polyline.push_back(s.origin);
  const TubeQuery tube = findTubeVertices(mesh, polyline, curve.closed, curve.radius);
  if (!tube.pointsOutside.empty()) {
    const int i = tube.pointsOutside.front();
    throw Error("curve sample " + std::to_string(i) + " at " + format(polyline[i]) +
                " lies outside the mesh (" + std::to_string(tube.pointsOutside.size()) + " of " +
                std::to_string(polyline.size()) + " samples are outside)");
  }
  if (tube.vertices.empty()) {
    std::ostringstream s;
    s << "no mesh vertex lies within the tube radius " << curve.radius
      << " of the curve (mean edge length " << mesh.meanEdgeLength() << "); increase the radius";
    throw Error(s.str());
  }
  const double epsilon = kCurveBlendEpsilon * mesh.meanEdgeLength();
  const std::size_t n = curve.samples.size();
  // Values first (independent per vertex), then the contributions in ascending vertex order.
  std::vector<Tensor> values(tube.vertices.size());
  for (std::size_t k = 0; k < tube.vertices.size(); ++k) {
    const TubeVertex& tv = tube.vertices[k];
    const LocalLinearization& a = curve.samples[tv.segment];
    const LocalLinearization& b = curve.samples[(tv.segment + 1) % n];
    const Vec3 q = (1 - tv.t) * a.origin + tv.t * b.origin;
    values[k] = interpolateLinearization(a, b, tv.t, q).evaluate(mesh.positions()[tv.vertex]);
  }
  CurveApplyReport report;
  const std::size_t claimedBefore = accumulator.claimedCount();
  for (std::size_t k = 0; k < tube.vertices.size(); ++k) {
    const TubeVertex& tv = tube.vertices[k];
    accumulator.add(tv.vertex, values[k], blendWeight(tv.distance, epsilon));
    report.maxDistance = std::max(report.maxDistance, tv.distance);
  }
  report.tubeVertices = tube.vertices.size();
  report.shared = report.tubeVertices - (accumulator.claimedCount() - claimedBefore);
  return report;
}

}  // namespace tfd::core
