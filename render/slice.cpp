// The cutting plane: the mesh cut by an axis-aligned plane, each cut polygon coloured by a
// quantity of the field interpolated linearly along the cut tet edges (the field is P1).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "render/colormap.h"
#include "render/scene_builder.h"

namespace tfd::render {

namespace {

std::vector<double> vertexQuantity(const core::TensorField& field, SliceQuantity q) {
  const auto& values = field.values();
  std::vector<double> out(values.size());
  tbb::parallel_for(std::size_t(0), values.size(), [&](std::size_t v) {
    switch (q) {
      case SliceQuantity::Mode:
        out[v] = core::mode(values[v]);
        break;
      // Scaled to [0, 1] (the discriminant of a unit deviator is at most 1/2), then a square
      // root to spread the small values near the curves.
      case SliceQuantity::Degeneracy:
        out[v] = std::sqrt(std::clamp(2 * core::normalizedDiscriminant(values[v]), 0.0, 1.0));
        break;
      case SliceQuantity::Norm:
        out[v] = values[v].norm();
        break;
    }
  });
  if (q == SliceQuantity::Norm) {
    const double top = *std::max_element(out.begin(), out.end());
    if (top > 0)
      for (double& x : out) x /= top;
  }
  return out;
}

Rgba colourOf(SliceQuantity q, double value) {
  return q == SliceQuantity::Mode ? coolWarm(value) : sequential(value);
}

}  // namespace

void addSlice(Scene& scene, const core::TensorField& field, const SliceSettings& s) {
  const core::TetMesh& mesh = field.mesh();
  const int axis = std::clamp(s.axis, 0, 2);
  const double lo = mesh.boundsMin()[axis], hi = mesh.boundsMax()[axis];
  // Keep the plane off the exact extremes so it cuts something.
  const double at = lo + std::clamp(s.position, 1e-6, 1 - 1e-6) * (hi - lo);
  const std::vector<double> q = vertexQuantity(field, s.quantity);
  ColouredTriangles& out = scene.slice;
  for (const auto& tet : mesh.tets()) {
    double d[4];
    int above = 0;
    for (int i = 0; i < 4; ++i) above += (d[i] = mesh.positions()[tet[i]][axis] - at) > 0;
    if (above == 0 || above == 4) continue;
    // Cut points on the edges whose ends lie on opposite sides, in cyclic order around the
    // polygon: walk the edges (i, j) with i above, j below, ordered so neighbours share a face.
    Vec3 p[4];
    double value[4];
    int n = 0;
    auto cut = [&](int i, int j) {
      const double t = d[i] / (d[i] - d[j]);
      p[n] = (1 - t) * mesh.positions()[tet[i]] + t * mesh.positions()[tet[j]];
      value[n] = (1 - t) * q[tet[i]] + t * q[tet[j]];
      ++n;
    };
    int up[4], down[4], nu = 0, nd = 0;
    for (int i = 0; i < 4; ++i) (d[i] > 0 ? up[nu++] : down[nd++]) = i;
    if (nu == 1 || nd == 1) {
      const int lone = nu == 1 ? up[0] : down[0];
      const int* others = nu == 1 ? down : up;
      for (int k = 0; k < 3; ++k) cut(lone, others[k]);
    } else {  // two and two: the quad a0-b0, a0-b1, a1-b1, a1-b0
      cut(up[0], down[0]);
      cut(up[0], down[1]);
      cut(up[1], down[1]);
      cut(up[1], down[0]);
    }
    for (int k = 1; k + 1 < n; ++k)
      for (int idx : {0, k, k + 1}) {
        for (int c = 0; c < 3; ++c) out.positions.push_back(static_cast<float>(p[idx][c]));
        out.colours.push_back(colourOf(s.quantity, value[idx]));
      }
  }
}

}  // namespace tfd::render
