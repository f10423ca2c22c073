#pragma once
// Reads a scan-line OpenEXR image into plain data, for inspection (`tfd info`) and for tests
// that check what the EXR slice writer produced. Only the OpenEXR library reads the file.
#include <array>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace tfd::io {

struct ExrAttribute {
  std::string type;             ///< OpenEXR's type name: "double", "v3d", "string", "int", …
  std::string text;             ///< for strings (and compression / line order names)
  std::vector<double> numbers;  ///< for numeric types: scalars, vectors, boxes (min then max)
};

struct ExrImage {
  std::array<int, 2> dataMin{0, 0}, dataMax{-1, -1};  ///< data window, inclusive
  int width = 0, height = 0;
  std::map<std::string, ExrAttribute> attributes;  ///< every header attribute except channels
  /// Channel name → pixel type name ("float", "half", "uint").
  std::map<std::string, std::string> channelTypes;
  /// Layer names as OpenEXR parses them (Imf::ChannelList::layers: the text before a
  /// channel name's last '.'); channels without a '.' (R, G, B, A) are in no layer.
  std::set<std::string> layers;
  /// Channel name → pixels converted to float, row-major from the data window's first row.
  std::map<std::string, std::vector<float>> pixels;

  float at(const std::string& channel, int column, int row) const {
    return pixels.at(channel)[std::size_t(row) * width + column];
  }
};

/// Throws core::Error naming the file when it cannot be opened or read.
ExrImage readExrImage(const std::filesystem::path& path);

}  // namespace tfd::io
