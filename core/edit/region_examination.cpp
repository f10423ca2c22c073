#include "core/edit/region_examination.h"

#include <tbb/parallel_invoke.h>

#include "core/error.h"

namespace tfd::core {

RegionExamination examineRegion(const TensorField& field, const std::vector<int>& tets,
                                DegenerateType type) {
  const TetMesh& mesh = field.mesh();
  RegionExamination x;
  tbb::parallel_invoke([&] { x.ball = checkTopologicalBall(mesh, tets); },
                       [&] {
                         x.vertices = regionVertices(mesh, tets);
                         try {
                           x.complex.emplace(regionComplex(mesh, tets));
                           x.vec.emplace(vectoriseEigenvector(field, *x.complex, type));
                         } catch (const Error&) {
                           x.error = std::current_exception();
                         }
                       });
  return x;
}

}  // namespace tfd::core
