// ExportLines: traced lines to .vtp (ParaView, with the eigenvalues along them) or .obj.
#include "io/curves/line_writers.h"

#include "graph/node_registry.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

const graph::Choices<io::VtkEncoding> kEncodings{{"appended", io::VtkEncoding::Appended},
                                                 {"base64", io::VtkEncoding::Base64},
                                                 {"ascii", io::VtkEncoding::Ascii}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "Writes lines; the format follows the extension: .vtp (ParaView polylines with the "
       "eigenvalues, arc length and line id per point, and why each line stopped) or .obj "
       "(two-point line elements, which every importer reads).")
      .category("Export")
      .sideEffect();
  d.input<core::Polylines>("lines");
  d.param<std::string>("path")
      .byDefault("lines.vtp")
      .outputFile("*.vtp *.obj")
      .doc("Output file: .vtp or .obj.");
  d.param<std::string>("encoding")
      .choices(kEncodings)
      .doc(".vtp data: appended raw binary (VTK's default), base64 or ascii text.");
}

void cook(graph::CookContext& c) {
  const auto lines = c.input<core::Polylines>("lines");
  const std::filesystem::path path = c.path("path");
  io::writeLines(path, *lines, c.param("encoding", kEncodings));
  c.wroteFile(path);
  c.info("wrote " + std::to_string(lines->lines.size()) + " lines to " + path.string());
}

}  // namespace

void registerExportLines(graph::NodeRegistry& r) { r.add("ExportLines", 1, declare, cook); }

}  // namespace tfd::nodes
