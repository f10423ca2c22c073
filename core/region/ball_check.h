#pragma once
// An independent check that a set of tets is a topological ball (paper §6.1, §6.4: the
// removal regions of the one-curve, two-curve and one-loop scenarios are balls). It does not
// use the incremental simple-tet test of tet_set.h, so it can check it.
//
// The union of the tets is a ball when: the tets are connected through faces; the boundary
// surface (faces with one side in the set: shared with a tet outside it, or on the domain
// surface) is a closed 2-manifold (every boundary edge on exactly two boundary faces, the
// boundary faces around every boundary vertex one cycle); the boundary is connected (no
// cavity); and its Euler characteristic V − E + F is 2. A compact connected polyhedron in R³
// whose boundary is one 2-sphere is a ball (Alexander). Cost: O(set size), sorted lists for the
// boundary, plus one int per mesh tet to index the members.
#include <span>
#include <string>

#include "core/tet_mesh.h"

namespace tfd::core {

struct BallCheck {
  bool ball = false;
  std::string problem;    ///< why not, e.g. "the boundary has 2 components (a cavity)"
  int components = 0;     ///< face-connected components of the tets
  int boundaryFaces = 0;  ///< faces of the boundary surface
  int surfaceFaces = 0;   ///< of which on the domain surface
  int boundaryComponents = 0;
  int eulerCharacteristic = 0;  ///< of the boundary surface
};

/// `tets`: distinct tet ids (any order). An empty set is not a ball.
BallCheck checkTopologicalBall(const TetMesh& mesh, std::span<const int> tets);

}  // namespace tfd::core
