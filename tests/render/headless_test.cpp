// Headless drawing through surfaceless EGL (no X server): the pictures show the curves in the
// Figure 5 colours inside a translucent boundary, the cutting plane's colour map, and the PNGs
// written read back identically.
#include <gtest/gtest.h>

#include <map>

#include "core/structured_mesh.h"
#include "render/headless.h"
#include "render/scene_builder.h"
#include "tests/support/image_checks.h"
#include "tests/support/temp_dir.h"

namespace tfd::render {
namespace {

core::DegenerateCurve straight(core::DegenerateType type, core::DegeneratePattern pattern, Vec3 a, Vec3 b,
                               int points = 20) {
  core::DegenerateCurve c;
  c.type = type;
  for (int i = 0; i < points; ++i) {
    c.points.push_back(a + (b - a) * (double(i) / (points - 1)));
    c.patterns.push_back(i == points / 2 ? core::DegeneratePattern::Transition : pattern);
  }
  return c;
}

TEST(HeadlessRender, CurvesInFigure5ColoursInsideTheBoundary) {
  auto mesh = core::makeBoxMesh(6, 6, 6, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  core::DegenerateCurves curves({
      straight(core::DegenerateType::Linear, core::DegeneratePattern::Wedge, {-0.8, -0.6, 0}, {0.8, -0.6, 0}),
      straight(core::DegenerateType::Linear, core::DegeneratePattern::Trisector, {-0.8, -0.2, 0},
               {0.8, -0.2, 0}),
      straight(core::DegenerateType::Planar, core::DegeneratePattern::Wedge, {-0.8, 0.2, 0}, {0.8, 0.2, 0}),
      straight(core::DegenerateType::Planar, core::DegeneratePattern::Trisector, {-0.8, 0.6, 0},
               {0.8, 0.6, 0}),
  });
  SceneInput in;
  in.mesh = mesh.get();
  in.curves = &curves;
  const Scene scene = buildScene(in);
  EXPECT_EQ(scene.curves.segmentCount(), 4u * 19);
  EXPECT_EQ(scene.points.positions.size(), 4u * 3) << "one transition point per curve";
  RenderRequest r;
  r.width = 320;
  r.height = 240;
  r.view = ViewPreset::Z;  // from above: all four curves visible side by side
  const Image image = renderImage(scene, r);
  test::keepImage(image, "headless_fig5_curves");
  ASSERT_EQ(image.width, 320);
  const test::ColourCounts counts = test::countColours(image);
  EXPECT_GT(counts.fig5.at("L-wedge"), 200);
  EXPECT_GT(counts.fig5.at("L-trisector"), 200);
  EXPECT_GT(counts.fig5.at("P-wedge"), 200);
  EXPECT_GT(counts.fig5.at("P-trisector"), 200);
  EXPECT_GT(counts.white, 20) << "transition points";
  EXPECT_GT(counts.background, 320 * 240 / 10);
  EXPECT_GT(counts.distinct, 8);
}

TEST(HeadlessRender, TheViewPresetsLookAlongTheirAxes) {
  // One red (P-trisector) curve along x: seen from x it is a dot, from z a long line.
  auto mesh = core::makeBoxMesh(3, 3, 3, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  core::DegenerateCurves curves({straight(core::DegenerateType::Planar, core::DegeneratePattern::Trisector,
                                          {-0.9, 0, 0}, {0.9, 0, 0})});
  SceneInput in;
  in.mesh = mesh.get();
  in.curves = &curves;
  const Scene scene = buildScene(in);
  RenderRequest r;
  r.width = r.height = 200;
  std::map<ViewPreset, int> red;
  for (ViewPreset v : {ViewPreset::X, ViewPreset::Z, ViewPreset::Iso}) {
    r.view = v;
    red[v] = test::countColours(renderImage(scene, r)).fig5.at("P-trisector");
  }
  EXPECT_LT(red[ViewPreset::X], 150);
  EXPECT_GT(red[ViewPreset::Z], 5 * red[ViewPreset::X]);
  EXPECT_GT(red[ViewPreset::Iso], 2 * red[ViewPreset::X]);
}

TEST(HeadlessRender, TheCuttingPlaneShowsTheModeColourMap) {
  auto mesh = core::makeBoxMesh(8, 8, 8, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  // Linear (mode +1) where x > 0, planar (mode -1) where x < 0.
  std::vector<core::Tensor> values;
  for (const Vec3& p : mesh->positions()) {
    core::Tensor t;
    const double s = p.x() > 0 ? 1 : -1;
    t.xx = 2 * s, t.yy = -s, t.zz = -s;
    values.push_back(t);
  }
  core::TensorField field(mesh, values);
  SceneInput in;
  in.mesh = mesh.get();
  in.field = &field;
  in.slice = SliceSettings{2, 0.5, SliceQuantity::Mode};
  const Scene scene = buildScene(in);
  EXPECT_FALSE(scene.slice.positions.empty());
  RenderRequest r;
  r.width = r.height = 200;
  r.view = ViewPreset::Z;
  r.draw.showBoundary = false;
  const Image image = renderImage(scene, r);
  // Left half blue-ish (planar), right half red-ish (linear).
  const std::uint8_t* left = image.pixel(60, 100);
  const std::uint8_t* right = image.pixel(140, 100);
  EXPECT_GT(left[2], left[0] + 60) << int(left[0]) << " " << int(left[2]);
  EXPECT_GT(right[0], right[2] + 60) << int(right[0]) << " " << int(right[2]);
}

TEST(HeadlessRender, PngsRoundTrip) {
  test::TempDir dir("render-png");
  Image image;
  image.width = 7;
  image.height = 3;
  for (int i = 0; i < 7 * 3 * 4; ++i) image.rgba.push_back(static_cast<std::uint8_t>(i * 5));
  writePng(image, dir.path() / "a.png");
  const Image back = readPng(dir.path() / "a.png");
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgba, image.rgba);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.png"}) << "no temporary file left";
  EXPECT_THROW(writePng(image, dir.path() / "missing" / "b.png"), std::runtime_error);
  EXPECT_THROW(readPng(dir.path() / "nope.png"), std::runtime_error);
}

}  // namespace
}  // namespace tfd::render
