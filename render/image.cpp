#include "render/image.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace tfd::render {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

[[noreturn]] void pngError(png_structp png, png_const_charp message) {
  auto* what = static_cast<std::string*>(png_get_error_ptr(png));
  *what = message;
  png_longjmp(png, 1);
}
void pngWarning(png_structp, png_const_charp) {}

/// Writes with libpng; returns "" or the reason. (No C++ objects with destructors live across
/// the setjmp in this function.)
std::string writeRows(std::FILE* file, const Image& image, std::vector<png_bytep>& rows) {
  std::string error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, pngError, pngWarning);
  if (!png) return "out of memory";
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return error.empty() ? "libpng failed" : error;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGB_ALPHA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return {};
}

std::string readRows(std::FILE* file, Image& image) {
  std::string error;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, pngError, pngWarning);
  if (!png) return "out of memory";
  png_infop info = png_create_info_struct(png);
  std::vector<png_bytep>* rows = new std::vector<png_bytep>();
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    delete rows;
    return error.empty() ? "libpng failed" : error;
  }
  png_init_io(png, file);
  png_read_info(png, info);
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
  png_read_update_info(png, info);
  image.width = static_cast<int>(png_get_image_width(png, info));
  image.height = static_cast<int>(png_get_image_height(png, info));
  image.rgba.assign(std::size_t(image.width) * image.height * 4, 0);
  for (int y = 0; y < image.height; ++y)
    rows->push_back(&image.rgba[std::size_t(y) * image.width * 4]);
  png_read_image(png, rows->data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  delete rows;
  return {};
}

}  // namespace

void writePng(const Image& image, const std::filesystem::path& path) {
  if (image.empty() || image.rgba.size() != std::size_t(image.width) * image.height * 4)
    throw std::runtime_error(path.string() + ": cannot write an empty image");
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  std::string error;
  {
    File file(std::fopen(tmp.c_str(), "wb"));
    if (!file) throw std::runtime_error(path.string() + ": cannot write: " + std::strerror(errno));
    std::vector<png_bytep> rows;
    for (int y = 0; y < image.height; ++y)
      rows.push_back(const_cast<png_bytep>(&image.rgba[std::size_t(y) * image.width * 4]));
    error = writeRows(file.get(), image, rows);
    if (error.empty() && std::fflush(file.get()) != 0) error = std::strerror(errno);
  }
  std::error_code ec;
  if (error.empty()) std::filesystem::rename(tmp, path, ec);
  if (!error.empty() || ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error(path.string() +
                             ": cannot write: " + (error.empty() ? ec.message() : error));
  }
}

Image readPng(const std::filesystem::path& path) {
  File file(std::fopen(path.c_str(), "rb"));
  if (!file) throw std::runtime_error(path.string() + ": cannot read: " + std::strerror(errno));
  Image image;
  std::string error = readRows(file.get(), image);
  if (!error.empty()) throw std::runtime_error(path.string() + ": not a readable PNG: " + error);
  return image;
}

}  // namespace tfd::render
