#include "ui/viewport/display_scene.h"

#include <string>

#include "nodes/display_values.h"
#include "ui/viewport/picking.h"

namespace tfd::ui {

namespace {

std::optional<render::Vec3> vec3Of(const graph::Node& n, std::string_view name) {
  const graph::ParamDecl* d = n.decl().findParam(name);
  if (!d || d->kind != graph::ParamKind::Vec3) return std::nullopt;
  const auto& v = std::get<graph::Vec3Param>(n.param(name));
  return render::Vec3(v[0], v[1], v[2]);
}

std::optional<double> doubleOf(const graph::Node& n, std::string_view name) {
  const graph::ParamDecl* d = n.decl().findParam(name);
  if (!d || d->kind != graph::ParamKind::Double) return std::nullopt;
  return std::get<double>(n.param(name));
}

}  // namespace

render::Scene displayScene(const graph::Graph& graph, const graph::CookResult& result,
                           std::string_view node,
                           const std::optional<render::SliceSettings>& slice) {
  if (!graph.findNode(node)) return {};
  const nodes::DisplayValues values = nodes::displayValues(graph, result, node);
  render::SceneInput in;
  in.mesh = values.mesh.get();
  in.field = values.field.get();
  in.curves = values.curves.get();
  for (const auto& c : values.constraints) in.constraints.push_back(c.get());
  in.slice = slice;
  render::Scene scene = render::buildScene(in);
  if (values.mesh)
    scene.bounds.extend(render::Bounds{values.mesh->boundsMin(), values.mesh->boundsMax()});
  return scene;
}

void addSelectionOverlay(render::Scene& scene, const graph::Node& n) {
  const graph::ParamDecl* region = n.decl().findParam("region");
  if (region && region->kind == graph::ParamKind::String) {
    const std::string& shape = std::get<std::string>(n.param("region"));
    const auto center = vec3Of(n, "center");
    if (shape == "sphere" && center && doubleOf(n, "radius"))
      render::addSphereOutline(scene, *center, *doubleOf(n, "radius"), render::kRegionColour);
    else if (shape == "box" && center && vec3Of(n, "size"))
      render::addBoxOutline(scene, *center, *vec3Of(n, "size"), render::kRegionColour);
  }
  for (const render::Vec3& p : pickedPoints(n)) render::addMarker(scene, p, render::kMarkerColour);
}

}  // namespace tfd::ui
