// The editor's viewport and start-up (bench/RESULTS.md, "Editor").
//
//   BM_ViewportFrame/<n>: one viewport frame (draw + glFinish) of a structured box of 6 n^3 tets
//       with an analytic field: translucent boundary, the extracted degenerate curves, a cutting
//       plane coloured by mode. Drawn by render::Renderer (the viewport's code) into an 800x600
//       4x multisampled target of a surfaceless EGL context: Mesa's llvmpipe on this machine.
//       n = 30 gives 162,000 tets, n = 55 gives 998,250.
//   BM_OpenDefaultToFirstFrame: tfd-editor's main window opens examples/default.tfd.json and
//       cooks it in the background; the time until the viewport has drawn the cooked display
//       node (needs an X display: run under xvfb-run).
//   BM_EditorMemory1M: the main window opens a graph reading a 998,250-tet mesh (.node/.ele),
//       with a FieldExpression field and its degenerate curves on display; reports the
//       process's resident memory before and after (MB), and the time to the first frame.
//       Run it alone (--benchmark_filter=EditorMemory) so earlier benchmarks' memory does not
//       count.
#include <benchmark/benchmark.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QSurfaceFormat>

#include <malloc.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

#include "core/design/field_expression.h"
#include "core/structured_mesh.h"
#include "core/topology/extract_degenerate_curves.h"
#include "graph/graph_file.h"
#include "io/tetgen/node_ele.h"
#include "nodes/display_values.h"
#include "nodes/register_all.h"
#include "render/headless.h"
#include "render/scene_builder.h"
#include "ui/cook/cook_controller.h"
#include "ui/viewport/gl_format.h"
#include "ui/viewport/viewport_panel.h"
#include "ui/window/main_window.h"

