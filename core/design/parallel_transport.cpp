#include "core/design/parallel_transport.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace tfd::core {
namespace {

Mat3 cross(const Vec3& w) {
  Mat3 m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

Vec3 defaultNormal(const Vec3& t) {
  int axis = 0;
  t.cwiseAbs().minCoeff(&axis);
  const Vec3 e = Vec3::Unit(axis);
  return (e - e.dot(t) * t).normalized();
}

}  // namespace

Mat3 transportRotation(const Vec3& a, const Vec3& b) {
  const Vec3 w = a.cross(b);
  const double c = a.dot(b);
  if (!(1 + c > 1e-12)) {
    throw Error("parallel transport: the tangent turns back by 180 degrees");
  }
  const Mat3 k = cross(w);
  return Mat3::Identity() + k + k * k / (1 + c);
}

double signedAngle(const Vec3& x, const Vec3& y, const Vec3& n) {
  return std::atan2(x.cross(y).dot(n), x.dot(y));
}

BishopFrames bishopFrames(std::span<const Vec3> tangents, bool closed,
                          const BishopOptions& options) {
  const std::size_t n = tangents.size();
  if (n == 0) throw Error("parallel transport: no tangents");
  if (closed && n < 2) throw Error("parallel transport: a closed curve needs two tangents");
  std::vector<Vec3> t(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double len = tangents[i].norm();
    if (!std::isfinite(len) || len == 0) {
      throw Error("parallel transport: tangent " + std::to_string(i) + " is zero or not finite");
    }
    t[i] = tangents[i] / len;
  }
  const auto transport = [&](std::size_t from, std::size_t to, const Vec3& u) -> Vec3 {
    try {
      return transportRotation(t[from], t[to]) * u;
    } catch (const Error&) {
      throw Error("parallel transport: the curve turns back by 180 degrees between points " +
                  std::to_string(from) + " and " + std::to_string(to) + " (use a smaller spacing)");
    }
  };

  Vec3 u0 = options.initialNormal - options.initialNormal.dot(t[0]) * t[0];
  u0 = u0.norm() > 1e-9 * std::max(1.0, options.initialNormal.norm()) ? u0.normalized()
                                                                      : defaultNormal(t[0]);
  std::vector<Vec3> u(n);
  u[0] = u0;
  for (std::size_t i = 1; i < n; ++i) {
    Vec3 next = transport(i - 1, i, u[i - 1]);
    // Re-orthonormalise against rounding drift (a no-op to ~1e-16 per step).
    next -= next.dot(t[i]) * t[i];
    u[i] = next.normalized();
  }
  BishopFrames out;
  if (closed) {
    const Vec3 back = transport(n - 1, 0, u[n - 1]);
    out.holonomy = signedAngle(u0, back - back.dot(t[0]) * t[0], t[0]);
    if (options.distributeHolonomy) {
      std::vector<double> s = options.arcLength;
      if (s.empty()) {
        for (std::size_t i = 0; i <= n; ++i) s.push_back(double(i));
      }
      if (s.size() != n + 1 || !(s[n] > s[0])) {
        throw Error("parallel transport: a closed curve of " + std::to_string(n) +
                    " points needs " + std::to_string(n + 1) + " arc-length values, got " +
                    std::to_string(options.arcLength.size()));
      }
      const double total = s[n] - s[0];
      for (std::size_t i = 1; i < n; ++i) {
        const double angle = -out.holonomy * (s[i] - s[0]) / total;
        u[i] = Eigen::AngleAxisd(angle, t[i]) * u[i];
      }
    }
  }
  out.frames.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.frames[i].col(0) = t[i];
    out.frames[i].col(1) = u[i];
    out.frames[i].col(2) = t[i].cross(u[i]);
  }
  return out;
}

}  // namespace tfd::core
