// The editor on screen (under Xvfb, Mesa's llvmpipe): the default example opened in the main
// window cooks in the background and the viewport shows the boundary with the degenerate
// curves in the Figure 5 colours; the node badges say cooked (exporters not run), a failing
// node turns red and what is downstream says so; a click on a drawn curve fills a selected
// LocalSmooth's `pick`; the cutting plane shows the mode's red and blue.
// With TFD_TEST_IMAGES=DIR the screenshots are kept there (docs/images comes from these).
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QImage>

#include <cstring>

#include <thread>

#include "graph/graph_file.h"
#include "nodes/register_all.h"
#include "render/image.h"
#include "tests/support/image_checks.h"
#include "tests/support/temp_dir.h"
#include "ui/canvas/canvas_scene.h"
#include "ui/canvas/canvas_style.h"
#include "ui/canvas/canvas_view.h"
#include "ui/cook/cook_controller.h"
#include "ui/document/graph_document.h"
#include "ui/viewport/viewport_panel.h"
#include "ui/window/info_panel.h"
#include "ui/window/main_window.h"

namespace tfd::ui {
namespace {

namespace fs = std::filesystem;

bool spinUntil(const std::function<bool()>& done, int timeoutMs = 120000) {
  QElapsedTimer t;
  t.start();
  while (!done() && t.elapsed() < timeoutMs) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return done();
}

render::Image toImage(const QImage& q) {
  const QImage c = q.convertToFormat(QImage::Format_RGBA8888);
  render::Image out;
  out.width = c.width();
  out.height = c.height();
  out.rgba.resize(std::size_t(c.width()) * c.height() * 4);
  for (int y = 0; y < c.height(); ++y)
    std::memcpy(&out.rgba[std::size_t(y) * c.width() * 4], c.constScanLine(y),
                std::size_t(c.width()) * 4);
  return out;
}

/// Pixels within 30 (per channel) of a colour.
int pixelsNear(const QImage& image, QColor colour) {
  const QImage c = image.convertToFormat(QImage::Format_RGB32);
  int n = 0;
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) {
      const QColor p = c.pixelColor(x, y);
      n += std::abs(p.red() - colour.red()) < 30 && std::abs(p.green() - colour.green()) < 30 &&
           std::abs(p.blue() - colour.blue()) < 30;
    }
  return n;
}

class Editor : public ::testing::Test {
 protected:
  void SetUp() override {
    nodes::registerAll(registry);
    // The default example at a smaller size, so the test cooks in seconds.
    graph::Graph g =
        graph::loadGraphFile(fs::path(TFD_SOURCE_DIR) / "examples" / "default.tfd.json", registry);
    g.setParam("ball", "target_tets", std::int64_t{8000});
    path = dir.path() / "default.tfd.json";
    graph::saveGraphFile(g, path);
    window = std::make_unique<MainWindow>(registry);
    window->prompts.saveChanges = [](const QString&) { return Prompts::Answer::Discard; };
    window->prompts.recover = [](const QString&) { return false; };
    window->prompts.error = [](const QString& e) { ADD_FAILURE() << e.toStdString(); };
    window->resize(1280, 800);
    window->show();
  }
  void TearDown() override { window.reset(); }

  /// Waits for the cook to end and the viewport to draw what it produced.
  void waitForFrame(int cooks) {
    ASSERT_TRUE(spinUntil([&] {
      return window->cook().finishedCooks() >= cooks && !window->cook().isCooking() &&
             window->viewport()->view()->framesOfCurrentScene() > 0;
    })) << "cooks: "
        << window->cook().finishedCooks();
  }

