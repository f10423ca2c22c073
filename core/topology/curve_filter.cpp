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

/// Points inside a tet (transition points and arc samples) lie on the curve between two
/// skeleton points of the same tet; the filters ignore them so that `arcSamples` never changes
/// which curves pass (a tet holding a short boundary arc can have two interior vertices while
/// the faces the curve crosses have one). A curve with no skeleton point keeps all its points.
bool onSkeleton(const PointSource& s) { return s.kind != PointSource::Kind::Tet; }

bool hasSkeletonPoint(const DegenerateCurve& curve) {
  return std::any_of(curve.sources.begin(), curve.sources.end(), onSkeleton);
}

}  // namespace

bool hugsBoundary(const DegenerateCurve& curve, const TetMesh& mesh) {
  const bool skeletonOnly = hasSkeletonPoint(curve);
  return !curve.sources.empty() &&
         std::all_of(curve.sources.begin(), curve.sources.end(), [&](const auto& s) {
           return (skeletonOnly && !onSkeleton(s)) || inBoundaryLayer(s, mesh);
         });
}

double skeletonLength(const DegenerateCurve& curve) {
  if (!hasSkeletonPoint(curve)) return curve.length();
  double length = 0;
  const Vec3* first = nullptr;
  const Vec3* previous = nullptr;
  for (std::size_t i = 0; i < curve.points.size(); ++i) {
    if (!onSkeleton(curve.sources[i])) continue;
    if (previous) length += (curve.points[i] - *previous).norm();
    if (!first) first = &curve.points[i];
    previous = &curve.points[i];
  }
  if (curve.closed) length += (*first - *previous).norm();
  return length;
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
    if (skeletonLength(c) < filter.minLength) continue;
    if (filter.dropBoundary && hugsBoundary(c, mesh)) continue;
    kept.push_back(c);
  }
  return DegenerateCurves(std::move(kept), curves.warnings(), curves.diagnostics());
}

}  // namespace tfd::core
