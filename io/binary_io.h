#pragma once
// Endian-aware loads and stores of scalars for binary mesh formats. Internal helper.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

namespace tfd::io {

enum class Endian { Little, Big };

inline constexpr Endian kNativeEndian =
    std::endian::native == std::endian::little ? Endian::Little : Endian::Big;

template <class T>
T byteSwapped(T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

/// Reads a T stored with `endian` byte order at p (no alignment needed).
template <class T>
T loadScalar(const char* p, Endian endian) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return endian == kNativeEndian ? value : byteSwapped(value);
}

/// Appends a T in `endian` byte order.
template <class T>
void appendScalar(std::string& out, T value, Endian endian) {
  if (endian != kNativeEndian) value = byteSwapped(value);
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

}  // namespace tfd::io
