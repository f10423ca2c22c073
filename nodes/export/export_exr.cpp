// ExportEXR: the field resampled on a voxel grid, one OpenEXR image per z-slice.
#include "io/volume/exr_writer.h"

#include "graph/node_registry.h"
#include "nodes/export/voxel_export_support.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Writes the field as a sequence of OpenEXR images, one per z-slice of a voxel grid "
       "(bottom to top), 32-bit float channels named `T.xx` ... plus a mask `A`; header "
       "attributes `tfd.*` give the voxel size, slice position and pixel placement.")
      .category("Export")
      .sideEffect();
  d.input<core::TensorField>("field");
  d.param<std::string>("path")
      .byDefault("slices/field.%04d.exr")
      .outputFile("*.exr")
      .doc("File pattern with one slice-number placeholder: %d, %04d or ####.");
  declareVoxelParams(d, "quantities");
  // typeVersion 1 named the list `quantity`, a comma-separated string.
  d.migration(1, [](graph::Json& p) { splitQuantityText(p, "quantity", "quantities"); });
}

void cook(graph::CookContext& c) {
  const auto field = c.input<core::TensorField>("field");
  io::ExrExportOptions o;
  o.voxelSize = voxelSizeOf(c, field->mesh());
  o.quantities = quantitiesOf(c, "quantities");
  o.source = "node " + c.nodeName();
  const std::filesystem::path pattern = c.path("path");
  const io::VoxelExportStats stats =
      io::writeFieldExrSlices(pattern.string(), *field, o, progressOf(c));
  for (const std::filesystem::path& file : stats.files) c.wroteFile(file);
  c.info(voxelInfo(std::to_string(stats.filesWritten) + " slices " + pattern.string(), stats));
}

}  // namespace

void registerExportExr(graph::NodeRegistry& r) { r.add("ExportEXR", 2, declare, cook); }

}  // namespace tfd::nodes
