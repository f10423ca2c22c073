// The exporters' parameters for files that show something as opened: ExportVDB.density (a fog
// volume grid; typeVersion 2 files keep writing no density), ExportEXR.preview (R, G, B) and
// ExportVTU.glyph_tensor / paraview_script. Cooks tests/data/graphs/nodes/exporters_v3.tfd.json
// and reads every file back with the libraries (OpenVDB, OpenEXR) or the independent VTK reader.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "io/volume/exr_reader.h"
#include "io/volume/vdb_reader.h"
#include "nodes/register_all.h"
#include "tests/support/builtin_nodes.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vtk_xml_reader.h"

namespace tfd::nodes {
namespace {

namespace fs = std::filesystem;

graph::CookResult cook(graph::Graph& g, const fs::path& outDir) {
  graph::CookOptions options;
  options.outDir = outDir;
  graph::Evaluator evaluator;
  return evaluator.cook(g, options);
}

std::map<std::string, std::string> gridClasses(const fs::path& file) {
  std::map<std::string, std::string> out;
  for (const auto& g : io::readVdbFile(file, false).grids) out[g.name] = g.gridClass;
  return out;
}

TEST(ExportViews, FixtureWritesDensityPreviewGlyphsAndScene) {
  test::TempDir dir("export-views");
  graph::Graph g = graph::loadGraphFile(TFD_TEST_DATA_DIR "/graphs/nodes/exporters_v3.tfd.json",
                                        test::builtinNodes());
  const graph::CookResult r = cook(g, dir.path());
  ASSERT_TRUE(r.ok());

  // typeVersion 2: the grids it always wrote, no density; typeVersion 3: density, a fog volume.
  EXPECT_EQ(gridClasses(dir.path() / "v2.vdb"),
            (std::map<std::string, std::string>{{"T.xx", "unknown"},
                                                {"T.xy", "unknown"},
                                                {"T.xz", "unknown"},
                                                {"T.yy", "unknown"},
                                                {"T.yz", "unknown"},
                                                {"T.zz", "unknown"}}));
  EXPECT_EQ(
      gridClasses(dir.path() / "v3.vdb"),
      (std::map<std::string, std::string>{{"T.eigval", "unknown"}, {"density", "fog volume"}}));
  for (const auto& grid : io::readVdbFile(dir.path() / "v3.vdb").grids) {
    if (grid.name != "density") continue;
    double lo = 2, hi = -1;
    for (const auto& v : grid.activeVoxels) {
      lo = std::min(lo, v.value[0]);
      hi = std::max(hi, v.value[0]);
    }
    EXPECT_GE(lo, 0.0);
    EXPECT_LE(hi, 1.0);
    EXPECT_GT(hi, 0.99);  // anisotropy: the strongest vertex's own voxel region reaches ~1
    EXPECT_LT(lo, hi);
  }

  // EXR: R, G, B in [0, 1] beside the data channels.
  const auto* exr = r.report("exr");
  ASSERT_NE(exr, nullptr);
  ASSERT_EQ(exr->files.size(), 2u);
  const io::ExrImage image = io::readExrImage(exr->files[0].path);
  for (const char* ch : {"R", "G", "B", "A", "T.xx"})
    EXPECT_EQ(image.channelTypes.count(ch), 1u) << ch;
  std::set<float> reds;
  for (float v : image.pixels.at("R")) {
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
    reds.insert(v);
  }
  EXPECT_GT(reds.size(), 5u);

  // VTU: T.glyph active; the script opens files that exist.
  const test::VtkXmlFile vtu = test::readVtkXmlFile(dir.path() / "f.vtu");
  EXPECT_EQ(
      vtu.root.child("UnstructuredGrid").child("Piece").child("PointData").attribute("Tensors"),
      "T.glyph");
  std::set<fs::path> written;
  for (const auto& f : r.report("vtu")->files) written.insert(f.path);
  EXPECT_EQ(written, (std::set<fs::path>{dir.path() / "f.vtu", dir.path() / "f.paraview.py"}));
  std::ifstream in(dir.path() / "f.paraview.py");
  std::stringstream text;
  text << in.rdbuf();
  const std::string script = text.str();
  const std::regex join(R"(os\.path\.join\(HERE, '([^']+)'\))");
  int opened = 0;
  for (auto it = std::sregex_iterator(script.begin(), script.end(), join);
       it != std::sregex_iterator(); ++it, ++opened)
    EXPECT_TRUE(fs::exists(dir.path() / (*it)[1].str())) << (*it)[1];
  EXPECT_EQ(opened, 1) << "no curves connected: the mesh only";
}

TEST(ExportViews, DensityAndPreviewOtherThanNoneOrDefaultAreErrorsWithAVolume) {
  test::TempDir dir("export-views-volume");
  const std::string text = R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
    "box": {"type": "TetMesh", "typeVersion": 1, "params": {"primitive": "box", "target_tets": 300}},
    "f": {"type": "FieldExpression", "typeVersion": 1},
    "noise": {"type": "GaborNoise", "typeVersion": 1, "params": {"voxel_size": 0.2}},
    "vdb": {"type": "ExportVDB", "typeVersion": 3, "params": {"path": "n.vdb", "density": "anisotropy"}},
    "exr": {"type": "ExportEXR", "typeVersion": 2, "params": {"path": "n.%d.exr", "preview": "anisotropy"}}},
    "links": [{"from": "box.mesh", "to": "f.mesh"}, {"from": "f.field", "to": "noise.field"},
              {"from": "noise.volume", "to": "vdb.volume"}, {"from": "noise.volume", "to": "exr.volume"}]})";
  graph::Graph g = graph::parseGraph(text, test::builtinNodes(), "test graph");
  const graph::CookResult r = cook(g, dir.path());
  for (const char* node : {"vdb", "exr"}) {
    const graph::NodeReport* rep = r.report(node);
    ASSERT_NE(rep, nullptr);
    std::string errors;
    for (const auto& m : rep->messages)
      if (m.severity == graph::Severity::Error) errors += m.text;
    EXPECT_NE(errors.find(node == std::string("vdb") ? "density" : "preview"), std::string::npos)
        << node << ": " << errors;
    EXPECT_NE(errors.find("field"), std::string::npos) << errors;
  }
}

}  // namespace
}  // namespace tfd::nodes
