#include "core/topology/curve_tets.h"

#include <algorithm>
#include <iterator>

namespace tfd::core {

std::vector<int> tetsOfSource(const TetMesh& mesh, const PointSource& source) {
  switch (source.kind) {
    case PointSource::Kind::Tet:
      return {source.id};
    case PointSource::Kind::Face: {
      std::vector<int> tets;
      for (int t : mesh.faceTets()[source.id])
        if (t >= 0) tets.push_back(t);
      std::sort(tets.begin(), tets.end());
      return tets;
    }
    case PointSource::Kind::Edge: {
      const auto& e = mesh.edges()[source.id];
      const auto a = mesh.vertexTets(e[0]), b = mesh.vertexTets(e[1]);
      std::vector<int> tets;
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(tets));
      return tets;
    }
    case PointSource::Kind::Vertex: {
      const auto a = mesh.vertexTets(source.id);
      return {a.begin(), a.end()};
    }
  }
  return {};
}

std::vector<int> segmentTets(const TetMesh& mesh, const DegenerateCurve& curve) {
  const std::size_t n = curve.sources.size();
  const std::size_t segments = n < 2 ? 0 : (curve.closed && n > 2 ? n : n - 1);
  std::vector<int> tets(segments, -1);
  std::vector<int> next = n > 0 ? tetsOfSource(mesh, curve.sources[0]) : std::vector<int>{};
  for (std::size_t i = 0; i < segments; ++i) {
    const std::vector<int> here = std::move(next);
    next = tetsOfSource(mesh, curve.sources[(i + 1) % n]);
    std::vector<int> common;
    std::set_intersection(here.begin(), here.end(), next.begin(), next.end(),
                          std::back_inserter(common));
    if (!common.empty()) tets[i] = common.front();
  }
  return tets;
}

}  // namespace tfd::core
