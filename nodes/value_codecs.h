#pragma once
// Binary codecs of the expensive graph value types, for the on-disk cook cache
// (graph/disk_cache.h): TetMesh (positions, tets, the tets' edge and face ids and each face's
// tets; the rest of the topology is read off the ids and verified on load,
// core/tet_mesh_restore.cpp),
// TensorField (its mesh embedded, shared again between values read in one cook) and
// DegenerateCurves. Other types (constraints, small meshes) are cheap to cook again, so nodes
// producing them are not stored.
#include "graph/value_codec.h"

namespace tfd::nodes {

/// The table, built once.
const graph::ValueCodecs& valueCodecs();

}  // namespace tfd::nodes
