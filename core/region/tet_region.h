#pragma once
// A region of a tet mesh as a value: the tets an edit changed (e.g. the ball of a curve
// removal, paper §6.4), for export (ExportVTU's `region` cell array) and display.
#include <cstddef>
#include <memory>
#include <vector>

#include "core/tet_mesh.h"

namespace tfd::core {

struct TetRegion {
  std::shared_ptr<const TetMesh> mesh;  ///< the mesh the tet ids refer to
  std::vector<int> tets;                ///< ascending
  std::size_t byteSize() const { return sizeof(*this) + tets.size() * sizeof(int); }
};

}  // namespace tfd::core
