// GaborNoise and the voxel exporters' `volume` input: the volume written to OpenVDB (a fog
// volume `density` grid) and OpenEXR (R = G = B = value, A = mask) is read back with the
// libraries and compared voxel by voxel with the node's output; an exporter takes exactly one
// of `field` and `volume`, and the field-only parameters are errors with `volume`.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "graph/evaluator.h"
#include "graph/graph_file.h"
#include "graph/node_registry.h"
#include "io/volume/exr_reader.h"
#include "io/volume/vdb_reader.h"
#include "nodes/register_all.h"
#include "nodes/value_types.h"
#include "tests/support/builtin_nodes.h"
#include "tests/support/temp_dir.h"

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

std::string messageOf(const graph::CookResult& result, const std::string& node,
                      graph::Severity severity = graph::Severity::Error) {
  const graph::NodeReport* r = result.report(node);
  if (r == nullptr) return "(no report)";
  for (const auto& m : r->messages)
    if (m.severity == severity) return m.text;
  return "(none)";
}

/// A box, a linear field along x, noise, and the exporters given in `exporters` / `links`.
std::string graphText(const std::string& noiseParams, const std::string& exporters,
                      const std::string& links) {
  return R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {
    "box": {"type": "TetMesh", "typeVersion": 1, "params": {"primitive": "box", "target_tets": 800}},
    "f": {"type": "FieldExpression", "typeVersion": 1,
          "params": {"xx": "1", "yy": "-0.5", "zz": "-0.5", "xy": "0", "yz": "0", "xz": "0"}},
    "noise": {"type": "GaborNoise", "typeVersion": 1, "params": )" +
         noiseParams + "}" + (exporters.empty() ? "" : ", ") + exporters + R"(},
    "links": [{"from": "box.mesh", "to": "f.mesh"}, {"from": "f.field", "to": "noise.field"})" +
         (links.empty() ? "" : ", ") + links + "]}";
}

TEST(GaborNoiseNode, VolumeExportsHoldTheNoiseVoxelForVoxel) {
  test::TempDir dir("gabor-node-files");
  const graph::CookResult r = cookText(
      graphText(R"({"frequency": 3, "voxel_size": 0.05, "range": "unit"})",
                R"("vdb": {"type": "ExportVDB", "typeVersion": 2, "params": {"path": "n.vdb"}},
                   "exr": {"type": "ExportEXR", "typeVersion": 2,
                           "params": {"path": "s/n.%03d.exr", "slice_count": 3}})",
                R"({"from": "noise.volume", "to": "vdb.volume"},
                   {"from": "noise.volume", "to": "exr.volume"})"),
      dir.path());
  ASSERT_TRUE(r.ok()) << messageOf(r, "noise") << messageOf(r, "vdb") << messageOf(r, "exr");
  const auto volume = r.output<core::ScalarVolume>("noise", "volume");
  const core::VoxelGrid& g = volume->grid;
  ASSERT_GT(volume->activeCount(), g.count() / 2);

  const io::VdbFileData vdb = io::readVdbFile(dir.path() / "n.vdb");
  ASSERT_EQ(vdb.grids.size(), 1u);
  const io::VdbGridData& grid = vdb.grids[0];
  EXPECT_EQ(grid.name, "density");
  EXPECT_EQ(grid.valueType, "float");
  EXPECT_EQ(grid.gridClass, "fog volume");
  EXPECT_NEAR(grid.voxelSize.x(), g.voxelSize, 1e-12);
  EXPECT_EQ(grid.activeVoxelCount, volume->activeCount());
  EXPECT_EQ(grid.inactiveNonBackground, 0u);
  double lo = 1, hi = 0;
  for (const auto& v : grid.activeVoxels) {
    ASSERT_TRUE(volume->inside(v.ijk[0], v.ijk[1], v.ijk[2]));
    ASSERT_EQ(float(v.value[0]), volume->at(v.ijk[0], v.ijk[1], v.ijk[2]));
    lo = std::min(lo, v.value[0]), hi = std::max(hi, v.value[0]);
  }
  EXPECT_LT(lo, 0.3);
  EXPECT_GT(hi, 0.7);

  std::vector<fs::path> slices;
  for (const auto& e : fs::directory_iterator(dir.path() / "s")) slices.push_back(e.path());
  std::sort(slices.begin(), slices.end());
  ASSERT_EQ(slices.size(), 3u) << "slice_count 3";
  const int n = g.dims()[2];
  for (int m = 0; m < 3; ++m) {
    const int s = int((m + 0.5) * n / 3);
    char name[32];
    std::snprintf(name, sizeof name, "n.%03d.exr", s);
    EXPECT_EQ(slices[m].filename(), name);
    const io::ExrImage image = io::readExrImage(slices[m]);
    ASSERT_EQ(image.width, g.dims()[0]);
    ASSERT_EQ(image.height, g.dims()[1]);
    EXPECT_EQ(image.channelTypes.size(), 4u);
    const int k = g.min[2] + s;
    for (int row = 0; row < image.height; ++row)
      for (int col = 0; col < image.width; ++col) {
        const int i = g.min[0] + col, j = g.max[1] - row;
        const float value = volume->at(i, j, k);
        ASSERT_EQ(image.at("R", col, row), value);
        ASSERT_EQ(image.at("G", col, row), value);
        ASSERT_EQ(image.at("B", col, row), value);
        ASSERT_EQ(image.at("A", col, row), volume->inside(i, j, k) ? 1.0f : 0.0f);
      }
  }
}

