#include "io/volume/vdb_layout_check.h"

#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.h"

namespace tfd::io {

namespace {

constexpr std::int64_t kVdbMagic = 0x56444220;       // "VDB "
constexpr std::uint32_t kFirstCheckedVersion = 222;  // and every later one, as 224

/// Little-endian reads with every length checked against the file's size.
class LayoutReader {
 public:
  explicit LayoutReader(const std::filesystem::path& path)
      : path_(path), in_(path, std::ios::binary) {
    std::error_code ec;
    size_ = std::filesystem::file_size(path, ec);
    if (!in_ || ec) throw core::Error("cannot read VDB file '" + path.string() + "'");
  }

  std::uint64_t position() const { return pos_; }
  std::uint64_t left() const { return size_ - pos_; }
  std::uint64_t size() const { return size_; }

  void seek(std::uint64_t at, const char* what) {
    if (at > size_) damaged(std::string(what) + " points at byte " + std::to_string(at));
    pos_ = at;
    in_.seekg(static_cast<std::streamoff>(at));
  }
  template <typename T>
  T value(const char* what) {
    need(sizeof(T), what);
    T v{};
    in_.read(reinterpret_cast<char*>(&v), sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  /// Skips `bytes`, which `what` announces.
  void skip(std::uint64_t bytes, const std::string& what) {
    need(bytes, what);
    seek(pos_ + bytes, what.c_str());
  }
  void skipString(const char* what) { skip(value<std::uint32_t>(what), what); }

  [[noreturn]] void damaged(const std::string& what) const {
    throw core::Error("cannot read VDB file '" + path_.string() + "': the file is damaged (" +
                      what + ", the file has " + std::to_string(size_) + " bytes)");
  }

 private:
  void need(std::uint64_t bytes, const std::string& what) const {
    if (bytes > left())
      damaged(what + " announces " + std::to_string(bytes) + " bytes at byte " +
              std::to_string(pos_) + ", " + std::to_string(left()) + " are left");
  }

  std::filesystem::path path_;
  std::ifstream in_;
  std::uint64_t size_ = 0, pos_ = 0;
};

/// A MetaMap: count, then per entry name, type name and a sized value.
void checkMetadata(LayoutReader& r, const char* owner) {
  const std::uint32_t count = r.value<std::uint32_t>(owner);
  if (count > r.left() / 12)
    r.damaged(std::string(owner) + " announces " + std::to_string(count) + " metadata entries");
  for (std::uint32_t i = 0; i < count; ++i) {
    r.skipString("a metadata name");
    r.skipString("a metadata type name");
    r.skip(r.value<std::uint32_t>("a metadata value"), "a metadata value");
  }
}

}  // namespace

VdbLayout checkVdbLayout(const std::filesystem::path& path) {
  LayoutReader r(path);
  VdbLayout layout;
  if (r.size() < 8 || r.value<std::int64_t>("the header") != kVdbMagic) return layout;
  layout.magic = true;
  // OpenVDB reads a file of a newer version than its own with its own layout (after a warning),
  // so such a file is checked as one of the last known version; older layouts are OpenVDB's.
  layout.version = r.value<std::uint32_t>("the header");
  if (layout.version < kFirstCheckedVersion) return layout;
  r.skip(8, "the header");  // library major and minor version
  layout.gridOffsets = r.value<char>("the header") != 0;
  r.skip(36, "the header");  // UUID
  checkMetadata(r, "the file metadata");
  const std::uint32_t grids = r.value<std::uint32_t>("the grid count");
  if (grids > r.left() / 36) r.damaged("it announces " + std::to_string(grids) + " grids");
  if (!layout.gridOffsets) return layout;  // descriptors and grids interleave: OpenVDB's part
  for (std::uint32_t g = 0; g < grids; ++g) {
    r.skipString("a grid name");
    r.skipString("a grid type");
    r.skipString("a grid's instance parent");
    const auto gridPos = r.value<std::int64_t>("a grid position");
    const auto blockPos = r.value<std::int64_t>("a grid position");
    const auto endPos = r.value<std::int64_t>("a grid position");
    if (gridPos < std::int64_t(r.position()) || blockPos < gridPos || endPos < blockPos ||
        std::uint64_t(endPos) > r.size())
      r.damaged("grid " + std::to_string(g) + " has positions " + std::to_string(gridPos) + ", " +
                std::to_string(blockPos) + ", " + std::to_string(endPos));
    r.seek(std::uint64_t(gridPos), "a grid position");
    r.skip(4, "a grid's compression flags");
    checkMetadata(r, "a grid's metadata");
    r.skipString("a grid's transform type");  // then the map's numbers, then the tree
    r.seek(std::uint64_t(endPos), "a grid's end position");
  }
  layout.checked = true;
  return layout;
}

}  // namespace tfd::io
