#pragma once
// A 128-bit content hash used as the cache key of cooked nodes (Gaffer-style hash() before
// compute()). Not cryptographic; stable across runs, platforms of the same endianness-neutral
// encoding (values are fed as explicit little-endian words) and thread counts.
#include <compare>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace tfd::graph {

struct Hash {
  std::uint64_t hi = 0, lo = 0;
  auto operator<=>(const Hash&) const = default;
  bool isZero() const { return hi == 0 && lo == 0; }
  /// 32 lowercase hex digits.
  std::string toHex() const;
};

/// Accumulates typed values. Every add() is framed (strings carry their length, each value a
/// tag), so different sequences of values cannot produce the same byte stream.
class Hasher {
 public:
  Hasher();
  Hasher& add(std::string_view text);
  Hasher& add(const char* text) { return add(std::string_view(text)); }
  Hasher& add(std::uint64_t value);
  Hasher& add(std::int64_t value);
  Hasher& add(int value) { return add(static_cast<std::int64_t>(value)); }
  Hasher& add(bool value);
  /// Hashes the bit pattern; -0.0 and 0.0 hash alike, every NaN hashes alike.
  Hasher& add(double value);
  Hasher& add(const Hash& value);
  Hash finish() const;

 private:
  void word(std::uint64_t w);
  std::uint64_t a_, b_, count_ = 0;
};

}  // namespace tfd::graph

template <>
struct std::hash<tfd::graph::Hash> {
  std::size_t operator()(const tfd::graph::Hash& h) const noexcept {
    return static_cast<std::size_t>(h.lo ^ (h.hi * 0x9e3779b97f4a7c15ull));
  }
};
