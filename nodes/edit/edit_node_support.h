#pragma once
// What the region edit nodes share (RemoveCurves, DeformCurve, ReconnectCurves): the ports
// (inputs `field` and optional `curves`; outputs `field`, `curves` and `region`), the
// `region_distance` and `retries` parameters, reading them, and publishing an edit's result
// (core/edit/edit_driver.h) with its report's info lines.
#include <memory>
#include <string>
#include <utility>

#include "core/region/tet_region.h"
#include "core/tensor_field.h"
#include "core/topology/degenerate_curves.h"
#include "graph/cook_context.h"
#include "graph/node_decl.h"
#include "nodes/value_types.h"

namespace tfd::nodes {

struct EditPortDocs {
  const char* curvesIn;   ///< the optional input `curves`
  const char* fieldOut;   ///< the output `field`
  const char* regionOut;  ///< the output `region`
};

/// Inputs `field`, optional `curves`; outputs `field`, `curves`, `region`.
inline void declareEditPorts(graph::NodeDecl& d, const EditPortDocs& docs) {
  d.input<core::TensorField>("field");
  d.input<core::DegenerateCurves>("curves").optional().doc(docs.curvesIn);
  d.output<core::TensorField>("field").doc(docs.fieldOut);
  d.output<core::DegenerateCurves>("curves").doc(
      "The curves of the new field (extracted with default settings), so edits chain.");
  d.output<core::TetRegion>("region").doc(docs.regionOut);
}

/// `region_distance` (default −1: 30 % of the bounding radius) and `retries` (0–10, default 2);
/// `around` says what the smallest ball holds, `retryAfter` what makes a try fail.
inline void declareEditRetryParams(graph::NodeDecl& d, const std::string& around,
                                   const std::string& retryAfter) {
  d.param<double>("region_distance")
      .byDefault(-1)
      .doc("How far the region grows beyond the smallest ball around " + around +
           " (a length); negative: 30 % of the mesh's bounding radius.");
  d.param<int>("retries").byDefault(2).min(0).max(10).doc(
      "Tries with a region grown by 1.5x each after " + retryAfter + ".");
}

/// The inputs and the retry parameters of an edit node, read in the order every edit uses.
struct EditInputs {
  double regionDistance = -1;
  int retries = 2;
  std::shared_ptr<const core::DegenerateCurves> curves;  ///< null when not connected
  std::shared_ptr<const core::TensorField> field;
};

inline EditInputs editInputs(graph::CookContext& c) {
  EditInputs in;
  in.regionDistance = c.param<double>("region_distance");
  in.retries = c.param<int>("retries");
  in.curves = c.inputOr<core::DegenerateCurves>("curves", nullptr);
  in.field = c.input<core::TensorField>("field");
  return in;
}

/// Info lines of the report, then the outputs `field`, `curves` and `region` of a result with
/// members field, curves, regionTets and report.lines().
template <class Result>
void publishEdit(graph::CookContext& c, const core::TensorField& input, Result&& r) {
  for (const std::string& line : r.report.lines()) c.info(line);
  c.setOutput("field", std::make_shared<const core::TensorField>(std::move(r.field)));
  c.setOutput("curves", std::make_shared<const core::DegenerateCurves>(std::move(r.curves)));
  c.setOutput("region", std::make_shared<const core::TetRegion>(
                            core::TetRegion{input.meshPtr(), std::move(r.regionTets)}));
}

}  // namespace tfd::nodes
