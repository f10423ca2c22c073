// ExportVDB: the field resampled on a voxel grid, or a scalar volume, for Houdini and Blender.
#include "io/volume/vdb_writer.h"

#include <nlohmann/json.hpp>

#include "graph/node_registry.h"
#include "nodes/export/voxel_export_support.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Writes an OpenVDB file. From `field`: float grids `T.xx T.yy T.zz T.xy T.yz T.xz`, "
       "optionally Vec3 grids `T.eigval` and `T.e1 T.e2 T.e3` (grid class unknown), and a "
       "float grid `density` (grid class fog volume, values in [0, 1]) of the measure chosen "
       "by `density`, so Blender's volume object and Houdini render it as imported; voxels "
       "whose centre lies inside the mesh are active, the rest inactive with value 0. From "
       "`volume`: one float grid `density` on the volume's voxels, active where its mask is "
       "set (a fog volume unless a value is negative, e.g. GaborNoise range signed). Connect "
       "exactly one of the two inputs. `vdb_print -l file.vdb` (Debian libopenvdb-tools) lists "
       "the grids and their classes.")
      .category("Export")
      .sideEffect();
  declareVoxelInputs(d);
  d.param<std::string>("path").byDefault("field.vdb").outputFile("*.vdb").doc("Output file.");
  declareVoxelParams(d, "quantities");
  d.param<std::string>("density")
      .choices(kVoxelDensityChoices)
      .doc(std::string("The scalar of the `field` written as the fog-volume grid `density` "
                       "(with `volume`, the volume is): ") +
           kVoxelDensityDoc);
  d.migration(1, [](graph::Json& p) { splitQuantityText(p, "quantities", "quantities"); });
  // typeVersion 2 wrote no density grid from a field: old files keep writing the same grids.
  d.migration(2, [](graph::Json& p) {
    if (!p.contains("density")) p["density"] = "none";
  });
}

void cook(graph::CookContext& c) {
  const VoxelSource source = voxelSourceOf(c, "quantities", "density");
  const std::filesystem::path path = c.path("path");
  io::VoxelExportStats stats;
  if (source == VoxelSource::Volume) {
    io::VolumeVdbOptions o;
    o.source = "node " + c.nodeName();
    stats = io::writeVolumeVdb(path, *c.input<core::ScalarVolume>("volume"), o, progressOf(c));
  } else {
    const auto field = c.input<core::TensorField>("field");
    io::VdbExportOptions o;
    o.voxelSize = voxelSizeOf(c, field->mesh());
    o.quantities = quantitiesOf(c, "quantities");
    o.quantities.density =
        io::voxelDensityFunction(c.param("density", kVoxelDensityChoices), *field);
    o.source = "node " + c.nodeName();
    stats = io::writeFieldVdb(path, *field, o, progressOf(c));
  }
  for (const std::filesystem::path& file : stats.files) c.wroteFile(file);
  c.info(voxelInfo(path.string(), stats));
}

}  // namespace

void registerExportVdb(graph::NodeRegistry& r) { r.add("ExportVDB", 3, declare, cook); }

}  // namespace tfd::nodes
