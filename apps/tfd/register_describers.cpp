// Every file kind `tfd info` can describe. The lead plugs the io-level describers in here
// (meshes, VTU/VTP, OpenVDB, OpenEXR slices, curve JSON); see file_describers.h.
#include "apps/tfd/file_describers.h"

namespace tfd::cli {

void registerFileDescribers(FileDescribers& describers, const graph::NodeRegistry& registry) {
  describers.add({".tfd.json"}, "tfd graph",
                 [&registry](const std::filesystem::path& file, std::ostream& out) {
                   return describeGraphFile(file, out, registry);
                 });
}

}  // namespace tfd::cli
