// ExportVTU: the field (and optionally the degenerate curves' Fig. 5 colours) for ParaView.
#include <nlohmann/json.hpp>

#include "core/topology/curve_tets.h"
#include "io/vtk/paraview_script.h"
#include "io/vtk/vtu_writer.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

const graph::Choices<io::VtkEncoding> kEncodings{{"appended", io::VtkEncoding::Appended},
                                                 {"base64", io::VtkEncoding::Base64},
                                                 {"ascii", io::VtkEncoding::Ascii}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "Writes the field to a VTK XML unstructured grid (.vtu) that ParaView opens: the "
       "active tensor `T` (xx, yy, zz, xy, yz, xz), `T.eigval`, `T.e1` `T.e2` `T.e3` and "
       "`T.type` (1 linear, -1 planar, 0 neutral). With `curves` connected, every tet that a "
       "degenerate curve passes through gets the cell arrays `curve_id` (-1 elsewhere) and "
       "`curve_colour` (the paper's Fig. 5 colours: L-wedge green, L-trisector blue, P-wedge "
       "yellow, P-trisector red, transition white); threshold on curve_id >= 0 to see them. "
       "With `region` connected (e.g. RemoveCurves' region), the cell array `region` is 1 on "
       "its tets and 0 elsewhere. With `glyph_tensor`, the point array `T.glyph` = T + c I "
       "(below) is added and made the active tensor, so ParaView's Tensor Glyph draws "
       "ellipsoids as opened. With `paraview_script`, a ParaView Python script "
       "`<name>.paraview.py` (and, with `curves` connected, the curves as `<name>.curves.vtp`) "
       "is written next to the .vtu: `paraview --script=<name>.paraview.py` opens the mesh, "
       "the curves in their Fig. 5 colours and the glyphs together; `pvpython "
       "<name>.paraview.py --png view.png` renders a picture.")
      .category("Export")
      .sideEffect();
  d.input<core::TensorField>("field");
  d.input<core::DegenerateCurves>("curves").optional().doc(
      "Degenerate curves of this field (ExtractDegenerateCurves) to colour the tets.");
  d.input<core::TetRegion>("region").optional().doc(
      "Tets of an edit's region (RemoveCurves) to mark with the cell array `region`.");
  d.param<std::string>("path").byDefault("field.vtu").outputFile("*.vtu").doc("Output file.");
  d.param<std::string>("encoding")
      .choices(kEncodings)
      .doc(
          "appended: raw appended binary data (smallest, fastest; VTK's word); base64: inline "
          "base64 binary (what VTK calls \"binary\"); ascii: readable text.");
  d.param<bool>("glyph_tensor")
      .byDefault(false)
      .doc(
          "Add `T.glyph` = T + c I with one c for the whole field, c = -min(l3) + 0.1 max|l| "
          "(l3 the smallest eigenvalue at any vertex, max|l| the largest eigenvalue magnitude): "
          "positive definite (every eigenvalue at least 0.1 max|l|, so no glyph is flat or "
          "inside out), the same eigenvectors as T, and one shift everywhere so glyph sizes "
          "compare across the mesh and each shape shows T's deviator (linear tensors cigars, "
          "planar ones discs). T's own eigenvalues have both signs (tfd keeps T traceless), "
          "which Tensor Glyph cannot draw as ellipsoids.");
  d.param<bool>("paraview_script")
      .byDefault(false)
      .doc(
          "Also write `<name>.paraview.py` (and `<name>.curves.vtp` with `curves` connected) "
          "next to the .vtu: a ParaView scene of the mesh, the curves coloured by `colour` with "
          "Map Scalars off, and ellipsoid glyphs of `T.glyph` (added whatever glyph_tensor "
          "says) at up to 800 random vertices.");
  d.migration(1, [](graph::Json& params) {
    // typeVersion 1 called raw appended data "binary"; VTK's own word is "appended".
    if (params.contains("encoding") && params["encoding"] == "binary")
      params["encoding"] = "appended";
  });
}

