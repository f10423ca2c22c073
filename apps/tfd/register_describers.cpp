// Every file kind `tfd info` can describe; see file_describers.h.
#include "apps/tfd/describe_io_files.h"
#include "apps/tfd/file_describers.h"

namespace tfd::cli {

void registerFileDescribers(FileDescribers& describers, const graph::NodeRegistry& registry) {
  describers.add({".tfd.json"}, "tfd graph",
                 [&registry](const std::filesystem::path& file, std::ostream& out) {
                   return describeGraphFile(file, out, registry);
                 });
  describers.add({".off", ".obj", ".ply", ".stl"}, "surface mesh", describeMesh);
  describers.add({".node", ".ele", ".msh"}, "tet mesh", describeMesh);
  describers.add({".vtu"}, "tet mesh (VTK)", describeVtu);
  describers.add({".vtp"}, "VTK polydata", describeVtp);
  describers.add({".vdb"}, "OpenVDB volume", describeVdb);
  describers.add({".exr"}, "OpenEXR image", describeExr);
  describers.add({".json"}, "degenerate curves", describeCurvesJson);
}

}  // namespace tfd::cli
