#pragma once
// Binary codecs of the expensive graph value types, for the on-disk cook cache
// (graph/disk_cache.h): TetMesh (positions and tets; the topology is derived again on load),
// TensorField (its mesh embedded, shared again between values read in one cook) and
// DegenerateCurves. Other types (constraints, small meshes) are cheap to cook again, so nodes
// producing them are not stored.
#include "graph/value_codec.h"

namespace tfd::nodes {

/// The table, built once.
const graph::ValueCodecs& valueCodecs();

}  // namespace tfd::nodes
