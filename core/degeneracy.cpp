#include "core/degeneracy.h"

namespace tfd::core {

const char* toString(DegenerateType type) {
  return type == DegenerateType::Linear ? "linear" : "planar";
}

const char* toString(DegeneratePattern pattern) {
  switch (pattern) {
    case DegeneratePattern::Wedge:
      return "wedge";
    case DegeneratePattern::Trisector:
      return "trisector";
    case DegeneratePattern::Transition:
      return "transition";
  }
  return "unknown";
}

std::array<std::uint8_t, 3> fig5Colour(DegenerateType type, DegeneratePattern pattern) {
  if (pattern == DegeneratePattern::Transition) return {255, 255, 255};
  if (type == DegenerateType::Linear)
    return pattern == DegeneratePattern::Wedge ? std::array<std::uint8_t, 3>{0, 200, 0}
                                               : std::array<std::uint8_t, 3>{0, 80, 255};
  return pattern == DegeneratePattern::Wedge ? std::array<std::uint8_t, 3>{255, 220, 0}
                                             : std::array<std::uint8_t, 3>{230, 0, 0};
}

}  // namespace tfd::core