/// Cell arrays marking the tets each curve segment passes through (core/topology/curve_tets.h)
/// with the segment's Fig. 5 colour. Where several curves share a tet, the lower id wins.
std::vector<io::NamedArray> curveCellArrays(const core::TetMesh& mesh,
                                            const core::DegenerateCurves& curves) {
  std::vector<double> ids(mesh.tetCount(), -1), colours(3 * mesh.tetCount(), 0);
  auto mark = [&](int tet, int id, core::DegenerateType type, core::DegeneratePattern pattern) {
    if (tet < 0 || (ids[tet] >= 0 && ids[tet] <= id)) return;
    ids[tet] = id;
    const auto rgb = core::fig5Colour(type, pattern);
    for (int k = 0; k < 3; ++k) colours[3 * tet + k] = rgb[k];
  };
  using core::DegeneratePattern;
  for (const core::DegenerateCurve& curve : curves.curves()) {
    const std::vector<int> tets = core::segmentTets(mesh, curve);
    const std::size_t n = curve.points.size();
    for (std::size_t i = 0; i < tets.size(); ++i) {
      // A segment's pattern is its ends' one; a transition end takes the other end's.
      const DegeneratePattern a = curve.patterns[i], b = curve.patterns[(i + 1) % n];
      mark(tets[i], curve.id, curve.type, a == DegeneratePattern::Transition ? b : a);
    }
    if (n == 1)
      for (int t : core::tetsOfSource(mesh, curve.sources[0]))
        mark(t, curve.id, curve.type, curve.patterns[0]);
  }
  return {{"curve_id", 1, std::move(ids), io::VtkType::Int32},
          {"curve_colour", 3, std::move(colours), io::VtkType::UInt8}};
}

void cook(graph::CookContext& c) {
  const auto field = c.input<core::TensorField>("field");
  io::VtuFieldOptions o;
  o.encoding = c.param("encoding", kEncodings);
  if (const auto curves = c.inputOr<core::DegenerateCurves>("curves", nullptr)) {
    o.cellData = curveCellArrays(field->mesh(), *curves);
    std::size_t marked = 0;
    for (std::size_t t = 0; t < field->mesh().tetCount(); ++t)
      marked += o.cellData[0].values[t] >= 0;
    c.info(std::to_string(marked) + " tets coloured by " + std::to_string(curves->size()) +
           " degenerate curves");
  }
  if (const auto region = c.inputOr<core::TetRegion>("region", nullptr)) {
    const std::size_t n = field->mesh().tetCount();
    if (region->mesh->tetCount() != n || region->mesh->vertexCount() != field->mesh().vertexCount())
      throw graph::NodeError("input 'region': the region belongs to another mesh than the field");
    std::vector<double> flags(n, 0);
    for (int t : region->tets) flags[t] = 1;
    o.cellData.push_back({"region", 1, std::move(flags), io::VtkType::UInt8});
    c.info(std::to_string(region->tets.size()) + " tets marked as the region");
  }
  const bool script = c.param<bool>("paraview_script");
  o.glyphTensor = script || c.param<bool>("glyph_tensor");
  const std::filesystem::path path = c.path("path");
  io::writeFieldVtu(path, *field, o, progressOf(c));
  c.wroteFile(path);
  c.info("wrote " + path.string());
  if (script) {
    const auto curves = c.inputOr<core::DegenerateCurves>("curves", nullptr);
    const io::ParaviewSceneFiles files = io::writeFieldParaviewScene(
        path, *field, curves.get(), o.tensorName + ".glyph", o.glyphMargin);
    if (!files.curves.empty()) c.wroteFile(files.curves);
    c.wroteFile(files.script);
    c.info("wrote " + files.script.string() +
           " (paraview --script=" + files.script.filename().string() + ")");
  }
}

}  // namespace

void registerExportVtu(graph::NodeRegistry& r) { r.add("ExportVTU", 2, declare, cook); }

}  // namespace tfd::nodes
