#pragma once
// TEMP stub (branch `remove`): the agreed interface of branch `sffield`, which owns this file.
#include <vector>

#include "core/degeneracy.h"
#include "core/progress.h"
#include "core/tensor_field.h"

namespace tfd::core {

/// §6.3: a field equal to `field` on every vertex outside the region and on the region's
/// held vertices (`held[v] != 0`, v a mesh vertex index), and free of degenerate points inside
/// the region (the region must be a topological ball whose held boundary has none).
TensorField singularityFreeField(const TensorField& field, const std::vector<int>& regionTets,
                                 const std::vector<char>& held, DegenerateType type,
                                 Progress& progress);

}  // namespace tfd::core
