#pragma once
// Values flowing between nodes: immutable, shared, type-erased (`std::shared_ptr<const void>`
// plus a ValueType identity). The graph layer knows no concrete value type; node files name
// theirs with TFD_GRAPH_VALUE_TYPE at global namespace scope, e.g.
//
//   TFD_GRAPH_VALUE_TYPE(tfd::core::TetMesh, "TetMesh");
//   TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::TensorField, "TensorField",
//                              [](const tfd::core::TensorField& f) { return ...bytes...; });
//
// The display name is stable (used in messages, `tfd nodes`, docs). The optional size function
// reports an approximate byte size for the memory-bounded cache (default: sizeof(T)); a lambda
// whose body contains a comma must be wrapped in parentheses (macro argument rules).
// Put all registrations for a type in one header so every translation unit sees the same one.
#include <cstddef>
#include <memory>
#include <string_view>
#include <type_traits>

namespace tfd::graph {

/// Identity and metadata of a value type. Compare by address (one instance per C++ type).
struct ValueType {
  std::string_view name;
  std::size_t (*byteSize)(const void* value);
};

/// Specialised by TFD_GRAPH_VALUE_TYPE; deliberately undefined for unregistered types.
template <class T>
struct ValueTraits;

namespace detail {
template <class T>
std::size_t valueByteSize(const void* value) {
  if constexpr (requires(const T& v) { ValueTraits<T>::byteSize(v); })
    return ValueTraits<T>::byteSize(*static_cast<const T*>(value));
  else
    return sizeof(T);
}
template <class T>
inline const ValueType kValueType{ValueTraits<T>::name, &valueByteSize<T>};
}  // namespace detail

/// The unique ValueType of a registered C++ type.
template <class T>
const ValueType* valueType() {
  return &detail::kValueType<std::remove_cv_t<T>>;
}

/// A type-erased immutable value. Empty when `data` is null.
struct Value {
  std::shared_ptr<const void> data;
  const ValueType* type = nullptr;

  explicit operator bool() const { return data != nullptr; }
  std::size_t byteSize() const { return data && type ? type->byteSize(data.get()) : 0; }

  template <class T>
  static Value of(std::shared_ptr<const T> v) {
    return Value{std::move(v), valueType<T>()};
  }
  /// The typed pointer, or null when empty or of another type.
  template <class T>
  std::shared_ptr<const T> as() const {
    if (!data || type != valueType<T>()) return nullptr;
    return std::static_pointer_cast<const T>(data);
  }
};

}  // namespace tfd::graph

/// Registers C++ type T as a graph value type named NAME. Use at global namespace scope.
#define TFD_GRAPH_VALUE_TYPE(T, NAME)              \
  template <>                                      \
  struct tfd::graph::ValueTraits<T> {              \
    static constexpr std::string_view name = NAME; \
  }

/// Same, with an approximate byte size `SIZE_FN(const T&) -> std::size_t` for the cache budget.
#define TFD_GRAPH_VALUE_TYPE_SIZED(T, NAME, SIZE_FN)   \
  template <>                                          \
  struct tfd::graph::ValueTraits<T> {                  \
    static constexpr std::string_view name = NAME;     \
    static std::size_t byteSize(const T& value) {      \
      return static_cast<std::size_t>(SIZE_FN(value)); \
    }                                                  \
  }
