// `tfd render`: every shipped example draws to a non-blank PNG with the Figure 5 colours of
// its curves, without an X server (surfaceless EGL); usage errors exit 2, nothing to draw 1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "render/image.h"
#include "tests/support/cli_runner.h"
#include "tests/support/image_checks.h"
#include "tests/support/temp_dir.h"

namespace tfd::test {
namespace {

namespace fs = std::filesystem;
const fs::path kExamples = fs::path(TFD_SOURCE_DIR) / "examples";

class Render : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
    unsetenv("DISPLAY");  // prove no X server is used
  }
  static std::string q(const fs::path& p) { return shellQuote(p.string()); }
};

struct Example {
  const char* file;
  const char* coarser;  ///< --set making the test quick (fewer tets, same topology)
  std::vector<const char*> colours;
};

TEST_F(Render, EveryExampleDrawsItsCurvesInFigure5Colours) {
  TempDir dir("cli-render");
  const Example examples[] = {
      {"default.tfd.json",
       "ball.target_tets=12000",
       {"L-wedge", "L-trisector", "P-wedge", "P-trisector"}},
      {"genus2_curves.tfd.json", "genus2.target_tets=30000", {"L-trisector", "P-wedge"}},
      {"surface_mesh.tfd.json", "pebble.target_tets=20000", {}},
  };
  for (const Example& e : examples) {
    SCOPED_TRACE(e.file);
    const fs::path png = dir.path() / (std::string(e.file) + ".png");
    const CliRun r = runCli("render " + q(kExamples / e.file) + " --set " + e.coarser +
                            " --size 480x360 -q -o " + q(png));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const render::Image image = render::readPng(png);
    keepImage(image, std::string("render_") + e.file);
    ASSERT_EQ(image.width, 480);
    ASSERT_EQ(image.height, 360);
    const ColourCounts c = countColours(image);
    EXPECT_GT(c.background, 480 * 360 / 5) << "framed with room around it";
    EXPECT_LT(c.background, 480 * 360 * 9 / 10) << "not blank";
    EXPECT_GT(c.distinct, 30);
    for (const char* colour : e.colours) EXPECT_GT(c.fig5.at(colour), 30) << colour;
    int curvePixels = 0;
    for (const auto& [name, n] : c.fig5) curvePixels += n;
    EXPECT_GT(curvePixels, 100) << "some degenerate curves are drawn";
  }
  EXPECT_EQ(dir.entries().size(), 3u) << "no exporter ran, no temporary file left";
}

TEST_F(Render, ViewsSlicesAndBadArguments) {
  TempDir dir("cli-render-args");
  const fs::path graph = kExamples / "default.tfd.json";
  const std::string coarse = " --set ball.target_tets=3000 -q";
  CliRun r = runCli("render " + q(graph) + coarse + " --node field --view z --slice z=0.5 " +
                    "--quantity degeneracy --size 200x150 -o " + q(dir.path() / "slice.png"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(countColours(render::readPng(dir.path() / "slice.png")).distinct, 50)
      << "a colour-mapped cut";
  r = runCli("render " + q(graph) + coarse + " --view sideways -o " + q(dir.path() / "x.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--view sideways: expected iso, x, y or z"), std::string::npos) << r.err;
  r = runCli("render " + q(graph) + coarse + " --size 10x10000 -o " + q(dir.path() / "x.png"));
  EXPECT_EQ(r.exitCode, 2);
  r = runCli("render " + q(graph) + coarse + " --node nope -o " + q(dir.path() / "x.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("unknown node \"nope\""), std::string::npos) << r.err;
  r = runCli("render " + q(graph) + coarse + " --node topology --slice y -o " +
             q(dir.path() / "x.png"));
  EXPECT_EQ(r.exitCode, 0) << "curves come with the field they were extracted from: " << r.err;
  r = runCli("render " + q(graph) + coarse + " -o " + q(dir.path() / "no" / "such" / "x.png"));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tfd::test
