#pragma once
// Fixed (Dirichlet) vertex values produced by the design elements (paper §5, "Design"), and the
// accumulator that blends the values several elements give to one vertex.
//
// Inputs: (vertex, tensor, weight) contributions from point and curve elements, in any order.
// Output: FixedValues with the vertex ids sorted ascending, one blended tensor per vertex
// (weighted mean Σ w_i T_i / Σ w_i), and counts for a short report.
// Guarantees: the result does not depend on the order in which contributions for *different*
// vertices arrive; contributions to the same vertex are summed in arrival order (callers add
// them sequentially, so the result is deterministic).
#include <cstddef>
#include <string>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

/// Result of applying a ConstraintSet to a mesh.
struct FixedValues {
  std::vector<int> vertices;      ///< fixed vertex ids, ascending, unique
  std::vector<Tensor> values;     ///< blended value per entry of `vertices`
  std::size_t contributions = 0;  ///< number of (vertex, value) pairs that were added
  std::size_t conflicts = 0;      ///< vertices claimed by more than one contribution
  std::size_t pointElements = 0;  ///< filled by applyConstraints
  std::size_t curveElements = 0;  ///< filled by applyConstraints

  bool empty() const { return vertices.empty(); }
  /// One line, e.g. "42 fixed vertices from 2 point / 1 curve elements (3 conflicts blended)".
  std::string summary() const;
};

/// Inverse-square distance weight w = 1 / (d² + ε²) used to blend overlapping elements;
/// `epsilon` should be a small fraction of the mesh's edge length.
double blendWeight(double distance, double epsilon);

/// Accumulates weighted contributions per vertex; `finish` returns the weighted means.
class FixedValueAccumulator {
 public:
  explicit FixedValueAccumulator(std::size_t vertexCount);

  /// Adds `weight * value` to vertex `vertex`. Throws core::Error for a vertex id out of range
  /// or a weight that is not finite and > 0.
  void add(int vertex, const Tensor& value, double weight);

  std::size_t vertexCount() const { return weights_.size(); }
  /// Number of distinct vertices with at least one contribution so far.
  std::size_t claimedCount() const { return claimed_.size(); }

  /// Sorted vertices, blended values and counts (pointElements/curveElements left at 0).
  FixedValues finish() const;

 private:
  std::vector<Tensor> sums_;
  std::vector<double> weights_;
  std::vector<int> counts_;
  std::vector<int> claimed_;  ///< vertices in first-claim order
  std::size_t contributions_ = 0;
};

}  // namespace tfd::core
