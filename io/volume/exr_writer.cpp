#include "io/volume/exr_writer.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <exception>
#include <functional>
#include <memory>
#include <set>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/temporary_files.h"
#include "io/volume/frame_pattern.h"
#include "io/volume/voxel_density.h"

namespace tfd::io {

namespace {

Imath::V3d v3d(const core::Vec3& v) { return Imath::V3d(v.x(), v.y(), v.z()); }

/// Imf::OStream onto an io::OutputFile. OpenEXR writes its line offset table from
/// ~OutputFile and swallows errors there; OutputFile remembers them and StagedFile::write's
/// check reports them, so a slice cut short by a full disk is never renamed into place.
class ExrOutput : public Imf::OStream {
 public:
  explicit ExrOutput(OutputFile& out) : Imf::OStream(out.target().c_str()), out_(out) {}
  void write(const char c[], int n) override {
    if (!out_.write(c, static_cast<std::size_t>(n)))
      throw core::Error("cannot write '" + out_.target().string() + "'");
  }
  uint64_t tellp() override { return out_.tell(); }
  void seekp(uint64_t pos) override {
    if (!out_.seek(pos)) throw core::Error("cannot write '" + out_.target().string() + "'");
  }

 private:
  OutputFile& out_;
};

/// An exporter owns its files: after a cook, the slices of `pattern` in `folder` that this
/// cook did not write (left by an earlier, longer export) are removed, so the folder holds one
/// consistent sequence.
void removeOtherSlices(const std::string& pattern, const std::filesystem::path& folder,
                       const std::vector<std::filesystem::path>& written) {
  namespace fs = std::filesystem;
  std::set<std::string> keep;
  for (const auto& p : written) keep.insert(p.filename().string());
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? fs::path(".") : folder, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::error_code fileError;
    if (!keep.count(name) && frameOfFileName(pattern, name) && it->is_regular_file(fileError))
      fs::remove(it->path(), fileError);
  }
}

/// Removes files, ignoring errors (cleanup after a failure).
void removeAll(const std::vector<std::filesystem::path>& paths) {
  std::error_code ec;
  for (const auto& p : paths) std::filesystem::remove(p, ec);
}

/// What the slices of one export hold: channel names and a filler for one row of one slice
/// (pixels of `width` × channel count floats, zero outside), returning how many voxels of the
/// row are inside. Called concurrently for different rows.
struct SliceContent {
  std::vector<std::string> channels;
  std::function<std::size_t(int j, int k, float* row)> fillRow;
  bool tensorAttributes = false;  ///< add tfd.tensorComponents
};

struct SliceOptions {
  int firstFrame = 0;
  int sliceCount = 0;
  std::string generator, source;
};

/// The z-slices to write: every one, or `count` evenly spaced ones (offsets from min z).
std::vector<int> chosenSlices(int slices, int count) {
  std::vector<int> out;
  if (count <= 0 || count >= slices) {
    for (int s = 0; s < slices; ++s) out.push_back(s);
    return out;
  }
  for (int m = 0; m < count; ++m) out.push_back(int((m + 0.5) * slices / count));
  return out;
}

VoxelExportStats writeSlices(const std::string& pattern, const VoxelLattice& lattice,
                             const SliceContent& content, const SliceOptions& options,
                             const core::Progress& progress) {
  namespace fs = std::filesystem;
  const bool ownsFolder = framePlaceholderInFileName(pattern);  // a bad pattern fails first
  VoxelExportStats stats;
  stats.lattice = lattice;
  const auto dims = lattice.dims();
  const int width = dims[0], height = dims[1], slices = dims[2];
  const std::vector<std::string>& names = content.channels;
  const int channels = static_cast<int>(names.size());

  const fs::path folder = fs::path(expandFramePattern(pattern, 0)).parent_path();
  if (ownsFolder) {  // temporaries of this pattern left by a killed process
    removeStaleTemporaries(folder, [&](const std::string& name) {
      return frameOfFileName(pattern, name).has_value();
    });
  }
  std::vector<std::unique_ptr<StagedFile>> staged;
  std::vector<fs::path> committed;
  const std::vector<int> chosen = chosenSlices(slices, options.sliceCount);
  try {
    std::vector<float> pixels(std::size_t(width) * height * channels);
    std::vector<std::size_t> rowActive(height);
    for (std::size_t n = 0; n < chosen.size(); ++n) {
      const int s = chosen[n];
      progress.throwIfCancelled();
      progress.report(double(n) / chosen.size(), "writing EXR slices");
      const int k = lattice.min[2] + s;
      tbb::parallel_for(0, height, [&](int row) {
        if (progress.cancelled()) return;
        rowActive[row] = content.fillRow(lattice.max[1] - row, k,
                                         pixels.data() + std::size_t(row) * width * channels);
      });
      progress.throwIfCancelled();
      for (std::size_t a : rowActive) stats.activeVoxels += a;
      const int frame = options.firstFrame + s;
      const fs::path target = expandFramePattern(pattern, frame);

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
      if (content.tensorAttributes)
        header.insert("tfd.tensorComponents", Imf::StringAttribute("xx,yy,zz,xy,yz,xz"));
      header.insert("tfd.generator", Imf::StringAttribute(options.generator));
      if (!options.source.empty()) {
        header.insert("tfd.source", Imf::StringAttribute(options.source));
      }
      staged.push_back(std::make_unique<StagedFile>(target));
      staged.back()->write([&](OutputFile& out) {
        try {
          ExrOutput stream(out);
          Imf::OutputFile file(stream, header);
          file.setFrameBuffer(frameBuffer);
          file.writePixels(height);
        } catch (const std::exception& e) {
          throw core::Error("cannot write EXR slice '" + target.string() + "': " + e.what());
        }
      });
    }
    progress.throwIfCancelled();
    for (auto& file : staged) {
      file->commit();
      committed.push_back(file->target());
    }
  } catch (...) {
    staged.clear();  // removes the temporaries not yet renamed
    removeAll(committed);
    throw;
  }
  if (ownsFolder) removeOtherSlices(pattern, folder, committed);
  progress.report(1.0, "writing EXR slices");
  stats.filesWritten = static_cast<int>(committed.size());
  stats.files = committed;
  return stats;
}

}  // namespace

