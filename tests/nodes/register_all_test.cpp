// The registered node types as a whole: every parameter feeds the cache key, the shipped
// examples load, and node-level behaviour that no core test covers (ExportVTU's curve colours,
// error messages naming the parameter).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"
#include "tests/support/builtin_nodes.h"
#include "tests/support/registry_hash_check.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vtk_xml_reader.h"

namespace tfd::nodes {
namespace {

namespace fs = std::filesystem;

graph::CookResult cookText(const std::string& text, const fs::path& outDir) {
  graph::Graph g = graph::parseGraph(text, test::builtinNodes(), "test graph");
  graph::CookOptions options;
  options.outDir = outDir;
  options.baseDir = outDir;
  graph::Evaluator evaluator;
  return evaluator.cook(g, options);
}

std::string errorOf(const graph::CookResult& result, const std::string& node) {
  const graph::NodeReport* r = result.report(node);
  if (r == nullptr) return "(no report)";
  for (const auto& m : r->messages)
    if (m.severity == graph::Severity::Error) return m.text;
  return "(no error)";
}

TEST(NodeTypes, EveryParameterOfEveryRegisteredTypeChangesTheHash) {
  test::expectEveryParameterChangesHash(test::builtinNodes());
}

TEST(NodeTypes, TheFirstNodeTypesAreRegisteredUnderTheirPublicNames) {
  for (const char* type :
       {"TetMesh", "FieldExpression", "PointConstraint", "MergeConstraints", "Propagate",
        "ExportVTU", "ExportVDB", "ExportEXR", "ExtractDegenerateCurves", "ExportCurves",
        "CurveConstraint", "LocalSmooth"})
    EXPECT_TRUE(test::builtinNodes().find(type) != nullptr) << type;
}

TEST(NodeTypes, EveryShippedExampleLoads) {
  int examples = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(TFD_SOURCE_DIR) / "examples")) {
    if (entry.path().string().ends_with(".tfd.json")) {
      SCOPED_TRACE(entry.path().string());
      EXPECT_NO_THROW(graph::loadGraphFile(entry.path(), test::builtinNodes()));
      ++examples;
    }
  }
  EXPECT_GE(examples, 3);
}

constexpr const char* kDesign = R"({
  "format": "tfd-graph", "formatVersion": 2,
  "nodes": {
    "ball": {"type": "TetMesh", "typeVersion": 1, "params": {"target_tets": 5000}},
    "p": {"type": "PointConstraint", "typeVersion": 1,
          "params": {"kind": "degenerate", "position": [0.1, 0.05, 0.02], "type": "planar"}},
    "field": {"type": "Propagate", "typeVersion": 1},
    "topology": {"type": "ExtractDegenerateCurves", "typeVersion": 1},
    "vtu": {"type": "ExportVTU", "typeVersion": 1, "params": {"path": "f.vtu"}}
  },
  "links": [
    {"from": "ball.mesh", "to": "field.mesh"}, {"from": "p.constraints", "to": "field.constraints"},
    {"from": "field.field", "to": "topology.field"}, {"from": "field.field", "to": "vtu.field"},
    {"from": "topology.curves", "to": "vtu.curves"}
  ]})";

TEST(NodeTypes, ExportVtuColoursTheTetsAlongEachCurveWithFigure5Colours) {
  test::TempDir dir("node-types-vtu");
  const graph::CookResult result = cookText(kDesign, dir.path());
  ASSERT_TRUE(result.ok()) << errorOf(result, "field") << errorOf(result, "vtu");
  const auto curves = result.output<core::DegenerateCurves>("topology", "curves");
  ASSERT_FALSE(curves->empty());

  const test::VtkXmlFile file = test::readVtkXmlFile(dir.path() / "f.vtu");
  const auto& cells = file.root.child("UnstructuredGrid").child("Piece").child("CellData");
  const std::vector<double> ids = file.values(file.array(cells, "curve_id"));
  const std::vector<double> rgb = file.values(file.array(cells, "curve_colour"));
  ASSERT_EQ(rgb.size(), 3 * ids.size());
  std::set<int> seen;
  for (std::size_t t = 0; t < ids.size(); ++t) {
    if (ids[t] < 0) {
      EXPECT_EQ(rgb[3 * t] + rgb[3 * t + 1] + rgb[3 * t + 2], 0) << "tet " << t;
      continue;
    }
    const core::DegenerateCurve& curve = curves->curve(static_cast<int>(ids[t]));
    seen.insert(curve.id);
    std::set<std::array<double, 3>> allowed;
    for (auto pattern : {core::DegeneratePattern::Wedge, core::DegeneratePattern::Trisector,
                         core::DegeneratePattern::Transition}) {
      const auto c = core::fig5Colour(curve.type, pattern);
      allowed.insert({double(c[0]), double(c[1]), double(c[2])});
    }
    EXPECT_TRUE(allowed.count({rgb[3 * t], rgb[3 * t + 1], rgb[3 * t + 2]})) << "tet " << t;
  }
  EXPECT_EQ(seen.size(), curves->size()) << "every curve marks at least one tet";
}

