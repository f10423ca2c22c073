// Standalone measurement, not part of the build: Gmsh's parallel HXT tetrahedraliser
// (Mesh.Algorithm3D = 10) against TetGen (io::tetrahedralize) on the surfaces of
// bench/tetgen_bench.cpp (unit sphere at 150K and 1M target tets) and examples/pebble.obj.
// Reports per surface and mesher: tets, tets / target, wall time, minimum dihedral angle,
// share of tets under 10°, radius-edge ratio (circumradius / shortest edge: max and 99th
// percentile). Build and run by hand (Debian libgmsh-dev 4.8), see bench/RESULTS.md, "Gmsh HXT".
// Two programs from this file: -DUSE_HXT links Gmsh, without it TetGen. Gmsh carries its own
// TetGen-derived code whose symbols clash with Debian's libtet: one process cannot hold both
// (TetGen crashes).
#ifdef USE_HXT
#include <gmsh.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/surface/primitives.h"
#include "io/mesh/surface_readers.h"
#ifndef USE_HXT
#include "io/tetgen/tetgen_mesher.h"
#endif

namespace {

using tfd::core::Vec3;
/// Gmsh's Mesh.MeshSizeMax relative to the surface's mean edge length (1: sizes from the surface).
double sizeFactor = 1;
using Tet = std::array<int, 4>;

struct Quality {
  double minDihedral = 180, under10 = 0, maxRadiusEdge = 0, p99RadiusEdge = 0;
};

Quality quality(const std::vector<Vec3>& p, const std::vector<Tet>& tets) {
  Quality q;
  std::vector<double> ratios(tets.size());
  std::size_t small = 0;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Vec3 a = p[tets[t][0]], b = p[tets[t][1]], c = p[tets[t][2]], d = p[tets[t][3]];
    const Vec3 v[4] = {a, b, c, d};
    // Face normals (outward or all inward: the angle between two faces is π − angle(n_i, n_j)).
    Vec3 n[4];
    for (int i = 0; i < 4; ++i) {
      const Vec3 &x = v[(i + 1) % 4], &y = v[(i + 2) % 4], &z = v[(i + 3) % 4];
      n[i] = (y - x).cross(z - x).normalized();
      if (n[i].dot(v[i] - x) > 0) n[i] = -n[i];  // outward
    }
    double tetMin = 180;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        tetMin =
            std::min(tetMin, 180 - std::acos(std::clamp(n[i].dot(n[j]), -1.0, 1.0)) * 180 / M_PI);
    q.minDihedral = std::min(q.minDihedral, tetMin);
    small += tetMin < 10;
    // Circumradius: |Σ| / (12 V) formula via the circumcentre solve.
    Eigen::Matrix3d m;
    m.row(0) = b - a;
    m.row(1) = c - a;
    m.row(2) = d - a;
    const Eigen::Vector3d rhs(0.5 * (b - a).squaredNorm(), 0.5 * (c - a).squaredNorm(),
                              0.5 * (d - a).squaredNorm());
    const double r = m.fullPivLu().solve(rhs).norm();
    double shortest = 1e300;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) shortest = std::min(shortest, (v[i] - v[j]).norm());
    ratios[t] = r / shortest;
  }
  std::sort(ratios.begin(), ratios.end());
  q.maxRadiusEdge = ratios.back();
  q.p99RadiusEdge = ratios[ratios.size() * 99 / 100];
  q.under10 = double(small) / double(tets.size());
  return q;
}

