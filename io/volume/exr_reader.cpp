#include "io/volume/exr_reader.h"

#include <OpenEXR/ImfBoxAttribute.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompressionAttribute.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfLineOrderAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <cstdint>
#include <exception>
#include <new>

#include "core/error.h"
#include "core/memory_budget.h"
#include "io/text_scanner.h"

namespace tfd::io {

namespace {

template <typename A>
const A* as(const Imf::Attribute& a) {
  return dynamic_cast<const A*>(&a);
}

ExrAttribute describe(const Imf::Attribute& a) {
  ExrAttribute out;
  out.type = a.typeName();
  if (const auto* s = as<Imf::StringAttribute>(a)) out.text = s->value();
  if (const auto* v = as<Imf::IntAttribute>(a)) out.numbers = {double(v->value())};
  if (const auto* v = as<Imf::FloatAttribute>(a)) out.numbers = {double(v->value())};
  if (const auto* v = as<Imf::DoubleAttribute>(a)) out.numbers = {v->value()};
  if (const auto* v = as<Imf::V2iAttribute>(a))
    out.numbers = {double(v->value().x), double(v->value().y)};
  if (const auto* v = as<Imf::V2fAttribute>(a)) out.numbers = {v->value().x, v->value().y};
  if (const auto* v = as<Imf::V2dAttribute>(a)) out.numbers = {v->value().x, v->value().y};
  if (const auto* v = as<Imf::V3iAttribute>(a)) {
    out.numbers = {double(v->value().x), double(v->value().y), double(v->value().z)};
  }
  if (const auto* v = as<Imf::V3fAttribute>(a)) {
    out.numbers = {v->value().x, v->value().y, v->value().z};
  }
  if (const auto* v = as<Imf::V3dAttribute>(a)) {
    out.numbers = {v->value().x, v->value().y, v->value().z};
  }
  if (const auto* v = as<Imf::Box2iAttribute>(a)) {
    const auto& b = v->value();
    out.numbers = {double(b.min.x), double(b.min.y), double(b.max.x), double(b.max.y)};
  }
  if (const auto* v = as<Imf::CompressionAttribute>(a)) {
    static const char* names[] = {"none",  "rle", "zips", "zip",  "piz",
                                  "pxr24", "b44", "b44a", "dwaa", "dwab"};
    const int c = int(v->value());
    out.text = c >= 0 && c < int(std::size(names)) ? names[c] : "unknown";
  }
  if (const auto* v = as<Imf::LineOrderAttribute>(a)) {
    out.text = v->value() == Imf::INCREASING_Y   ? "increasing y"
               : v->value() == Imf::DECREASING_Y ? "decreasing y"
                                                 : "random y";
  }
  return out;
}

const char* pixelTypeName(Imf::PixelType t) {
  switch (t) {
    case Imf::UINT:
      return "uint";
    case Imf::HALF:
      return "half";
    case Imf::FLOAT:
      return "float";
    default:
      return "unknown";
  }
}

}  // namespace

ExrImage readExrImage(const std::filesystem::path& path) {
  ExrImage image;
  try {
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i dw = header.dataWindow();
    image.dataMin = {dw.min.x, dw.min.y};
    image.dataMax = {dw.max.x, dw.max.y};
    // In 64 bits: a damaged header can announce any window.
    const std::int64_t width = std::int64_t(dw.max.x) - dw.min.x + 1;
    const std::int64_t height = std::int64_t(dw.max.y) - dw.min.y + 1;
    if (width <= 0 || height <= 0 || width > (1 << 30) || height > (1 << 30))
      throw core::Error("EXR file '" + path.string() + "': its data window (" +
                        std::to_string(width) + " x " + std::to_string(height) +
                        " pixels) is empty or out of range (a damaged file?)");
    double channels = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) channels += 1;
    core::checkMemory(double(width) * double(height) * channels * sizeof(float),
                      "EXR file '" + path.string() + "' (its data window of " +
                          std::to_string(width) + " x " + std::to_string(height) + " pixels, " +
                          std::to_string(int(channels)) + " channels, as the file announces)");
    image.width = int(width);
    image.height = int(height);
    for (auto it = header.begin(); it != header.end(); ++it) {
      if (std::string(it.name()) == "channels") continue;
      image.attributes[it.name()] = describe(it.attribute());
    }
    header.channels().layers(image.layers);
    Imf::FrameBuffer frameBuffer;
    const std::size_t count = std::size_t(image.width) * image.height;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
      image.channelTypes[it.name()] = pixelTypeName(it.channel().type);
      auto& pixels = image.pixels[it.name()];
      pixels.assign(count, 0.0f);
      // Base shifted so the data window's first pixel lands at pixels[0].
      char* base = reinterpret_cast<char*>(pixels.data()) -
                   (std::ptrdiff_t(dw.min.x) + std::ptrdiff_t(dw.min.y) * image.width) *
                       std::ptrdiff_t(sizeof(float));
      frameBuffer.insert(it.name(),
                         Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * image.width));
    }
    file.setFrameBuffer(frameBuffer);
    file.readPixels(dw.min.y, dw.max.y);
  } catch (const core::Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw core::Error("cannot read EXR file '" + path.string() +
                      "': it asks for more memory than can be allocated (a damaged file?)");
  } catch (const std::exception& e) {
    throw core::Error("cannot read EXR file '" + path.string() + "': " + printableText(e.what()));
  }
  return image;
}

}  // namespace tfd::io
