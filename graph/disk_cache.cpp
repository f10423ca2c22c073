#include "graph/disk_cache.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "graph/errors.h"

namespace tfd::graph {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'T', 'F', 'D', 'C', 'A', 'C', 'H', 'E'};
constexpr std::size_t kHeaderBytes = 64;

struct Header {
  char magic[8];
  std::uint32_t version, reserved;
  std::uint64_t keyHi, keyLo;
  std::uint64_t metaSize, metaSum, payloadSize, payloadSum;
};
static_assert(sizeof(Header) == kHeaderBytes);

void writeMessages(ByteWriter& w, const std::vector<NodeMessage>& messages) {
  w.u64(messages.size());
  for (const NodeMessage& m : messages) {
    w.u8(static_cast<std::uint8_t>(m.severity)).str(m.text);
    w.u8(static_cast<std::uint8_t>(m.kind)).str(m.port).str(m.sourceNode);
  }
}

std::vector<NodeMessage> readMessages(ByteReader& r) {
  std::vector<NodeMessage> out(r.count(26));
  for (NodeMessage& m : out) {
    const std::uint8_t severity = r.u8();
    if (severity > static_cast<std::uint8_t>(Severity::Error)) throw GraphError("bad severity");
    m.severity = static_cast<Severity>(severity);
    m.text = r.str();
    const std::uint8_t kind = r.u8();
    if (kind > static_cast<std::uint8_t>(MessageKind::UpstreamFailed))
      throw GraphError("bad message kind");
    m.kind = static_cast<MessageKind>(kind);
    m.port = r.str();
    m.sourceNode = r.str();
  }
  return out;
}

/// A read-only mapping of a whole entry file (writers rename a new file over the entry and
/// never change one in place, so the mapped bytes stay valid until unmapped).
class MappedFile {
 public:
  explicit MappedFile(const fs::path& path, std::size_t size) : size_(size) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || size == 0) {
      if (fd >= 0) ::close(fd);
      return;
    }
    void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    ::close(fd);
    if (p != MAP_FAILED) data_ = static_cast<const char*>(p);
  }
  ~MappedFile() {
    if (data_) ::munmap(const_cast<char*>(data_), size_);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  const char* data() const { return data_; }

 private:
  const char* data_ = nullptr;
  std::size_t size_;
};

}  // namespace

struct DiskCache::Raw {
  std::string meta;
  std::shared_ptr<MappedFile> file;  // when the payload was asked for
  std::string_view payload;
};

DiskCache::DiskCache(fs::path dir, std::uint64_t budgetBytes, const ValueCodecs& codecs)
    : dir_(std::move(dir)), budget_(budgetBytes), codecs_(codecs) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_, ec))
    throw GraphError("--cache " + dir_.string() + ": cannot create the folder" +
                     (ec ? ": " + ec.message() : std::string()));
}

fs::path DiskCache::entryPath(const Hash& key) const { return dir_ / (key.toHex() + ".tfdc"); }

bool DiskCache::canStore(const NodeDecl& decl) const {
  for (const PortDecl& out : decl.outputs())
    if (!codecs_.find(out.type)) return false;
  return true;
}

void DiskCache::warn(std::string text) {
  std::lock_guard lock(mutex_);
  warnings_.push_back(std::move(text));
}

std::vector<std::string> DiskCache::warnings() const {
  std::lock_guard lock(mutex_);
  return warnings_;
}

DiskCache::Counters DiskCache::counters() const {
  std::lock_guard lock(mutex_);
  return counters_;
}

std::optional<DiskCache::Raw> DiskCache::readVerified(const Hash& key, bool withPayload) {
  const fs::path path = entryPath(key);
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;  // absent: a plain miss
  auto damaged = [&](const std::string& why) -> std::optional<Raw> {
    warn("cache entry " + path.string() + " is damaged (" + why + "); cooking the node instead");
    return std::nullopt;
  };
  Header h{};
  if (!in.read(reinterpret_cast<char*>(&h), sizeof h)) return damaged("truncated header");
  if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) return damaged("not a tfd cache entry");
  if (h.version != kDiskCacheVersion)
    return damaged("format version " + std::to_string(h.version) + ", expected " +
                   std::to_string(kDiskCacheVersion));
  if (h.keyHi != key.hi || h.keyLo != key.lo) return damaged("its key differs from its name");
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || h.metaSize > size || h.payloadSize > size ||
      size != kHeaderBytes + h.metaSize + h.payloadSize)
    return damaged("size " + std::to_string(size) + " does not match its header");
  Raw raw;
  raw.meta.resize(h.metaSize);
  if (!in.read(raw.meta.data(), static_cast<std::streamsize>(h.metaSize)))
    return damaged("truncated");
  if (checksum64(raw.meta) != h.metaSum) return damaged("checksum mismatch in its description");
  if (withPayload) {
    raw.file = std::make_shared<MappedFile>(path, size);
    if (!raw.file->data()) return damaged("cannot map it");
    raw.payload = std::string_view(raw.file->data() + kHeaderBytes + h.metaSize, h.payloadSize);
    if (checksum64(raw.payload) != h.payloadSum) return damaged("checksum mismatch in its values");
  }
  return raw;
}

