#include "core/surface/primitives.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "core/memory_budget.h"
#include "core/surface/implicit_surface.h"
#include "core/surface/surface_remesh.h"

namespace tfd::core {
namespace {

constexpr double kPi = std::numbers::pi;

void requirePositive(double value, const char* name) {
  if (!(value > 0) || !std::isfinite(value)) {
    std::ostringstream s;
    s << "primitive: " << name << " must be a positive number, got " << value;
    throw Error(s.str());
  }
}

/// Signed distance to a torus around the z axis centred at (cx, 0, 0).
double torusDistance(const Vec3& p, double cx, double R, double r) {
  const double dx = p.x() - cx;
  const double q = std::sqrt(dx * dx + p.y() * p.y()) - R;
  return std::sqrt(q * q + p.z() * p.z()) - r;
}

/// Closest point on the torus around the z axis centred at the origin.
Vec3 projectToTorus(const Vec3& p, double R, double r) {
  const double rho = std::hypot(p.x(), p.y());
  const Vec3 ring = rho > 0 ? Vec3(R * p.x() / rho, R * p.y() / rho, 0) : Vec3(R, 0, 0);
  Vec3 d = p - ring;
  if (d.norm() == 0) d = ring;  // on the ring itself: any direction works; take radial
  return ring + r * d.normalized();
}

/// Smooth union of two tori side by side along x: the double torus' implicit function.
ImplicitFunction doubleTorusFunction(double R, double r) {
  const double c = R + r / 2, k = r / 2;
  return [=](const Vec3& p) {
    const double a = torusDistance(p, -c, R, r), b = torusDistance(p, c, R, r);
    const double h = std::max(k - std::abs(a - b), 0.0) / k;
    return std::min(a, b) - h * h * k / 4;
  };
}

Vec3 doubleTorusHalfExtent(double R, double r) { return Vec3(2 * R + 1.5 * r, R + r, r) * 1.01; }

/// Geodesic icosphere: each face split n × n, points welded by their canonical barycentric
/// key, so neighbouring faces produce bit-identical shared vertices.
SurfaceMesh geodesicSphere(double radius, int n) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  const Vec3 v[12] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  SurfaceMesh mesh;
  std::map<std::array<int, 6>, int> ids;
  auto point = [&](const int* f, int i, int j) {
    std::array<std::pair<int, int>, 3> w = {{{f[0], n - i - j}, {f[1], i}, {f[2], j}}};
    std::sort(w.begin(), w.end());
    std::array<int, 6> key{};
    int k = 0;
    for (const auto& [vertex, weight] : w) {
      if (weight > 0) key[k++] = vertex, key[k++] = weight;
    }
    for (; k < 6; ++k) key[k] = -1;
    auto [it, inserted] = ids.emplace(key, int(mesh.positions.size()));
    if (inserted) {
      Vec3 p = Vec3::Zero();
      for (const auto& [vertex, weight] : w) p += double(weight) * v[vertex];
      mesh.positions.push_back(radius * p.normalized());
    }
    return it->second;
  };
  for (const auto& f : faces) {
    for (int i = 0; i < n; ++i) {
      for (int j = 0; i + j < n; ++j) {
        mesh.triangles.push_back({point(f, i, j), point(f, i + 1, j), point(f, i, j + 1)});
        if (i + j + 2 <= n) {
          mesh.triangles.push_back(
              {point(f, i + 1, j), point(f, i + 1, j + 1), point(f, i, j + 1)});
        }
      }
    }
  }
  return mesh;
}

/// The surface mesh makePrimitive builds at `edgeLength`, estimated before building it: its
/// triangle count (from the clamped subdivision counts, or area / area of an equilateral
/// triangle of the effective edge length) and the memory that takes with the remesher's
/// working data (about 160 bytes per triangle, measured on tori of 10K to 1M triangles).
void checkSurfaceMemory(const PrimitiveSpec& spec, double edgeLength) {
  const double R = spec.majorRadius, r = spec.minorRadius;
  double triangles = 0;
  std::ostringstream what;
  what << "primitive " << primitiveShapeName(spec.shape);
  switch (spec.shape) {
    case PrimitiveShape::Sphere: {
      const double icosaEdge = spec.radius * 4 / std::sqrt(10 + 2 * std::sqrt(5.0));
      const double n = std::clamp(std::round(1.16 * icosaEdge / edgeLength), 1.0, 4000.0);
      triangles = 20 * n * n;
      what << " (radius " << spec.radius << ")";
      break;
    }
    case PrimitiveShape::Box: {
      double n[3];
      for (int i = 0; i < 3; ++i)
        n[i] = std::clamp(std::round(spec.size[i] / edgeLength), 1.0, 2e4);
      triangles = 4 * (n[0] * n[1] + n[1] * n[2] + n[2] * n[0]);
      what << " (size " << spec.size.x() << " " << spec.size.y() << " " << spec.size.z() << ")";
      break;
    }
    case PrimitiveShape::Torus:
    case PrimitiveShape::DoubleTorus: {
      const bool twin = spec.shape == PrimitiveShape::DoubleTorus;
      const double L = std::min(edgeLength, twin ? r / 2 : r);
      const double area = (twin ? 2 : 1) * 4 * kPi * kPi * R * r;
      triangles = area / (std::sqrt(3.0) / 4 * L * L);
      if (!twin) {  // the parametric grid before remeshing
        const double nu = std::clamp(std::round(2 * kPi * R / L), 6.0, 1e5);
        const double nv = std::clamp(std::round(2 * kPi * r / L), 6.0, 1e5);
        triangles = std::max(triangles, 2 * nu * nv);
      }
      what << " (major radius " << R << ", minor radius " << r << ")";
      break;
    }
  }
  what << ": its surface of about " << std::setprecision(3) << triangles
       << " triangles (edge length " << edgeLength << ")";
  checkMemory(triangles * 160, what.str());
}

/// primitiveVolume without the double torus' integration (twice the single torus' volume,
/// within a few percent): for the estimate made before anything is built.
double approximateVolume(const PrimitiveSpec& spec) {
  if (spec.shape != PrimitiveShape::DoubleTorus) return primitiveVolume(spec);
  validatePrimitive(spec);
  return 2 * (2 * kPi * kPi * spec.majorRadius * spec.minorRadius * spec.minorRadius);
}

}  // namespace

