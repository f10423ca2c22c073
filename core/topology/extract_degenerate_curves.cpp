#include "core/topology/extract_degenerate_curves.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/topology/curve_assembly.h"
#include "core/topology/face_prefilter.h"
#include "core/topology/face_solver.h"
#include "core/topology/generic_perturbation.h"
#include "core/topology/tet_connection.h"
#include "core/topology/zheng_pang.h"

namespace tfd::core {
namespace {

using namespace topology;

constexpr std::size_t kFaceGrain = 4096;

void checkOptions(const ExtractOptions& o) {
  if (!(o.perturbation >= 0 && o.perturbation <= 1e-2))
    throw Error("extract degenerate curves: option 'perturbation' must be in [0, 0.01], got " +
                std::to_string(o.perturbation));
  if (o.maxPerturbationRounds < 0 || o.maxPerturbationRounds > 8)
    throw Error(
        "extract degenerate curves: option 'maxPerturbationRounds' must be in [0, 8], got " +
        std::to_string(o.maxPerturbationRounds));
  if (o.arcSamples < 0 || o.arcSamples > 64)
    throw Error("extract degenerate curves: option 'arcSamples' must be in [0, 64], got " +
                std::to_string(o.arcSamples));
  if (!(o.edgeTolerance >= 0 && o.edgeTolerance <= 1e-3))
    throw Error("extract degenerate curves: option 'edgeTolerance' must be in [0, 0.001], got " +
                std::to_string(o.edgeTolerance));
}

std::string plural(std::int64_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// Everything the rounds share.
class Extractor {
 public:
  Extractor(const TensorField& field, const ExtractOptions& options, const Progress& progress)
      : field_(field),
        mesh_(field.mesh()),
        options_(options),
        progress_(progress),
        base_(mesh_.vertexCount()),
        working_(mesh_.vertexCount()),
        gap_(mesh_.vertexCount(), 0),
        zero_(mesh_.vertexCount(), 0),
        level_(mesh_.vertexCount(), 0),
        changed_(mesh_.vertexCount(), 1),
        faceSlot_(mesh_.faces().size(), -1) {}

  DegenerateCurves run();

 private:
  void forVertices(const auto& body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, base_.size(), 8192),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        if (progress_.cancelled()) return;
                        for (std::size_t v = r.begin(); v != r.end(); ++v) body(v);
                      });
    progress_.throwIfCancelled();
  }
  void solveFaces(int round);
  void buildNodes();
  void connectTets();
  std::vector<int> flaggedVertices() const;
  void perturb(const std::vector<int>& vertices);
  double localScale(int vertex) const;
  DegenerateCurves finish();

  struct FaceRecord {
    int face;
    FaceSolution solution;
  };

  const TensorField& field_;
  const TetMesh& mesh_;
  const ExtractOptions& options_;
  const Progress& progress_;
  std::vector<Tensor> base_, working_;
  std::vector<double> gap_;
  std::vector<char> zero_;  ///< working tensor is exactly zero
  std::vector<int> level_;
  std::vector<char> changed_;
  std::vector<int> faceSlot_;
  std::vector<FaceRecord> records_;

  // Rebuilt each round.
  std::vector<CurveNode> nodes_;
  std::vector<int> tetStart_, tetNodeIds_, tetsWithNodes_;
  std::vector<TetConnection> connections_;

  ExtractionDiagnostics diagnostics_;
  std::int64_t zeroFaces_ = 0;
};