TEST(NodeTypes, BadParametersFailTheNodeNamingTheParameter) {
  test::TempDir dir("node-types-bad");
  std::string text = kDesign;
  text.replace(text.find(R"("path": "f.vtu")"), 15, R"("path": "f.vtu", "encoding": "ascii")");
  const std::string torus =
      R"("params": {"primitive": "torus", "major_radius": 0.5, "minor_radius": 0.6})";
  std::string bad = text;
  bad.replace(bad.find(R"("params": {"target_tets": 5000})"), 31, torus);
  graph::CookResult r = cookText(bad, dir.path());
  EXPECT_NE(errorOf(r, "ball").find("parameter 'minor_radius'"), std::string::npos)
      << errorOf(r, "ball");
  bad = text;
  bad.replace(bad.find(R"("params": {"target_tets": 5000})"), 31,
              R"("params": {"target_tets": 5000, "quality": 1.05})");
  r = cookText(bad, dir.path());
  EXPECT_NE(errorOf(r, "ball").find("parameter 'quality'"), std::string::npos)
      << errorOf(r, "ball");
  EXPECT_TRUE(dir.entries().empty()) << "nothing written";
}

TEST(NodeTypes, FieldExpressionRefusesAnExpressionThatDoesNotParseWhenItIsSet) {
  // The declaration's check runs on every set: the editor validates as the user types, a file
  // with a bad expression fails to load at the parameter's place, and `--set` is refused.
  graph::NodeRegistry registry;
  registerAll(registry);
  graph::Graph g(registry);
  g.addNode("FieldExpression", "e");
  try {
    g.setParam("e", "xy", std::string("x * * y"));
    FAIL() << "accepted";
  } catch (const graph::GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("parameter \"xy\" of node \"e\" (FieldExpression): "),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(g.param("e", "xy"), graph::ParamValue(std::string("y")));
  g.setParam("e", "xy", std::string("sin(x) * y"));
  try {
    graph::parseGraph(R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
        "e": {"type": "FieldExpression", "typeVersion": 1, "params": {"zz": "1 +"}}},
        "links": []})",
                      registry, "bad.tfd.json");
    FAIL() << "loaded";
  } catch (const graph::LoadError& e) {
    EXPECT_EQ(e.pointer(), "/nodes/e/params/zz");
  }
}

TEST(NodeTypes, VoxelExportsRefuseAVoxelSizeThatGivesTooManyVoxels) {
  test::TempDir dir("node-types-voxels");
  const graph::CookResult r = cookText(R"({
    "format": "tfd-graph", "formatVersion": 2,
    "nodes": {
      "box": {"type": "TetMesh", "typeVersion": 1, "params": {"primitive": "box", "target_tets": 500}},
      "f": {"type": "FieldExpression", "typeVersion": 1},
      "vdb": {"type": "ExportVDB", "typeVersion": 1, "params": {"voxel_size": 1e-5}},
      "exr": {"type": "ExportEXR", "typeVersion": 1, "params": {"voxel_size": 1e-5}}
    },
    "links": [{"from": "box.mesh", "to": "f.mesh"}, {"from": "f.field", "to": "vdb.field"},
              {"from": "f.field", "to": "exr.field"}]})",
                                       dir.path());
  for (const char* node : {"vdb", "exr"}) {
    SCOPED_TRACE(node);
    EXPECT_NE(errorOf(r, node).find("parameter 'voxel_size': voxel size 1e-05 gives"),
              std::string::npos)
        << errorOf(r, node);
  }
  EXPECT_TRUE(dir.entries().empty()) << "nothing written";
}

/// A unit cube as a CAD tool might export it: 6 quads, every face with its own 4 vertices,
/// moved by `seam` × (face number) along x (0: the copies coincide exactly); face
/// `reversedFace` (if any) wound the wrong way, face `missingFace` (if any) left out.
void writeCubeOfSeparateFaces(const fs::path& file, double seam, int reversedFace = -1,
                              int missingFace = -1) {
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::ofstream obj(file);
  obj.precision(17);
  int next = 1;
  for (int f = 0; f < 6; ++f) {
    for (int i : quads[f])
      obj << "v " << corners[i][0] + seam * f << " " << corners[i][1] << " " << corners[i][2]
          << "\n";
    if (f == missingFace) {
      // its vertices only
    } else if (f == reversedFace)
      obj << "f " << next + 3 << " " << next + 2 << " " << next + 1 << " " << next << "\n";
    else
      obj << "f " << next << " " << next + 1 << " " << next + 2 << " " << next + 3 << "\n";
    next += 4;
  }
}

