#include "core/edit/local_smooth.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "core/region/vertex_selection.h"
#include "core/topology/extract_degenerate_curves.h"

namespace tfd::core {
namespace {

std::string format(const Vec3& p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

void checkPositive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0) {
    std::ostringstream s;
    s << name << ": must be a positive number, got " << value;
    throw Error(s.str());
  }
}

std::vector<int> curveRegion(const TensorField& field, const LocalSmoothOptions& options,
                             double* pickDistance, const Progress& progress);

}  // namespace

std::string LocalSmoothReport::summary() const {
  std::ostringstream s;
  s << "smoothed " << freeVertices << " of " << regionVertices << " region vertices";
  if (boundaryFixed > 0) s << " (" << boundaryFixed << " on the domain boundary held fixed)";
  s << " in " << iterations << " iterations";
  return s.str();
}

std::vector<int> smoothRegionVertices(const TensorField& field, const LocalSmoothOptions& options,
                                      double* pickDistance, const Progress& progress) {
  const TetMesh& mesh = field.mesh();
  std::vector<int> region;
  std::ostringstream what;
  switch (options.region) {
    case SmoothRegionShape::Sphere: {
      if (!options.center.allFinite()) throw Error("center: not finite");
      checkPositive(options.radius, "radius");
      region = verticesInSphere(mesh, options.center, options.radius);
      what << "the sphere at " << format(options.center) << " radius " << options.radius;
      break;
    }
    case SmoothRegionShape::Box: {
      if (!options.center.allFinite()) throw Error("center: not finite");
      for (int a = 0; a < 3; ++a) checkPositive(options.size[a], "size");
      region = verticesInBox(mesh, options.center, options.size);
      what << "the box at " << format(options.center) << " size " << format(options.size);
      break;
    }
    case SmoothRegionShape::Curve:
      region = curveRegion(field, options, pickDistance, progress);
      what << "the tube of radius " << options.radius << " around the degenerate curve nearest "
           << format(options.pick);
      break;
  }
  if (region.empty()) throw Error(what.str() + " contains no mesh vertex");
  return region;
}

LocalSmoothResult smoothVertices(const TensorField& field, const std::vector<int>& region,
                                 const SolverOptions& solver, const Progress& progress) {
  const TetMesh& mesh = field.mesh();
  const std::size_t n = mesh.vertexCount();
  LocalSmoothReport report;
  report.regionVertices = region.size();
  std::vector<int> freeVertices;
  freeVertices.reserve(region.size());
  for (std::size_t k = 0; k < region.size(); ++k) {
    const int v = region[k];
    if (v < 0 || static_cast<std::size_t>(v) >= n || (k > 0 && region[k - 1] >= v)) {
      throw Error("local smooth: region vertex ids must be ascending, unique and in range");
    }
    if (mesh.isBoundaryVertex(v)) {
      ++report.boundaryFixed;  // K = R ∩ ∂M is part of the boundary condition
    } else {
      freeVertices.push_back(v);
    }
  }
  report.freeVertices = freeVertices.size();
  if (freeVertices.empty()) return {field, report};

  // Set-up proportional to the region: only the free rows of the stiffness matrix.
  const HarmonicSolver harmonic = HarmonicSolver::forRegion(field.meshPtr(), freeVertices, solver);
  progress.throwIfCancelled();
  // The trace (dropped by the traceless solve) is smoothed as one more harmonic scalar, in the
  // same solve, when the field has one (beyond rounding) at a free vertex or at a neighbour of
  // one.
  double maxTrace = 0, maxNorm = 0;
  for (int v : freeVertices) {
    for (int t : mesh.vertexTets(v)) {
      for (int w : mesh.tets()[t]) {
        maxTrace = std::max(maxTrace, std::abs(field.at(w).trace()));
        maxNorm = std::max(maxNorm, field.at(w).norm());
      }
    }
  }
  const bool hasTrace = traceBeyondRounding(maxTrace, maxNorm);
  const SolveResult solved = hasTrace ? harmonic.solveWithTrace(field.values(), progress)
                                      : harmonic.solve(field.values(), progress);
  report.iterations = solved.iterations;
  report.relativeResidual = solved.relativeResidual;

  std::vector<Tensor> values = field.values();  // everything outside the free set: bitwise kept
  for (int v : freeVertices) values[v] = solved.values[v];
  return {TensorField(field.meshPtr(), std::move(values)), report};
}

LocalSmoothResult localSmooth(const TensorField& field, const LocalSmoothOptions& options,
                              const Progress& progress) {
  double pickDistance = 0;
  const std::vector<int> region = smoothRegionVertices(field, options, &pickDistance, progress);
  LocalSmoothResult result = smoothVertices(field, region, options.solver, progress);
  result.report.pickDistance = pickDistance;
  return result;
}

namespace {

std::vector<int> curveRegion(const TensorField& field, const LocalSmoothOptions& options,
                             double* pickDistance, const Progress& progress) {
  if (!options.pick.allFinite()) throw Error("pick: not finite");
  checkPositive(options.radius, "radius");
  std::optional<DegenerateCurves> extracted;
  const DegenerateCurves* curves = options.curves;
  if (curves == nullptr) {
    progress.report(0, "extracting degenerate curves");
    extracted = extractDegenerateCurves(field, {}, progress);
    curves = &*extracted;
  }
  const std::optional<CurvePick> picked = curves->pick(options.pick);
  if (!picked) {
    throw Error("pick: the field has no degenerate curve to pick near " + format(options.pick));
  }
  if (pickDistance) *pickDistance = picked->distance;
  return verticesAroundCurve(field.mesh(), curves->curve(picked->curveId), options.radius);
}

}  // namespace

}  // namespace tfd::core
