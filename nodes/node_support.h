#pragma once
// Small helpers shared by node files: parameter conversions and progress.
#include <string>

#include "core/progress.h"
#include "core/tensor.h"
#include "graph/cook_context.h"

namespace tfd::nodes {

inline core::Vec3 toVec3(const graph::Vec3Param& v) { return {v[0], v[1], v[2]}; }

inline core::Vec3 vec3Param(const graph::CookContext& c, std::string_view name) {
  return toVec3(c.param<graph::Vec3Param>(name));
}

/// A core::Progress that reports into the node's progress and sees its cancellation.
inline core::Progress progressOf(const graph::CookContext& c) {
  return core::Progress(c.progressCallback(), &c.cancelFlag());
}

}  // namespace tfd::nodes
