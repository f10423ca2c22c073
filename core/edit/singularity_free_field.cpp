#include "core/edit/singularity_free_field.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "core/design/parallel_transport.h"
#include "core/edit/angle_field.h"
#include "core/edit/reference_field.h"
#include "core/edit/region_complex.h"
#include "core/edit/smooth_directions.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/error.h"
#include "core/solve/harmonic_solver.h"

namespace tfd::core {
namespace {

/// Largest turn of N across a region edge next to a weak vertex kept as it is (radians), the
/// relative gap below which a vertex's N is weak, and the vertex rings around rougher edges
/// given the harmonic extension of N.
constexpr double kMaxTurn = std::numbers::pi / 6;
constexpr double kWeakGap = 0.1;
constexpr int kRepairRings = 2;

template <class F>
void forEach(int n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 256), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) f(i);
  });
}

/// Held per local vertex: asked for, or touching a tet outside the region.
std::vector<char> heldVertices(const TetMesh& mesh, const RegionComplex& region,
                               const std::vector<char>& held) {
  std::vector<char> out(region.vertices.size(), 0);
  forEach(static_cast<int>(region.vertices.size()), [&](int i) {
    const int v = region.vertices[i];
    bool h = held[v] != 0;
    for (int t : mesh.vertexTets(v)) h = h || region.localTet(t) < 0;
    out[i] = h;
  });
  return out;
}

/// The local vertex nearest the mean of the region's vertices (lowest index on ties).
int centralVertex(const TetMesh& mesh, const RegionComplex& region) {
  Vec3 mean = Vec3::Zero();
  for (int v : region.vertices) mean += mesh.positions()[v];
  mean /= static_cast<double>(region.vertices.size());
  int best = 0;
  for (int i = 1; i < static_cast<int>(region.vertices.size()); ++i) {
    if ((mesh.positions()[region.vertices[i]] - mean).squaredNorm() <
        (mesh.positions()[region.vertices[best]] - mean).squaredNorm())
      best = i;
  }
  return best;
}

/// N where it is smooth; its harmonic extension around edges where it turns by more than 30°
/// next to a vertex where it is ill-defined: the gap between its eigenvalue and the nearest one
/// below a tenth of the deviator's spread (core/edit/smooth_directions.h); with
/// `everyFastTurn`, around every edge where it turns by more than 30°.
DirectionRepair repairDirections(const TetMesh& mesh, const RegionComplex& region,
                                 const std::vector<Vec3>& directions,
                                 const std::vector<char>& fixed,
                                 const std::vector<ValuesAndMedium>& eig, DegenerateType type,
                                 bool everyFastTurn, const Progress& progress) {
  const int count = static_cast<int>(region.vertices.size());
  std::vector<char> weak(count, 1);
  if (!everyFastTurn) {
    forEach(count, [&](int i) {
      const Vec3& l = eig[i].values;
      const double own = type == DegenerateType::Linear ? l[0] - l[1] : l[1] - l[2];
      weak[i] = own < kWeakGap * (l[0] - l[2]);
    });
  }
  return repairRoughDirections(mesh, region, directions, fixed, weak, kMaxTurn, kRepairRings,
                               progress);
}

void gaps(const Vec3& l, double& g12, double& g23) {
  g12 = std::min(g12, l[0] - l[1]);
  g23 = std::min(g23, l[1] - l[2]);
}

}  // namespace

std::string SingularityFreeReport::summary() const {
  std::ostringstream s;
  s << "singularity-free field on " << regionTets << " tets: " << freeVertices << " of "
    << regionVertices << " vertices solved (" << heldVertices << " held) in " << iterations
    << " iterations; smallest eigenvalue gaps " << freeMinGap12 << ", " << freeMinGap23
    << " inside (" << heldMinGap12 << ", " << heldMinGap23 << " held)";
  if (traceSolved) s << "; trace solved beside them";
  if (nonBallSteps > 0) s << "; " << nonBallSteps << " tets not in a ball order";
  if (roughEdges > 0)
    s << "; non-repeating eigenvector smoothed at " << repairedDirections << " vertices around "
      << roughEdges << " edges where it turned by more than 30°";
  return s.str();
}

