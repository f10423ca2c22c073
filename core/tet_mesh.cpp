#include "core/tet_mesh.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/point_locator.h"
#include "core/tet_mesh_local.h"

namespace tfd::core {
namespace {

using tet_local::kEdge;
using tet_local::kFace;

struct FaceRecord {
  std::array<int, 3> key;  // sorted vertex ids
  int tet;
  int local;  // index of the opposite vertex in the tet
  bool operator<(const FaceRecord& o) const {
    if (key != o.key) return key < o.key;
    return tet < o.tet;
  }
};

std::array<int, 3> sortedTriple(int a, int b, int c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

std::vector<FaceRecord> faceRecords(const std::vector<TetMesh::Tet>& tets) {
  std::vector<FaceRecord> records(tets.size() * 4);
  tbb::parallel_for(std::size_t(0), tets.size(), [&](std::size_t t) {
    for (int i = 0; i < 4; ++i) {
      const auto& f = kFace[i];
      records[t * 4 + i] = {sortedTriple(tets[t][f[0]], tets[t][f[1]], tets[t][f[2]]),
                            static_cast<int>(t), i};
    }
  });
  tbb::parallel_sort(records.begin(), records.end());
  return records;
}

/// Reports problems as sentences; counts beyond `maxReported` are summarised.
class ProblemList {
 public:
  explicit ProblemList(int maxReported) : max_(maxReported) {}
  template <class Fn>
  void add(const std::string& kind, Fn&& describe) {
    auto& count = counts_[kind];
    if (count++ < max_) problems_.push_back(describe());
  }
  std::vector<std::string> finish() {
    for (const auto& [kind, count] : counts_) {
      if (count > max_) {
        problems_.push_back(std::to_string(count - max_) + " more: " + kind);
      }
    }
    return std::move(problems_);
  }

 private:
  int max_;
  std::vector<std::string> problems_;
  std::map<std::string, int> counts_;
};

}  // namespace

std::vector<std::string> TetMesh::validate(const std::vector<Vec3>& positions,
                                           const std::vector<Tet>& tets, int maxReported) {
  ProblemList problems(maxReported);
  const int n = static_cast<int>(positions.size());
  if (tets.empty()) return {"the mesh has no tetrahedra"};
  for (int v = 0; v < n; ++v) {
    if (!positions[v].allFinite()) {
      problems.add("non-finite vertex coordinates",
                   [&] { return "vertex " + std::to_string(v) + " has a non-finite coordinate"; });
    }
  }
  std::vector<unsigned char> used(n, 0);
  bool indicesOk = true;
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const auto& tet = tets[t];
    bool inRange = true;
    for (int i = 0; i < 4; ++i) {
      if (tet[i] < 0 || tet[i] >= n) {
        inRange = indicesOk = false;
        problems.add("vertex index out of range", [&] {
          return "tet " + std::to_string(t) + " uses vertex " + std::to_string(tet[i]) +
                 ", out of range [0, " + std::to_string(n) + ")";
        });
      }
    }
    if (!inRange) continue;
    for (int i = 0; i < 4; ++i) used[tet[i]] = 1;
    bool repeated = false;
    for (const auto& e : kEdge) repeated |= tet[e[0]] == tet[e[1]];
    if (repeated) {
      indicesOk = false;
      problems.add("tet repeating a vertex",
                   [&] { return "tet " + std::to_string(t) + " repeats a vertex"; });
      continue;
    }
    double vol = 0;
    const bool volumeOk = tet_local::volumeOk(positions, tet, vol);
    if (!volumeOk) {
      const bool inverted = vol < 0;
      problems.add(inverted ? "inverted tets" : "zero-volume tets", [&] {
        std::ostringstream s;
        s << "tet " << t << (inverted ? " is inverted (signed volume " : " has zero volume (")
          << vol << ")";
        return s.str();
      });
    }
  }
  for (int v = 0; v < n; ++v) {
    if (!used[v]) {
      problems.add("vertices used by no tet",
                   [&] { return "vertex " + std::to_string(v) + " is used by no tet"; });
    }
  }
  if (indicesOk) {
    const auto records = faceRecords(tets);
    for (std::size_t i = 0; i + 2 < records.size(); ++i) {
      if (records[i].key == records[i + 2].key &&
          (i == 0 || records[i - 1].key != records[i].key)) {
        const auto& k = records[i].key;
        problems.add("non-manifold faces", [&] {
          return "face (" + std::to_string(k[0]) + ", " + std::to_string(k[1]) + ", " +
                 std::to_string(k[2]) + ") is shared by more than two tets (non-manifold)";
        });
      }
    }
  }
  return problems.finish();
}

TetMesh::TetMesh(std::vector<Vec3> positions, std::vector<Tet> tets, const Progress& progress)
    : positions_(std::move(positions)), tets_(std::move(tets)) {
  // The fast checks cover everything validate() reports; only a mesh that fails one pays for
  // validate() itself, which then words every problem.
  if (!quickCheckAndVolumes() || !buildIncidence(progress) || !buildEdgesAndFaces(progress))
    throwInvalid();
  progress.throwIfCancelled();
  buildSummaries();
  buildBoundary();
}

TetMesh::~TetMesh() = default;

void TetMesh::throwInvalid() const {
  const auto problems = validate(positions_, tets_);
  std::string message = "invalid tet mesh (" + std::to_string(positions_.size()) + " vertices, " +
                        std::to_string(tets_.size()) + " tets): ";
  for (std::size_t i = 0; i < problems.size(); ++i) message += (i ? "; " : "") + problems[i];
  if (problems.empty()) message += "inconsistent topology";
  throw Error(message);
}

TetMesh::Face TetMesh::orientedBoundaryFace(int face) const {
  const int t = faceTets_[face][0];
  int local = 0;
  while (tetFaces_[t][local] != face) ++local;
  const auto& tet = tets_[t];
  Face f = {tet[kFace[local][0]], tet[kFace[local][1]], tet[kFace[local][2]]};
  const Vec3 n = (positions_[f[1]] - positions_[f[0]]).cross(positions_[f[2]] - positions_[f[0]]);
  if (n.dot(positions_[tet[local]] - positions_[f[0]]) > 0) std::swap(f[1], f[2]);
  return f;
}

void TetMesh::buildBoundary() {
  boundaryFaces_.clear();
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    if (faceTets_[f][1] < 0) boundaryFaces_.push_back(static_cast<int>(f));
  }
  isBoundary_.assign(positions_.size(), 0);
  vertexNormals_.assign(positions_.size(), Vec3::Zero());
  for (int f : boundaryFaces_) {
    const Face o = orientedBoundaryFace(f);
    // The cross product's length is twice the area: an area-weighted sum.
    const Vec3 n = (positions_[o[1]] - positions_[o[0]]).cross(positions_[o[2]] - positions_[o[0]]);
    for (int v : o) {
      isBoundary_[v] = 1;
      vertexNormals_[v] += n;
    }
  }
  boundaryVertices_.clear();
  for (std::size_t v = 0; v < positions_.size(); ++v) {
    if (!isBoundary_[v]) continue;
    boundaryVertices_.push_back(static_cast<int>(v));
    const double len = vertexNormals_[v].norm();
    if (len > 0) vertexNormals_[v] /= len;
  }
}

Eigen::Vector4d TetMesh::barycentric(int t, const Vec3& p) const {
  const auto& k = tets_[t];
  const Vec3& a = positions_[k[0]];
  Mat3 m;
  m.col(0) = positions_[k[1]] - a;
  m.col(1) = positions_[k[2]] - a;
  m.col(2) = positions_[k[3]] - a;
  const Vec3 w = m.inverse() * (p - a);
  return {1 - w.sum(), w[0], w[1], w[2]};
}

const PointLocator& TetMesh::locator() const {
  std::call_once(locatorOnce_, [this] {
    locator_ = std::make_unique<PointLocator>(*this);
    locatorBuilt_.store(true, std::memory_order_release);
  });
  return *locator_;
}

}  // namespace tfd::core
