#pragma once
// Degenerate-curve extraction for a piecewise-linear tensor field on a tet mesh (paper §3–4:
// "the degenerate curves are extracted based on the method of Zheng and Pang [2004]", with the
// exact face and tet algebra of the algorithms note §2–5).
//
// Pipeline (each stage deterministic for any thread count):
//  1. per vertex: deviator (the topology only depends on it) and a lower bound of its distance
//     to the degenerate set;
//  2. per unique face, in parallel with one output slot per face: eigen-gap and Bernstein
//     pre-filters (conservative), then the exact conic-intersection solver (face_solver.h);
//  3. points on edges / vertices are canonicalised (one node per edge parameter / vertex) and
//     shared by every tet around them; face points are shared by the face's two tets;
//  4. per tet with points, in parallel: θ-ordering on the tet conic with the midpoint rule
//     (tet_connection.h) and wedge / trisector / transition classification on the exact arcs
//     (segment_classification.h);
//  5. non-generic faces or tets (block-diagonal fields, curves along edges or through vertices,
//     tangencies, odd point counts) get a deterministic perturbation of their vertices
//     (generic_perturbation.h) and everything touching those vertices is recomputed, for up to
//     maxPerturbationRounds rounds; what remains is reported as warnings;
//  6. serial chaining into polylines (curve_assembly.h) and canonical ordering.
#include "core/progress.h"
#include "core/tensor_field.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::core {

struct ExtractOptions {
  /// Skip faces that provably hold no degenerate point (eigen-gap and Bernstein tests). Only
  /// affects speed: the tests are conservative.
  bool prefilter = true;
  /// Relative size ε of the deterministic fallback perturbation of non-generic vertices
  /// (scaled by the largest tensor norm around the vertex). 0 disables the fallback.
  double perturbation = 1e-7;
  /// Fallback rounds; each round multiplies ε by 10 for vertices that are still non-generic.
  int maxPerturbationRounds = 3;
  /// Extra points per tet segment sampled on the exact curve, for smoother drawing.
  int arcSamples = 0;
  /// Barycentric tolerance below which a face point counts as lying on an edge or vertex.
  double edgeTolerance = 1e-10;
};

/// Extracts and classifies the degenerate curves of `field`. Warns (instead of failing) for a
/// zero or constant field and for non-generic leftovers (counts of odd tets etc.). Throws
/// core::Error for invalid options (naming the option) and core::Cancelled when cancelled.
DegenerateCurves extractDegenerateCurves(const TensorField& field,
                                         const ExtractOptions& options = {},
                                         const Progress& progress = {});

}  // namespace tfd::core
