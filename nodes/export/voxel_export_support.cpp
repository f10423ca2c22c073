#include "nodes/export/voxel_export_support.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "graph/errors.h"
#include "nodes/value_types.h"

namespace tfd::nodes {

void declareVoxelSize(graph::NodeDecl& d) {
  d.param<double>("voxel_size")
      .byDefault(0)
      .min(0)
      .doc("World units per voxel; 0 picks the mesh's longest bounding-box side / 128.");
}

void declareVoxelParams(graph::NodeDecl& d, const std::string& quantitiesName) {
  declareVoxelSize(d);
  d.param<std::vector<std::string>>(quantitiesName)
      .byDefault({"tensor"})
      .choices(kVoxelQuantityChoices)
      .minSize(1)
      .doc(
          "Any of: tensor (six components xx yy zz xy yz xz), eigenvalues (l1 >= l2 >= l3), "
          "eigenvectors (e1 e2 e3, sign arbitrary).");
}

void declareVoxelInputs(graph::NodeDecl& d) {
  d.input<core::TensorField>("field").optional().doc(
      "The field to resample (connect this or `volume`, not both).");
  d.input<core::ScalarVolume>("volume").optional().doc(
      "A scalar volume (e.g. GaborNoise), written on its own voxels; `voxel_size` and the "
      "quantities apply to `field` only.");
}

VoxelSource voxelSourceOf(const graph::CookContext& c, const std::string& quantitiesName,
                          const std::string& densityName) {
  const bool field = c.hasInput("field"), volume = c.hasInput("volume");
  if (field && volume) {
    throw graph::NodeError(
        "inputs 'field' and 'volume' are both connected: connect one of them (use one exporter "
        "per input)");
  }
  if (!field && !volume) {
    throw graph::NodeError("no input: connect input 'field' (a tensor field) or 'volume'");
  }
  if (field) return VoxelSource::Field;
  if (c.param<double>("voxel_size") != 0) {
    throw c.paramError("voxel_size",
                       "applies to input 'field' only: a volume is written on its own voxels "
                       "(set them where it is made); use 0 with input 'volume'");
  }
  if (c.param<std::vector<std::string>>(quantitiesName) != std::vector<std::string>{"tensor"}) {
    throw c.paramError(quantitiesName,
                       "applies to input 'field' only; leave it at [\"tensor\"] with input "
                       "'volume'");
  }
  if (!densityName.empty()) {
    const std::string density = c.param<std::string>(densityName);
    if (density != "degeneracy" && density != "none") {
      throw c.paramError(densityName,
                         "applies to input 'field' only (the volume itself is written); leave "
                         "it at \"degeneracy\" or \"none\" with input 'volume'");
    }
  }
  return VoxelSource::Volume;
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

core::VoxelGrid voxelGridOf(const graph::CookContext& c, const core::TetMesh& mesh) {
  return io::latticeForMesh(mesh, voxelSizeOf(c, mesh));
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