void Extractor::solveFaces(int round) {
  const auto& faces = mesh_.faces();
  const std::size_t faceCount = faces.size();
  // Stage 1: which faces to (re)solve. Round 0: all; later: faces touching changed vertices.
  // Fixed chunks, each with its own candidate list, concatenated in chunk order.
  const std::size_t chunks = (faceCount + kFaceGrain - 1) / kFaceGrain;
  struct Chunk {
    std::vector<int> candidates;
    std::int64_t culledGap = 0, culledBernstein = 0, zero = 0;
  };
  std::vector<Chunk> chunk(chunks);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    if (progress_.cancelled()) return;
    Chunk& out = chunk[c];
    const std::size_t end = std::min(faceCount, (c + 1) * kFaceGrain);
    for (std::size_t f = c * kFaceGrain; f != end; ++f) {
      const auto& fv = faces[f];
      if (round > 0 && !changed_[fv[0]] && !changed_[fv[1]] && !changed_[fv[2]]) continue;
      if (zero_[fv[0]] && zero_[fv[1]] && zero_[fv[2]]) {
        ++out.zero;
        continue;
      }
      if (options_.prefilter) {
        const Tensor* t[3] = {&working_[fv[0]], &working_[fv[1]], &working_[fv[2]]};
        const double g[3] = {gap_[fv[0]], gap_[fv[1]], gap_[fv[2]]};
        if (gapExcludesFace(t, g)) {
          ++out.culledGap;
          continue;
        }
        if (bernsteinExcludesFace(*t[0], *t[1], *t[2])) {
          ++out.culledBernstein;
          continue;
        }
      }
      out.candidates.push_back(int(f));
    }
  });
  progress_.throwIfCancelled();

  std::vector<int> candidates;
  std::int64_t culledGap = 0, culledBernstein = 0, zero = 0;
  for (const Chunk& c : chunk) {
    candidates.insert(candidates.end(), c.candidates.begin(), c.candidates.end());
    culledGap += c.culledGap, culledBernstein += c.culledBernstein, zero += c.zero;
  }
  if (round == 0) {
    diagnostics_.facesCulledByGap = culledGap;
    diagnostics_.facesCulledByBernstein = culledBernstein;
    zeroFaces_ = zero;
  }
  diagnostics_.facesSolved += std::int64_t(candidates.size());

  // Stage 2: exact solve, one output slot per candidate.
  std::vector<FaceSolution> solutions(candidates.size());
  const FaceSolverOptions solverOptions{options_.edgeTolerance};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      if (progress_.cancelled()) return;
                      for (std::size_t i = r.begin(); i != r.end(); ++i) {
                        const auto& fv = faces[candidates[i]];
                        solutions[i] = solveFace(working_[fv[0]], working_[fv[1]], working_[fv[2]],
                                                 solverOptions);
                      }
                    });
  progress_.throwIfCancelled();

  // Stage 3: update the sparse face records. Faces processed again but no longer candidates
  // lose their old result; candidates store theirs (serial, in face order).
  if (round > 0) {
    for (FaceRecord& rec : records_) {
      const auto& fv = faces[rec.face];
      if ((changed_[fv[0]] || changed_[fv[1]] || changed_[fv[2]]) &&
          !std::binary_search(candidates.begin(), candidates.end(), rec.face))
        rec.solution = FaceSolution{};
    }
  }
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const FaceSolution& solution = solutions[i];
    int& slot = faceSlot_[candidates[i]];
    if (solution.count > 0 || (solution.flags & kFaceNeedsFallback)) {
      if (slot < 0) {
        slot = int(records_.size());
        records_.push_back({candidates[i], solution});
      } else {
        records_[slot].solution = solution;
      }
    } else if (slot >= 0) {
      records_[slot].solution = FaceSolution{};
    }
  }
}

