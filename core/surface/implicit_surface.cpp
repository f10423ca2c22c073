#include "core/surface/implicit_surface.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/error.h"

namespace tfd::core {
namespace {

// Six tets of the Kuhn split of a cube; corners numbered by bits (x = 1, y = 2, z = 4). Each
// tet walks from corner 0 to corner 7 along one permutation of the axes.
constexpr int kKuhnTets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                 {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

Vec3 gradient(const ImplicitFunction& f, const Vec3& p, double h) {
  Vec3 g;
  for (int i = 0; i < 3; ++i) {
    Vec3 a = p, b = p;
    a[i] += h;
    b[i] -= h;
    g[i] = (f(a) - f(b)) / (2 * h);
  }
  return g;
}

}  // namespace

Vec3 projectToImplicit(const ImplicitFunction& f, const Vec3& p, double h, int iterations) {
  Vec3 x = p;
  double fx = f(x);
  for (int it = 0; it < iterations && fx != 0; ++it) {
    const Vec3 g = gradient(f, x, h);
    const double g2 = g.squaredNorm();
    if (!(g2 > 0)) break;
    const Vec3 y = x - fx * g / g2;
    const double fy = f(y);
    if (!(std::abs(fy) < std::abs(fx))) break;
    x = y;
    fx = fy;
  }
  return x;
}

SurfaceMesh polygonizeImplicit(const ImplicitFunction& f, const Vec3& lo, const Vec3& hi,
                               double cell) {
  if (!(cell > 0)) throw Error("polygonizeImplicit: cell size must be positive");
  int n[3];
  double step[3];
  for (int i = 0; i < 3; ++i) {
    n[i] = std::max(1, int(std::ceil((hi[i] - lo[i]) / cell)));
    step[i] = (hi[i] - lo[i]) / n[i];
  }
  const long nx = n[0] + 1, ny = n[1] + 1, nz = n[2] + 1;
  if (nx * ny * nz > 200'000'000L) throw Error("polygonizeImplicit: grid too fine");
  auto gridId = [&](long i, long j, long k) { return i + nx * (j + ny * k); };
  auto gridPoint = [&](long id) {
    const long i = id % nx, j = (id / nx) % ny, k = id / (nx * ny);
    return Vec3(lo[0] + i * step[0], lo[1] + j * step[1], lo[2] + k * step[2]);
  };
  std::vector<double> value(nx * ny * nz);
  tbb::parallel_for(long(0), long(value.size()), [&](long id) {
    const double v = f(gridPoint(id));
    value[id] = v == 0 ? std::numeric_limits<double>::min() : v;  // zero counts as outside
  });

  SurfaceMesh mesh;
  std::unordered_map<long long, int> edgeVertex;
  const long long total = nx * ny * nz;
  auto crossing = [&](long a, long b) {
    if (a > b) std::swap(a, b);
    const long long key = a * total + b;
    auto [it, inserted] = edgeVertex.emplace(key, int(mesh.positions.size()));
    if (inserted) {
      // Secant start, refined by a few steps of regula falsi along the grid edge.
      Vec3 pa = gridPoint(a), pb = gridPoint(b);
      double fa = value[a], fb = value[b];
      Vec3 x = pa;
      for (int it = 0; it < 4; ++it) {
        const double t = fa / (fa - fb);
        x = pa + t * (pb - pa);
        const double fx = f(x);
        if (fx == 0) break;
        if ((fx < 0) == (fa < 0)) {
          pa = x;
          fa = fx;
        } else {
          pb = x;
          fb = fx;
        }
      }
      mesh.positions.push_back(x);
    }
    return it->second;
  };
  auto addTriangle = [&](int p, int q, int r, const Vec3& inside, const Vec3& outside) {
    const Vec3& a = mesh.positions[p];
    const Vec3 normal = (mesh.positions[q] - a).cross(mesh.positions[r] - a);
    if (normal.dot(outside - inside) >= 0) {
      mesh.triangles.push_back({p, q, r});
    } else {
      mesh.triangles.push_back({p, r, q});
    }
  };

  for (long k = 0; k < n[2]; ++k) {
    for (long j = 0; j < n[1]; ++j) {
      for (long i = 0; i < n[0]; ++i) {
        long corner[8];
        for (int c = 0; c < 8; ++c) corner[c] = gridId(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2));
        for (const auto& tet : kKuhnTets) {
          long in[4], out[4];
          int ni = 0, no = 0;
          for (int c : tet) {
            const long id = corner[c];
            if (value[id] < 0) {
              in[ni++] = id;
            } else {
              out[no++] = id;
            }
          }
          if (ni == 0 || no == 0) continue;
          Vec3 inC = Vec3::Zero(), outC = Vec3::Zero();
          for (int a = 0; a < ni; ++a) inC += gridPoint(in[a]) / ni;
          for (int a = 0; a < no; ++a) outC += gridPoint(out[a]) / no;
          if (ni == 1 || no == 1) {
            const long lone = ni == 1 ? in[0] : out[0];
            const long* others = ni == 1 ? out : in;
            // One crossing per statement: as arguments of one call their order (so the
            // vertices' numbering, so the remeshed surface) would be the compiler's choice.
            // This is the order GCC chose when they were arguments, so meshes stay the same.
            const int c2 = crossing(lone, others[2]);
            const int c1 = crossing(lone, others[1]);
            const int c0 = crossing(lone, others[0]);
            addTriangle(c0, c1, c2, inC, outC);
          } else {
            // Quad through the four crossing edges, in cyclic order.
            const int p0 = crossing(in[0], out[0]), p1 = crossing(in[0], out[1]);
            const int p2 = crossing(in[1], out[1]), p3 = crossing(in[1], out[0]);
            addTriangle(p0, p1, p2, inC, outC);
            addTriangle(p0, p2, p3, inC, outC);
          }
        }
      }
    }
  }
  return mesh;
}

}  // namespace tfd::core