/// A graph of one TetMesh node "m" meshing cube.obj, plus `extra` parameters (", ...").
std::string cubeMeshGraph(const std::string& extra = "", int targetTets = 2000) {
  return R"({"format": "tfd-graph", "formatVersion": 2,
      "nodes": {"m": {"type": "TetMesh", "typeVersion": 1,
                      "params": {"file": "cube.obj", "target_tets": )" +
         std::to_string(targetTets) + extra + R"(}}}, "links": []})";
}

/// The info messages of node "m", one per line.
std::string infoOfM(const graph::CookResult& r) {
  std::string info;
  for (const auto& m : r.report("m")->messages) info += m.text + "\n";
  return info;
}

/// Node "m" meshed a unit cube and said `said` in its info.
void expectUnitCubeSaying(const graph::CookResult& r, const std::string& said,
                          double tolerance = 1e-9) {
  ASSERT_TRUE(r.ok()) << errorOf(r, "m");
  EXPECT_NEAR(r.output<core::TetMesh>("m", "mesh")->totalVolume(), 1, tolerance);
  EXPECT_NE(infoOfM(r).find(said), std::string::npos) << infoOfM(r);
}

TEST(NodeTypes, TetMeshWeldsSeamsAndRefinesACoarseSurfaceToTheTargetCount) {
  test::TempDir dir("node-types-cube");
  writeCubeOfSeparateFaces(dir.path() / "cube.obj", 0);
  const graph::CookResult r = cookText(cubeMeshGraph("", 4000), dir.path());
  ASSERT_TRUE(r.ok()) << errorOf(r, "m");
  const auto mesh = r.output<core::TetMesh>("m", "mesh");
  EXPECT_NEAR(mesh->totalVolume(), 1, 1e-9);
  EXPECT_GT(mesh->tetCount(), 2000u);
  EXPECT_LT(mesh->tetCount(), 8000u);
  const std::string info = infoOfM(r);
  EXPECT_NE(info.find("welded 16 vertices"), std::string::npos) << info;
  EXPECT_NE(info.find("TetGen refines the boundary too"), std::string::npos) << info;
}

TEST(NodeTypes, TetMeshReversesTrianglesWoundAgainstTheirNeighbours) {
  test::TempDir dir("node-types-wound");
  writeCubeOfSeparateFaces(dir.path() / "cube.obj", 0, 3);
  expectUnitCubeSaying(cookText(cubeMeshGraph(), dir.path()),
                       "reversed 2 triangles to agree in orientation");
}

TEST(NodeTypes, TetMeshNamesTheHolesOfAnOpenSurfaceAndFillsThemWhenAsked) {
  test::TempDir dir("node-types-holes");
  writeCubeOfSeparateFaces(dir.path() / "cube.obj", 0, -1, 1);  // no top
  const graph::CookResult open = cookText(cubeMeshGraph(), dir.path());
  ASSERT_FALSE(open.ok());
  const std::string error = errorOf(open, "m");
  EXPECT_NE(error.find("It has 1 hole (a loop of 4 open edges): fill_holes ≥ 4 closes it"),
            std::string::npos)
      << error;
  expectUnitCubeSaying(cookText(cubeMeshGraph(R"(, "fill_holes": 4)"), dir.path()),
                       "closed 1 hole with 4 triangles");
}

TEST(NodeTypes, TetMeshWeldsSeamsWrittenARoundingErrorApart) {
  // The faces' copies of a corner up to 5e-9 apart: welded by default (a thousandth of the
  // median edge, 1); with weld_tolerance 0 the cube is open, and the error says which
  // tolerance would close it.
  test::TempDir dir("node-types-seams");
  writeCubeOfSeparateFaces(dir.path() / "cube.obj", 1e-9);
  expectUnitCubeSaying(cookText(cubeMeshGraph(), dir.path()),
                       "welded 16 vertices repeated at the same position or within 0.001 of", 1e-8);

  const graph::CookResult open = cookText(cubeMeshGraph(R"(, "weld_tolerance": 0.0)"), dir.path());
  ASSERT_FALSE(open.ok());
  const std::string error = errorOf(open, "m");
  EXPECT_NE(error.find("the surface is not closed"), std::string::npos) << error;
  EXPECT_NE(error.find("a weld_tolerance above 5e-09 welds them"), std::string::npos) << error;
}

}  // namespace
}  // namespace tfd::nodes
