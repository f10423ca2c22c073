#include "ui/document/node_ui.h"

#include <cmath>

#include "nodes/display_values.h"

namespace tfd::ui {

QPointF nodePosition(const graph::Node& node) {
  const graph::Json& ui = node.ui();
  auto it = ui.find("position");
  if (it == ui.end() || !it->is_array() || it->size() != 2) return {};
  const graph::Json& p = *it;
  if (!p[0].is_number() || !p[1].is_number()) return {};
  return {p[0].get<double>(), p[1].get<double>()};
}

graph::Json withPosition(graph::Json ui, QPointF position) {
  if (!ui.is_object()) ui = graph::Json::object();
  ui["position"] = graph::Json::array({static_cast<std::int64_t>(std::lround(position.x())),
                                       static_cast<std::int64_t>(std::lround(position.y()))});
  return ui;
}

graph::Json withDisplayFlag(graph::Json ui, bool on) {
  if (!ui.is_object()) ui = graph::Json::object();
  if (on)
    ui[nodes::kDisplayFlagKey] = true;
  else
    ui.erase(nodes::kDisplayFlagKey);
  return ui;
}

}  // namespace tfd::ui