namespace {

using namespace tfd;
namespace fs = std::filesystem;

/// A linear traceless field: its degenerate curves cross the box (as a propagated design's do).
core::TensorExpressions analyticField() {
  core::TensorExpressions e;
  e.components = {"x + 0.3", "y - 0.2", "-x - y", "z", "0.5 * x + 0.1", "0.4 * y - 0.3 * z"};
  return e;
}

std::shared_ptr<const core::TensorField> boxField(int n) {
  auto mesh = core::makeBoxMesh(n, n, n, core::Vec3(-1, -1, -1), core::Vec3(1, 1, 1));
  return std::make_shared<const core::TensorField>(
      core::evaluateFieldExpression(mesh, analyticField()));
}

void BM_ViewportFrame(benchmark::State& state) {
  const int n = int(state.range(0));
  const auto field = boxField(n);
  const core::DegenerateCurves curves = core::extractDegenerateCurves(*field);
  render::SceneInput in;
  in.mesh = &field->mesh();
  in.field = field.get();
  in.curves = &curves;
  in.slice = render::SliceSettings{};
  const render::Scene scene = render::buildScene(in);
  std::unique_ptr<render::HeadlessContext> context;
  try {
    context = std::make_unique<render::HeadlessContext>(800, 600);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  render::Renderer renderer;
  std::string error;
  if (!renderer.initialize(&error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  context->bind();
  renderer.upload(scene);
  render::Camera camera;
  camera.frame(scene.bounds, 800.0 / 600.0);
  for (auto _ : state) {
    camera.orbit(3, 0);  // a turning view, as while orbiting
    renderer.draw(camera, 800, 600);
    context->finish();
  }
  state.counters["tets"] = double(field->mesh().tetCount());
  state.counters["curve_segments"] = double(scene.curves.segmentCount());
  state.counters["triangles"] =
      double(scene.boundary.indices.size() / 3 + scene.slice.positions.size() / 9);
  state.counters["fps"] =
      benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
  state.SetLabel(render::Renderer::contextDescription());
  renderer.release();
}
BENCHMARK(BM_ViewportFrame)
    ->Arg(30)
    ->Arg(55)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(3.0)
    ->UseRealTime();

double residentMb(const char* key) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key, 0) == 0) return std::stod(line.substr(std::string(key).size())) / 1024.0;
  return 0;
}

/// Opens a graph in a shown main window; returns seconds until the viewport has drawn the
/// cooked display node (negative on timeout).
double openToFirstFrame(ui::MainWindow& window, const fs::path& graph) {
  QElapsedTimer timer;
  timer.start();
  if (!window.openFile(graph)) return -1;
  ui::ViewportPanel* panel = window.viewport();
  while (timer.elapsed() < 600000) {
    QApplication::processEvents(QEventLoop::AllEvents, 5);
    if (!window.cook().isCooking() && window.cook().finishedCooks() > 0 &&
        !panel->shownNode().empty() && panel->view()->framesOfCurrentScene() > 0)
      return double(timer.nsecsElapsed()) * 1e-9;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return -1;
}

/// "" when every node of the last cook succeeded, else the first failure.
std::string firstFailure(ui::MainWindow& window) {
  for (const graph::NodeReport& r : window.cook().lastResult().reports)
    if (r.state == graph::NodeState::Failed || r.state == graph::NodeState::UpstreamFailed)
      return r.node + " failed" + (r.messages.empty() ? "" : ": " + r.messages.front().text);
  return {};
}

void reportDrawn(benchmark::State& state, ui::MainWindow& window) {
  const render::Scene& scene = window.viewport()->view()->scene();
  state.counters["curve_segments"] = double(scene.curves.segmentCount());
  state.counters["boundary_triangles"] = double(scene.boundary.indices.size() / 3);
  if (const std::string failure = firstFailure(window); !failure.empty())
    state.SkipWithError(failure.c_str());
}

struct EditorFixture {
  graph::NodeRegistry registry;
  std::unique_ptr<ui::MainWindow> window;
  bool ready(benchmark::State& state) {
    if (!qApp || QGuiApplication::platformName() == "offscreen") {
      state.SkipWithError("needs an X display (run under xvfb-run)");
      return false;
    }
    nodes::registerAll(registry);
    window = std::make_unique<ui::MainWindow>(registry);
    window->prompts.recover = [](const QString&) { return false; };
    window->resize(1280, 800);
    window->show();
    for (int i = 0; i < 20; ++i) QApplication::processEvents(QEventLoop::AllEvents, 10);
    return true;
  }
};

void BM_OpenDefaultToFirstFrame(benchmark::State& state) {
  for (auto _ : state) {
    EditorFixture f;
    if (!f.ready(state)) return;
    const double s =
        openToFirstFrame(*f.window, fs::path(TFD_SOURCE_DIR) / "examples" / "default.tfd.json");
    if (s < 0) state.SkipWithError("the example did not cook and draw in 10 minutes");
    state.SetIterationTime(s);
    reportDrawn(state, *f.window);
  }
}
BENCHMARK(BM_OpenDefaultToFirstFrame)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

void BM_EditorMemory1M(benchmark::State& state) {
  const fs::path dir = fs::temp_directory_path() / "tfd-editor-bench";
  fs::create_directories(dir);
  for (auto _ : state) {
    EditorFixture f;
    if (!f.ready(state)) return;
    const double empty = residentMb("VmRSS:");
    // The mesh file is made here, its memory handed back before the editor opens it.
    io::writeTetgen(dir / "box1m",
                    *core::makeBoxMesh(55, 55, 55, core::Vec3(-1, -1, -1), core::Vec3(1, 1, 1)));
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";  // restarts VmHWM (the peak) from here
    graph::Graph g(f.registry);
    g.addNode("TetMesh", "mesh");
    g.setParam("mesh", "file", (dir / "box1m.ele").string());
    g.addNode("FieldExpression", "field");
    const auto e = analyticField();
    for (int i = 0; i < 6; ++i)
      g.setParam("field", core::tensorComponentNames()[i], e.components[i]);
    g.addNode("ExtractDegenerateCurves", "curves");
    g.connect({"mesh", "mesh"}, {"field", "mesh"});
    g.connect({"field", "field"}, {"curves", "field"});
    graph::saveGraphFile(g, dir / "memory.tfd.json");
    const double before = residentMb("VmRSS:");
    const double s = openToFirstFrame(*f.window, dir / "memory.tfd.json");
    if (s < 0) state.SkipWithError("the graph did not cook and draw in 10 minutes");
    state.SetIterationTime(s);
    reportDrawn(state, *f.window);
    state.counters["rss_empty_editor_MB"] = empty;
    state.counters["rss_before_open_MB"] = before;
    state.counters["rss_loaded_MB"] = residentMb("VmRSS:");
    state.counters["peak_MB"] = residentMb("VmHWM:");
  }
  fs::remove_all(dir);
}
BENCHMARK(BM_EditorMemory1M)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(ui::viewportSurfaceFormat());
  if (!qEnvironmentVariableIsSet("DISPLAY")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
