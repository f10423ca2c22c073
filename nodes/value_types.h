#pragma once
// The graph value types of tfd's nodes, with their stable display names and approximate sizes
// for the memory-bounded cook cache. Include this header in every node file.
#include "core/design/design_element.h"
#include "core/scalar_volume.h"
#include "core/region/tet_region.h"
#include "core/surface/surface_mesh.h"
#include "core/synth/instance_points.h"
#include "core/tensor_field.h"
#include "core/tet_mesh.h"
#include "core/topology/degenerate_curves.h"
#include "core/trace/polylines.h"
#include "graph/value.h"

namespace tfd::nodes::detail {
std::size_t meshBytes(const core::TetMesh& mesh);
std::size_t fieldBytes(const core::TensorField& field);
std::size_t constraintBytes(const core::ConstraintSet& set);
std::size_t curvesBytes(const core::DegenerateCurves& curves);
std::size_t surfaceMeshBytes(const core::SurfaceMesh& mesh);
std::size_t instancePointsBytes(const core::InstancePoints& points);
std::size_t volumeBytes(const core::ScalarVolume& volume);
std::size_t linesBytes(const core::Polylines& lines);
std::size_t regionBytes(const core::TetRegion& region);
}  // namespace tfd::nodes::detail

TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::TetMesh, "TetMesh", tfd::nodes::detail::meshBytes);
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::TensorField, "TensorField", tfd::nodes::detail::fieldBytes);
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::ConstraintSet, "Constraints",
                           tfd::nodes::detail::constraintBytes);
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::DegenerateCurves, "DegenerateCurves",
                           tfd::nodes::detail::curvesBytes);
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::SurfaceMesh, "Mesh", tfd::nodes::detail::surfaceMeshBytes);
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::InstancePoints, "Points",
                           tfd::nodes::detail::instancePointsBytes);
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::ScalarVolume, "Volume", tfd::nodes::detail::volumeBytes);
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::Polylines, "Lines", tfd::nodes::detail::linesBytes);
TFD_GRAPH_VALUE_TYPE_SIZED(tfd::core::TetRegion, "Region", tfd::nodes::detail::regionBytes);
