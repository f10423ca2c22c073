#pragma once
// What a VTK XML file (.vtu, .vtp) holds, read from its element tree without decoding the
// data: dataset type, point and cell counts, and the point and cell arrays with their types,
// component counts and which are active. For `tfd info`; returns data, the CLI words it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tfd::io {

struct VtkArraySummary {
  std::string name;
  std::string type;  ///< VTK's word: Float32, Float64, Int32, UInt8, ...
  int components = 1;
  std::string active;  ///< the attribute it is active for (Scalars, Vectors, Tensors, ...) or ""
};

struct VtkXmlSummary {
  std::string dataset;     ///< UnstructuredGrid, PolyData, ...
  std::string encoding;    ///< ascii, binary (inline base64), appended; "mixed" when they differ
  std::string compressor;  ///< "" when uncompressed
  std::int64_t points = 0, cells = 0;  ///< summed over pieces; PolyData cells are all kinds
  std::int64_t verts = 0, lines = 0, strips = 0, polys = 0;  ///< PolyData only
  int pieces = 0;
  std::vector<VtkArraySummary> pointArrays, cellArrays;  ///< those of the first piece
};

/// Throws core::Error naming the file and line for unreadable or malformed files.
VtkXmlSummary summarizeVtkXml(const std::filesystem::path& path);

}  // namespace tfd::io
