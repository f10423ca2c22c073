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
#include <memory>
#include <set>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/temporary_files.h"
#include "io/volume/frame_pattern.h"

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

/// The header of slice k (frame `frame`): size, compression and the tfd.* attributes that
/// place the slice in space (docs/outputs.md); the channels are added by the caller.
Imf::Header sliceHeader(const VoxelLattice& lattice, int k, int frame,
                        const ExrExportOptions& options) {
  const auto dims = lattice.dims();
  Imf::Header header(dims[0], dims[1]);
  header.compression() = Imf::ZIP_COMPRESSION;
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
  header.insert("tfd.sliceCount", Imf::IntAttribute(dims[2]));
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
  return header;
}

}  // namespace

VoxelExportStats writeFieldExrSlices(const std::string& pattern, const core::TensorField& field,
                                     const ExrExportOptions& options,
                                     const core::Progress& progress) {
  namespace fs = std::filesystem;
  const bool ownsFolder = framePlaceholderInFileName(pattern);  // a bad pattern fails first
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

  const fs::path folder = fs::path(expandFramePattern(pattern, 0)).parent_path();
  if (ownsFolder) {  // temporaries of this pattern left by a killed process
    removeStaleTemporaries(folder, [&](const std::string& name) {
      return frameOfFileName(pattern, name).has_value();
    });
  }
  std::vector<std::unique_ptr<StagedFile>> staged;
  std::vector<fs::path> committed;
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

      Imf::Header header = sliceHeader(lattice, k, frame, options);
      Imf::FrameBuffer frameBuffer;
      const std::size_t xStride = sizeof(float) * channels;
      for (int c = 0; c < channels; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        frameBuffer.insert(
            names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + c), xStride,
                                 xStride * width));
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
  stats.filesWritten = slices;
  stats.files = committed;
  return stats;
}

}  // namespace tfd::io
