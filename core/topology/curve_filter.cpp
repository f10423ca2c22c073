#include "core/topology/curve_filter.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace tfd::core {
namespace {

/// Vertices of the simplex a curve point came from that are not on the boundary.
template <class Ids>
int interiorVertices(const TetMesh& mesh, const Ids& ids) {
  int n = 0;
  for (int v : ids) n += !mesh.isBoundaryVertex(v);
  return n;
}

bool inBoundaryLayer(const PointSource& s, const TetMesh& mesh) {
  if (s.id < 0) return false;
  switch (s.kind) {
    case PointSource::Kind::Face:
      return interiorVertices(mesh, mesh.faces()[s.id]) <= 1;
    case PointSource::Kind::Edge:
      return interiorVertices(mesh, mesh.edges()[s.id]) <= 1;
    case PointSource::Kind::Vertex:
      return mesh.isBoundaryVertex(s.id);
    case PointSource::Kind::Tet:
      return interiorVertices(mesh, mesh.tets()[s.id]) <= 1;
  }
  return false;
}

}  // namespace

bool hugsBoundary(const DegenerateCurve& curve, const TetMesh& mesh) {
  return !curve.sources.empty() &&
         std::all_of(curve.sources.begin(), curve.sources.end(),
                     [&](const auto& s) { return inBoundaryLayer(s, mesh); });
}

int boundaryCurveCount(const DegenerateCurves& curves, const TetMesh& mesh) {
  return static_cast<int>(std::count_if(curves.curves().begin(), curves.curves().end(),
                                        [&](const auto& c) { return hugsBoundary(c, mesh); }));
}

DegenerateCurves filterCurves(const DegenerateCurves& curves, const TetMesh& mesh,
                              const CurveFilter& filter) {
  if (!(filter.minLength >= 0) || !std::isfinite(filter.minLength))
    throw Error("min_length must be a finite number >= 0");
  std::vector<DegenerateCurve> kept;
  for (const DegenerateCurve& c : curves.curves()) {
    if (c.length() < filter.minLength) continue;
    if (filter.dropBoundary && hugsBoundary(c, mesh)) continue;
    kept.push_back(c);
  }
  return DegenerateCurves(std::move(kept), curves.warnings(), curves.diagnostics());
}

}  // namespace tfd::core
