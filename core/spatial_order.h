#pragma once
// A spatial order for mesh numbering: points sorted along a Hilbert curve through their
// bounding box. TetGen numbers its Steiner points and tets in the order its refinement made
// them, so face neighbours end up ~200K ids apart in a 1M-tet mesh and every sweep over
// neighbours (region growing, assembly, extraction) misses the cache at each step. Along a
// Hilbert curve, nearby ids are nearby in space (and, unlike Z-order, the curve never jumps
// across the box), so neighbours mostly share cache lines and pages.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

/// Index along the Hilbert curve of `bits` levels through the grid of 2^bits cells per axis
/// (1 ≤ bits ≤ 21; each coordinate < 2^bits): consecutive indices are face-adjacent cells.
std::uint64_t hilbertIndex(std::array<std::uint32_t, 3> cell, int bits);

/// The permutation that sorts `points` by the Hilbert index of their cell (2^21 cells per
/// axis over the points' bounding cube), ties by position in `points`: order[k] is the
/// point that goes to place k. Deterministic for any thread count.
std::vector<int> hilbertOrder(std::span<const Vec3> points);

/// Renumbers a tet mesh in place along the Hilbert curve: the vertices from `firstFree` on by
/// position (those before keep their ids: an input surface's, say), then the tets by centroid.
/// Each tet keeps its vertex order, so its orientation.
void renumberSpatially(std::vector<Vec3>& positions, std::vector<std::array<int, 4>>& tets,
                       std::size_t firstFree);

}  // namespace tfd::core