std::string primitiveShapeName(PrimitiveShape shape) {
  return primitiveShapeNames()[static_cast<int>(shape)];
}

std::vector<std::string> primitiveShapeNames() {
  return {"sphere", "box", "torus", "double_torus"};
}

void validatePrimitive(const PrimitiveSpec& spec) {
  switch (spec.shape) {
    case PrimitiveShape::Sphere:
      requirePositive(spec.radius, "radius");
      break;
    case PrimitiveShape::Box:
      requirePositive(spec.size.x(), "size x");
      requirePositive(spec.size.y(), "size y");
      requirePositive(spec.size.z(), "size z");
      break;
    case PrimitiveShape::Torus:
    case PrimitiveShape::DoubleTorus:
      requirePositive(spec.majorRadius, "major radius");
      requirePositive(spec.minorRadius, "minor radius");
      if (!(spec.minorRadius < spec.majorRadius)) {
        std::ostringstream s;
        s << "primitive: minor radius (" << spec.minorRadius
          << ") must be smaller than the major radius (" << spec.majorRadius << ")";
        throw Error(s.str());
      }
      break;
  }
}

double primitiveVolume(const PrimitiveSpec& spec) {
  validatePrimitive(spec);
  const double R = spec.majorRadius, r = spec.minorRadius;
  switch (spec.shape) {
    case PrimitiveShape::Sphere:
      return 4.0 / 3.0 * kPi * std::pow(spec.radius, 3);
    case PrimitiveShape::Box:
      return spec.size.prod();
    case PrimitiveShape::Torus:
      return 2 * kPi * kPi * R * r * r;
    case PrimitiveShape::DoubleTorus: {
      // The solid is symmetric in x, y and z and, along each vertical line, is one interval
      // |z| < zmax(x, y) (both tori's distances grow with |z|, so does their smooth minimum).
      // Integrate 2·zmax over the quarter footprint x, y > 0 by the midpoint rule, zmax by
      // bisection: about 0.1 % accurate.
      const auto f = doubleTorusFunction(R, r);
      const Vec3 half = doubleTorusHalfExtent(R, r);
      // Cells of r / 50, at most 4·10^6 of them (a thin tube gets coarser cells, not a runaway).
      const double h = std::max(r / 50, std::sqrt(half.x() * half.y() / 4e6));
      const int nx = int(std::ceil(half.x() / h)), ny = int(std::ceil(half.y() / h));
      const double hx = half.x() / nx, hy = half.y() / ny;
      std::vector<double> rows(ny, 0.0);  // per row, summed in order: thread-count independent
      tbb::parallel_for(0, ny, [&](int j) {
        double sum = 0;
        for (int i = 0; i < nx; ++i) {
          const double x = (i + 0.5) * hx, y = (j + 0.5) * hy;
          if (!(f(Vec3(x, y, 0)) < 0)) continue;
          double lo = 0, hi = half.z();
          for (int it = 0; it < 40; ++it) {
            const double mid = (lo + hi) / 2;
            (f(Vec3(x, y, mid)) < 0 ? lo : hi) = mid;
          }
          sum += lo + hi;  // 2 · zmax
        }
        rows[j] = sum;
      });
      double total = 0;
      for (double row : rows) total += row;
      return 4 * total * hx * hy;
    }
  }
  return 0;
}

