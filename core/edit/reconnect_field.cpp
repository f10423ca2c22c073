#include "core/edit/reconnect_field.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/solve/harmonic_solver.h"

namespace tfd::core {
namespace {

/// The sheet's tets as a mesh of their own (vertices renumbered in ascending mesh order).
std::shared_ptr<const TetMesh> sheetMesh(const TetMesh& mesh, const std::vector<int>& tets,
                                         std::vector<int>& vertices) {
  for (int t : tets)
    for (int v : mesh.tets()[t]) vertices.push_back(v);
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  auto local = [&](int v) {
    return int(std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
  };
  std::vector<Vec3> positions;
  positions.reserve(vertices.size());
  for (int v : vertices) positions.push_back(mesh.positions()[v]);
  std::vector<TetMesh::Tet> localTets;
  localTets.reserve(tets.size());
  for (int t : tets) {
    const auto& q = mesh.tets()[t];
    localTets.push_back({local(q[0]), local(q[1]), local(q[2]), local(q[3])});
  }
  return std::make_shared<const TetMesh>(std::move(positions), std::move(localTets));
}

}  // namespace

TensorField reconnectField(const TensorField& field, const std::vector<int>& sheetTets,
                           const RegionVertices& rv, DegenerateType type, const Progress& progress,
                           ReconnectFieldReport& report) {
  const TetMesh& mesh = field.mesh();
  // Step 4: the sheet.
  std::vector<int> sheetVertices;
  const auto local = sheetMesh(mesh, sheetTets, sheetVertices);
  std::vector<Tensor> localValues;
  std::vector<char> localHeld(sheetVertices.size(), 0);
  for (std::size_t i = 0; i < sheetVertices.size(); ++i) {
    localValues.push_back(field.at(sheetVertices[i]));
    localHeld[i] = rv.held[sheetVertices[i]];
  }
  std::vector<int> all(local->tetCount());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = int(t);
  const TensorField sheetField = singularityFreeField(
      TensorField(local, std::move(localValues)), all, localHeld, type, progress, &report.sheet);
  std::vector<Tensor> values = field.values();
  std::vector<char> onSheet(mesh.vertexCount(), 0);
  report.sheetVertices = sheetVertices.size();
  report.sheetSolved = 0;
  for (std::size_t i = 0; i < sheetVertices.size(); ++i) {
    const int v = sheetVertices[i];
    onSheet[v] = 1;
    if (rv.held[v]) continue;
    values[v] = sheetField.at(int(i));
    ++report.sheetSolved;
  }
  // Step 5: the rest of the region, harmonic with the sheet and the region's boundary held.
  std::vector<int> free;
  for (int v : rv.free)
    if (!onSheet[v]) free.push_back(v);
  report.sidesSolved = free.size();
  if (free.empty()) return TensorField(field.meshPtr(), std::move(values));
  double maxTrace = 0, maxNorm = 0;
  for (int v : rv.vertices) {
    maxTrace = std::max(maxTrace, std::abs(values[v].trace()));
    maxNorm = std::max(maxNorm, values[v].norm());
  }
  const bool hasTrace = traceBeyondRounding(maxTrace, maxNorm);
  const HarmonicSolver solver = HarmonicSolver::forRegion(field.meshPtr(), free);
  SolveResult solved = hasTrace ? solver.solveWithTrace(std::move(values), progress)
                                : solver.solve(std::move(values), progress);
  report.iterations = solved.iterations, report.relativeResidual = solved.relativeResidual;
  return TensorField(field.meshPtr(), std::move(solved.values));
}

}  // namespace tfd::core
