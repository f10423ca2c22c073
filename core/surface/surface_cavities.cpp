#include "core/surface/surface_cavities.h"

#include <cmath>

#include "core/surface/surface_check.h"

namespace tfd::core {
namespace {

struct Piece {
  double volume = 0;  ///< signed, from its first vertex (translation-free)
  int origin = -1;    ///< that vertex
  int largest = -1;   ///< its triangle of largest area
  double area = -1;   ///< of that triangle
};

}  // namespace

std::vector<Vec3> cavityPoints(const SurfaceMesh& mesh) {
  const auto& p = mesh.positions;
  const std::vector<int> pieceOf = vertexPieces(mesh);
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    if (pieceOf[t[0]] == int(pieces.size())) pieces.push_back({0, t[0], -1, -1});
    Piece& piece = pieces[pieceOf[t[0]]];
    const Vec3 &o = p[piece.origin], a = p[t[0]] - o, b = p[t[1]] - o, c = p[t[2]] - o;
    piece.volume += a.dot(b.cross(c)) / 6;
    const double area = 0.5 * (b - a).cross(c - a).norm();
    if (area > piece.area) piece.area = area, piece.largest = int(i);
  }
  if (pieces.size() < 2) return {};
  const Piece* outer = &pieces.front();
  for (const Piece& piece : pieces)
    if (std::abs(piece.volume) > std::abs(outer->volume)) outer = &piece;
  const double side = outer->volume > 0 ? 1.0 : -1.0;  // along the normals: out of the material
  std::vector<Vec3> points;
  for (const Piece& piece : pieces) {
    if (!(piece.volume * side < 0) || !(piece.area > 0)) continue;
    const auto& t = mesh.triangles[piece.largest];
    const Vec3 normal = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).normalized();
    const Vec3 centroid = (p[t[0]] + p[t[1]] + p[t[2]]) / 3;
    const Vec3 point = centroid + side * 1e-3 * std::sqrt(piece.area) * normal;
    if (point.allFinite()) points.push_back(point);  // not for coordinates near overflow
  }
  return points;
}

}  // namespace tfd::core
