#pragma once
// Random vectors drawn in a fixed order, the same with every compiler.
#include "core/tensor.h"

namespace tfd::test {

/// Three draws of `dist` as a vector. `Vec3(u(rng), u(rng), u(rng))` leaves the order of the
/// draws to the compiler (C++ does not sequence a function's arguments): GCC draws z first and
/// Clang x first, so one seed made different jittered meshes in the Release build (GCC) and the
/// sanitizer build (Clang), and tests designed on the first failed on the second. This draws
/// z, then y, then x: GCC's order, so the fixtures are the ones the tests were designed on.
template <class Distribution, class Engine>
core::Vec3 drawVec3(Distribution& dist, Engine& rng) {
  const double z = dist(rng);
  const double y = dist(rng);
  const double x = dist(rng);
  return {x, y, z};
}

}  // namespace tfd::test
