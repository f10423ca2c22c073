#include "io/volume/vdb_reader.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include <fstream>
#include <ios>
#include <new>

#include "core/error.h"
#include "core/memory_budget.h"
#include "io/text_scanner.h"
#include "io/volume/vdb_layout_check.h"
#include "io/volume/vdb_support.h"

namespace tfd::io {

namespace {

std::map<std::string, std::string> metadataText(const openvdb::MetaMap& meta) {
  std::map<std::string, std::string> out;
  for (auto it = meta.beginMeta(); it != meta.endMeta(); ++it) {
    out[it->first] = it->second ? it->second->str() : std::string();
  }
  return out;
}

/// A metadata entry of type T, or null when it is missing, of another type or empty (a damaged
/// file can hold an entry without a value, where MetaMap::getMetadata would dereference null).
template <class T>
std::shared_ptr<const T> typedEntry(const openvdb::MetaMap& meta, const std::string& name) {
  const openvdb::Metadata::ConstPtr entry = meta[name];
  if (!entry || entry->typeName() != T::staticTypeName()) return nullptr;
  return std::static_pointer_cast<const T>(entry);
}

std::array<double, 3> asArray(float v) { return {v, 0, 0}; }
std::array<double, 3> asArray(double v) { return {v, 0, 0}; }
std::array<double, 3> asArray(int v) { return {double(v), 0, 0}; }
template <typename T>
std::array<double, 3> asArray(const openvdb::math::Vec3<T>& v) {
  return {double(v[0]), double(v[1]), double(v[2])};
}

template <typename GridT>
bool loadValues(const openvdb::GridBase& base, VdbGridData& out) {
  const auto* grid = dynamic_cast<const GridT*>(&base);
  if (!grid) return false;
  out.background = asArray(grid->background());
  for (auto it = grid->cbeginValueOn(); it; ++it) {
    if (it.isVoxelValue()) {
      const auto c = it.getCoord();
      out.activeVoxels.push_back({{c.x(), c.y(), c.z()}, asArray(*it)});
    } else {
      openvdb::CoordBBox box;
      it.getBoundingBox(box);
      for (auto c = box.begin(); c; ++c) {
        out.activeVoxels.push_back({{(*c).x(), (*c).y(), (*c).z()}, asArray(*it)});
      }
    }
  }
  for (auto leaf = grid->tree().cbeginLeaf(); leaf; ++leaf) {
    for (auto it = leaf->cbeginValueOff(); it; ++it) {
      if (!openvdb::math::isExactlyEqual(*it, grid->background())) ++out.inactiveNonBackground;
    }
  }
  out.valuesLoaded = true;
  return true;
}

/// What the file says a grid takes in memory (OpenVDB's "file_mem_bytes" statistics, written
/// with every grid), checked against the memory budget before any tree is read; with values,
/// also the list of active voxels ("file_voxel_count").
void checkAnnouncedSizes(openvdb::io::File& file, const std::string& name, bool withValues) {
  const openvdb::GridPtrVecPtr grids = file.readAllGridMetadata();
  for (const auto& grid : *grids) {
    const std::string what =
        "VDB file '" + name + "': grid '" + printableText(grid->getName()) + "'";
    if (const auto bytes = typedEntry<openvdb::Int64Metadata>(*grid, "file_mem_bytes"))
      core::checkMemory(double(bytes->value()), what + " (as the file announces)");
    const auto voxels = typedEntry<openvdb::Int64Metadata>(*grid, "file_voxel_count");
    if (withValues && voxels)
      core::checkMemory(double(voxels->value()) * sizeof(VdbGridData::Voxel),
                        what + "'s list of " + std::to_string(voxels->value()) +
                            " active voxels (as the file announces)");
  }
}

/// The grids, read through a stream that throws at the first read past the end of the file.
/// OpenVDB's tree readers loop over counts from the file without looking at the stream state
/// (RootNode::readTopology and its tile count), so a damaged count would keep them reading
/// nothing for minutes; with the exception a damaged file ends where its bytes end.
openvdb::GridPtrVecPtr readGridsStrictly(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  in.exceptions(std::ios::failbit | std::ios::badbit | std::ios::eofbit);
  openvdb::io::Stream stream(in, /*delayLoad=*/false);
  return stream.getGrids();
}

/// An OpenVDB exception's text without its class prefix ("KeyError: ..."), printable.
std::string openVdbReason(const openvdb::Exception& e) {
  std::string text = e.what();
  if (const auto colon = text.find(": ");
      colon != std::string::npos && colon < 24 && text.compare(colon - 5, 5, "Error") == 0)
    text = text.substr(colon + 2);
  if (text.empty()) text = "no reason given";
  // A damaged name can make OpenVDB's message hundreds of megabytes long (a grid type of
  // announced length, mostly unread): quote its start only.
  constexpr std::size_t kQuoted = 200;
  if (text.size() > kQuoted)
    text = text.substr(0, kQuoted) + "... (" + std::to_string(text.size()) + " characters)";
  return "the file is damaged or not an OpenVDB file (OpenVDB: " + printableText(text) + ")";
}

/// What a grid's metadata and transform say (no tree needed).
VdbGridData describeGrid(const openvdb::GridBase& grid, const std::filesystem::path& path) {
  VdbGridData g;
  g.name = grid.getName();
  g.valueType = grid.valueType();
  if (g.valueType.empty())
    throw core::Error("cannot read VDB file '" + path.string() + "': grid '" +
                      printableText(g.name) + "' has no value type (the file is damaged)");
  g.gridClass = openvdb::GridBase::gridClassToString(grid.getGridClass());
  g.vectorType = openvdb::GridBase::vecTypeToString(grid.getVectorType());
  g.saveFloatAsHalf = grid.saveFloatAsHalf();
  g.metadata = metadataText(grid);
  if (!grid.constTransformPtr())
    throw core::Error("cannot read VDB file '" + path.string() + "': grid '" +
                      printableText(g.name) + "' has no transform (the file is damaged)");
  const auto& xf = grid.constTransform();
  g.linearTransform = xf.isLinear();
  const openvdb::Vec3d vs = xf.voxelSize();
  g.voxelSize = core::Vec3(vs[0], vs[1], vs[2]);
  const openvdb::Vec3d o = xf.indexToWorld(openvdb::Vec3d(0, 0, 0));
  g.indexOrigin = core::Vec3(o[0], o[1], o[2]);
  return g;
}

/// The active voxel count and bounds the writer recorded in the grid's metadata (OpenVDB's
/// "file_voxel_count", "file_bbox_min", "file_bbox_max", written unless switched off).
void takeRecordedStatistics(const openvdb::GridBase& grid, VdbGridData& g) {
  const auto count = typedEntry<openvdb::Int64Metadata>(grid, "file_voxel_count");
  const auto lo = typedEntry<openvdb::Vec3IMetadata>(grid, "file_bbox_min");
  const auto hi = typedEntry<openvdb::Vec3IMetadata>(grid, "file_bbox_max");
  if (!count || count->value() < 0) {
    g.activeVoxelsKnown = false;
    return;
  }
  g.activeVoxelCount = std::size_t(count->value());
  if (g.activeVoxelCount > 0 && lo && hi) {
    g.activeMin = {lo->value().x(), lo->value().y(), lo->value().z()};
    g.activeMax = {hi->value().x(), hi->value().y(), hi->value().z()};
  }
}

/// OpenVDB reads the trees of a file without grid offsets when it opens it (File::open), and
/// an older file's layout is not checked: neither is safe to give OpenVDB (see the header).
void refuseUncheckedLayout(const std::filesystem::path& path, const VdbLayout& layout) {
  if (layout.checked || !layout.magic) return;  // checked, or OpenVDB says what it is
  const std::string start = "cannot read VDB file '" + path.string() + "': ";
  if (layout.version < 222)
    throw core::Error(start + "its format version " + std::to_string(layout.version) +
                      " is older than OpenVDB 2 (222); tfd reads versions from 222 on");
  throw core::Error(start +
                    "it was written as a stream (its grids have no offsets), which tfd does "
                    "not read; `vdb_print` reads it, or save it again as a file");
}

/// Every exception a damaged file can make OpenVDB or the standard library throw, as our error
/// naming the file.
template <class Read>
void readNamingTheFile(const std::filesystem::path& path, Read&& read) {
  try {
    read();
  } catch (const core::Error&) {
    throw;
  } catch (const openvdb::Exception& e) {
    throw core::Error("cannot read VDB file '" + path.string() + "': " + openVdbReason(e));
  } catch (const std::ios_base::failure&) {
    throw core::Error("cannot read VDB file '" + path.string() +
                      "': the file is damaged (it ends inside what it announces)");
  } catch (const std::bad_alloc&) {
    throw core::Error("cannot read VDB file '" + path.string() +
                      "': it asks for more memory than can be allocated (a damaged file?)");
  } catch (const std::exception& e) {
    throw core::Error("cannot read VDB file '" + path.string() + "': the file is damaged (" +
                      printableText(e.what()) + ")");
  }
}

}  // namespace

VdbFileData readVdbMetadata(const std::filesystem::path& path) {
  initializeOpenVdb();
  VdbFileData data;
  readNamingTheFile(path, [&] {
    refuseUncheckedLayout(path, checkVdbLayout(path));
    openvdb::io::File file(path.string());
    file.open(false);
    data.fileMetadata = metadataText(*file.getMetadata());
    const openvdb::GridPtrVecPtr grids = file.readAllGridMetadata();
    for (const auto& grid : *grids) {
      VdbGridData g = describeGrid(*grid, path);
      takeRecordedStatistics(*grid, g);
      data.grids.push_back(std::move(g));
    }
  });
  return data;
}

VdbFileData readVdbFile(const std::filesystem::path& path, bool withValues) {
  initializeOpenVdb();
  VdbFileData data;
  readNamingTheFile(path, [&] {
    checkVdbLayout(path);
    openvdb::io::File file(path.string());
    file.open(false);  // read everything now; the file is closed at the end of this scope
    data.fileMetadata = metadataText(*file.getMetadata());
    checkAnnouncedSizes(file, path.string(), withValues);
    file.close();
    const openvdb::GridPtrVecPtr grids = readGridsStrictly(path);
    for (const auto& grid : *grids) {
      VdbGridData g = describeGrid(*grid, path);
      g.activeVoxelCount = grid->activeVoxelCount();
      const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
      if (!box.empty()) {
        g.activeMin = {box.min().x(), box.min().y(), box.min().z()};
        g.activeMax = {box.max().x(), box.max().y(), box.max().z()};
      }
      if (withValues) {
        loadValues<openvdb::FloatGrid>(*grid, g) || loadValues<openvdb::DoubleGrid>(*grid, g) ||
            loadValues<openvdb::Vec3SGrid>(*grid, g) || loadValues<openvdb::Vec3DGrid>(*grid, g) ||
            loadValues<openvdb::Int32Grid>(*grid, g);
      }
      data.grids.push_back(std::move(g));
    }
  });
  return data;
}

}  // namespace tfd::io
