// Propagate: harmonic propagation of design constraints (paper §5, Equation 1), optionally
// boundary-conforming (Equation 4) or with curvature-tensor boundary values.
#include "core/design/propagate.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

void declare(graph::NodeDecl& d) {
  d.doc(
       "Propagates the design constraints over the mesh: the five traceless components are "
       "harmonic (Eq. 1) away from the fixed vertices. With `boundary_conforming` a second "
       "solve makes the boundary normal an eigenvector (Eq. 4); with `curvature_boundary` the "
       "boundary takes the surface's curvature tensor instead.")
      .category("Design");
  d.input<core::TetMesh>("mesh").doc("The volume.");
  d.input<core::ConstraintSet>("constraints")
      .optional()
      .doc(
          "Design elements (merge several with MergeConstraints). Optional with "
          "curvature_boundary.");
  d.output<core::TensorField>("field").doc("Symmetric traceless tensor per vertex.");
  d.param<bool>("boundary_conforming")
      .byDefault(true)
      .doc(
          "Second solve with every boundary vertex fixed to its value with the tangent-normal "
          "block zeroed (Eq. 4): the surface normal is an eigenvector on the boundary.");
  d.param<bool>("curvature_boundary")
      .byDefault(false)
      .doc(
          "Fix the boundary to the surface curvature tensor (Rusinkiewicz 2004) lifted to 3D; "
          "replaces the boundary-conforming solve.");
  d.param<double>("normal_eigenvalue")
      .byDefault(0)
      .doc("curvature_boundary: the eigenvalue given to the normal direction.");
  d.param<double>("tolerance")
      .byDefault(1e-8)
      .min(1e-14)
      .max(1e-2)
      .doc("Relative residual at which each conjugate-gradient solve stops.");
}

void cook(graph::CookContext& c) {
  core::PropagateOptions o;
  o.boundaryConforming = c.param<bool>("boundary_conforming");
  o.curvatureBoundary = c.param<bool>("curvature_boundary");
  o.normalEigenvalue = c.param<double>("normal_eigenvalue");
  o.tolerance = c.param<double>("tolerance");
  static const auto kNone = std::make_shared<const core::ConstraintSet>();
  const auto constraints = c.inputOr<core::ConstraintSet>("constraints", kNone);
  core::PropagateResult result =
      core::propagate(c.input<core::TetMesh>("mesh"), *constraints, o, progressOf(c));
  c.info(result.report.summary());
  c.setOutput("field", std::make_shared<const core::TensorField>(std::move(result.field)));
}

}  // namespace

void registerPropagate(graph::NodeRegistry& r) { r.add("Propagate", 1, declare, cook); }

}  // namespace tfd::nodes
