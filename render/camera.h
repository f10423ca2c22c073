#pragma once
// An orbit camera (z up): a target point, a distance, yaw about z and pitch above the xy plane,
// a vertical field of view. Orbit, pan, zoom and frame, the iso/x/y/z presets of `tfd render`,
// projection of points to pixels and rays through pixels (pixel y grows downwards).
#include <Eigen/Dense>

#include <optional>
#include <string_view>

namespace tfd::render {

using Vec3 = Eigen::Vector3d;
using Mat4 = Eigen::Matrix4d;

struct Bounds {
  Vec3 min = Vec3::Constant(1e300), max = Vec3::Constant(-1e300);
  bool valid() const { return min.x() <= max.x(); }
  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const Bounds& b) {
    if (b.valid()) extend(b.min), extend(b.max);
  }
  Vec3 center() const { return valid() ? Vec3(0.5 * (min + max)) : Vec3::Zero(); }
  double radius() const { return valid() ? 0.5 * (max - min).norm() : 1.0; }
};

/// iso: from (+x, −y, +z) at 35° elevation; x, y, z: looking down that axis from its positive side.
enum class ViewPreset { Iso, X, Y, Z };
std::optional<ViewPreset> parseViewPreset(std::string_view name);

struct Ray {
  Vec3 origin, direction;  ///< direction is unit
};

class Camera {
 public:
  Vec3 target = Vec3::Zero();
  double distance = 4;
  double yaw = -0.7853981633974483;   ///< radians about z; 0 looks from +x
  double pitch = 0.6154797086703874;  ///< radians above the xy plane, in [−π/2, π/2]
  double fovY = 0.6108652381980153;   ///< 35° vertical field of view
  double sceneRadius = 1;             ///< sets the near and far planes

  Vec3 eye() const;
  /// Unit vectors of the view: towards the eye from the target, right, up.
  Vec3 backward() const;
  Vec3 right() const;
  Vec3 up() const;
  Mat4 view() const;
  Mat4 projection(double aspect) const;

  /// Mouse drags in pixels: orbit (about the target), pan (in the view plane), zoom (factor > 1
  /// moves closer).
  void orbit(double dxPixels, double dyPixels);
  void pan(double dxPixels, double dyPixels, int viewportHeight);
  void zoom(double factor);
  /// Looks at the bounds' centre from the nearest distance at which all eight corners of the
  /// box fit in the view (with a margin), for the current direction and this aspect ratio.
  void frame(const Bounds& bounds, double aspect = 4.0 / 3.0);
  void setPreset(ViewPreset preset);

  /// Pixel position (x right, y down) and depth in [0, 1] of a world point; nothing when it is
  /// behind the eye.
  std::optional<Eigen::Vector3d> project(const Vec3& p, int width, int height) const;
  Ray rayThrough(double px, double py, int width, int height) const;
};

}  // namespace tfd::render