SurfaceMesh makeSphere(double radius, double edgeLength) {
  requirePositive(radius, "radius");
  requirePositive(edgeLength, "edge length");
  // Mean edge of the projected n-frequency icosphere ≈ 1.16 · (icosahedron edge) / n.
  const double icosaEdge = radius * 4 / std::sqrt(10 + 2 * std::sqrt(5.0));
  const int n = std::clamp(int(std::lround(1.16 * icosaEdge / edgeLength)), 1, 4000);
  return geodesicSphere(radius, n);
}

SurfaceMesh makeBox(const Vec3& size, double edgeLength) {
  validatePrimitive({.shape = PrimitiveShape::Box, .size = size});
  requirePositive(edgeLength, "edge length");
  int n[3];
  for (int i = 0; i < 3; ++i) n[i] = std::clamp(int(std::lround(size[i] / edgeLength)), 1, 20000);
  const Vec3 lo = -size / 2;
  SurfaceMesh mesh;
  std::map<std::array<int, 3>, int> ids;  // grid index -> vertex id (surface points only)
  auto vertex = [&](std::array<int, 3> g) {
    auto [it, inserted] = ids.emplace(g, int(mesh.positions.size()));
    if (inserted) {
      Vec3 p;
      for (int i = 0; i < 3; ++i) {
        p[i] = g[i] == n[i] ? lo[i] + size[i] : lo[i] + size[i] * g[i] / n[i];
      }
      mesh.positions.push_back(p);
    }
    return it->second;
  };
  // Each face: axis a fixed at 0 or n[a]; (u, v) the other two axes in right-handed order.
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < n[u]; ++i) {
        for (int j = 0; j < n[v]; ++j) {
          std::array<int, 3> g00{}, g10{}, g11{}, g01{};
          g00[a] = g10[a] = g11[a] = g01[a] = side ? n[a] : 0;
          g00[u] = i, g00[v] = j;
          g10[u] = i + 1, g10[v] = j;
          g11[u] = i + 1, g11[v] = j + 1;
          g01[u] = i, g01[v] = j + 1;
          const int p00 = vertex(g00), p10 = vertex(g10), p11 = vertex(g11), p01 = vertex(g01);
          // u × v = +a: counter-clockwise seen from +a, i.e. outward on the far side.
          if (side) {
            mesh.triangles.push_back({p00, p10, p11});
            mesh.triangles.push_back({p00, p11, p01});
          } else {
            mesh.triangles.push_back({p00, p11, p10});
            mesh.triangles.push_back({p00, p01, p11});
          }
        }
      }
    }
  }
  return mesh;
}

