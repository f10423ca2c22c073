#include "nodes/export/voxel_export_support.h"

#include <sstream>

#include "core/error.h"

namespace tfd::nodes {

void declareVoxelParams(graph::NodeDecl& d, const std::string& quantitiesName) {
  d.param<double>("voxel_size")
      .byDefault(0)
      .min(0)
      .doc("World units per voxel; 0 picks the mesh's longest bounding-box side / 128.");
  d.param<std::string>(quantitiesName)
      .byDefault("tensor")
      .doc(
          "Comma-separated: tensor (six components xx yy zz xy yz xz), eigenvalues "
          "(l1 >= l2 >= l3), eigenvectors (e1 e2 e3, sign arbitrary).");
}

double voxelSizeOf(const graph::CookContext& c, const core::TetMesh& mesh) {
  double h = c.param<double>("voxel_size");
  if (h == 0) {
    const double extent = (mesh.boundsMax() - mesh.boundsMin()).maxCoeff();
    if (!(extent > 0)) throw c.paramError("voxel_size", "the mesh has no extent to size voxels by");
    h = extent / 128;
  }
  try {
    io::latticeForMesh(mesh, h);  // refuses sizes that give no voxel or far too many
  } catch (const core::Error& e) {
    throw c.paramError("voxel_size", e.what());
  }
  return h;
}

io::VoxelQuantities quantitiesOf(const graph::CookContext& c, const std::string& name) {
  std::vector<std::string> names;
  std::stringstream list(c.param<std::string>(name));
  for (std::string item; std::getline(list, item, ',');) {
    const auto first = item.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    names.push_back(item.substr(first, item.find_last_not_of(" \t") - first + 1));
  }
  if (names.empty()) throw c.paramError(name, "name at least one quantity, e.g. \"tensor\"");
  try {
    return io::VoxelQuantities::fromNames(names);
  } catch (const core::Error& e) {
    throw c.paramError(name, e.what());
  }
}

std::string voxelInfo(const std::string& what, const io::VoxelExportStats& stats) {
  const auto dims = stats.lattice.dims();
  std::ostringstream s;
  s << "wrote " << what << ": " << dims[0] << " x " << dims[1] << " x " << dims[2] << " voxels of "
    << stats.lattice.voxelSize << ", " << stats.activeVoxels << " inside";
  return s.str();
}

}  // namespace tfd::nodes
