#pragma once
// Polylines with per-point attributes: what `Hyperstreamlines` outputs and `Streamtubes` and
// `ExportLines` consume (paper §8, the noodles of Figure 20).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/tensor.h"

namespace tfd::core {

/// Which eigenvector field a line follows (eigenvalues sorted λ1 ≥ λ2 ≥ λ3).
enum class EigenFamily : std::uint8_t { Major, Medium, Minor };
const char* toString(EigenFamily family);

/// Why a line ends.
enum class LineStop : std::uint8_t {
  Degenerate,  ///< the eigen-gap of the followed eigenvector fell below the threshold
  Boundary,    ///< the next step would leave the mesh
  SharpTurn,   ///< the direction turned more than the allowed angle in one step
  MaxLength,   ///< the line reached its maximum length
  TooClose,    ///< the line came closer than the test distance to another line (or itself)
};
const char* toString(LineStop stop);

/// One line: its points in order and, per point, the eigenvalues λ1 ≥ λ2 ≥ λ3 of the
/// interpolated tensor there. `stops[0]` is why the start ends, `stops[1]` the end.
struct Polyline {
  std::vector<Vec3> points;
  std::vector<Vec3> eigenvalues;
  std::array<LineStop, 2> stops{LineStop::Boundary, LineStop::Boundary};
  double length() const;
};

/// Immutable graph value ("Lines"): the lines and the eigenvector field they follow.
struct Polylines {
  std::vector<Polyline> lines;
  EigenFamily family = EigenFamily::Major;

  std::size_t pointCount() const;
  double totalLength() const;
  std::size_t byteSize() const;
  /// "12 major lines, 3400 points, length 18.2; ends: 5 degenerate, 19 boundary, ...".
  std::string summary() const;
};

}  // namespace tfd::core
