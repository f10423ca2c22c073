#pragma once
// The hook behind `tfd info FILE`: a describer per file-name suffix. The graph layer describes
// graph files; the io layer's formats (meshes, VTU/VTP, VDB, EXR, curve JSON) are plugged in
// by registerFileDescribers() in register_describers.cpp, e.g.
//
//   describers.add({".vdb"}, "OpenVDB volume", [](const std::filesystem::path& p,
//                                                 std::ostream& out) {
//     out << io::describeVdb(p);   // grids, types, bounds, voxel size...
//     return 0;                    // exit code: 0 described, 2 unreadable / not that format
//   });
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace tfd::graph {
class NodeRegistry;
}

namespace tfd::cli {

/// Writes a summary of the file to `out`; returns the exit code (0 ok, 2 unreadable or not of
/// the expected format; print the reason with printError). May throw std::exception (then: 2).
using Describer = std::function<int(const std::filesystem::path& file, std::ostream& out)>;

class FileDescribers {
 public:
  /// `suffixes` are matched case-insensitively against the end of the file name; the longest
  /// matching suffix wins (".tfd.json" before ".json").
  void add(std::vector<std::string> suffixes, std::string what, Describer describer);
  /// The describer for `file`, or null.
  const Describer* find(const std::filesystem::path& file) const;
  /// "suffix (what)" for every registration, for the "no describer" message.
  std::string known() const;

 private:
  struct Entry {
    std::vector<std::string> suffixes;
    std::string what;
    Describer describer;
  };
  std::vector<Entry> entries_;
};

/// Registers every describer `tfd info` knows (register_describers.cpp).
void registerFileDescribers(FileDescribers& describers, const graph::NodeRegistry& registry);

/// The graph-file describer (format version, generator, nodes, links, whether it loads).
int describeGraphFile(const std::filesystem::path& file, std::ostream& out,
                      const graph::NodeRegistry& registry);

}  // namespace tfd::cli
