// TEMP stub (branch `remove`) of branch `sffield`'s two functions, for testing the removal
// machinery until that branch lands: sign propagation by breadth-first search, and a harmonic
// re-solve of the free vertices in place of the §6.3 angle-based field. Drop with its commit.
#include <algorithm>
#include <queue>

#include "core/edit/singularity_free_field.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/error.h"
#include "core/solve/harmonic_solver.h"

namespace tfd::core {

VectorisedEigenvector vectoriseEigenvector(const TensorField& field,
                                           const std::vector<int>& regionTets,
                                           DegenerateType type) {
  const TetMesh& mesh = field.mesh();
  VectorisedEigenvector r;
  for (int t : regionTets)
    for (int v : mesh.tets()[t]) r.vertices.push_back(v);
  std::sort(r.vertices.begin(), r.vertices.end());
  r.vertices.erase(std::unique(r.vertices.begin(), r.vertices.end()), r.vertices.end());
  if (r.vertices.empty()) throw Error("vectorise: empty region");
  std::vector<int> index(mesh.vertexCount(), -1);
  for (std::size_t i = 0; i < r.vertices.size(); ++i) index[r.vertices[i]] = int(i);
  const int column = type == DegenerateType::Linear ? 0 : 2;
  std::vector<Vec3> raw(r.vertices.size());
  for (std::size_t i = 0; i < raw.size(); ++i)
    raw[i] = eigenDecompose(field.at(r.vertices[i])).vectors.col(column);
  std::vector<std::vector<int>> adj(r.vertices.size());
  for (int t : regionTets)
    for (int e : mesh.tetEdges()[t]) {
      const auto& ed = mesh.edges()[e];
      adj[index[ed[0]]].push_back(index[ed[1]]);
      adj[index[ed[1]]].push_back(index[ed[0]]);
    }
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  std::vector<char> done(raw.size(), 0);
  std::queue<int> q;
  q.push(0), done[0] = 1;
  std::size_t seen = 1;
  while (!q.empty()) {
    const int i = q.front();
    q.pop();
    for (int j : adj[i]) {
      if (done[j]) continue;
      if (raw[j].dot(raw[i]) < 0) raw[j] = -raw[j];
      done[j] = 1, ++seen;
      q.push(j);
    }
  }
  if (seen != raw.size()) throw Error("vectorise: the region is not connected");
  for (std::size_t i = 0; i < adj.size(); ++i)
    for (int j : adj[i]) r.signConflicts += int(i) < j && raw[i].dot(raw[j]) < 0;
  r.directions = std::move(raw);
  return r;
}

TensorField singularityFreeField(const TensorField& field, const std::vector<int>& regionTets,
                                 const std::vector<char>& held, DegenerateType,
                                 Progress& progress) {
  const TetMesh& mesh = field.mesh();
  std::vector<int> free;
  for (int t : regionTets)
    for (int v : mesh.tets()[t])
      if (!held[v]) free.push_back(v);
  std::sort(free.begin(), free.end());
  free.erase(std::unique(free.begin(), free.end()), free.end());
  if (free.empty()) return field;
  SolverOptions o;
  o.tolerance = 1e-10;
  const HarmonicSolver solver = HarmonicSolver::forRegion(field.meshPtr(), free, o);
  SolveResult s = solver.solve(field.values(), progress);
  return TensorField(field.meshPtr(), std::move(s.values));
}

}  // namespace tfd::core