SurfaceMesh makeTorus(double majorRadius, double minorRadius, double edgeLength) {
  const double R = majorRadius, r = minorRadius;
  validatePrimitive({.shape = PrimitiveShape::Torus, .majorRadius = R, .minorRadius = r});
  requirePositive(edgeLength, "edge length");
  const double L = std::min(edgeLength, r);
  const int nu = std::clamp(int(std::lround(2 * kPi * R / L)), 6, 100000);
  const int nv = std::clamp(int(std::lround(2 * kPi * r / L)), 6, 100000);
  SurfaceMesh mesh;
  for (int i = 0; i < nu; ++i) {
    const double u = 2 * kPi * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = 2 * kPi * j / nv;
      const double rho = R + r * std::cos(v);
      mesh.positions.emplace_back(rho * std::cos(u), rho * std::sin(u), r * std::sin(v));
    }
  }
  auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
  // ∂p/∂u × ∂p/∂v points away from the tube centre: (i, j) → (i+1, j) → (i+1, j+1) is outward.
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  remeshIsotropic(
      mesh, L, [=](const Vec3& p) { return projectToTorus(p, R, r); }, 6);
  return mesh;
}

SurfaceMesh makeDoubleTorus(double majorRadius, double minorRadius, double edgeLength) {
  const double R = majorRadius, r = minorRadius;
  validatePrimitive({.shape = PrimitiveShape::DoubleTorus, .majorRadius = R, .minorRadius = r});
  requirePositive(edgeLength, "edge length");
  const double L = std::min(edgeLength, r / 2);
  const auto f = doubleTorusFunction(R, r);
  const Vec3 half = doubleTorusHalfExtent(R, r) + Vec3::Constant(L);
  SurfaceMesh mesh = polygonizeImplicit(f, -half, half, 1.5 * L);
  const double h = 1e-6 * R;
  remeshIsotropic(
      mesh, L, [&](const Vec3& p) { return projectToImplicit(f, p, h); }, 8);
  return mesh;
}

SurfaceMesh makePrimitive(const PrimitiveSpec& spec, double edgeLength) {
  validatePrimitive(spec);
  requirePositive(edgeLength, "edge length");
  checkSurfaceMemory(spec, edgeLength);
  switch (spec.shape) {
    case PrimitiveShape::Sphere:
      return makeSphere(spec.radius, edgeLength);
    case PrimitiveShape::Box:
      return makeBox(spec.size, edgeLength);
    case PrimitiveShape::Torus:
      return makeTorus(spec.majorRadius, spec.minorRadius, edgeLength);
    case PrimitiveShape::DoubleTorus:
      return makeDoubleTorus(spec.majorRadius, spec.minorRadius, edgeLength);
  }
  return {};
}

double edgeLengthForTargetTets(double volume, double targetTets) {
  requirePositive(volume, "volume");
  requirePositive(targetTets, "target tet count");
  // TetGen quality meshes (q1.414, volume bound 1.8 V/N) of a surface with edge length L have
  // interior edges of about L when L³ ≈ 12 V/N (a regular tet of edge L has volume L³/8.5;
  // Delaunay meshes have many flatter tets). Calibrated for spheres, boxes and tori from 10K
  // to 1M tets, see bench/RESULTS.md.
  constexpr double kVolumeFactor = 12.0;
  return std::cbrt(kVolumeFactor * volume / targetTets);
}

SurfaceMesh makePrimitiveForTets(const PrimitiveSpec& spec, double targetTets) {
  checkSurfaceMemory(spec, edgeLengthForTargetTets(approximateVolume(spec), targetTets));
  return makePrimitive(spec, edgeLengthForTargetTets(primitiveVolume(spec), targetTets));
}

}  // namespace tfd::core
