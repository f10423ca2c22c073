// ExportVTU: the field (and optionally the degenerate curves' Fig. 5 colours) for ParaView.
#include "core/point_locator.h"
#include "io/vtk/vtu_writer.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Writes the field to a VTK XML unstructured grid (.vtu) that ParaView opens: the "
       "active tensor `T` (xx, yy, zz, xy, yz, xz), `T.eigval`, `T.e1` `T.e2` `T.e3` and "
       "`T.type` (1 linear, -1 planar, 0 neutral). With `curves` connected, every tet that a "
       "degenerate curve passes through gets the cell arrays `curve_id` (-1 elsewhere) and "
       "`curve_colour` (the paper's Fig. 5 colours: L-wedge green, L-trisector blue, P-wedge "
       "yellow, P-trisector red, transition white); threshold on curve_id >= 0 to see them.")
      .category("Export")
      .sideEffect();
  d.input<core::TensorField>("field");
  d.input<core::DegenerateCurves>("curves").optional().doc(
      "Degenerate curves of this field (ExtractDegenerateCurves) to colour the tets.");
  d.param<std::string>("path").byDefault("field.vtu").outputFile("*.vtu").doc("Output file.");
  d.param<std::string>("encoding")
      .choices({"binary", "base64", "ascii"})
      .doc(
          "binary: raw appended data (smallest, fastest); base64: inline binary; ascii: "
          "readable text.");
}

io::VtkEncoding encodingOf(const std::string& name) {
  if (name == "ascii") return io::VtkEncoding::Ascii;
  if (name == "base64") return io::VtkEncoding::Base64;
  return io::VtkEncoding::Appended;
}

/// Cell arrays marking the tets each curve point and segment midpoint lies in. Where several
/// curves share a tet, the lower id wins (deterministic).
std::vector<io::NamedArray> curveCellArrays(const core::TetMesh& mesh,
                                            const core::DegenerateCurves& curves) {
  std::vector<double> ids(mesh.tetCount(), -1), colours(3 * mesh.tetCount(), 0);
  auto mark = [&](const core::Vec3& p, int id, core::CurveType type, core::PointPattern pattern) {
    const auto hit = mesh.locator().locate(p, 1e-9);
    if (!hit || (ids[hit->tet] >= 0 && ids[hit->tet] <= id)) return;
    ids[hit->tet] = id;
    const auto rgb = core::fig5Colour(type, pattern);
    for (int k = 0; k < 3; ++k) colours[3 * hit->tet + k] = rgb[k];
  };
  for (const core::DegenerateCurve& curve : curves.curves()) {
    const std::size_t n = curve.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      mark(curve.points[i], curve.id, curve.type, curve.patterns[i]);
      if (i + 1 < n || (curve.closed && n > 2)) {
        const std::size_t j = (i + 1) % n;
        const core::PointPattern midPattern =
            curve.patterns[i] == curve.patterns[j]                ? curve.patterns[i]
            : curve.patterns[i] == core::PointPattern::Transition ? curve.patterns[j]
                                                                  : curve.patterns[i];
        mark(0.5 * (curve.points[i] + curve.points[j]), curve.id, curve.type, midPattern);
      }
    }
  }
  return {{"curve_id", 1, std::move(ids), io::VtkType::Int32},
          {"curve_colour", 3, std::move(colours), io::VtkType::UInt8}};
}

void cook(graph::CookContext& c) {
  const auto field = c.input<core::TensorField>("field");
  io::VtuFieldOptions o;
  o.encoding = encodingOf(c.param<std::string>("encoding"));
  if (const auto curves = c.inputOr<core::DegenerateCurves>("curves", nullptr)) {
    o.cellData = curveCellArrays(field->mesh(), *curves);
    std::size_t marked = 0;
    for (std::size_t t = 0; t < field->mesh().tetCount(); ++t)
      marked += o.cellData[0].values[t] >= 0;
    c.info(std::to_string(marked) + " tets coloured by " + std::to_string(curves->size()) +
           " degenerate curves");
  }
  const std::filesystem::path path = c.path("path");
  io::writeFieldVtu(path, *field, o, progressOf(c));
  c.wroteFile(path);
  c.info("wrote " + path.string());
}

}  // namespace

void registerExportVtu(graph::NodeRegistry& r) { r.add("ExportVTU", 1, declare, cook); }

}  // namespace tfd::nodes
