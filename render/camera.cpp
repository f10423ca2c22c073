#include "render/camera.h"

#include <algorithm>
#include <cmath>

namespace tfd::render {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::optional<ViewPreset> parseViewPreset(std::string_view name) {
  if (name == "iso") return ViewPreset::Iso;
  if (name == "x") return ViewPreset::X;
  if (name == "y") return ViewPreset::Y;
  if (name == "z") return ViewPreset::Z;
  return std::nullopt;
}

Vec3 Camera::backward() const {
  return {std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
}
Vec3 Camera::right() const { return {-std::sin(yaw), std::cos(yaw), 0}; }
Vec3 Camera::up() const { return backward().cross(right()).normalized(); }
Vec3 Camera::eye() const { return target + distance * backward(); }

Mat4 Camera::view() const {
  const Vec3 b = backward(), r = right(), u = up(), e = eye();
  Mat4 m = Mat4::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = b.transpose();
  m(0, 3) = -r.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = -b.dot(e);
  return m;
}

Mat4 Camera::projection(double aspect) const {
  const double zNear = std::max(1e-4 * sceneRadius, distance - 3 * sceneRadius);
  const double zFar = distance + 3 * sceneRadius;
  const double f = 1.0 / std::tan(fovY / 2);
  Mat4 p = Mat4::Zero();
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (zFar + zNear) / (zNear - zFar);
  p(2, 3) = 2 * zFar * zNear / (zNear - zFar);
  p(3, 2) = -1;
  return p;
}

void Camera::orbit(double dx, double dy) {
  yaw -= dx * 0.008;
  pitch = std::clamp(pitch + dy * 0.008, -kPi / 2, kPi / 2);
}

void Camera::pan(double dx, double dy, int viewportHeight) {
  const double perPixel = 2 * distance * std::tan(fovY / 2) / std::max(1, viewportHeight);
  target += (-dx * right() + dy * up()) * perPixel;
}

void Camera::zoom(double factor) {
  distance = std::clamp(distance / factor, 1e-3 * sceneRadius, 100 * sceneRadius);
}

void Camera::frame(const Bounds& bounds, double aspect) {
  target = bounds.center();
  sceneRadius = std::max(1e-9, bounds.radius());
  const double ty = std::tan(fovY / 2) * 0.9, tx = ty * std::max(0.1, aspect);
  double d = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec3 c(k & 1 ? bounds.max.x() : bounds.min.x(), k & 2 ? bounds.max.y() : bounds.min.y(),
                 k & 4 ? bounds.max.z() : bounds.min.z());
    const Vec3 r = c - target;
    const double z = r.dot(backward());
    d = std::max({d, z + std::abs(r.dot(right())) / tx, z + std::abs(r.dot(up())) / ty});
  }
  distance = std::max(d, 1e-3 * sceneRadius);
}

void Camera::setPreset(ViewPreset preset) {
  switch (preset) {
    case ViewPreset::Iso:
      yaw = -kPi / 4, pitch = std::atan(1 / std::sqrt(2.0));
      break;
    case ViewPreset::X:
      yaw = 0, pitch = 0;
      break;
    case ViewPreset::Y:
      yaw = kPi / 2, pitch = 0;
      break;
    case ViewPreset::Z:
      yaw = -kPi / 2, pitch = kPi / 2;
      break;
  }
}

std::optional<Eigen::Vector3d> Camera::project(const Vec3& p, int width, int height) const {
  const Eigen::Vector4d clip = projection(double(width) / std::max(1, height)) * view() *
                               Eigen::Vector4d(p.x(), p.y(), p.z(), 1);
  if (clip.w() <= 1e-12) return std::nullopt;
  const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
  return Eigen::Vector3d((ndc.x() + 1) * 0.5 * width, (1 - ndc.y()) * 0.5 * height,
                         (ndc.z() + 1) * 0.5);
}

Ray Camera::rayThrough(double px, double py, int width, int height) const {
  const double aspect = double(width) / std::max(1, height);
  const double t = std::tan(fovY / 2);
  const double x = (2 * px / width - 1) * t * aspect;
  const double y = (1 - 2 * py / height) * t;
  return {eye(), (x * right() + y * up() - backward()).normalized()};
}

}  // namespace tfd::render
