#include "io/volume/voxel_quantities.h"

#include <algorithm>

#include "core/error.h"

namespace tfd::io {

VoxelScalarFunction interpolateVertexScalars(std::shared_ptr<const core::TetMesh> mesh,
                                             std::vector<double> values) {
  if (!mesh) throw core::Error("vertex scalars without a mesh");
  if (values.size() != mesh->vertexCount()) {
    throw core::Error("vertex scalars: " + std::to_string(values.size()) + " values for " +
                      std::to_string(mesh->vertexCount()) + " mesh vertices");
  }
  return [mesh = std::move(mesh), values = std::move(values)](const core::Vec3&,
                                                              const VoxelSample& s) {
    const auto& t = mesh->tets()[s.tet];
    return values[t[0]] * s.barycentric[0] + values[t[1]] * s.barycentric[1] +
           values[t[2]] * s.barycentric[2] + values[t[3]] * s.barycentric[3];
  };
}

int VoxelQuantities::channelCount() const {
  return (tensor ? 6 : 0) + (eigenvalues ? 3 : 0) + (eigenvectors ? 9 : 0) + (density ? 1 : 0);
}

std::vector<std::string> VoxelQuantities::channelNames(const std::string& tensorName) const {
  std::vector<std::string> names;
  if (tensor) {
    for (const char* c : {"xx", "yy", "zz", "xy", "yz", "xz"})
      names.push_back(tensorName + "." + c);
  }
  const auto vec3 = [&](const std::string& base) {
    for (const char* c : {".x", ".y", ".z"}) names.push_back(base + c);
  };
  if (eigenvalues) vec3(tensorName + ".eigval");
  if (eigenvectors) {
    for (const char* e : {".e1", ".e2", ".e3"}) vec3(tensorName + e);
  }
  if (density) names.push_back("density");
  return names;
}

void VoxelQuantities::evaluate(const core::Vec3& position, const VoxelSample& sample,
                               float* out) const {
  const core::Tensor& t = sample.value;
  if (tensor) {
    for (double c : t.components()) *out++ = static_cast<float>(c);
  }
  if (eigenvalues || eigenvectors) {
    const core::EigenDecomposition e = core::eigenDecompose(t);
    if (eigenvalues) {
      for (int i = 0; i < 3; ++i) *out++ = static_cast<float>(e.values[i]);
    }
    if (eigenvectors) {
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i) *out++ = static_cast<float>(e.vectors(i, c));
    }
  }
  if (density) *out++ = static_cast<float>(density(position, sample));
}

}  // namespace tfd::io
