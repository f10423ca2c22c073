#pragma once
// What the viewport draws: the display node's output (nodes/display_values.h, the same values
// `tfd render` draws) as a render::Scene, plus the overlays of the selected node read from its
// parameters by name, so new node types get them without editor changes: a `region` choice of
// sphere/box with `center`, `radius`, `size` is outlined; `pick`, `picks` and position-hinted
// `points` are marked. Runs on the UI thread; no OpenGL.
#include <optional>
#include <string_view>

#include "graph/evaluator.h"
#include "graph/graph.h"
#include "render/scene.h"
#include "render/scene_builder.h"

namespace tfd::ui {

/// The scene of `node`'s cooked values in `result` (empty when nothing drawable has cooked),
/// with a cutting plane when `slice` is set and a field reaches the node.
render::Scene displayScene(const graph::Graph& graph, const graph::CookResult& result,
                           std::string_view node,
                           const std::optional<render::SliceSettings>& slice);

/// Adds the selected node's region outline and pick markers (see above) to `scene`.
void addSelectionOverlay(render::Scene& scene, const graph::Node& selected);

}  // namespace tfd::ui
