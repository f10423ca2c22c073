#include "core/edit/deformation_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/edit/deform_paths.h"
#include "core/error.h"
#include "core/point_locator.h"
#include "core/solve/harmonic_solver.h"

namespace tfd::core {
namespace {

std::string pointText(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", p.x(), p.y(), p.z());
  return buf;
}

double signedVolume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a));
}

}  // namespace

int walkToPoint(const TetMesh& mesh, int t, const Vec3& p, Eigen::Vector4d& bary) {
  constexpr double kTolerance = 1e-12;
  const std::size_t maxSteps = 4096 + mesh.tetCount() / 16;
  for (std::size_t step = 0; step < maxSteps; ++step) {
    bary = mesh.barycentric(t, p);
    int k = 0;
    bary.minCoeff(&k);
    if (bary[k] >= -kTolerance) return t;
    // Leave through the face opposite the most negative weight (a visibility walk).
    const auto& ft = mesh.faceTets()[mesh.tetFaces()[t][k]];
    const int n = ft[0] == t ? ft[1] : ft[0];
    if (n < 0) break;  // outside, or a concavity in the way: ask the point locator
    t = n;
  }
  if (const auto loc = mesh.locator().locate(p)) {  // rare: a walk blocked by a concavity
    bary = loc->barycentric;
    return loc->tet;
  }
  bary = bary.cwiseMax(0.0);
  bary /= bary.sum();
  return -1 - t;  // outside: −1 − (the last tet of the walk)
}

std::vector<int> polylineTets(const TetMesh& mesh, std::span<const Vec3> poly, int startTet,
                              double step) {
  std::vector<int> tets;
  Eigen::Vector4d bary;
  int t = startTet;
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    const double len = (poly[i + 1] - poly[i]).norm();
    const int n = std::max(1, int(std::ceil(len / step)));
    for (int k = 0; k <= n; ++k) {
      const Vec3 p = poly[i] + (poly[i + 1] - poly[i]) * (double(k) / n);
      const int found = walkToPoint(mesh, t, p, bary);
      if (found < 0) throw Error("target: the point " + pointText(p) + " is outside the mesh");
      t = found;
      tets.push_back(t);
      // A point on a face, edge or vertex lies in every tet around it: take them all.
      for (int j = 0; j < 4; ++j)
        if (bary[j] < 1e-9) {
          const int f = mesh.tetFaces()[t][j];
          for (int n2 : mesh.faceTets()[f])
            if (n2 >= 0) tets.push_back(n2);
        }
    }
  }
  std::sort(tets.begin(), tets.end());
  tets.erase(std::unique(tets.begin(), tets.end()), tets.end());
  return tets;
}

DeformedField deformField(const TensorField& field, std::span<const int> regionTets,
                          const RegionVertices& rv, std::span<const int> envelopeTets,
                          const std::vector<char>& thick, const std::vector<char>& anchor,
                          std::span<const Vec3> gamma1, std::span<const Vec3> gamma2,
                          const Progress& progress) {
  const TetMesh& mesh = field.mesh();
  const auto& pos = mesh.positions();
  DeformedField r;
  // φ as positions, identity everywhere to start with.
  std::vector<double> phi(3 * mesh.vertexCount());
  for (int v : rv.vertices)
    for (int c = 0; c < 3; ++c) phi[3 * v + c] = pos[v][c];
  enum Role : unsigned char { Outside, Identity, Envelope, Solved };
  std::vector<unsigned char> role(mesh.vertexCount(), Outside);
  for (int v : rv.vertices) role[v] = Identity;
  for (int t : envelopeTets)
    for (int v : mesh.tets()[t]) role[v] = Envelope;
  std::vector<int> solveSet;
  for (int v : rv.free) {
    if (role[v] == Envelope) continue;
    if (anchor[v] || mesh.isBoundaryVertex(v)) continue;  // held at the identity
    if (thick[v]) {
      role[v] = Envelope;
      continue;
    }
    role[v] = Solved;
    solveSet.push_back(v);
  }
  for (int v : rv.vertices) {
    if (role[v] == Envelope) {
      // φ(v) = q + (v − p) for p the closest point of γ2 and q its partner on γ1.
      int seg = 0;
      double t = 0;
      distanceToPolyline(pos[v], gamma2, &seg, &t);
      const Vec3 p = (1 - t) * gamma2[seg] + t * gamma2[seg + 1];
      const Vec3 q = (1 - t) * gamma1[seg] + t * gamma1[seg + 1];
      const Vec3 image = q + (pos[v] - p);
      for (int c = 0; c < 3; ++c) phi[3 * v + c] = image[c];
      r.movedVertices.push_back(v);
      ++r.envelopeVertices;
    } else if (role[v] == Solved) {
      r.movedVertices.push_back(v);
    }
  }
  r.solvedVertices = solveSet.size();
  r.identityVertices = rv.vertices.size() - r.envelopeVertices - r.solvedVertices;
  if (!solveSet.empty()) {
    const HarmonicSolver solver = HarmonicSolver::forRegion(field.meshPtr(), solveSet);
    r.iterations = solver.solveColumns(phi, 3, progress);
  }
  auto image = [&](int v) { return Vec3(phi[3 * v], phi[3 * v + 1], phi[3 * v + 2]); };
  // Fold-overs: tets of M whose image is inverted or flat (the mesh's tets are positive).
  std::vector<char> onCurve(mesh.tetCount(), 0);
  for (int t : envelopeTets) onCurve[t] = 1;
  for (int t : regionTets) {
    const auto& k = mesh.tets()[t];
    if (signedVolume6(image(k[0]), image(k[1]), image(k[2]), image(k[3])) <= 0) {
      ++r.foldOvers;
      r.foldOversOnCurve += onCurve[t];
    }
  }
  // Interpolation: the new tensor at v is the old field at φ(v).
  r.values = field.values();
  std::vector<char> outside(r.movedVertices.size(), 0);
  tbb::parallel_for(std::size_t(0), r.movedVertices.size(), [&](std::size_t i) {
    const int v = r.movedVertices[i];
    Eigen::Vector4d bary;
    int t = walkToPoint(mesh, mesh.vertexTets(v)[0], image(v), bary);
    if (t < 0) t = -1 - t, outside[i] = 1;
    r.values[v] = field.interpolate(t, bary);
  });
  for (char o : outside) r.outsidePreimages += o;
  return r;
}

}  // namespace tfd::core
