#pragma once
// Element synthesis (paper §8.2, Fig. 2): sticks along the major eigenvector in linear regions
// and leaves normal to the minor eigenvector in planar regions, at anisotropic Poisson-disk
// samples of a metric built from the tensor (core/synth/spacing_metric.h), with colliding
// elements rejected.
#include <cstdint>
#include <string>

#include "core/progress.h"
#include "core/surface/surface_mesh.h"
#include "core/synth/element_shapes.h"
#include "core/synth/instance_points.h"
#include "core/tensor_field.h"

namespace tfd::core {

struct ElementSynthesisOptions {
  double size = 0;        ///< element length in world units; 0: the mesh's bounding diagonal / 25
  double density = 1;     ///< base Poisson spacing r = size / density
  double anisotropy = 1;  ///< κ of the metric: spacing r·exp(κ λ_k / s) along e_k
  std::uint64_t seed = 1;
  int attempts = 30;           ///< candidates tried around a sample before it retires (Bridson)
  int maxElements = 100000;    ///< stop after this many elements
  bool rejectOverlaps = true;  ///< drop a candidate whose element box meets an accepted one
};

struct ElementSynthesisReport {
  double size = 0;                  ///< the element length used (resolved when options.size was 0)
  std::size_t samples = 0;          ///< accepted Poisson samples
  std::size_t lines = 0;            ///< sticks (linear region)
  std::size_t boxes = 0;            ///< leaves (planar region)
  std::size_t neutral = 0;          ///< samples with no element: neutral or zero deviator
  std::size_t overlapRejected = 0;  ///< candidates dropped because their element collided
  bool hitMaxElements = false;
  std::string summary() const;
};

struct ElementPlacement {
  InstancePoints points;  ///< one per element, in acceptance order
  ElementSynthesisReport report;
};

/// Places elements in the field's mesh. Samples come from Bridson's active-list dart throwing
/// generalised to the metric M (candidates at metric distance 1–2 from a sample; a candidate q
/// conflicts with a sample p when (q−p)ᵀ ½(M(p)+M(q)) (q−p) < 1), restarted from random points
/// of the volume until 64 darts in a row fail. At each sample the tensor's deviator A decides:
/// λ2 < 0 (linear) gives a stick whose local x is e1; λ2 > 0 (planar) a leaf whose local z
/// (normal) is e3 and local x is e1; neutral or zero A gives no element. The local frame is the
/// right-handed eigenframe [e1 e2 e3] at the sample. Element boxes are the shapes' bounding
/// boxes scaled by `size` and tested exactly (core/synth/oriented_box.h).
///
/// The sampling is one sequential pass driven by one seeded generator, so the result is the
/// same for a seed on any number of threads. Throws core::Error for non-positive size, density
/// or attempts.
ElementPlacement placeElements(const TensorField& field, const ElementShapes& shapes,
                               const ElementSynthesisOptions& options,
                               const Progress& progress = {});

/// The elements as one triangle mesh: each instance's shape rotated by its `orient`, scaled by
/// its `scale` and moved to its position (in parallel, into fixed slots: deterministic).
SurfaceMesh instanceElements(const InstancePoints& points, const ElementShapes& shapes);

/// The rotation matrix of a unit quaternion stored as (w, x, y, z).
Mat3 rotationOf(const Eigen::Vector4d& orient);

}  // namespace tfd::core
