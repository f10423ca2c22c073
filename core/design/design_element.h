#pragma once
// Design elements (paper §5, "Design"): a tensor value, or a degenerate tensor with the local
// linearisation T0 + (x−x0)Tx + (y−y0)Ty + (z−z0)Tz of Equation 2, in a user-rotatable frame.
#include <array>
#include <vector>

#include "core/degeneracy.h"
#include "core/tensor.h"

namespace tfd::core {

/// A local linearisation in a frame: value(p) = R (T0 + Σ_i d_i T_i) Rᵀ with d = Rᵀ(p − origin).
/// The frame's third column is the non-degenerate eigenvector of a degenerate element (the 2x2
/// blocks of T_x, T_y act on the degenerate plane spanned by the first two columns, Eq. 3).
struct LocalLinearization {
  Vec3 origin = Vec3::Zero();
  Mat3 frame = Mat3::Identity();         ///< columns: local x, y, z axes (orthonormal)
  Tensor value;                          ///< T0, in local coordinates
  std::array<Tensor, 3> jacobian{};      ///< T_x, T_y, T_z, in local coordinates
  Tensor evaluate(const Vec3& p) const;  ///< world-space tensor at p (traceless part)
};

/// A point design element applied to the vertices of the tet that holds it and to every vertex
/// within its support radius: max(radius, radiusEdges × the mesh's mean edge length).
struct PointElement {
  LocalLinearization field;
  bool degenerate = false;
  double radius = 0;       ///< absolute support radius (0: none)
  double radiusEdges = 0;  ///< support radius in mean edge lengths of the mesh (0: none)
};

/// The support a degenerate point gets by default, in mean edge lengths. Fixing only the 4
/// vertices of the holding tet lets the harmonic solve close the point's degenerate curve into
/// a speck about one tet long; fixing a ball of radius r keeps the linearisation's straight
/// degenerate line (Eq. 2–3) for a length of at least 2r, a curve a user can see.
inline constexpr double kAutoPointSupportEdges = 3.0;

/// Non-degenerate element: eigenvalues along the frame's columns (traceless part is taken).
LocalLinearization makeTensorLinearization(const Vec3& origin, const Mat3& frame,
                                           const Vec3& eigenvalues);
/// Degenerate element with the paper's defaults: eigenvalues (−1,−1,2) in the frame for linear,
/// (1,1,−2) for planar (the non-degenerate eigenvector is the frame's z axis), Jacobian of
/// Eq. 3 for a wedge and Ty negated for a trisector.
LocalLinearization makeDegenerateLinearization(const Vec3& origin, const Mat3& frame,
                                               DegenerateType type, DegeneratePattern pattern);

/// Rotation from Euler angles in degrees, applied about x, then y, then z (R = Rz Ry Rx).
Mat3 rotationFromEulerDegrees(const Vec3& degrees);

/// A sampled design curve (paper §5, "Parameterization"): one linearisation per sample, with
/// the sample's (rotated) parallel-transport frame. Vertices within `radius` of the curve
/// (a tube) take the value of the nearest sample's linearisation.
struct CurveElement {
  std::vector<LocalLinearization> samples;
  bool closed = false;
  bool degenerate = false;
  double radius = 0;
};

/// What Propagate receives: every design element of the graph, in input order.
struct ConstraintSet {
  std::vector<PointElement> points;
  std::vector<CurveElement> curves;
  bool empty() const { return points.empty() && curves.empty(); }
};

}  // namespace tfd::core