TensorField singularityFreeField(const TensorField& field, const std::vector<int>& regionTets,
                                 const std::vector<char>& held, DegenerateType type,
                                 const Progress& progress) {
  return singularityFreeField(field, regionTets, held, type, progress, nullptr);
}

TensorField singularityFreeField(const TensorField& field, const std::vector<int>& regionTets,
                                 const std::vector<char>& held, DegenerateType type,
                                 const Progress& progress, SingularityFreeReport* report) {
  const TetMesh& mesh = field.mesh();
  if (held.size() != mesh.vertexCount()) {
    throw Error("singularity-free field: `held` has " + std::to_string(held.size()) +
                " entries for " + std::to_string(mesh.vertexCount()) + " mesh vertices");
  }
  progress.report(0, "orienting the non-repeating eigenvector");
  const RegionComplex region = regionComplex(mesh, regionTets);
  return singularityFreeField(field, region, vectoriseEigenvector(field, region, type), held, type,
                              progress, report);
}

TensorField singularityFreeField(const TensorField& field, const RegionComplex& region,
                                 const VectorisedEigenvector& n, const std::vector<char>& held,
                                 DegenerateType type, const Progress& progress,
                                 SingularityFreeReport* report, bool smoothEveryFastTurn) {
  const TetMesh& mesh = field.mesh();
  if (held.size() != mesh.vertexCount()) {
    throw Error("singularity-free field: `held` has " + std::to_string(held.size()) +
                " entries for " + std::to_string(mesh.vertexCount()) + " mesh vertices");
  }
  if (n.vertices != region.vertices) {
    throw Error("singularity-free field: the vectorised eigenvector is not of this region");
  }
  const char* which = type == DegenerateType::Linear ? "major" : "minor";
  if (n.signConflicts > 0) {
    throw Error(std::string("singularity-free field: the ") + which +
                " eigenvector cannot be oriented in the region (" +
                std::to_string(n.signConflicts) +
                " edges disagree): the region holds a degenerate point where it repeats");
  }
  const int count = static_cast<int>(region.vertices.size());
  const std::vector<char> fixed = heldVertices(mesh, region, held);
  SingularityFreeReport r;
  r.regionTets = region.tets.size();
  r.regionVertices = region.vertices.size();
  r.heldVertices = static_cast<std::size_t>(std::count(fixed.begin(), fixed.end(), 1));
  r.freeVertices = r.regionVertices - r.heldVertices;
  if (r.heldVertices == 0) throw Error("singularity-free field: the region has no held vertex");

  // The Laplacian of Equation 6 and its multigrid depend only on which vertices are held: built
  // while the directions are prepared and the reference field propagates (sequential, §6.3: a
  // ball order).
  // The deviator's eigen-decomposition per region vertex (medium eigenvector, values): the
  // vectorisation's when it kept them (the same decompositions of the same tensors).
  const bool decomposed = n.eigen.size() == static_cast<std::size_t>(count);
  std::vector<ValuesAndMedium> computed(decomposed ? 0 : count);
  const std::vector<ValuesAndMedium>& eig = decomposed ? n.eigen : computed;
  std::vector<double> trace(count);
  std::optional<DirectionRepair> repaired;
  ReferenceField ref;
  std::vector<double> theta;  // θ at every region vertex: held ones lifted, the rest a start
  std::optional<JumpLaplacian> laplacian;
  progress.report(0.1, "eigenvectors, reference field and the Laplacian");  // not from a worker
  tbb::parallel_invoke(
      [&] {
        forEach(count, [&](int i) {
          const Tensor& t = field.at(region.vertices[i]);
          if (!decomposed) computed[i] = ValuesAndMedium::of(eigenDecompose(t.deviator()));
          trace[i] = t.trace();
        });
        progress.throwIfCancelled();
        repaired = repairDirections(mesh, region, n.directions, fixed, eig, type,
                                    smoothEveryFastTurn, progress);
        progress.throwIfCancelled();
        const int seed = centralVertex(mesh, region);
        ref = referenceField(mesh, region, repaired->directions, seed, eig[seed].medium,
                             report != nullptr);
        // The held angles, lifted along the jumps (period π: the medium eigenvector is a line),
        // while the multigrid may still be in set-up.
        std::vector<double> raw(count, 0.0);
        forEach(count, [&](int i) {
          if (fixed[i])
            raw[i] = signedAngle(ref.reference[i], eig[i].medium, repaired->directions[i]);
        });
        theta = liftAngles(region, fixed, raw, ref.jumps, std::numbers::pi);
      },
      [&] { laplacian.emplace(mesh, region, fixed, progress, JumpLaplacian::HeldCheck::Assumed); });
  const std::vector<Vec3>& directions = repaired->directions;
  r.roughEdges = repaired->roughEdges;
  r.repairedDirections = repaired->solvedVertices;
  double maxTrace = 0, maxNorm = 0;  // at the held vertices, whose values the solve spreads
  for (int i = 0; i < count; ++i) {
    if (!fixed[i]) continue;
    maxTrace = std::max(maxTrace, std::abs(trace[i]));
    maxNorm = std::max(maxNorm, field.at(region.vertices[i]).norm());
  }
  const bool hasTrace = r.traceSolved = traceBeyondRounding(maxTrace, maxNorm);
  r.nonBallSteps = ref.nonBallSteps;
  r.maxHolonomyDefect = ref.maxHolonomyDefect;
  progress.throwIfCancelled();

  // Columns θ, λ1, λ3 (and the trace): θ with the jumps, the others harmonic.
  progress.report(0.4, "solving the angle field and the eigenvalues");
  const int width = hasTrace ? 4 : 3;
  std::vector<double> values(static_cast<std::size_t>(count) * width);
  forEach(count, [&](int i) {
    values[i * width] = theta[i];
    values[i * width + 1] = eig[i].values[0];
    values[i * width + 2] = eig[i].values[2];
    if (hasTrace) values[i * width + 3] = trace[i];
  });
  // θ has the jumps. Solved to the relative residual of every harmonic solve in tfd
  // (SolverOptions::tolerance): θ and the eigenvalues to ~1e-8 of their scale, far below what
  // moves a degenerate point, in three iterations fewer than 1e-10 took (16 → 13 on the 1M
  // torus's removal).
  JumpSolveOptions solve;
  solve.tolerance = SolverOptions{}.tolerance;
  const JumpSolveResult solved = laplacian->solve(ref.jumps, values, width, solve, progress);
  r.iterations = solved.iterations;
  r.relativeResidual = solved.relativeResidual;

  // Recombine at the solved vertices: frame (N, medium, N × medium) and λ1, −λ1 − λ3, λ3.
  progress.report(0.9, "recombining tensors");
  std::vector<Tensor> out = field.values();
  forEach(count, [&](int i) {
    if (fixed[i]) return;
    const Vec3& nd = directions[i];
    const Vec3& u = ref.reference[i];
    const double th = values[i * width];
    const Vec3 medium = std::cos(th) * u + std::sin(th) * nd.cross(u);
    const Vec3 other = nd.cross(medium);
    const double l1 = values[i * width + 1], l3 = values[i * width + 2], l2 = -l1 - l3;
    const Vec3 major = type == DegenerateType::Linear ? nd : other;
    const Vec3 minor = type == DegenerateType::Linear ? other : nd;
    Mat3 m = l1 * major * major.transpose() + l2 * medium * medium.transpose() +
             l3 * minor * minor.transpose();
    if (hasTrace) m += values[i * width + 3] / 3 * Mat3::Identity();
    out[region.vertices[i]] = Tensor::fromMatrix(m);
  });

  const double inf = std::numeric_limits<double>::infinity();
  r.heldMinGap12 = r.heldMinGap23 = r.freeMinGap12 = r.freeMinGap23 = inf;
  for (int i = 0; i < count; ++i) {
    if (fixed[i]) {
      gaps(eig[i].values, r.heldMinGap12, r.heldMinGap23);
    } else {
      const double l1 = values[i * width + 1], l3 = values[i * width + 2];
      gaps(Vec3(l1, -l1 - l3, l3), r.freeMinGap12, r.freeMinGap23);
    }
  }
  if (r.freeVertices == 0) r.freeMinGap12 = r.freeMinGap23 = 0;
  if (report) *report = r;
  progress.report(1, "");
  return TensorField(field.meshPtr(), std::move(out));
}

}  // namespace tfd::core
