#pragma once
// TEMP stub (branch `remove`): the agreed interface of branch `sffield`, which owns this file.
#include <vector>

#include "core/degeneracy.h"
#include "core/tensor.h"
#include "core/tensor_field.h"

namespace tfd::core {

/// Which eigenvector does not repeat at a degenerate point of `type`: the major one for
/// Linear (λ2 = λ3), the minor one for Planar (λ1 = λ2).
/// The non-repeating eigenvector made a vector field over the vertices of `regionTets` by
/// parallel transport from a seed vertex: each vertex's sign agrees with an already oriented
/// neighbour. Throws core::Error when the region is not connected.
struct VectorisedEigenvector {
  std::vector<int> vertices;     ///< region vertices, ascending
  std::vector<Vec3> directions;  ///< unit, one per entry of `vertices`
  int signConflicts = 0;         ///< region edges whose two directions disagree in sign (0 when the
                                 ///< region holds no degenerate point)
};
VectorisedEigenvector vectoriseEigenvector(const TensorField& field,
                                           const std::vector<int>& regionTets, DegenerateType type);

}  // namespace tfd::core
