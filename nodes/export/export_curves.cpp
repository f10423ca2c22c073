// ExportCurves: degenerate curves to .json (tfd-degenerate-curves), .vtp or .obj.
#include "io/curves/curve_writers.h"

#include "graph/node_registry.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Writes degenerate curves; the format follows the extension: .json (the "
       "tfd-degenerate-curves exchange format), .vtp (ParaView polylines with type, pattern "
       "and Fig. 5 colour arrays) or .obj (line elements).")
      .category("Export")
      .sideEffect();
  d.input<core::DegenerateCurves>("curves");
  d.param<std::string>("path")
      .byDefault("curves.json")
      .outputFile("*.json *.vtp *.obj")
      .doc("Output file: .json, .vtp or .obj.");
}

void cook(graph::CookContext& c) {
  const auto curves = c.input<core::DegenerateCurves>("curves");
  const std::filesystem::path path = c.path("path");
  io::writeCurves(path, *curves);
  c.wroteFile(path);
  c.info("wrote " + std::to_string(curves->size()) + " curves to " + path.string());
}

}  // namespace

void registerExportCurves(graph::NodeRegistry& r) { r.add("ExportCurves", 1, declare, cook); }

}  // namespace tfd::nodes
