#include "io/volume/exr_writer.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <exception>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"

namespace tfd::io {

namespace {

/// Where the frame placeholder sits in a pattern and how wide it is.
struct Placeholder {
  std::size_t begin = 0, end = 0;  ///< [begin, end) in the pattern
  int width = 0;                   ///< zero-padding width (0: none)
};

/// Finds the single placeholder; `%%` is a literal percent sign. Throws core::Error otherwise.
Placeholder findPlaceholder(const std::string& pattern) {
  std::vector<Placeholder> found;
  for (std::size_t i = 0; i < pattern.size();) {
    if (pattern[i] == '%') {
      if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
        i += 2;
        continue;
      }
      std::size_t j = i + 1;
      int width = 0;
      while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) {
        width = std::min(width * 10 + (pattern[j] - '0'), 64);
        ++j;
      }
      if (j >= pattern.size() || pattern[j] != 'd') {
        throw core::Error("EXR path pattern '" + pattern +
                          "': only %d, %0Nd or a run of # may stand for the slice number "
                          "(write %% for a percent sign)");
      }
      found.push_back({i, j + 1, width});
      i = j + 1;
    } else if (pattern[i] == '#') {
      std::size_t j = i;
      while (j < pattern.size() && pattern[j] == '#') ++j;
      found.push_back({i, j, static_cast<int>(std::min<std::size_t>(j - i, 64))});
      i = j;
    } else {
      ++i;
    }
  }
  if (found.size() != 1) {
    throw core::Error("EXR path pattern '" + pattern + "' must hold exactly one slice number " +
                      "placeholder (like %04d or ####), found " + std::to_string(found.size()));
  }
  return found.front();
}

std::string unescapePercent(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out += s[i];
    if (s[i] == '%' && i + 1 < s.size() && s[i + 1] == '%') ++i;
  }
  return out;
}

Imath::V3d v3d(const core::Vec3& v) { return Imath::V3d(v.x(), v.y(), v.z()); }

/// Removes files, ignoring errors (cleanup after a failure).
void removeAll(const std::vector<std::filesystem::path>& paths) {
  std::error_code ec;
  for (const auto& p : paths) std::filesystem::remove(p, ec);
}

}  // namespace

std::string expandFramePattern(const std::string& pattern, int frame) {
  const Placeholder ph = findPlaceholder(pattern);
  char digits[96];
  std::snprintf(digits, sizeof digits, "%0*d", ph.width, frame);
  return unescapePercent(pattern.substr(0, ph.begin)) + digits +
         unescapePercent(pattern.substr(ph.end));
}

