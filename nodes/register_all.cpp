#include "nodes/register_all.h"

#include "graph/node_registry.h"

namespace tfd::nodes {

// One registration function per node file (nodes/<type>.cpp).
void registerTetMesh(graph::NodeRegistry&);
void registerFieldExpression(graph::NodeRegistry&);
void registerPointConstraint(graph::NodeRegistry&);
void registerCurveConstraint(graph::NodeRegistry&);
void registerMergeConstraints(graph::NodeRegistry&);
void registerPropagate(graph::NodeRegistry&);
void registerLocalSmooth(graph::NodeRegistry&);
void registerRemoveCurves(graph::NodeRegistry&);
void registerDeformCurve(graph::NodeRegistry&);
void registerReconnectCurves(graph::NodeRegistry&);
void registerExtractDegenerateCurves(graph::NodeRegistry&);
void registerGaborNoise(graph::NodeRegistry&);
void registerExportVtu(graph::NodeRegistry&);
void registerExportVdb(graph::NodeRegistry&);
void registerExportExr(graph::NodeRegistry&);
void registerExportCurves(graph::NodeRegistry&);
void registerElementSynthesis(graph::NodeRegistry&);
void registerExportMesh(graph::NodeRegistry&);
void registerHyperstreamlines(graph::NodeRegistry&);
void registerStreamtubes(graph::NodeRegistry&);
void registerExportLines(graph::NodeRegistry&);

void registerAll(graph::NodeRegistry& registry) {
  registerTetMesh(registry);
  registerFieldExpression(registry);
  registerPointConstraint(registry);
  registerCurveConstraint(registry);
  registerMergeConstraints(registry);
  registerPropagate(registry);
  registerLocalSmooth(registry);
  registerRemoveCurves(registry);
  registerDeformCurve(registry);
  registerReconnectCurves(registry);
  registerExtractDegenerateCurves(registry);
  registerGaborNoise(registry);
  registerExportVtu(registry);
  registerExportVdb(registry);
  registerExportExr(registry);
  registerExportCurves(registry);
  registerElementSynthesis(registry);
  registerExportMesh(registry);
  registerHyperstreamlines(registry);
  registerStreamtubes(registry);
  registerExportLines(registry);
}

}  // namespace tfd::nodes
