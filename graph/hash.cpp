#include "graph/hash.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace tfd::graph {

namespace {
constexpr std::uint64_t kPrime1 = 0x9e3779b185ebca87ull;
constexpr std::uint64_t kPrime2 = 0xc2b2ae3d27d4eb4full;

std::uint64_t fmix(std::uint64_t k) {  // MurmurHash3 finaliser: full avalanche
  k ^= k >> 33;
  k *= 0xff51afd7ed558ccdull;
  k ^= k >> 33;
  k *= 0xc4ceb9fe1a85ec53ull;
  k ^= k >> 33;
  return k;
}
}  // namespace

std::string Hash::toHex() const {
  static const char* digits = "0123456789abcdef";
  std::string out(32, '0');
  for (int i = 0; i < 16; ++i) {
    out[15 - i] = digits[(hi >> (4 * i)) & 0xf];
    out[31 - i] = digits[(lo >> (4 * i)) & 0xf];
  }
  return out;
}

Hasher::Hasher() : a_(0x243f6a8885a308d3ull), b_(0x13198a2e03707344ull) {}

void Hasher::word(std::uint64_t w) {
  ++count_;
  a_ = std::rotl((a_ ^ w) * kPrime1, 31) * kPrime2;
  b_ = std::rotl(b_ + w * kPrime2, 27) * kPrime1 + (a_ >> 17);
}

Hasher& Hasher::add(std::string_view text) {
  word(0x5354520000000000ull ^ text.size());  // tag "STR" + length
  std::size_t i = 0;
  for (; i + 8 <= text.size(); i += 8) {
    std::uint64_t w = 0;
    for (int k = 0; k < 8; ++k)
      w |= static_cast<std::uint64_t>(static_cast<unsigned char>(text[i + k])) << (8 * k);
    word(w);
  }
  if (i < text.size()) {
    std::uint64_t w = 0;
    for (int k = 0; i + k < text.size(); ++k)
      w |= static_cast<std::uint64_t>(static_cast<unsigned char>(text[i + k])) << (8 * k);
    word(w);
  }
  return *this;
}

Hasher& Hasher::add(std::uint64_t value) {
  word(0x55363400000000ull);  // "U64"
  word(value);
  return *this;
}

Hasher& Hasher::add(std::int64_t value) {
  word(0x49363400000000ull);  // "I64"
  word(static_cast<std::uint64_t>(value));
  return *this;
}

Hasher& Hasher::add(bool value) {
  word(0x424f4f4c00000000ull | (value ? 1u : 0u));
  return *this;
}

Hasher& Hasher::add(double value) {
  if (value == 0.0) value = 0.0;                // fold -0.0
  if (std::isnan(value)) value = std::nan("");  // fold NaN payloads
  word(0x4636340000000000ull);                  // "F64"
  word(std::bit_cast<std::uint64_t>(value));
  return *this;
}

Hasher& Hasher::add(const Hash& value) {
  word(0x4853480000000000ull);  // "HSH"
  word(value.hi);
  word(value.lo);
  return *this;
}

Hash Hasher::finish() const {
  std::uint64_t a = fmix(a_ ^ count_);
  std::uint64_t b = fmix(b_ + a * kPrime1);
  return Hash{fmix(a ^ std::rotl(b, 29)), b};
}

}  // namespace tfd::graph
