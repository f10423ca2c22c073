// Streamtubes: tubes or ribbons swept along lines with twist-free frames (paper §8, the
// noodles of Figure 20).
#include "core/trace/streamtubes.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

const graph::Choices<core::TubeProfile> kProfiles{{"circle", core::TubeProfile::Circle},
                                                  {"ribbon", core::TubeProfile::Ribbon}};
const graph::Choices<core::TubeWidth> kWidths{{"constant", core::TubeWidth::Constant},
                                              {"major", core::TubeWidth::Major},
                                              {"medium", core::TubeWidth::Medium},
                                              {"minor", core::TubeWidth::Minor}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "Sweeps a circle or a flat ribbon along every line with twist-free (Bishop) frames; "
       "each line becomes one closed surface with flat end caps. The width may follow the "
       "magnitude of an eigenvalue.")
      .category("Synth");
  d.input<core::Polylines>("lines");
  d.output<core::SurfaceMesh>("mesh").doc("All tubes as one triangle mesh, outward facing.");
  d.param<std::string>("profile").choices(kProfiles).doc(
      "circle: a round tube; ribbon: a flat band (a thin rectangle).");
  d.param<double>("radius").byDefault(0.01).min(1e-9).doc(
      "Tube radius, or half the ribbon's width (world units).");
  d.param<int>("sides").byDefault(8).range(3, 64).doc("circle: sides of the polygon.");
  d.param<double>("thickness").byDefault(0.2).range(0.01, 1).doc("ribbon: thickness over width.");
  d.param<std::string>("width_by")
      .choices(kWidths)
      .doc(
          "constant, or the magnitude of the major, medium or minor eigenvalue along the "
          "lines (from min_width × radius at its smallest to radius at its largest).");
  d.param<double>("min_width")
      .byDefault(0.25)
      .range(0, 1)
      .doc("With width_by an eigenvalue: the thinnest width as a fraction of radius.");
}

void cook(graph::CookContext& c) {
  core::TubeOptions o;
  o.profile = c.param("profile", kProfiles);
  o.radius = c.param<double>("radius");
  o.sides = c.param<int>("sides");
  o.ribbonThickness = c.param<double>("thickness");
  o.width = c.param("width_by", kWidths);
  o.minWidth = c.param<double>("min_width");
  const auto lines = c.input<core::Polylines>("lines");
  auto mesh = std::make_shared<const core::SurfaceMesh>(core::sweepTubes(*lines, o, progressOf(c)));
  c.info(std::to_string(lines->lines.size()) + " tubes, " + std::to_string(mesh->positions.size()) +
         " vertices, " + std::to_string(mesh->triangles.size()) + " triangles");
  c.setOutput("mesh", std::move(mesh));
}

}  // namespace

void registerStreamtubes(graph::NodeRegistry& r) { r.add("Streamtubes", 1, declare, cook); }

}  // namespace tfd::nodes
