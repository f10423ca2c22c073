#pragma once
// Reads the degenerate-curve exchange format that writeCurvesJson writes
// (io/curves/curve_writers.h, "tfd-degenerate-curves", formatVersion 1), for `tfd info` and
// for tools that read curves back. Strict: every problem is a core::Error naming the file and
// the JSON pointer of the place ("curve file 'c.json' at /curves/2/points/5: expected
// [x, y, z] with 3 finite numbers, found ..."); text from the file is quoted printably.
#include <filesystem>
#include <vector>

#include "core/degeneracy.h"
#include "core/tensor.h"

namespace tfd::io {

struct CurveFileEntry {
  int id = 0;
  core::DegenerateType type = core::DegenerateType::Linear;
  bool closed = false;
  std::vector<core::Vec3> points;
  std::vector<core::DegeneratePattern> patterns;  ///< one per point
};

struct CurveFile {
  int formatVersion = 1;
  std::vector<CurveFileEntry> curves;
};

CurveFile readCurvesJson(const std::filesystem::path& path);

}  // namespace tfd::io