void Extractor::buildNodes() {
  const auto& faces = mesh_.faces();
  const auto& edges = mesh_.edges();
  const auto& positions = mesh_.positions();
  nodes_.clear();
  std::vector<std::pair<int, int>> tetNode;                      // (tet, node)
  std::map<int, std::vector<std::pair<double, int>>> edgeNodes;  // edge → (parameter, node)
  std::map<int, int> vertexNodes;

  std::vector<int> order;  // records in face order
  order.reserve(records_.size());
  for (int i = 0; i < int(records_.size()); ++i)
    if (records_[i].solution.count > 0) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return records_[a].face < records_[b].face; });

  const double tol = options_.edgeTolerance;
  const auto edgeTets = [&](int a, int b) {
    const auto ta = mesh_.vertexTets(a), tb = mesh_.vertexTets(b);
    std::vector<int> common;
    std::set_intersection(ta.begin(), ta.end(), tb.begin(), tb.end(), std::back_inserter(common));
    return common;
  };
  for (int index : order) {
    const FaceRecord& rec = records_[index];
    const auto& fv = faces[rec.face];
    for (int k = 0; k < rec.solution.count; ++k) {
      const FacePoint& p = rec.solution.points[k];
      const Vec3& b = p.barycentric;
      int small = 0, smallIndex = -1, largest = 0;
      for (int i = 0; i < 3; ++i) {
        if (b[i] <= tol) ++small, smallIndex = i;
        if (b[i] > b[largest]) largest = i;
      }
      CurveNode node;
      node.eigenvector = p.eigenvector;
      node.sigma = p.sigma;
      std::vector<int> tets;
      if (small == 0) {
        node.position = b[0] * positions[fv[0]] + b[1] * positions[fv[1]] + b[2] * positions[fv[2]];
        node.source = {PointSource::Kind::Face, rec.face};
        const auto& ft = mesh_.faceTets()[rec.face];
        node.onBoundary = ft[1] < 0;
        tets.push_back(ft[0]);
        if (ft[1] >= 0) tets.push_back(ft[1]);
      } else if (small == 1) {
        const int j = fv[(smallIndex + 1) % 3], l = fv[(smallIndex + 2) % 3];
        const int lo = std::min(j, l), hi = std::max(j, l);
        const double wLo = b[lo == j ? (smallIndex + 1) % 3 : (smallIndex + 2) % 3];
        const double wHi = b[hi == j ? (smallIndex + 1) % 3 : (smallIndex + 2) % 3];
        const double param = std::clamp(wHi / (wLo + wHi), 0.0, 1.0);
        const TetMesh::Edge key{lo, hi};
        const auto it = std::lower_bound(edges.begin(), edges.end(), key);
        const int edge = int(it - edges.begin());
        auto& list = edgeNodes[edge];
        bool known = false;
        for (const auto& [q, id] : list) known = known || std::abs(q - param) < 1e-7;
        if (known) continue;
        list.emplace_back(param, int(nodes_.size()));
        node.position = (1 - param) * positions[lo] + param * positions[hi];
        node.source = {PointSource::Kind::Edge, edge};
        tets = edgeTets(lo, hi);
        for (int t : tets) {
          for (int face : mesh_.tetFaces()[t]) {
            const auto& f = faces[face];
            const bool hasLo = f[0] == lo || f[1] == lo || f[2] == lo;
            const bool hasHi = f[0] == hi || f[1] == hi || f[2] == hi;
            if (hasLo && hasHi && mesh_.faceTets()[face][1] < 0) node.onBoundary = true;
          }
        }
      } else {
        const int v = fv[largest];
        if (vertexNodes.count(v)) continue;
        vertexNodes[v] = int(nodes_.size());
        node.position = positions[v];
        node.source = {PointSource::Kind::Vertex, v};
        node.onBoundary = mesh_.isBoundaryVertex(v);
        const auto vt = mesh_.vertexTets(v);
        tets.assign(vt.begin(), vt.end());
      }
      const int id = int(nodes_.size());
      nodes_.push_back(node);
      for (int t : tets) tetNode.emplace_back(t, id);
    }
  }
  std::sort(tetNode.begin(), tetNode.end());
  tetNode.erase(std::unique(tetNode.begin(), tetNode.end()), tetNode.end());
  tetsWithNodes_.clear();
  tetStart_.clear();
  tetNodeIds_.clear();
  for (std::size_t i = 0; i < tetNode.size(); ++i) {
    if (i == 0 || tetNode[i].first != tetNode[i - 1].first) {
      tetsWithNodes_.push_back(tetNode[i].first);
      tetStart_.push_back(int(i));
    }
    tetNodeIds_.push_back(tetNode[i].second);
  }
  tetStart_.push_back(int(tetNode.size()));
  diagnostics_.facePoints = std::int64_t(nodes_.size());
}

