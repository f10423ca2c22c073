// ExportEXR: the field resampled on a voxel grid, or a scalar volume, one OpenEXR image per
// z-slice.
#include "io/volume/exr_writer.h"

#include "graph/node_registry.h"
#include "nodes/export/voxel_export_support.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Writes a sequence of OpenEXR images, one per z-slice of a voxel grid (bottom to top); "
       "header attributes `tfd.*` give the voxel size, slice position and pixel placement. "
       "From `field`: 32-bit float channels named `T.xx` ... (OpenEXR layers: `T.xx` is "
       "channel `xx` of layer `T`, `T.eigval.x` channel `x` of layer `T.eigval`), a preview "
       "`R`, `G`, `B` of the measure chosen by `preview` through a dark-blue, teal, "
       "yellow-green, light-yellow colour map (0 to 1), and a mask `A`. From `volume`: "
       "the value in `R`, `G`, `B` and its mask in `A`, on the volume's voxels. Connect "
       "exactly one of the two inputs.")
      .category("Export")
      .sideEffect();
  declareVoxelInputs(d);
  d.param<std::string>("path")
      .byDefault("slices/field.%04d.exr")
      .outputFile("*.exr")
      .doc("File pattern with one slice-number placeholder: %d, %04d or ####.");
  declareVoxelParams(d, "quantities");
  d.param<std::string>("preview")
      .choices(kVoxelDensityChoices)
      .doc(std::string("The scalar of the `field` shown in the preview channels R, G, B, so "
                       "a plain image viewer or Blender's compositor shows the slice (with "
                       "`volume`, R, G, B hold the volume): ") +
           kVoxelDensityDoc);
  d.param<int>("slice_count")
      .byDefault(0)
      .min(0)
      .doc(
          "0 writes every z-slice; n writes n evenly spaced cross sections, numbered by their "
          "slice as if all were written.");
  // typeVersion 1 named the list `quantity`, a comma-separated string.
  d.migration(1, [](graph::Json& p) { splitQuantityText(p, "quantity", "quantities"); });
}

void cook(graph::CookContext& c) {
  const VoxelSource source = voxelSourceOf(c, "quantities", "preview");
  const std::filesystem::path pattern = c.path("path");
  const int sliceCount = c.param<int>("slice_count");
  io::VoxelExportStats stats;
  if (source == VoxelSource::Volume) {
    io::VolumeExrOptions o;
    o.sliceCount = sliceCount;
    o.source = "node " + c.nodeName();
    stats = io::writeVolumeExrSlices(pattern.string(), *c.input<core::ScalarVolume>("volume"), o,
                                     progressOf(c));
  } else {
    const auto field = c.input<core::TensorField>("field");
    io::ExrExportOptions o;
    o.voxelSize = voxelSizeOf(c, field->mesh());
    o.quantities = quantitiesOf(c, "quantities");
    o.preview = io::voxelDensityFunction(c.param("preview", kVoxelDensityChoices), *field);
    o.sliceCount = sliceCount;
    o.source = "node " + c.nodeName();
    stats = io::writeFieldExrSlices(pattern.string(), *field, o, progressOf(c));
  }
  for (const std::filesystem::path& file : stats.files) c.wroteFile(file);
  c.info(voxelInfo(std::to_string(stats.filesWritten) + " slices " + pattern.string(), stats));
}

}  // namespace

void registerExportExr(graph::NodeRegistry& r) { r.add("ExportEXR", 2, declare, cook); }

}  // namespace tfd::nodes
