#pragma once
// Deterministic tiny perturbation of vertex tensors, the fallback for non-generic fields
// (algorithms note §3.3-1(a)).
//
// Fields whose off-diagonal blocks vanish (T13 = T23 ≡ 0, as the paper's default design
// elements give), curves running exactly along mesh edges or through vertices, constant
// regions and tangencies make the face and tet problems non-generic: degenerate points stop
// being isolated or stop being reliable. Adding ε·s·ξ(v) to the tensor of each affected vertex
// v, with ξ(v) ∈ [−1, 1]⁵ a fixed pseudo-random vector derived from the vertex id only and s the
// largest tensor norm in v's one-ring, makes the PL field generic while moving the curves by
// O(ε) relative: the note found identical topology for ε = 1e-7 and 1e-4. Perturbed vertex
// values depend only on (vertex id, level), never on threads or visiting order.
#include <cstdint>

#include "core/tensor.h"

namespace tfd::core::topology {

/// ξ(v): five numbers in [−1, 1] from a hash of the vertex id (as a traceless tensor).
Tensor perturbationDirection(std::int64_t vertex);

/// The perturbation for `vertex` at fallback `level` ≥ 1: ε·10^(level−1)·s·ξ(vertex).
inline Tensor vertexPerturbation(std::int64_t vertex, int level, double epsilon,
                                 double localScale) {
  if (level <= 0) return Tensor{};
  double amplitude = epsilon * localScale;
  for (int i = 1; i < level; ++i) amplitude *= 10;
  return perturbationDirection(vertex) * amplitude;
}

}  // namespace tfd::core::topology
