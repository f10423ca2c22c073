#include "render/scene.h"

namespace tfd::render {

void LineSet::add(const Vec3& a, const Vec3& b, Rgba ca, Rgba cb) {
  for (const Vec3* p : {&a, &b})
    for (int i = 0; i < 3; ++i) positions.push_back(static_cast<float>((*p)[i]));
  colours.push_back(ca);
  colours.push_back(cb);
}

void PointSet::add(const Vec3& p, Rgba c) {
  for (int i = 0; i < 3; ++i) positions.push_back(static_cast<float>(p[i]));
  colours.push_back(c);
}

}  // namespace tfd::render