TEST(GaborNoiseNode, ExportersTakeExactlyOneOfFieldAndVolume) {
  test::TempDir dir("gabor-node-errors");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("e": {"type": "EXPORT", "typeVersion": 2, "params": {}})",
       "no input: connect input 'field'"},
      {R"("e": {"type": "EXPORT", "typeVersion": 2, "params": {}})",
       "inputs 'field' and 'volume' are both connected"},
      {R"("e": {"type": "EXPORT", "typeVersion": 2, "params": {"voxel_size": 0.1}})",
       "parameter 'voxel_size': applies to input 'field' only"},
      {R"("e": {"type": "EXPORT", "typeVersion": 2, "params": {"quantities": ["eigenvalues"]}})",
       "parameter 'quantities': applies to input 'field' only"}};
  for (const char* type : {"ExportVDB", "ExportEXR"}) {
    for (const auto& [node, expected] : cases) {
      SCOPED_TRACE(std::string(type) + " " + expected);
      std::string nodes = node;
      nodes.replace(nodes.find("EXPORT"), 6, type);
      std::string links;
      if (expected.find("no input") == std::string::npos)
        links = R"({"from": "noise.volume", "to": "e.volume"})";
      if (expected.find("both") != std::string::npos)
        links += R"(, {"from": "f.field", "to": "e.field"})";
      const graph::CookResult r =
          cookText(graphText(R"({"voxel_size": 0.1})", nodes, links), dir.path());
      EXPECT_NE(messageOf(r, "e").find(expected), std::string::npos) << messageOf(r, "e");
    }
  }
  EXPECT_TRUE(dir.entries().empty()) << "nothing written";
}

TEST(GaborNoiseNode, WarnsWhenAPeriodSpansFewerThanThreeVoxels) {
  test::TempDir dir("gabor-node-warning");
  const graph::CookResult r =
      cookText(graphText(R"({"frequency": 8, "voxel_size": 0.05})", "", ""), dir.path());
  ASSERT_TRUE(r.ok()) << messageOf(r, "noise");
  EXPECT_NE(messageOf(r, "noise", graph::Severity::Warning).find("fewer than 3 voxels"),
            std::string::npos);
  const graph::CookResult fine =
      cookText(graphText(R"({"frequency": 2, "voxel_size": 0.05})", "", ""), dir.path());
  EXPECT_EQ(messageOf(fine, "noise", graph::Severity::Warning), "(none)");
}

}  // namespace
}  // namespace tfd::nodes