void print(const char* surface, const char* mesher, double target, std::size_t tets, double seconds,
           const Quality& q) {
  std::printf("| %s | %s | %zu | %.3f | %.2f | %.2f | %.4f %% | %.2f | %.3f |\n", surface, mesher,
              tets, double(tets) / target, seconds, q.minDihedral, 100 * q.under10, q.maxRadiusEdge,
              q.p99RadiusEdge);
  std::fflush(stdout);
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

void measure(const char* name, const tfd::core::SurfaceMesh& surface, double target, int threads) {
#ifndef USE_HXT
  (void)threads;
  // TetGen (single-threaded), the project's settings.
  {
    tfd::io::TetgenOptions options;
    options.targetTets = target;
    const auto t0 = std::chrono::steady_clock::now();
    const auto mesh = tfd::io::tetrahedralize(surface, options);
    const double s = seconds(t0);
    print(name, "TetGen", target, mesh->tetCount(), s, quality(mesh->positions(), mesh->tets()));
  }
#else
  // HXT on the same triangles: a discrete surface, one volume, sizes from the boundary.
  gmsh::model::add(name);
  const int s = gmsh::model::addDiscreteEntity(2);
  std::vector<std::size_t> nodeTags(surface.positions.size());
  std::vector<double> coords;
  for (std::size_t i = 0; i < surface.positions.size(); ++i) {
    nodeTags[i] = i + 1;
    for (int a = 0; a < 3; ++a) coords.push_back(surface.positions[i][a]);
  }
  gmsh::model::mesh::addNodes(2, s, nodeTags, coords);
  std::vector<std::size_t> triTags, triNodes;
  for (std::size_t i = 0; i < surface.triangles.size(); ++i) {
    triTags.push_back(i + 1);
    for (int k : surface.triangles[i]) triNodes.push_back(std::size_t(k) + 1);
  }
  gmsh::model::mesh::addElementsByType(s, 2, triTags, triNodes);
  const int loop = gmsh::model::geo::addSurfaceLoop({s});
  gmsh::model::geo::addVolume({loop});
  gmsh::model::geo::synchronize();
  gmsh::option::setNumber("Mesh.Algorithm3D", 10);
  gmsh::option::setNumber("General.NumThreads", threads);
  gmsh::option::setNumber("Mesh.Optimize", 1);
  // Count control: interior sizes at most sizeFactor × the surface's mean edge length.
  double edgeSum = 0;
  for (const auto& t : surface.triangles)
    for (int k = 0; k < 3; ++k)
      edgeSum += (surface.positions[t[k]] - surface.positions[t[(k + 1) % 3]]).norm();
  const double meanEdge = edgeSum / (3.0 * double(surface.triangles.size()));
  gmsh::option::setNumber("Mesh.MeshSizeMax", sizeFactor * meanEdge);
  const auto t0 = std::chrono::steady_clock::now();
  gmsh::model::mesh::generate(3);
  const double sec = seconds(t0);
  std::vector<std::size_t> all;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(all, xyz, param);
  std::size_t maxTag = 0;
  for (auto t : all) maxTag = std::max(maxTag, t);
  std::vector<Vec3> p(maxTag + 1, Vec3::Zero());
  for (std::size_t i = 0; i < all.size(); ++i)
    p[all[i]] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  std::vector<std::size_t> tetTags, tetNodes;
  gmsh::model::mesh::getElementsByType(4, tetTags, tetNodes);
  std::vector<Tet> tets(tetTags.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) tets[t][k] = int(tetNodes[4 * t + k]);
  char label[64];
  std::snprintf(label, sizeof label, "HXT, %d threads, size factor %.2f", threads, sizeFactor);
  print(name, label, target, tets.size(), sec, quality(p, tets));
  gmsh::model::remove();
#endif
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = argc > 1 ? std::atoi(argv[1]) : 2;
  const std::string pebble = argc > 2 ? argv[2] : "examples/pebble.obj";
  if (argc > 3) sizeFactor = std::atof(argv[3]);
#ifdef USE_HXT
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
#endif
  std::printf(
      "| surface | mesher | tets | tets/target | wall s | min dihedral ° | tets < 10° | max "
      "radius-edge | 99th pct radius-edge |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (double target : {150'000.0, 1'000'000.0}) {
    const auto sphere = tfd::core::makePrimitiveForTets(tfd::core::PrimitiveSpec{}, target);
    measure(target < 5e5 ? "sphere 150K" : "sphere 1M", sphere, target, threads);
  }
  measure("pebble.obj", tfd::io::readObj(pebble), 80'000, threads);
#ifdef USE_HXT
  gmsh::finalize();
#endif
}
