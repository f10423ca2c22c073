#pragma once
// An RGBA8 picture (rows top to bottom) and its PNG file form (libpng).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace tfd::render {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, first row at the top

  bool empty() const { return width <= 0 || height <= 0; }
  const std::uint8_t* pixel(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

/// Writes an 8-bit RGBA PNG atomically (temporary file, then rename): no partial file is left.
/// Throws std::runtime_error naming the file.
void writePng(const Image& image, const std::filesystem::path& path);
/// Reads a PNG (any colour type, converted to RGBA8). Throws std::runtime_error naming the file.
Image readPng(const std::filesystem::path& path);

}  // namespace tfd::render
