// ElementSynthesis: sticks in linear regions and leaves in planar regions, at anisotropic
// Poisson-disk samples of the field (paper §8.2, Fig. 2).
#include "core/synth/element_synthesis.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Places geometry elements that follow the field (Fig. 2): where the field is linear "
       "(middle eigenvalue below 0) a line element (a stick) along the major eigenvector, "
       "where it is planar a box element (a leaf) whose normal is the minor eigenvector. "
       "Elements sit at anisotropic Poisson-disk samples of the metric exp(-2 anisotropy "
       "A/s)/r² (A the deviator, s its RMS norm over the mesh, r = size/density): spacing "
       "r exp(anisotropy λ/s) along each eigenvector, continuous across degenerate curves. "
       "A candidate whose element's box meets an accepted one is dropped. The same seed "
       "gives the same elements on any number of threads.")
      .category("Synthesis");
  d.input<core::TensorField>("field");
  d.input<core::SurfaceMesh>("line_element")
      .optional()
      .doc(
          "Mesh for line elements, its long axis along x (recentred, scaled to a longest "
          "side of 1, then by size); default: a built-in wooden stick.");
  d.input<core::SurfaceMesh>("box_element")
      .optional()
      .doc(
          "Mesh for box elements, long axis along x and normal along z (recentred, scaled to "
          "a longest side of 1, then by size); default: a built-in leaf.");
  d.output<core::SurfaceMesh>("mesh").doc("Every element's triangles in one mesh.");
  d.output<core::InstancePoints>("points").doc(
      "One point per element: position, orient quaternion, scale, kind (line or box).");
  d.param<double>("size").byDefault(0).min(0).doc(
      "Element length in world units; 0: the mesh's bounding-box diagonal / 25.");
  d.param<double>("density").byDefault(1).min(0.05).max(20).doc(
      "Packing: the Poisson spacing is size / density, so the number of samples grows "
      "with density³ (more of them then collide and are dropped).");
  d.param<double>("anisotropy")
      .byDefault(1)
      .min(0)
      .max(5)
      .doc("How much the eigenvalues stretch the spacing (0: isotropic spacing).");
  d.param<int>("seed").byDefault(1).min(0).doc("Random seed.");
  d.param<int>("max_elements")
      .byDefault(100000)
      .min(1)
      .max(10000000)
      .doc("Stop after this many elements (a warning says so).");
  d.param<bool>("reject_overlaps")
      .byDefault(true)
      .doc("Drop candidates whose element box meets an accepted element's box (exact test).");
}

void cook(graph::CookContext& c) {
  core::ElementSynthesisOptions o;
  o.size = c.param<double>("size");
  o.density = c.param<double>("density");
  o.anisotropy = c.param<double>("anisotropy");
  o.seed = std::uint64_t(c.param<int>("seed"));
  o.maxElements = c.param<int>("max_elements");
  o.rejectOverlaps = c.param<bool>("reject_overlaps");
  core::ElementShapes shapes;
  if (c.hasInput("line_element"))
    shapes.line = core::normalizedElement(*c.input<core::SurfaceMesh>("line_element"),
                                          "input 'line_element':");
  if (c.hasInput("box_element"))
    shapes.box =
        core::normalizedElement(*c.input<core::SurfaceMesh>("box_element"), "input 'box_element':");
  const auto field = c.input<core::TensorField>("field");
  core::ElementPlacement placed = core::placeElements(*field, shapes, o, progressOf(c));
  c.info(placed.report.summary());
  if (placed.points.points.empty())
    c.warning("no elements: the field's deviator is zero or neutral at every sample");
  if (placed.report.hitMaxElements)
    c.warning("stopped at max_elements = " + std::to_string(o.maxElements) +
              "; raise it or lower density");
  c.setOutput("mesh", std::make_shared<const core::SurfaceMesh>(
                          core::instanceElements(placed.points, shapes)));
  c.setOutput("points", std::make_shared<const core::InstancePoints>(std::move(placed.points)));
}

}  // namespace

void registerElementSynthesis(graph::NodeRegistry& r) {
  r.add("ElementSynthesis", 1, declare, cook);
}

}  // namespace tfd::nodes
