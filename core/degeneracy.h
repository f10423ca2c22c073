#pragma once
// The vocabulary of degeneracy shared by design (core/design) and extraction (core/topology):
// the L/P type of a degenerate point or curve and the 2-D pattern around it (paper §3).
#include <array>
#include <cstdint>

namespace tfd::core {

/// L-type (linear: the non-repeated eigenvalue is the major one, λ1 > λ2 = λ3) or P-type
/// (planar: it is the minor one, λ1 = λ2 > λ3).
enum class DegenerateType { Linear, Planar };

/// 2-D pattern of the field projected on the degenerate plane at a point of a degenerate curve:
/// wedge (index +½), trisector (−½), or a transition point between the two (where the curve's
/// tangent is perpendicular to the non-repeated eigenvector). A design element is a wedge or a
/// trisector; transition points only arise on extracted curves.
enum class DegeneratePattern { Wedge, Trisector, Transition };

const char* toString(DegenerateType type);        ///< "linear" / "planar"
const char* toString(DegeneratePattern pattern);  ///< "wedge" / "trisector" / "transition"

/// The paper's Fig. 5 colour code (§4): L-wedge green, L-trisector blue, P-wedge yellow,
/// P-trisector red; transition points white. RGB, 0–255.
std::array<std::uint8_t, 3> fig5Colour(DegenerateType type, DegeneratePattern pattern);

}  // namespace tfd::core
