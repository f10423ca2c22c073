#include "tests/support/solid_meshes.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/structured_mesh.h"

namespace tfd::test {

using core::TetMesh;
using core::Vec3;

namespace {

/// Deterministic value in [−1, 1] for an integer key (splitmix64).
double hashUnit(std::uint64_t i) {
  std::uint64_t z = i * 0x9e3779b97f4a7c15ULL + 0x632be59bd9b4e019ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

double signedVolume(const std::vector<Vec3>& p, const TetMesh::Tet& t) {
  return (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).dot(p[t[3]] - p[t[0]]);
}

/// Swaps two vertices of every tet the map turned inside out.
void orient(const std::vector<Vec3>& positions, std::vector<TetMesh::Tet>& tets) {
  for (auto& t : tets)
    if (signedVolume(positions, t) < 0) std::swap(t[2], t[3]);
}

}  // namespace

std::shared_ptr<const TetMesh> mappedBall(int n, double radius) {
  const auto box = core::makeBoxMesh(n, n, n, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  std::vector<Vec3> positions;
  positions.reserve(box->vertexCount());
  for (const Vec3& p : box->positions()) {
    const Vec3 q = p.cwiseProduct(p);
    positions.push_back(radius *
                        Vec3(p.x() * std::sqrt(1 - q.y() / 2 - q.z() / 2 + q.y() * q.z() / 3),
                             p.y() * std::sqrt(1 - q.z() / 2 - q.x() / 2 + q.z() * q.x() / 3),
                             p.z() * std::sqrt(1 - q.x() / 2 - q.y() / 2 + q.x() * q.y() / 3)));
  }
  std::vector<TetMesh::Tet> tets = box->tets();
  orient(positions, tets);
  return std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
}

std::shared_ptr<const TetMesh> mappedTorus(int nAround, int n, double major, double minor) {
  // Grid (i, j, k), i around the ring (periodic: i = nAround is i = 0), (j, k) across the tube.
  const auto box = core::makeBoxMesh(nAround, n, n, Vec3(0, -1, -1), Vec3(nAround, 1, 1));
  const int rowX = nAround + 1;
  std::vector<int> id(box->vertexCount(), -1);
  std::vector<Vec3> positions;
  for (std::size_t v = 0; v < box->vertexCount(); ++v) {
    const int i = static_cast<int>(v) % rowX;
    if (i == nAround) continue;
    const Vec3& p = box->positions()[v];
    const double s = p.y() * std::sqrt(1 - p.z() * p.z() / 2);
    const double t = p.z() * std::sqrt(1 - p.y() * p.y() / 2);
    const double angle = 2 * std::numbers::pi * i / nAround;
    const double rho = major + minor * s;
    id[v] = static_cast<int>(positions.size());
    positions.emplace_back(rho * std::cos(angle), rho * std::sin(angle), minor * t);
  }
  for (std::size_t v = 0; v < box->vertexCount(); ++v)
    if (id[v] < 0) id[v] = id[v - nAround];  // the seam: i = nAround -> i = 0
  std::vector<TetMesh::Tet> tets = box->tets();
  for (auto& t : tets)
    for (int& v : t) v = id[v];
  orient(positions, tets);
  return std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
}

std::shared_ptr<const TetMesh> carvedSolid(int n, const Vec3& lo, const Vec3& hi,
                                           const std::function<bool(const Vec3&)>& inside,
                                           double jitter) {
  const auto box = core::makeBoxMesh(n, n, n, lo, hi);
  std::vector<Vec3> moved = box->positions();
  if (jitter > 0) {
    const Vec3 cell = (hi - lo) / n;
    for (std::size_t v = 0; v < moved.size(); ++v) {
      if (box->isBoundaryVertex(static_cast<int>(v))) continue;
      for (int a = 0; a < 3; ++a) moved[v][a] += jitter * cell[a] * hashUnit(3 * v + a);
    }
  }
  std::vector<int> newId(moved.size(), -1);
  std::vector<TetMesh::Tet> tets;
  for (const auto& t : box->tets()) {
    Vec3 c = Vec3::Zero();
    for (int v : t) c += moved[v] / 4.0;
    if (!inside(c)) continue;
    tets.push_back(t);
    for (int v : t) newId[v] = 0;
  }
  std::vector<Vec3> positions;
  for (std::size_t v = 0; v < newId.size(); ++v) {
    if (newId[v] != 0) continue;
    newId[v] = static_cast<int>(positions.size());
    positions.push_back(moved[v]);
  }
  for (auto& t : tets)
    for (int& v : t) v = newId[v];
  return std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
}

std::shared_ptr<const TetMesh> coneMesh(const core::SurfaceMesh& surface, const Vec3& apex) {
  std::vector<Vec3> positions = surface.positions;
  const int centre = static_cast<int>(positions.size());
  positions.push_back(apex);
  std::vector<TetMesh::Tet> tets;
  tets.reserve(surface.triangles.size());
  // Counter-clockwise seen from outside: (apex, a, b, c) is positively oriented.
  for (const auto& t : surface.triangles) tets.push_back({centre, t[0], t[1], t[2]});
  orient(positions, tets);
  return std::make_shared<const TetMesh>(std::move(positions), std::move(tets));
}

bool insideTorus(const Vec3& p, double major, double minor) {
  const double d = std::hypot(p.x(), p.y()) - major;
  return d * d + p.z() * p.z() < minor * minor;
}

bool insideDoubleTorus(const Vec3& p, double major, double minor) {
  const Vec3 shift(major + minor / 2, 0, 0);
  return insideTorus(p - shift, major, minor) || insideTorus(p + shift, major, minor);
}

}  // namespace tfd::test