void Extractor::connectTets() {
  connections_.assign(tetsWithNodes_.size(), TetConnection{});
  const auto& tets = mesh_.tets();
  const auto& positions = mesh_.positions();
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, tetsWithNodes_.size(), 16),
      [&](const tbb::blocked_range<std::size_t>& r) {
        if (progress_.cancelled()) return;
        std::vector<TetNode> local;
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const int t = tetsWithNodes_[i];
          const auto& tv = tets[t];
          const TetLinearField linear(
              {positions[tv[0]], positions[tv[1]], positions[tv[2]], positions[tv[3]]},
              {working_[tv[0]], working_[tv[1]], working_[tv[2]], working_[tv[3]]});
          local.clear();
          for (int k = tetStart_[i]; k < tetStart_[i + 1]; ++k) {
            const CurveNode& n = nodes_[tetNodeIds_[k]];
            local.push_back({tetNodeIds_[k], n.position, n.eigenvector,
                             n.source.kind == PointSource::Kind::Face});
          }
          connections_[i] = connectTet(linear, local, options_.arcSamples);
        }
      });
  progress_.throwIfCancelled();
}

std::vector<int> Extractor::flaggedVertices() const {
  std::vector<int> vertices;
  for (const FaceRecord& rec : records_) {
    if (rec.solution.flags & kFaceNeedsFallback) {
      const auto& fv = mesh_.faces()[rec.face];
      vertices.insert(vertices.end(), fv.begin(), fv.end());
    }
  }
  for (std::size_t i = 0; i < tetsWithNodes_.size(); ++i) {
    if (connections_[i].flags != 0) {
      const auto& tv = mesh_.tets()[tetsWithNodes_[i]];
      vertices.insert(vertices.end(), tv.begin(), tv.end());
    }
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

double Extractor::localScale(int vertex) const {
  double s = 0;
  for (int t : mesh_.vertexTets(vertex))
    for (int w : mesh_.tets()[t]) s = std::max(s, base_[w].norm());
  return s;
}

void Extractor::perturb(const std::vector<int>& vertices) {
  std::fill(changed_.begin(), changed_.end(), 0);
  for (int v : vertices) {
    const int level = ++level_[v];
    working_[v] = base_[v] + vertexPerturbation(v, level, options_.perturbation, localScale(v));
    gap_[v] = degeneracyDistanceLowerBound(working_[v]);
    zero_[v] = working_[v] == Tensor{};
    changed_[v] = 1;
  }
}

DegenerateCurves Extractor::run() {
  diagnostics_.faces = std::int64_t(mesh_.faces().size());
  forVertices([&](std::size_t v) { base_[v] = field_.at(int(v)).deviator(); });
  double maxNorm = 0;
  for (std::size_t v = 0; v < base_.size(); ++v) {
    const double n = base_[v].norm();
    if (!std::isfinite(n)) {
      const Vec3& p = mesh_.positions()[v];
      throw Error("extract degenerate curves: the field is not finite at vertex " +
                  std::to_string(v) + " (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                  ", " + std::to_string(p.z()) + ")");
    }
    maxNorm = std::max(maxNorm, n);
  }
  if (maxNorm == 0) {
    return DegenerateCurves({}, {"the field is zero everywhere: no degenerate curves"},
                            diagnostics_);
  }
  double maxDifference = 0;
  for (const Tensor& t : base_) maxDifference = std::max(maxDifference, (t - base_[0]).norm());
  if (maxDifference <= 1e-12 * maxNorm) {
    const Tensor unit = base_[0] * (1 / base_[0].norm());
    const bool degenerate = zhengPangDiscriminant(zhengPangFunctions(unit)) < 1e-20;
    return DegenerateCurves(
        {},
        {degenerate ? "the field is constant and degenerate everywhere: every point is "
                      "degenerate, there are no isolated degenerate curves"
                    : "the field is constant: no degenerate curves"},
        diagnostics_);
  }
  working_ = base_;
  forVertices([&](std::size_t v) {
    gap_[v] = degeneracyDistanceLowerBound(working_[v]);
    zero_[v] = working_[v] == Tensor{};
  });

  const int maxRounds = options_.perturbation > 0 ? options_.maxPerturbationRounds : 0;
  for (int round = 0;; ++round) {
    progress_.report(0.1 + 0.8 * round / (maxRounds + 1), "degenerate points on faces");
    solveFaces(round);
    buildNodes();
    progress_.report(0.1 + 0.8 * (round + 0.5) / (maxRounds + 1), "connecting points in tets");
    connectTets();
    diagnostics_.rounds = round;
    if (round >= maxRounds) break;
    const std::vector<int> flagged = flaggedVertices();
    if (flagged.empty()) break;
    perturb(flagged);
  }
  progress_.report(0.95, "chaining degenerate curves");
  return finish();
}

DegenerateCurves Extractor::finish() {
  std::vector<AssemblySegment> segments;
  std::int64_t odd = 0, heuristic = 0, ambiguous = 0;
  for (std::size_t i = 0; i < connections_.size(); ++i) {
    const TetConnection& c = connections_[i];
    odd += (c.flags & kTetOdd) != 0;
    heuristic += (c.flags & kTetHeuristic) != 0;
    ambiguous += (c.flags & (kTetAmbiguous | kTetOffConic)) != 0;
    for (const TetSegment& s : c.segments)
      segments.push_back({s.from, s.to, tetsWithNodes_[i], s.arc});
  }
  std::int64_t unresolved = 0;
  for (const FaceRecord& rec : records_)
    unresolved += (rec.solution.flags & kFaceNeedsFallback) != 0;
  for (int l : level_) diagnostics_.perturbedVertices += l > 0;
  diagnostics_.unresolvedFaces = unresolved;
  diagnostics_.oddTets = odd;
  diagnostics_.heuristicTets = heuristic;

  AssemblyResult assembled = assembleCurves(nodes_, segments);
  diagnostics_.danglingEnds = assembled.danglingEnds;
  diagnostics_.junctions = assembled.junctions;

  std::vector<std::string> warnings;
  if (zeroFaces_ > 0)
    warnings.push_back(plural(zeroFaces_, "face", "faces") +
                       " where the field vanishes (triple degeneracy) were skipped");
  if (unresolved > 0)
    warnings.push_back(plural(unresolved, "face", "faces") +
                       " stayed non-generic after the perturbation fallback; points there may "
                       "be missing");
  if (odd > 0)
    warnings.push_back(plural(odd, "tet", "tets") +
                       " had an odd number of degenerate points (tangency or edge hit); some "
                       "points there are left unconnected");
  if (heuristic > 0)
    warnings.push_back(plural(heuristic, "tet", "tets") +
                       " with a non-generic field were connected by nearest pairs");
  if (ambiguous > 0)
    warnings.push_back(plural(ambiguous, "tet", "tets") +
                       " had points on their boundary or off their curve (numerically "
                       "ambiguous connections)");
  if (assembled.danglingEnds > 0)
    warnings.push_back(plural(assembled.danglingEnds, "curve end", "curve ends") +
                       " inside the volume (curves should end on the boundary)");
  if (assembled.junctions > 0)
    warnings.push_back(plural(assembled.junctions, "point", "points") +
                       " where more than two curve segments meet");
  if (assembled.mixedTypeCurves > 0)
    warnings.push_back(plural(assembled.mixedTypeCurves, "curve", "curves") +
                       " with both linear and planar points (a triple degeneracy nearby)");
  return DegenerateCurves(std::move(assembled.curves), std::move(warnings), diagnostics_);
}

}  // namespace

DegenerateCurves extractDegenerateCurves(const TensorField& field, const ExtractOptions& options,
                                         const Progress& progress) {
  checkOptions(options);
  Extractor extractor(field, options, progress);
  return extractor.run();
}

}  // namespace tfd::core