VoxelExportStats writeFieldExrSlices(const std::string& pattern, const core::TensorField& field,
                                     const ExrExportOptions& options,
                                     const core::Progress& progress) {
  namespace fs = std::filesystem;
  findPlaceholder(pattern);  // a bad pattern fails before any work
  const VoxelQuantities& quantities = options.quantities;
  if (quantities.channelCount() == 0) {
    throw core::Error("EXR export to '" + pattern + "': no quantity selected");
  }
  VoxelExportStats stats;
  stats.lattice =
      latticeForMesh(field.mesh(), options.voxelSize, options.origin, options.maxVoxels);
  const VoxelLattice& lattice = stats.lattice;
  const auto dims = lattice.dims();
  const int width = dims[0], height = dims[1], slices = dims[2];

  std::vector<std::string> names = quantities.channelNames(options.tensorName);
  if (options.mask) names.push_back("A");
  const int channels = static_cast<int>(names.size());
  const int quantityChannels = quantities.channelCount();

  static std::atomic<unsigned> counter{0};
  const std::string stageTag =
      ".tfd-staged" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  std::vector<fs::path> targets, staged, committed;
  field.mesh().locator();  // build once, outside the parallel loops
  try {
    std::vector<float> pixels(std::size_t(width) * height * channels);
    std::vector<std::size_t> rowActive(height);
    for (int s = 0; s < slices; ++s) {
      progress.throwIfCancelled();
      progress.report(double(s) / slices, "writing EXR slices");
      const int k = lattice.min[2] + s;
      tbb::parallel_for(0, height, [&](int row) {
        if (progress.cancelled()) return;
        const int j = lattice.max[1] - row;
        float* out = pixels.data() + std::size_t(row) * width * channels;
        std::size_t active = 0;
        RowSampler sampler(field);
        for (int c = 0; c < width; ++c, out += channels) {
          const core::Vec3 p = lattice.centre(lattice.min[0] + c, j, k);
          const VoxelSample sample = sampler(p);
          if (sample.inside()) {
            quantities.evaluate(p, sample, out);
            if (options.mask) out[quantityChannels] = 1.0f;
            ++active;
          } else {
            std::fill(out, out + channels, 0.0f);
          }
        }
        rowActive[row] = active;
      });
      progress.throwIfCancelled();
      for (std::size_t a : rowActive) stats.activeVoxels += a;

      const int frame = options.firstFrame + s;
      const fs::path target = expandFramePattern(pattern, frame);
      fs::path stage = target;
      std::string stageName = ".";  // hidden, extension kept last
      stageName += target.stem().string();
      stageName += stageTag;
      stageName += target.extension().string();
      stage.replace_filename(stageName);
      targets.push_back(target);

      Imf::Header header(width, height);
      header.compression() = Imf::ZIP_COMPRESSION;
      Imf::FrameBuffer frameBuffer;
      const std::size_t xStride = sizeof(float) * channels;
      for (int c = 0; c < channels; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        frameBuffer.insert(
            names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + c), xStride,
                                 xStride * width));
      }
      const double h = lattice.voxelSize;
      header.insert("tfd.voxelSize", Imf::DoubleAttribute(h));
      header.insert("tfd.origin", Imf::V3dAttribute(v3d(lattice.origin)));
      header.insert("tfd.indexMin",
                    Imf::V3iAttribute(Imath::V3i(lattice.min[0], lattice.min[1], lattice.min[2])));
      header.insert("tfd.indexMax",
                    Imf::V3iAttribute(Imath::V3i(lattice.max[0], lattice.max[1], lattice.max[2])));
      header.insert("tfd.axis", Imf::StringAttribute("z"));
      header.insert("tfd.sliceIndex", Imf::IntAttribute(k));
      header.insert("tfd.frame", Imf::IntAttribute(frame));
      header.insert("tfd.sliceCount", Imf::IntAttribute(slices));
      const core::Vec3 firstPixel = lattice.centre(lattice.min[0], lattice.max[1], k);
      header.insert("tfd.z", Imf::DoubleAttribute(firstPixel.z()));
      header.insert("tfd.firstPixel", Imf::V3dAttribute(v3d(firstPixel)));
      header.insert("tfd.columnStep", Imf::V3dAttribute(Imath::V3d(h, 0, 0)));
      header.insert("tfd.rowStep", Imf::V3dAttribute(Imath::V3d(0, -h, 0)));
      header.insert("tfd.tensorComponents", Imf::StringAttribute("xx,yy,zz,xy,yz,xz"));
      header.insert("tfd.generator", Imf::StringAttribute(options.generator));
      if (!options.source.empty()) {
        header.insert("tfd.source", Imf::StringAttribute(options.source));
      }
      writeAtomically(stage, [&](const fs::path& temp) {
        try {
          Imf::OutputFile file(temp.c_str(), header);
          file.setFrameBuffer(frameBuffer);
          file.writePixels(height);
        } catch (const std::exception& e) {
          throw core::Error("cannot write EXR slice '" + target.string() + "': " + e.what());
        }
      });
      staged.push_back(stage);
    }
    progress.throwIfCancelled();
    for (std::size_t s = 0; s < staged.size(); ++s) {
      std::error_code ec;
      fs::rename(staged[s], targets[s], ec);
      if (ec) {
        throw core::Error("cannot write EXR slice '" + targets[s].string() + "': " + ec.message());
      }
      committed.push_back(targets[s]);
    }
  } catch (...) {
    removeAll(staged);
    removeAll(committed);
    throw;
  }
  progress.report(1.0, "writing EXR slices");
  stats.filesWritten = slices;
  stats.files = committed;
  return stats;
}

}  // namespace tfd::io
