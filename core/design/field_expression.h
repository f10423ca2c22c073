#pragma once
// Tensor fields from expressions in x, y, z (muParser syntax), for analytic test fields and
// procedural designs.
#include <array>
#include <memory>
#include <string>

#include "core/progress.h"
#include "core/tensor_field.h"

namespace tfd::core {

/// Component expressions in VTK order (xx, yy, zz, xy, yz, xz); variables x, y, z and the
/// constants `pi`, `_e`; the usual functions (sin, cos, exp, sqrt, ...).
struct TensorExpressions {
  std::array<std::string, 6> components{"0", "0", "0", "0", "0", "0"};
};

/// Names of the components in TensorExpressions order: "xx", "yy", "zz", "xy", "yz", "xz".
const std::array<const char*, 6>& tensorComponentNames();

/// Checks that every expression parses and uses only x, y, z. Throws core::Error naming the
/// component, the position and the problem, e.g. `component "xy": unexpected token "*" at
/// position 3`.
void checkExpressions(const TensorExpressions& expressions);

/// Evaluates the expressions at every mesh vertex (in parallel, deterministic) and keeps the
/// traceless part. Throws core::Error when an expression is invalid or gives a non-finite value
/// (naming the component and the vertex position).
TensorField evaluateFieldExpression(std::shared_ptr<const TetMesh> mesh,
                                    const TensorExpressions& expressions,
                                    const Progress& progress = {});

}  // namespace tfd::core
