#pragma once
// The editor's data kept in a node's "ui" object (headless tools ignore it): the canvas
// position {"position": [x, y]} and the display flag {"display": true} (nodes/display_values.h).
#include <QPointF>

#include "graph/graph.h"

namespace tfd::ui {

/// The node's canvas position; (0, 0) when it has none.
QPointF nodePosition(const graph::Node& node);
/// `ui` with "position" set to the rounded coordinates (whole scene units keep files tidy).
graph::Json withPosition(graph::Json ui, QPointF position);
/// `ui` with "display" set (true) or removed (false).
graph::Json withDisplayFlag(graph::Json ui, bool on);

}  // namespace tfd::ui
