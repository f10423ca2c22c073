#pragma once
// Procedural closed surfaces (sphere, box, torus, genus-2 double torus) at a chosen resolution,
// so examples, tests and benchmarks need no data files.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/surface/surface_mesh.h"

namespace tfd::core {

enum class PrimitiveShape { Sphere, Box, Torus, DoubleTorus };

/// Shape and dimensions; each shape reads only its own fields. Every solid is centred at the
/// origin; tori lie in the xy plane around the z axis.
struct PrimitiveSpec {
  PrimitiveShape shape = PrimitiveShape::Sphere;
  double radius = 1.0;        ///< sphere
  Vec3 size = Vec3(2, 2, 2);  ///< box edge lengths
  double majorRadius = 1.0;   ///< tori: ring radius (centre to tube centre)
  double minorRadius = 0.4;   ///< tori: tube radius, < majorRadius
};

/// "sphere", "box", "torus", "double_torus", for messages and test names.
std::string primitiveShapeName(PrimitiveShape shape);
/// Canonical names, in enum order.
std::vector<std::string> primitiveShapeNames();

/// Throws core::Error naming the parameter when a dimension is not positive and finite, or a
/// torus tube radius is not below the ring radius.
void validatePrimitive(const PrimitiveSpec& spec);

/// Volume of the exact solid: analytic for sphere, box and torus; for the double torus (no
/// closed form) a midpoint-rule integral of its implicit function on a fine grid (about 0.3 %).
double primitiveVolume(const PrimitiveSpec& spec);

/// Closed, manifold, outward-oriented (counter-clockwise seen from outside) triangle surface of
/// the solid with edges close to `edgeLength`; the Euler characteristic is 2 (sphere, box),
/// 0 (torus) or −2 (double torus).
/// - sphere: geodesic icosphere (each icosahedron face split n × n, projected on the sphere);
/// - box: a structured grid on each face, two triangles per cell;
/// - torus: parametric grid, then isotropic remeshing projected on the exact torus;
/// - double torus: the smooth union of two overlapping tori (side by side along x, centres at
///   ±(R + r/2)), polygonised by marching tetrahedra and isotropically remeshed onto the
///   implicit surface.
/// The edge length is clamped so the shape stays resolved (at most about the tube or sphere
/// radius). Deterministic. Throws core::Error for invalid dimensions or a non-positive length.
SurfaceMesh makePrimitive(const PrimitiveSpec& spec, double edgeLength);

SurfaceMesh makeSphere(double radius, double edgeLength);
SurfaceMesh makeBox(const Vec3& size, double edgeLength);
SurfaceMesh makeTorus(double majorRadius, double minorRadius, double edgeLength);
SurfaceMesh makeDoubleTorus(double majorRadius, double minorRadius, double edgeLength);

/// Surface edge length that makes a quality tet mesh of a solid of `volume` have about
/// `targetTets` tets when its interior edges match the surface edges (calibrated against
/// TetGen, see io/tetgen/tetgen_mesher.h).
double edgeLengthForTargetTets(double volume, double targetTets);

/// makePrimitive(spec, edgeLengthForTargetTets(primitiveVolume(spec), targetTets)).
SurfaceMesh makePrimitiveForTets(const PrimitiveSpec& spec, double targetTets);

}  // namespace tfd::core
