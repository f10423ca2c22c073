#include "nodes/export/voxel_export_support.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"

namespace tfd::nodes {

void declareVoxelParams(graph::NodeDecl& d, const std::string& quantitiesName) {
  d.param<double>("voxel_size")
      .byDefault(0)
      .min(0)
      .doc("World units per voxel; 0 picks the mesh's longest bounding-box side / 128.");
  d.param<std::vector<std::string>>(quantitiesName)
      .byDefault({"tensor"})
      .choices(kVoxelQuantityChoices)
      .minSize(1)
      .doc(
          "Any of: tensor (six components xx yy zz xy yz xz), eigenvalues (l1 >= l2 >= l3), "
          "eigenvectors (e1 e2 e3, sign arbitrary).");
}

void splitQuantityText(graph::Json& params, const std::string& from, const std::string& to) {
  if (!params.contains(from)) return;
  const graph::Json old = params[from];
  params.erase(from);
  if (!old.is_string()) {  // not what version 1 wrote: let validation report it
    params[to] = old;
    return;
  }
  graph::Json list = graph::Json::array();
  std::stringstream text(old.get<std::string>());
  for (std::string item; std::getline(text, item, ',');) {
    const auto first = item.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    list.push_back(item.substr(first, item.find_last_not_of(" \t") - first + 1));
  }
  params[to] = list;
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
  io::VoxelQuantities q;
  q.tensor = false;
  for (bool io::VoxelQuantities::*flag : c.paramList(name, kVoxelQuantityChoices)) {
    if (q.*flag) throw c.paramError(name, "a quantity is listed twice");
    q.*flag = true;
  }
  return q;
}

std::string voxelInfo(const std::string& what, const io::VoxelExportStats& stats) {
  const auto dims = stats.lattice.dims();
  std::ostringstream s;
  s << "wrote " << what << ": " << dims[0] << " x " << dims[1] << " x " << dims[2] << " voxels of "
    << stats.lattice.voxelSize << ", " << stats.activeVoxels << " inside";
  return s.str();
}

}  // namespace tfd::nodes
