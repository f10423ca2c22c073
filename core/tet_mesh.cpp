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

namespace tfd::core {
namespace {

// Local vertex pairs of the six edges and local vertex triples of the four faces (the face
// opposite vertex i leaves out i).
constexpr int kEdgeLocal[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr int kFaceLocal[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};

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
      const auto& f = kFaceLocal[i];
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
    for (const auto& e : kEdgeLocal) repeated |= tet[e[0]] == tet[e[1]];
    if (repeated) {
      indicesOk = false;
      problems.add("tet repeating a vertex",
                   [&] { return "tet " + std::to_string(t) + " repeats a vertex"; });
      continue;
    }
    const double vol =
        signedVolume(positions[tet[0]], positions[tet[1]], positions[tet[2]], positions[tet[3]]);
    // Relative to the cube of the tet's longest edge, so the check is scale-free.
    double longest = 0;
    for (const auto& e : kEdgeLocal) {
      longest = std::max(longest, (positions[tet[e[0]]] - positions[tet[e[1]]]).norm());
    }
    if (!(vol > 1e-14 * longest * longest * longest)) {
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

TetMesh::TetMesh(std::vector<Vec3> positions, std::vector<Tet> tets)
    : positions_(std::move(positions)), tets_(std::move(tets)) {
  if (const auto problems = validate(positions_, tets_); !problems.empty()) {
    std::string message = "invalid tet mesh (" + std::to_string(positions_.size()) +
                          " vertices, " + std::to_string(tets_.size()) + " tets): ";
    for (std::size_t i = 0; i < problems.size(); ++i) {
      message += (i ? "; " : "") + problems[i];
    }
    throw Error(message);
  }
  buildTopology();
  buildBoundary();
}

TetMesh::~TetMesh() = default;

void TetMesh::buildTopology() {
  const std::size_t nt = tets_.size();
  const std::size_t nv = positions_.size();

  // Faces: sort (sorted triple, tet) records, one face per run of equal keys.
  const auto records = faceRecords(tets_);
  tetFaces_.resize(nt);
  faces_.clear();
  faceTets_.clear();
  faces_.reserve(records.size() / 2 + 1);
  faceTets_.reserve(records.size() / 2 + 1);
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (i == 0 || records[i].key != records[i - 1].key) {
      faces_.push_back(records[i].key);
      faceTets_.push_back({records[i].tet, -1});
    } else {
      faceTets_.back()[1] = records[i].tet;
    }
    tetFaces_[records[i].tet][records[i].local] = static_cast<int>(faces_.size()) - 1;
  }

  // Edges: sort 64-bit keys (low id, high id).
  std::vector<std::pair<std::uint64_t, int>> edgeRecords(nt * 6);
  tbb::parallel_for(std::size_t(0), nt, [&](std::size_t t) {
    for (int i = 0; i < 6; ++i) {
      std::uint64_t a = tets_[t][kEdgeLocal[i][0]], b = tets_[t][kEdgeLocal[i][1]];
      if (a > b) std::swap(a, b);
      edgeRecords[t * 6 + i] = {(a << 32) | b, static_cast<int>(t * 6 + i)};
    }
  });
  tbb::parallel_sort(edgeRecords.begin(), edgeRecords.end());
  tetEdges_.resize(nt);
  edges_.clear();
  for (std::size_t i = 0; i < edgeRecords.size(); ++i) {
    if (i == 0 || edgeRecords[i].first != edgeRecords[i - 1].first) {
      edges_.push_back({static_cast<int>(edgeRecords[i].first >> 32),
                        static_cast<int>(edgeRecords[i].first & 0xffffffffu)});
    }
    const int slot = edgeRecords[i].second;
    tetEdges_[slot / 6][slot % 6] = static_cast<int>(edges_.size()) - 1;
  }

  // Vertex-to-tet incidence (CSR, ascending tet ids by construction).
  vertexTetStart_.assign(nv + 1, 0);
  for (const auto& tet : tets_)
    for (int v : tet) ++vertexTetStart_[v + 1];
  for (std::size_t v = 0; v < nv; ++v) vertexTetStart_[v + 1] += vertexTetStart_[v];
  vertexTetIds_.resize(vertexTetStart_.back());
  std::vector<int> fill(vertexTetStart_.begin(), vertexTetStart_.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for (int v : tets_[t]) vertexTetIds_[fill[v]++] = static_cast<int>(t);

  // Volumes, bounds and mean edge length (deterministic reductions).
  volumes_.resize(nt);
  tbb::parallel_for(std::size_t(0), nt, [&](std::size_t t) {
    const auto& k = tets_[t];
    volumes_[t] = signedVolume(positions_[k[0]], positions_[k[1]], positions_[k[2]],
                               positions_[k[3]]);
  });
  totalVolume_ = 0;
  for (double v : volumes_) totalVolume_ += v;
  boundsMin_ = boundsMax_ = positions_[0];
  for (const auto& p : positions_) {
    boundsMin_ = boundsMin_.cwiseMin(p);
    boundsMax_ = boundsMax_.cwiseMax(p);
  }
  double lengthSum = 0;
  for (const auto& e : edges_) lengthSum += (positions_[e[0]] - positions_[e[1]]).norm();
  meanEdgeLength_ = edges_.empty() ? 0 : lengthSum / static_cast<double>(edges_.size());
}

TetMesh::Face TetMesh::orientedBoundaryFace(int face) const {
  const int t = faceTets_[face][0];
  int local = 0;
  while (tetFaces_[t][local] != face) ++local;
  const auto& tet = tets_[t];
  Face f = {tet[kFaceLocal[local][0]], tet[kFaceLocal[local][1]], tet[kFaceLocal[local][2]]};
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
    const Vec3 n =
        (positions_[o[1]] - positions_[o[0]]).cross(positions_[o[2]] - positions_[o[0]]);
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
  std::call_once(locatorOnce_, [this] { locator_ = std::make_unique<PointLocator>(*this); });
  return *locator_;
}

}  // namespace tfd::core
