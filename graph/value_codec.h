#pragma once
// Serialisation of graph values for the on-disk cook cache. The graph layer knows no concrete
// value type: the node layer registers an encoder and a decoder per expensive type (meshes,
// fields, curves) in a ValueCodecs table, and the cache stores only nodes whose every output
// has one. Decoders rebuild the value through its public constructor (so every invariant is
// checked again) and throw on anything malformed; the cache then treats the entry as a miss.
//
// DecodeMemo lets values that share a part (a TensorField and its TetMesh) share it again
// after loading: a decoder keys the part by the checksum of its bytes.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include "graph/byte_stream.h"
#include "graph/value.h"

namespace tfd::graph {

class DecodeMemo {
 public:
  /// The object stored under (kind, checksum), made by `make` the first time.
  template <class T, class Make>
  std::shared_ptr<const T> shared(std::string_view kind, std::uint64_t checksum, Make&& make) {
    auto& slot = objects_[{std::string(kind), checksum}];
    if (!slot) slot = std::shared_ptr<const T>(make());
    return std::static_pointer_cast<const T>(slot);
  }

 private:
  std::map<std::pair<std::string, std::uint64_t>, std::shared_ptr<const void>> objects_;
};

struct ValueCodec {
  std::function<void(const Value&, ByteWriter&)> encode;
  std::function<Value(ByteReader&, DecodeMemo&)> decode;
};

class ValueCodecs {
 public:
  template <class T>
  void add(std::function<void(const T&, ByteWriter&)> encode,
           std::function<std::shared_ptr<const T>(ByteReader&, DecodeMemo&)> decode) {
    codecs_[valueType<T>()] = ValueCodec{
        [encode](const Value& v, ByteWriter& w) { encode(*v.as<T>(), w); },
        [decode](ByteReader& r, DecodeMemo& memo) { return Value::of<T>(decode(r, memo)); }};
  }
  /// Null when the type has no codec (its nodes are not stored on disk).
  const ValueCodec* find(const ValueType* type) const {
    auto it = codecs_.find(type);
    return it == codecs_.end() ? nullptr : &it->second;
  }

 private:
  std::map<const ValueType*, ValueCodec> codecs_;
};

}  // namespace tfd::graph
