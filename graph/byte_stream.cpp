#include "graph/byte_stream.h"

namespace tfd::graph {

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

std::uint64_t checksum64(std::string_view bytes) {
  constexpr std::uint64_t kPrime = 0x100000001b3ull;
  std::uint64_t lane[4] = {0xcbf29ce484222325ull, 0x84222325cbf29ce4ull, 0x9e3779b97f4a7c15ull,
                           0xc2b2ae3d27d4eb4full};
  const char* p = bytes.data();
  std::size_t n = bytes.size();
  for (; n >= 32; n -= 32, p += 32) {
    for (int i = 0; i < 4; ++i) {
      std::uint64_t w;
      std::memcpy(&w, p + 8 * i, 8);
      lane[i] = (lane[i] ^ w) * kPrime;
      lane[i] ^= lane[i] >> 29;
    }
  }
  std::uint64_t h = fnv1a64(std::string_view(p, n)) ^ bytes.size();
  for (const std::uint64_t l : lane) {
    h = (h ^ l) * kPrime;
    h ^= h >> 29;
  }
  return h;
}

}  // namespace tfd::graph