VoxelExportStats writeFieldExrSlices(const std::string& pattern, const core::TensorField& field,
                                     const ExrExportOptions& options,
                                     const core::Progress& progress) {
  framePlaceholderInFileName(pattern);  // a bad pattern fails first
  const VoxelQuantities& quantities = options.quantities;
  if (quantities.channelCount() == 0 && !options.preview) {
    throw core::Error("EXR export to '" + pattern + "': no quantity selected");
  }
  const VoxelLattice lattice =
      latticeForMesh(field.mesh(), options.voxelSize, options.origin, options.maxVoxels);
  SliceContent content;
  content.channels = quantities.channelNames(options.tensorName);
  const bool preview = bool(options.preview);
  if (preview) content.channels.insert(content.channels.end(), {"R", "G", "B"});
  if (options.mask) content.channels.push_back("A");
  content.tensorAttributes = true;
  const int channels = static_cast<int>(content.channels.size());
  const int quantityChannels = quantities.channelCount();
  const int maskChannel = quantityChannels + (preview ? 3 : 0);
  content.fillRow = [&](int j, int k, float* out) {
    std::size_t active = 0;
    RowSampler sampler(field);
    for (int i = lattice.min[0]; i <= lattice.max[0]; ++i, out += channels) {
      const core::Vec3 p = lattice.centre(i, j, k);
      const VoxelSample sample = sampler(p);
      if (sample.inside()) {
        quantities.evaluate(p, sample, out);
        if (preview) {
          const auto rgb = previewColour(options.preview(p, sample));
          std::copy(rgb.begin(), rgb.end(), out + quantityChannels);
        }
        if (options.mask) out[maskChannel] = 1.0f;
        ++active;
      } else {
        std::fill(out, out + channels, 0.0f);
      }
    }
    return active;
  };
  field.mesh().locator();  // build once, outside the parallel loops
  return writeSlices(pattern, lattice, content,
                     {options.firstFrame, options.sliceCount, options.generator, options.source},
                     progress);
}

VoxelExportStats writeVolumeExrSlices(const std::string& pattern, const core::ScalarVolume& volume,
                                      const VolumeExrOptions& options,
                                      const core::Progress& progress) {
  framePlaceholderInFileName(pattern);  // a bad pattern fails first
  const VoxelLattice& lattice = volume.grid;
  if (lattice.count() == 0)
    throw core::Error("EXR export to '" + pattern + "': the volume has no voxels");
  if (volume.values.size() != lattice.count() || volume.mask.size() != lattice.count())
    throw core::Error("EXR export to '" + pattern + "': the volume's arrays do not match its grid");
  SliceContent content;
  content.channels = {"R", "G", "B", "A"};
  content.fillRow = [&](int j, int k, float* out) {
    std::size_t active = 0;
    for (int i = lattice.min[0]; i <= lattice.max[0]; ++i, out += 4) {
      const std::size_t v = lattice.offset(i, j, k);
      const float value = volume.mask[v] ? volume.values[v] : 0.0f;
      out[0] = out[1] = out[2] = value;
      out[3] = volume.mask[v] ? 1.0f : 0.0f;
      active += volume.mask[v] ? 1 : 0;
    }
    return active;
  };
  return writeSlices(pattern, lattice, content,
                     {options.firstFrame, options.sliceCount, options.generator, options.source},
                     progress);
}

}  // namespace tfd::io