std::optional<CacheEntry> DiskCache::readMeta(const Hash& key, const NodeDecl& decl) {
  std::optional<Raw> raw = readVerified(key, false);
  if (!raw) return std::nullopt;
  CacheEntry entry;
  try {
    ByteReader r(raw->meta);
    if (r.str() != decl.typeName() || r.i64() != decl.typeVersion())
      throw GraphError("it was made by another node type");
    entry.seconds = r.f64();
    entry.messages = readMessages(r);
    entry.files.resize(r.count(25));
    for (FileStamp& f : entry.files) {
      f.path = r.str();
      f.exists = r.u8() != 0;
      f.size = r.u64();
      f.mtime = r.i64();
    }
    const std::uint64_t outputs = r.count(8);
    if (outputs != decl.outputs().size()) throw GraphError("its outputs differ from the node's");
    for (const PortDecl& port : decl.outputs())
      if (r.str() != port.type->name) throw GraphError("its output types differ from the node's");
    if (!r.atEnd()) throw GraphError("trailing bytes");
  } catch (const GraphError& e) {
    warn("cache entry " + entryPath(key).string() + " is damaged (" + e.what() +
         "); cooking the node instead");
    return std::nullopt;
  }
  std::error_code ec;  // mark as recently used
  fs::last_write_time(entryPath(key), fs::file_time_type::clock::now(), ec);
  std::lock_guard lock(mutex_);
  ++counters_.hits;
  return entry;
}

std::optional<std::vector<Value>> DiskCache::readOutputs(const Hash& key, const NodeDecl& decl,
                                                         DecodeMemo& memo) {
  std::optional<Raw> raw = readVerified(key, true);
  if (!raw) return std::nullopt;
  std::vector<Value> outputs;
  try {
    ByteReader r(raw->payload);
    for (const PortDecl& port : decl.outputs()) {
      const ValueCodec* codec = codecs_.find(port.type);
      if (!codec) throw GraphError(std::string("no codec for ") + std::string(port.type->name));
      ByteReader part(r.bytes(r.u64(), "an output"));
      outputs.push_back(codec->decode(part, memo));
      if (!part.atEnd()) throw GraphError("trailing bytes after an output");
    }
    if (!r.atEnd()) throw GraphError("trailing bytes");
  } catch (const std::exception& e) {  // a decoder may throw core::Error too
    warn("cache entry " + entryPath(key).string() + " is damaged (" + e.what() +
         "); cooking the node instead");
    return std::nullopt;
  }
  std::lock_guard lock(mutex_);
  ++counters_.loads;
  return outputs;
}

void DiskCache::store(const Hash& key, const NodeDecl& decl, const CacheEntry& entry) {
  if (!canStore(decl)) return;
  ByteWriter meta;
  meta.str(decl.typeName()).i64(decl.typeVersion()).f64(entry.seconds);
  writeMessages(meta, entry.messages);
  meta.u64(entry.files.size());
  for (const FileStamp& f : entry.files)
    meta.str(f.path.string()).u8(f.exists ? 1 : 0).u64(f.size).i64(f.mtime);
  meta.u64(decl.outputs().size());
  for (const PortDecl& port : decl.outputs()) meta.str(port.type->name);
  ByteWriter payload;
  for (std::size_t i = 0; i < decl.outputs().size(); ++i) {
    ByteWriter part;
    codecs_.find(decl.outputs()[i].type)->encode(entry.outputs[i], part);
    payload.str(part.bytes());  // size, then the bytes
  }
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.version = kDiskCacheVersion;
  h.keyHi = key.hi;
  h.keyLo = key.lo;
  h.metaSize = meta.bytes().size();
  h.metaSum = checksum64(meta.bytes());
  h.payloadSize = payload.bytes().size();
  h.payloadSum = checksum64(payload.bytes());

  static std::atomic<unsigned> counter{0};
  const fs::path target = entryPath(key);
  const fs::path temp = dir_ / ("." + key.toHex() + ".tmp" + std::to_string(getpid()) + "-" +
                                std::to_string(counter++));
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  bool ok = f != nullptr;
  if (ok) {
    ok =
        std::fwrite(&h, sizeof h, 1, f) == 1 &&
        std::fwrite(meta.bytes().data(), 1, meta.bytes().size(), f) == meta.bytes().size() &&
        std::fwrite(payload.bytes().data(), 1, payload.bytes().size(), f) == payload.bytes().size();
    ok = (std::fclose(f) == 0) && ok;
  }
  const std::string why = std::strerror(errno);
  std::error_code ec;
  if (ok) fs::rename(temp, target, ec);
  if (!ok || ec) {
    fs::remove(temp, ec);
    warn("cannot write cache entry " + target.string() + ": " + (ok ? ec.message() : why));
    return;
  }
  std::lock_guard lock(mutex_);
  ++counters_.stores;
}

void DiskCache::evict() {
  struct Item {
    fs::path path;
    std::uintmax_t size;
    fs::file_time_type time;
  };
  std::vector<Item> items;
  std::uintmax_t total = 0;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir_, ec)) {
    if (e.path().extension() != ".tfdc" || !e.is_regular_file(ec)) continue;
    Item item{e.path(), e.file_size(ec), e.last_write_time(ec)};
    if (ec) continue;
    total += item.size;
    items.push_back(std::move(item));
  }
  if (total <= budget_) return;
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    return a.time != b.time ? a.time < b.time : a.path < b.path;
  });
  std::uint64_t removed = 0;
  for (const Item& item : items) {
    if (total <= budget_) break;
    if (fs::remove(item.path, ec)) {
      total -= item.size;
      ++removed;
    }
  }
  std::lock_guard lock(mutex_);
  counters_.evictions += removed;
}

}  // namespace tfd::graph
