#pragma once
// Implicit surfaces: polygonisation by marching tetrahedra and projection onto the zero set.
#include <functional>

#include "core/surface/surface_mesh.h"

namespace tfd::core {

/// A scalar function whose negative region is the solid and whose zero set is its surface.
using ImplicitFunction = std::function<double(const Vec3&)>;

/// Triangulates the zero set of `f` inside the box [lo, hi] by marching tetrahedra over a grid
/// of cubic cells of about `cell` size, each split into six tets around its main diagonal
/// (a conforming split, so neighbouring cells agree on shared faces). Grid values of exactly 0
/// count as outside, so the result is a closed, edge- and vertex-manifold surface, oriented
/// with counter-clockwise triangles seen from outside (f > 0). The solid must lie strictly
/// inside the box. Triangles can be tiny or thin; remesh the result for quality.
/// Deterministic (the grid is scanned in a fixed order).
SurfaceMesh polygonizeImplicit(const ImplicitFunction& f, const Vec3& lo, const Vec3& hi,
                               double cell);

/// Moves p onto the zero set of f by Newton steps along the central-difference gradient
/// (step `h`), at most `iterations` times; stops when |f| no longer decreases.
Vec3 projectToImplicit(const ImplicitFunction& f, const Vec3& p, double h, int iterations = 6);

}  // namespace tfd::core
