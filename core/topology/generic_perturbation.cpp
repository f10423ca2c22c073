#include "core/topology/generic_perturbation.h"

namespace tfd::core::topology {
namespace {

std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace

Tensor perturbationDirection(std::int64_t vertex) {
  std::array<double, 5> c{};
  std::uint64_t state = splitMix64(std::uint64_t(vertex) * 0x2545F4914F6CDD1Dull + 0x7F4A7C15ull);
  for (double& x : c) {
    state = splitMix64(state);
    x = double(state >> 11) * (2.0 / 9007199254740992.0) - 1.0;  // 53 bits → [−1, 1)
  }
  return Tensor::fromVec5(c);
}

}  // namespace tfd::core::topology
