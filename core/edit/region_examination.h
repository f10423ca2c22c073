#pragma once
// What a try of a region edit (removal §6.4, reconnection §6.2) reads off its grown region: the
// independent ball check, and meanwhile its vertices, complex and vectorised non-repeating
// eigenvector (both only read the region). The caller checks them in its own order: an error of
// the vectorisation is kept for the point where that order would meet it (`vectorised()`).
#include <exception>
#include <optional>
#include <vector>

#include "core/edit/region_complex.h"
#include "core/edit/vectorise_eigenvector.h"
#include "core/region/ball_check.h"
#include "core/region/region_vertices.h"
#include "core/tensor_field.h"

namespace tfd::core {

struct RegionExamination {
  BallCheck ball;
  RegionVertices vertices;
  std::optional<RegionComplex> complex;
  std::optional<VectorisedEigenvector> vec;
  std::exception_ptr error;  ///< a core::Error of the complex or the vectorisation

  /// Rethrows the kept error, if any.
  void throwIfFailed() const {
    if (error) std::rethrow_exception(error);
  }
};

/// `tets`: the region's distinct tets, ascending.
RegionExamination examineRegion(const TensorField& field, const std::vector<int>& tets,
                                DegenerateType type);

}  // namespace tfd::core
