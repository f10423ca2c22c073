#pragma once
// Tetrahedral mesh with its derived topology, built once and shared (paper section 4).
#include <Eigen/Dense>
#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/tensor.h"

namespace tfd::core {

class PointLocator;

/// Immutable tetrahedral mesh. Tets are positively oriented: det[p1−p0, p2−p0, p3−p0] > 0.
/// The constructor validates the input and derives, once: unique edges and faces (vertex ids
/// sorted ascending, lists sorted lexicographically, so numbering depends only on the input),
/// the one or two tets of each face, boundary faces and vertices, area-weighted outward
/// boundary normals, vertex-to-tet incidence and tet volumes. Build work runs in parallel and is
/// deterministic for any thread count: edges and faces are grouped by their lowest vertex
/// (core/tet_mesh_topology.cpp), which gives the same numbering as one global sort.
class TetMesh {
 public:
  using Tet = std::array<int, 4>;
  using Face = std::array<int, 3>;
  using Edge = std::array<int, 2>;

  /// Throws core::Error listing the problems found by validate() (at most a handful, with
  /// counts), e.g. "tet 12 is inverted (volume -0.003)". Throws core::Cancelled when
  /// `progress` is cancelled while the topology is built (checked inside every pass).
  TetMesh(std::vector<Vec3> positions, std::vector<Tet> tets,
          const Progress& progress = Progress());

  /// The topology ids the on-disk cook cache stores with a mesh: tetEdges(), tetFaces() and
  /// faceTets() of the mesh built from the same positions and tets.
  struct StoredTopology {
    std::vector<std::array<int, 6>> tetEdges;
    std::vector<std::array<int, 4>> tetFaces;
    std::vector<std::array<int, 2>> faceTets;
  };
  /// Restores a mesh without sorting anything again: edges and faces are read off the stored
  /// ids and everything is verified (ids in range and all in use, every tet's edges and faces
  /// consistent, edges and faces strictly ascending, faceTets exactly the tets naming each
  /// face), which proves the result identical to TetMesh(positions, tets). Throws core::Error
  /// when the mesh is invalid or the ids do not match its tets (core/tet_mesh_restore.cpp).
  TetMesh(std::vector<Vec3> positions, std::vector<Tet> tets, StoredTopology stored);
  ~TetMesh();
  TetMesh(const TetMesh&) = delete;
  TetMesh& operator=(const TetMesh&) = delete;

  /// Problems that make a mesh unusable, each one a sentence: vertex index out of range, a tet
  /// repeating a vertex, a zero-volume or inverted tet, a face shared by more than two tets
  /// (non-manifold), a vertex no tet uses, a non-finite coordinate, no tets at all.
  /// Empty when the mesh is valid. At most `maxReported` individual problems are spelled out.
  static std::vector<std::string> validate(const std::vector<Vec3>& positions,
                                           const std::vector<Tet>& tets, int maxReported = 5);

  std::size_t vertexCount() const { return positions_.size(); }
  std::size_t tetCount() const { return tets_.size(); }
  const std::vector<Vec3>& positions() const { return positions_; }
  const std::vector<Tet>& tets() const { return tets_; }

  const std::vector<Edge>& edges() const { return edges_; }
  /// Edge ids of tet t in the order (01, 02, 03, 12, 13, 23) of its local vertices.
  const std::vector<std::array<int, 6>>& tetEdges() const { return tetEdges_; }
  const std::vector<Face>& faces() const { return faces_; }
  /// For each face its tets; the second is −1 on the boundary.
  const std::vector<std::array<int, 2>>& faceTets() const { return faceTets_; }
  /// Face ids of tet t; entry i is the face opposite local vertex i.
  const std::vector<std::array<int, 4>>& tetFaces() const { return tetFaces_; }

  /// Ids of boundary faces (faces with one tet), ascending.
  const std::vector<int>& boundaryFaces() const { return boundaryFaces_; }
  /// Boundary face f's vertices ordered so the right-hand normal points out of the volume.
  Face orientedBoundaryFace(int face) const;
  /// Boundary vertex ids, ascending.
  const std::vector<int>& boundaryVertices() const { return boundaryVertices_; }
  bool isBoundaryVertex(int v) const { return isBoundary_[v] != 0; }
  /// Unit outward normal per vertex, the area-weighted mean of its boundary faces' normals;
  /// zero for interior vertices.
  const std::vector<Vec3>& vertexNormals() const { return vertexNormals_; }

  /// Tets that use vertex v, ascending.
  std::span<const int> vertexTets(int v) const {
    return {vertexTetIds_.data() + vertexTetStart_[v],
            vertexTetIds_.data() + vertexTetStart_[v + 1]};
  }
  const std::vector<double>& tetVolumes() const { return volumes_; }
  double totalVolume() const { return totalVolume_; }
  double meanEdgeLength() const { return meanEdgeLength_; }
  const Vec3& boundsMin() const { return boundsMin_; }
  const Vec3& boundsMax() const { return boundsMax_; }

  /// Barycentric coordinates of p with respect to tet t (they sum to 1).
  Eigen::Vector4d barycentric(int t, const Vec3& p) const;
  /// Point location structure, built on first use (thread-safe) and kept with the mesh.
  const PointLocator& locator() const;
  /// Whether locator() has been built already (core::locatePoints() then uses it).
  bool hasLocator() const { return locatorBuilt_.load(std::memory_order_acquire); }

 private:
  // Construction steps (core/tet_mesh_topology.cpp). The checks return false at the first
  // problem; throwInvalid() then lists every problem with validate().
  bool quickCheckAndVolumes();
  bool buildIncidence(const Progress& progress);
  bool buildEdgesAndFaces(const Progress& progress);
  bool restoreEdgesAndFaces();
  void buildSummaries();
  [[noreturn]] void throwInvalid() const;
  void buildBoundary();

  std::vector<Vec3> positions_;
  std::vector<Tet> tets_;
  std::vector<Edge> edges_;
  std::vector<std::array<int, 6>> tetEdges_;
  std::vector<Face> faces_;
  std::vector<std::array<int, 2>> faceTets_;
  std::vector<std::array<int, 4>> tetFaces_;
  std::vector<int> boundaryFaces_;
  std::vector<int> boundaryVertices_;
  std::vector<unsigned char> isBoundary_;
  std::vector<Vec3> vertexNormals_;
  std::vector<int> vertexTetStart_;
  std::vector<int> vertexTetIds_;
  std::vector<double> volumes_;
  double totalVolume_ = 0;
  double meanEdgeLength_ = 0;
  Vec3 boundsMin_ = Vec3::Zero(), boundsMax_ = Vec3::Zero();
  mutable std::unique_ptr<PointLocator> locator_;
  mutable std::once_flag locatorOnce_;
  mutable std::atomic<bool> locatorBuilt_ = false;
};

/// Signed volume of the tet (a, b, c, d): positive when positively oriented.
inline double signedVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

}  // namespace tfd::core