  test::TempDir dir{"editor-gl"};
  graph::NodeRegistry registry;
  fs::path path;
  std::unique_ptr<MainWindow> window;
};

TEST_F(Editor, TheDefaultExampleShowsCurvesInFigure5ColoursAndCookedBadges) {
  ASSERT_TRUE(window->openFile(path));
  waitForFrame(1);
  ViewportWidget* view = window->viewport()->view();
  ASSERT_TRUE(view->glReady()) << view->glStatus().toStdString();
  EXPECT_EQ(window->viewport()->shownNode(), "topology") << "the last node with outputs";
  const render::Image shot = toImage(view->grabFramebuffer());
  test::keepImage(shot, "editor_viewport");
  const test::ColourCounts counts = test::countColours(shot);
  int colours = 0;
  for (const auto& [name, n] : counts.fig5) colours += n > 30;
  EXPECT_GE(colours, 3) << "curves of at least three Figure 5 kinds are visible";
  EXPECT_GT(counts.distinct, 20);
  EXPECT_LT(counts.background, shot.width * shot.height * 9 / 10) << "the viewport is not blank";
  EXPECT_GT(counts.constraint, 20) << "the design elements' frames";

  // Badges: every node with outputs cooked, the exporters not run.
  for (const graph::Node& n : window->document().graph().nodes()) {
    SCOPED_TRACE(n.name());
    const NodeStatus::State s = window->canvas()->nodeItem(n.name())->status().state;
    if (n.decl().isSink())
      EXPECT_EQ(s, NodeStatus::State::Idle);
    else
      EXPECT_EQ(s, NodeStatus::State::Cooked);
  }
  window->canvasView()->frameAll();
  QCoreApplication::processEvents();
  const QImage canvas = window->canvasView()->grab().toImage();
  test::keepImage(toImage(canvas), "editor_canvas");
  EXPECT_GT(pixelsNear(canvas, style::cookedGreen()), 9 * 10) << "nine green badges";
  EXPECT_LT(pixelsNear(canvas, style::errorRed()), 5);
  test::keepImage(toImage(window->grab().toImage()), "editor_window");
}

TEST_F(Editor, AFailingNodeIsRedAndDownstreamSaysSo) {
  ASSERT_TRUE(window->openFile(path));
  waitForFrame(1);
  ASSERT_TRUE(window->document().setParam("ball", "file", std::string("missing.obj")));
  ASSERT_TRUE(spinUntil(
      [&] { return window->cook().finishedCooks() >= 2 && !window->cook().isCooking(); }));
  QCoreApplication::processEvents();
  EXPECT_EQ(window->canvas()->nodeItem("ball")->status().state, NodeStatus::State::Failed);
  EXPECT_EQ(window->canvas()->nodeItem("topology")->status().state,
            NodeStatus::State::UpstreamFailed);
  EXPECT_FALSE(window->canvas()->nodeItem("design")->status().hasError())
      << "an unrelated branch is fine";
  window->canvas()->selectNodes({"ball"});
  window->canvasView()->frameAll();
  QCoreApplication::processEvents();
  const QImage canvas = window->canvasView()->grab().toImage();
  test::keepImage(toImage(canvas), "editor_canvas_error");
  EXPECT_GT(pixelsNear(canvas, style::errorRed()), 20);
  EXPECT_TRUE(window->info()->toPlainText().contains("missing.obj"))
      << "the info panel shows the selected node's error: "
      << window->info()->toPlainText().toStdString();
  test::keepImage(toImage(window->grab().toImage()), "editor_window_error");
}

TEST_F(Editor, AClickOnADrawnCurveFillsTheSelectedNodesPick) {
  ASSERT_TRUE(window->openFile(path));
  waitForFrame(1);
  GraphDocument& doc = window->document();
  ASSERT_EQ(doc.addNode("LocalSmooth", {740, 520}, "smooth"), "smooth");
  ASSERT_TRUE(doc.connect({"field", "field"}, {"smooth", "field"}));
  ASSERT_TRUE(doc.setDisplayNode("topology"));  // the curves to pick on
  window->canvas()->selectNodes({"smooth"});
  waitForFrame(2);
  ViewportWidget* view = window->viewport()->view();
  const auto& xyz = view->scene().curves.positions;
  ASSERT_GE(xyz.size(), 6u);
  // The segment nearest the eye: no other curve can stand in front of its midpoint.
  const render::Vec3 eye = view->camera().eye();
  render::Vec3 mid = render::Vec3::Zero();
  for (std::size_t i = 0; i + 6 <= xyz.size(); i += 6) {
    const render::Vec3 a(xyz[i], xyz[i + 1], xyz[i + 2]), b(xyz[i + 3], xyz[i + 4], xyz[i + 5]);
    const render::Vec3 m = 0.5 * (a + b);
    if (i == 0 || (m - eye).norm() < (mid - eye).norm()) mid = m;
  }
  const auto pixel = view->camera().project(mid, view->width(), view->height());
  ASSERT_TRUE(pixel);
  const int steps = doc.undoStack()->count();
  ASSERT_TRUE(window->viewport()->clickAt(QPointF((*pixel)[0], (*pixel)[1])));
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
  const auto pick = std::get<graph::Vec3Param>(doc.graph().node("smooth").param("pick"));
  EXPECT_LT((render::Vec3(pick[0], pick[1], pick[2]) - mid).norm(), 0.05);
  // A click far from every curve changes nothing.
  EXPECT_FALSE(window->viewport()->clickAt(QPointF(2, 2)));
  EXPECT_EQ(doc.undoStack()->count(), steps + 1);
}

TEST_F(Editor, TheCuttingPlaneShowsTheModeInRedAndBlue) {
  ASSERT_TRUE(window->openFile(path));
  waitForFrame(1);
  render::SliceSettings s;
  s.axis = 2;
  s.position = 0.5;
  s.quantity = render::SliceQuantity::Mode;
  window->viewport()->setSlice(s);
  ViewportWidget* view = window->viewport()->view();
  ASSERT_TRUE(spinUntil([&] { return view->framesOfCurrentScene() > 0; }));
  const QImage shot = view->grabFramebuffer();
  test::keepImage(toImage(shot), "editor_viewport_cut");
  // The cool-warm map: +1 (linear) red, -1 (planar) blue, seen through the boundary.
  const QImage rgb = shot.convertToFormat(QImage::Format_RGB32);
  int reddish = 0, bluish = 0;
  for (int y = 0; y < rgb.height(); ++y)
    for (int x = 0; x < rgb.width(); ++x) {
      const QColor p = rgb.pixelColor(x, y);
      reddish += p.red() > p.blue() + 60 && p.red() > p.green() + 40;
      bluish += p.blue() > p.red() + 60 && p.blue() > p.green() + 20;
    }
  const int area = rgb.width() * rgb.height();
  EXPECT_GT(reddish, area / 100) << "linear (red) regions";
  EXPECT_GT(bluish, area / 100) << "planar (blue) regions";
}

}  // namespace
}  // namespace tfd::ui
