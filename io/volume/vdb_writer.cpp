#include "io/volume/vdb_writer.h"

#include <openvdb/io/Archive.h>
#include <openvdb/openvdb.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/volume/vdb_support.h"

namespace tfd::io {

namespace {

using FloatLeaf = openvdb::FloatTree::LeafNodeType;
using Vec3Leaf = openvdb::Vec3STree::LeafNodeType;

constexpr int kLeafDim = int(FloatLeaf::DIM);  // 8
static_assert(kLeafDim == int(Vec3Leaf::DIM));

/// One output grid: which float channels of VoxelQuantities::evaluate it takes.
struct GridPlan {
  std::string name;
  int firstChannel = 0;
  bool vector = false;  ///< three channels into a Vec3SGrid, else one into a FloatGrid
  bool tensorDerived = true;
  std::string component;  ///< "xx"… for the six tensor grids
};

std::vector<GridPlan> planGrids(const VoxelQuantities& q, const std::string& tensorName) {
  std::vector<GridPlan> plans;
  int channel = 0;
  if (q.tensor) {
    for (const char* c : {"xx", "yy", "zz", "xy", "yz", "xz"}) {
      plans.push_back({tensorName + "." + c, channel++, false, true, c});
    }
  }
  if (q.eigenvalues) {
    plans.push_back({tensorName + ".eigval", channel, true, true, {}});
    channel += 3;
  }
  if (q.eigenvectors) {
    for (const char* e : {".e1", ".e2", ".e3"}) {
      plans.push_back({tensorName + e, channel, true, true, {}});
      channel += 3;
    }
  }
  if (q.density) plans.push_back({"density", channel++, false, false, {}});
  return plans;
}

/// The leaves one 8³ block produced (empty when no voxel centre of the block is inside).
struct BlockLeaves {
  std::vector<std::unique_ptr<FloatLeaf>> floats;
  std::vector<std::unique_ptr<Vec3Leaf>> vectors;
  std::size_t active = 0;
};

/// What openvdb::io::File::write does (a seekable archive with grid offsets, so readers can
/// load grids one by one), but onto a stream we own: io::File writes through its own
/// std::ofstream and never checks it, so a full disk produced a truncated file and success.
class SeekableVdbArchive : public openvdb::io::Archive {
 public:
  void write(std::ostream& os, const openvdb::GridPtrVec& grids, const openvdb::MetaMap& meta) {
    openvdb::io::Archive::write(os, grids, /*seekable=*/true, meta);
  }
};

/// Floor division by the leaf size, valid for negative indices.
int leafBlock(int index) { return index >= 0 ? index / kLeafDim : -((-index - 1) / kLeafDim) - 1; }

/// Writes `grids` and the file metadata (generator, source when given, `extra`, voxel
/// convention) atomically.
void writeVdbFile(const std::filesystem::path& path, const openvdb::GridPtrVec& grids,
                  const std::string& generator, const std::string& source,
                  const openvdb::MetaMap& extra) {
  openvdb::MetaMap fileMeta;
  fileMeta.insertMeta("generator", openvdb::StringMetadata(generator));
  if (!source.empty()) fileMeta.insertMeta("source", openvdb::StringMetadata(source));
  for (auto it = extra.beginMeta(); it != extra.endMeta(); ++it)
    fileMeta.insertMeta(it->first, *it->second);
  fileMeta.insertMeta("voxel_convention",
                      openvdb::StringMetadata("voxel (i,j,k) is centred on world = origin + "
                                              "voxelSize * (i,j,k)"));
  writeAtomically(path, [&](OutputFile& out) {
    try {
      SeekableVdbArchive().write(out.stream(), grids, fileMeta);
    } catch (const openvdb::Exception& e) {
      throw core::Error("cannot write VDB file '" + path.string() + "': " + e.what());
    }
    // OpenVDB does not look at the stream state: writeAtomically's check (OutputFile::close)
    // reports a full disk or a file-size limit, and the old file stays.
  });
}

openvdb::math::Transform::Ptr latticeTransform(const VoxelLattice& lattice) {
  const auto transform = openvdb::math::Transform::createLinearTransform(lattice.voxelSize);
  transform->postTranslate(
      openvdb::Vec3d(lattice.origin.x(), lattice.origin.y(), lattice.origin.z()));
  return transform;
}

/// Fog volume (what Blender's volume object and Houdini render as imported) when no active
/// value is negative, else unknown: a fog volume's density is never negative, and a signed
/// scalar is no signed distance either (OpenVDB's other scalar class, level set).
openvdb::GridClass densityGridClass(const openvdb::FloatGrid& grid) {
  for (auto it = grid.cbeginValueOn(); it; ++it)
    if (!(*it >= 0)) return openvdb::GRID_UNKNOWN;
  return openvdb::GRID_FOG_VOLUME;
}

}  // namespace

VoxelExportStats writeFieldVdb(const std::filesystem::path& path, const core::TensorField& field,
                               const VdbExportOptions& options, const core::Progress& progress) {
  const VoxelQuantities& quantities = options.quantities;
  if (quantities.channelCount() == 0) {
    throw core::Error("VDB export of '" + path.string() + "': no quantity selected");
  }
  VoxelExportStats stats;
  stats.lattice =
      latticeForMesh(field.mesh(), options.voxelSize, options.origin, options.maxVoxels);
  const VoxelLattice& lattice = stats.lattice;
  initializeOpenVdb();

  const std::vector<GridPlan> plans = planGrids(quantities, options.tensorName);
  const int channels = quantities.channelCount();
  int floatGrids = 0, vectorGrids = 0;
  for (const auto& p : plans) (p.vector ? vectorGrids : floatGrids)++;

  const auto transform = latticeTransform(lattice);
  std::vector<openvdb::FloatGrid::Ptr> floatOut;
  std::vector<openvdb::Vec3SGrid::Ptr> vectorOut;
  openvdb::GridPtrVec grids;
  for (const auto& p : plans) {
    openvdb::GridBase::Ptr grid;
    if (p.vector) {
      auto g = openvdb::Vec3SGrid::create(openvdb::Vec3s(0, 0, 0));
      g->setVectorType(openvdb::VEC_INVARIANT);
      vectorOut.push_back(g);
      grid = g;
    } else {
      auto g = openvdb::FloatGrid::create(0.0f);
      floatOut.push_back(g);
      grid = g;
    }
    grid->setName(p.name);
    grid->setTransform(transform->copy());
    grid->setSaveFloatAsHalf(false);
    grid->setGridClass(openvdb::GRID_UNKNOWN);  // density: densityGridClass once filled
    if (p.tensorDerived) {
      grid->insertMeta("tensor_components", openvdb::StringMetadata("xx,yy,zz,xy,yz,xz"));
    }
    if (!p.component.empty()) grid->insertMeta("component", openvdb::StringMetadata(p.component));
    grids.push_back(grid);
  }

  // Leaf blocks covering the lattice, processed one z-layer of blocks at a time.
  const std::array<int, 3> blockMin{leafBlock(lattice.min[0]), leafBlock(lattice.min[1]),
                                    leafBlock(lattice.min[2])};
  const std::array<int, 3> blockMax{leafBlock(lattice.max[0]), leafBlock(lattice.max[1]),
                                    leafBlock(lattice.max[2])};
  const int nbx = blockMax[0] - blockMin[0] + 1;
  const int nby = blockMax[1] - blockMin[1] + 1;
  const int layers = blockMax[2] - blockMin[2] + 1;
  field.mesh().locator();  // build once, outside the parallel loop
  std::vector<BlockLeaves> layer(std::size_t(nbx) * nby);
  for (int bz = blockMin[2]; bz <= blockMax[2]; ++bz) {
    progress.throwIfCancelled();
    progress.report(double(bz - blockMin[2]) / layers, "sampling voxels");
    tbb::parallel_for(0, nbx * nby, [&](int b) {
      if (progress.cancelled()) return;
      BlockLeaves& out = layer[b];
      const openvdb::Coord leafOrigin((blockMin[0] + b % nbx) * kLeafDim,
                                      (blockMin[1] + b / nbx) * kLeafDim, bz * kLeafDim);
      std::vector<float> values(channels);
      RowSampler sampler(field);
      for (int k = std::max(leafOrigin.z(), lattice.min[2]);
           k <= std::min(leafOrigin.z() + kLeafDim - 1, lattice.max[2]); ++k) {
        for (int j = std::max(leafOrigin.y(), lattice.min[1]);
             j <= std::min(leafOrigin.y() + kLeafDim - 1, lattice.max[1]); ++j) {
          for (int i = std::max(leafOrigin.x(), lattice.min[0]);
               i <= std::min(leafOrigin.x() + kLeafDim - 1, lattice.max[0]); ++i) {
            const core::Vec3 p = lattice.centre(i, j, k);
            const VoxelSample sample = sampler(p);
            if (!sample.inside()) continue;
            if (out.active++ == 0) {
              for (int g = 0; g < floatGrids; ++g)
                out.floats.push_back(std::make_unique<FloatLeaf>(leafOrigin, 0.0f, false));
              for (int g = 0; g < vectorGrids; ++g) {
                out.vectors.push_back(
                    std::make_unique<Vec3Leaf>(leafOrigin, openvdb::Vec3s(0, 0, 0), false));
              }
            }
            quantities.evaluate(p, sample, values.data());
            const openvdb::Index offset = FloatLeaf::coordToOffset(openvdb::Coord(i, j, k));
            int f = 0, v = 0;
            for (const auto& plan : plans) {
              const float* c = values.data() + plan.firstChannel;
              if (plan.vector) {
                out.vectors[v++]->setValueOn(offset, openvdb::Vec3s(c[0], c[1], c[2]));
              } else {
                out.floats[f++]->setValueOn(offset, c[0]);
              }
            }
          }
        }
      }
    });
    progress.throwIfCancelled();
    // Serial insertion in block order: the trees do not depend on the thread count.
    for (auto& block : layer) {
      for (int g = 0; g < int(block.floats.size()); ++g)
        floatOut[g]->tree().addLeaf(block.floats[g].release());
      for (int g = 0; g < int(block.vectors.size()); ++g)
        vectorOut[g]->tree().addLeaf(block.vectors[g].release());
      stats.activeVoxels += block.active;
      block = BlockLeaves();
    }
  }
  progress.throwIfCancelled();
  progress.report(1.0, "writing");
  for (std::size_t g = 0; g < plans.size(); ++g) {
    if (!plans[g].tensorDerived) {
      auto& density = static_cast<openvdb::FloatGrid&>(*grids[g]);
      density.setGridClass(densityGridClass(density));
    }
  }

  openvdb::MetaMap extra;
  extra.insertMeta("tensor_components", openvdb::StringMetadata("xx,yy,zz,xy,yz,xz"));
  writeVdbFile(path, grids, options.generator, options.source, extra);
  stats.filesWritten = 1;
  stats.files = {path};
  return stats;
}

VoxelExportStats writeVolumeVdb(const std::filesystem::path& path, const core::ScalarVolume& volume,
                                const VolumeVdbOptions& options, const core::Progress& progress) {
  const VoxelLattice& lattice = volume.grid;
  if (lattice.count() == 0)
    throw core::Error("VDB export of '" + path.string() + "': the volume has no voxels");
  if (volume.values.size() != lattice.count() || volume.mask.size() != lattice.count())
    throw core::Error("VDB export of '" + path.string() +
                      "': the volume's arrays do not match "
                      "its grid");
  initializeOpenVdb();
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setName(options.gridName);
  grid->setTransform(latticeTransform(lattice));
  grid->setSaveFloatAsHalf(false);

  const std::array<int, 3> blockMin{leafBlock(lattice.min[0]), leafBlock(lattice.min[1]),
                                    leafBlock(lattice.min[2])};
  const int nb[3] = {leafBlock(lattice.max[0]) - blockMin[0] + 1,
                     leafBlock(lattice.max[1]) - blockMin[1] + 1,
                     leafBlock(lattice.max[2]) - blockMin[2] + 1};
  std::vector<std::unique_ptr<FloatLeaf>> leaves(std::size_t(nb[0]) * nb[1] * nb[2]);
  std::vector<std::size_t> active(leaves.size(), 0);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t b) {
    if (progress.cancelled()) return;
    const openvdb::Coord leafOrigin(
        (blockMin[0] + int(b % nb[0])) * kLeafDim,
        (blockMin[1] + int(b / nb[0] % nb[1])) * kLeafDim,
        (blockMin[2] + int(b / (std::size_t(nb[0]) * nb[1]))) * kLeafDim);
    for (int k = std::max(leafOrigin.z(), lattice.min[2]);
         k <= std::min(leafOrigin.z() + kLeafDim - 1, lattice.max[2]); ++k)
      for (int j = std::max(leafOrigin.y(), lattice.min[1]);
           j <= std::min(leafOrigin.y() + kLeafDim - 1, lattice.max[1]); ++j)
        for (int i = std::max(leafOrigin.x(), lattice.min[0]);
             i <= std::min(leafOrigin.x() + kLeafDim - 1, lattice.max[0]); ++i) {
          const std::size_t v = lattice.offset(i, j, k);
          if (!volume.mask[v]) continue;
          if (!leaves[b]) leaves[b] = std::make_unique<FloatLeaf>(leafOrigin, 0.0f, false);
          leaves[b]->setValueOn(FloatLeaf::coordToOffset(openvdb::Coord(i, j, k)),
                                volume.values[v]);
          ++active[b];
        }
  });
  progress.throwIfCancelled();
  VoxelExportStats stats;
  stats.lattice = lattice;
  for (std::size_t b = 0; b < leaves.size(); ++b) {  // block order: thread-count independent
    if (leaves[b]) grid->tree().addLeaf(leaves[b].release());
    stats.activeVoxels += active[b];
  }
  grid->setGridClass(densityGridClass(*grid));
  progress.report(1.0, "writing");
  writeVdbFile(path, {grid}, options.generator, options.source, openvdb::MetaMap());
  stats.filesWritten = 1;
  stats.files = {path};
  return stats;
}

}  // namespace tfd::io
