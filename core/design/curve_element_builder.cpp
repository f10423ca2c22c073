#include "core/design/curve_element_builder.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "core/design/parallel_transport.h"
#include "core/design/spline.h"
#include "core/error.h"

namespace tfd::core {
namespace {

/// Full 3x3 local Jacobian term from a 2x2 block on the degenerate plane (local x, y).
Tensor fromBlock(const Eigen::Matrix2d& b) { return Tensor{b(0, 0), b(1, 1), 0, b(0, 1), 0, 0}; }

void checkBlocks(const PatternBlocks& blocks) {
  for (const auto& [name, m] : {std::pair{"Tx", &blocks.tx}, std::pair{"Ty", &blocks.ty}}) {
    if (!m->allFinite()) {
      throw Error(std::string("pattern: the 2x2 block of ") + name + " is not finite");
    }
    if (std::abs((*m)(0, 1) - (*m)(1, 0)) > 1e-12 * std::max(1.0, m->cwiseAbs().maxCoeff())) {
      throw Error(std::string("pattern: the 2x2 block of ") + name + " must be symmetric");
    }
  }
  const double scale =
      std::max({blocks.tx.cwiseAbs().maxCoeff(), blocks.ty.cwiseAbs().maxCoeff(), 1e-300});
  if (std::abs(patternDelta(blocks)) <= 1e-9 * scale * scale) {
    throw Error(
        "pattern: the custom 2x2 blocks give neither a wedge nor a trisector (their 2-D index "
        "determinant is zero)");
  }
}

std::string withoutPrefix(std::string message) {
  constexpr std::string_view prefix = "curve: ";
  if (message.starts_with(prefix)) message.erase(0, prefix.size());
  return message;
}

}  // namespace

PatternBlocks defaultPatternBlocks(DegeneratePattern pattern) {
  if (pattern == DegeneratePattern::Transition)
    throw Error("degenerate curve element: the pattern must be wedge or trisector");
  PatternBlocks b;
  b.tx << 1, 0, 0, -1;
  const double s = pattern == DegeneratePattern::Wedge ? 1 : -1;
  b.ty << 0, s, s, 0;
  return b;
}

double patternDelta(const PatternBlocks& blocks) {
  const double ax = 0.5 * (blocks.tx(0, 0) - blocks.tx(1, 1));
  const double ay = 0.5 * (blocks.ty(0, 0) - blocks.ty(1, 1));
  const double bx = blocks.tx(0, 1), by = blocks.ty(0, 1);
  return ax * by - ay * bx;
}

CurveElement buildCurveElement(const CurveOptions& options, CurveBuildReport* report) {
  if (!std::isfinite(options.radius) || options.radius <= 0) {
    std::ostringstream s;
    s << "radius: must be a positive number, got " << options.radius;
    throw Error(s.str());
  }
  if (!std::isfinite(options.spacing) || options.spacing <= 0) {
    std::ostringstream s;
    s << "spacing: must be a positive number, got " << options.spacing;
    throw Error(s.str());
  }
  if (options.kind == CurveKind::Tensor && !options.eigenvalues.allFinite()) {
    throw Error("eigenvalues: not finite");
  }
  if (options.customPattern) checkBlocks(*options.customPattern);
  std::optional<Spline> spline;
  try {
    spline.emplace(options.points, options.closed);
  } catch (const Error& e) {
    throw Error("points: " + withoutPrefix(e.what()));
  }
  CurveSamples samples;
  try {
    samples = spline->sample(options.spacing);
  } catch (const Error& e) {
    throw Error("spacing: " + withoutPrefix(e.what()));
  }
  BishopOptions bishop;
  bishop.arcLength = samples.arcLength;
  const BishopFrames frames = bishopFrames(samples.tangents, samples.closed, bishop);
  const Mat3 user = rotationFromEulerDegrees(options.rotation);

  CurveElement curve;
  curve.closed = samples.closed;
  curve.degenerate = options.kind == CurveKind::Degenerate;
  curve.radius = options.radius;
  curve.samples.reserve(samples.positions.size());
  for (std::size_t i = 0; i < samples.positions.size(); ++i) {
    const Mat3& f = frames.frames[i];  // (t, u, v)
    Mat3 frame;
    frame << f.col(1), f.col(2), f.col(0);  // (u, v, t): the tangent is the local z axis
    frame = frame * user;
    if (options.kind == CurveKind::Tensor) {
      curve.samples.push_back(
          makeTensorLinearization(samples.positions[i], frame, options.eigenvalues));
    } else {
      LocalLinearization s =
          makeDegenerateLinearization(samples.positions[i], frame, options.type, options.pattern);
      if (options.customPattern) {
        s.jacobian[0] = fromBlock(options.customPattern->tx);
        s.jacobian[1] = fromBlock(options.customPattern->ty);
        s.jacobian[2] = Tensor{};
      }
      // Canonical tube coordinates: the pattern is given per tube radius (see the header).
      for (Tensor& j : s.jacobian) j *= 1.0 / options.radius;
      curve.samples.push_back(s);
    }
  }
  if (report) {
    report->samples = curve.samples.size();
    report->length = samples.length;
    report->spacing = samples.spacing;
    report->holonomyDegrees = frames.holonomy * 180 / std::numbers::pi;
  }
  return curve;
}

}  // namespace tfd::core
