#include "core/surface/surface_curvature.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace tfd::core {

namespace {

/// Minimal rotation taking unit vector a to unit vector b.
Mat3 rotationBetween(const Vec3& a, const Vec3& b) {
  const Vec3 k = a.cross(b);
  const double c = a.dot(b);
  if (c < -1 + 1e-12) {
    // Opposite vectors: rotate by π about any axis orthogonal to a.
    Vec3 axis = a.unitOrthogonal();
    return 2 * axis * axis.transpose() - Mat3::Identity();
  }
  Mat3 kx;
  kx << 0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0;
  return Mat3::Identity() + kx + kx * kx / (1 + c);
}

/// Second fundamental form of one face as a 3×3 tensor in its plane (Rusinkiewicz §3.1).
Mat3 faceForm(const std::array<Vec3, 3>& p, const std::array<Vec3, 3>& n, Vec3& faceNormal,
              double& area) {
  const Vec3 cross = (p[1] - p[0]).cross(p[2] - p[0]);
  area = 0.5 * cross.norm();
  faceNormal = area > 0 ? Vec3(cross.normalized()) : Vec3::Zero();
  if (area <= 0) return Mat3::Zero();
  const Vec3 u = (p[1] - p[0]).normalized();
  const Vec3 v = faceNormal.cross(u);
  // Unknowns (E, F, G) of II = [E F; F G]; two equations per edge.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const int a = (i + 1) % 3, b = (i + 2) % 3;
    const Vec3 e = p[b] - p[a];
    const Vec3 dn = n[b] - n[a];
    const double eu = e.dot(u), ev = e.dot(v);
    const Eigen::Vector3d row1(eu, ev, 0), row2(0, eu, ev);
    ata += row1 * row1.transpose() + row2 * row2.transpose();
    atb += row1 * dn.dot(u) + row2 * dn.dot(v);
  }
  const Eigen::Vector3d efg = ata.ldlt().solve(atb);
  return efg[0] * u * u.transpose() + efg[1] * (u * v.transpose() + v * u.transpose()) +
         efg[2] * v * v.transpose();
}

}  // namespace

std::vector<Tensor> boundaryCurvatureTensors(const TetMesh& mesh) {
  const auto& faces = mesh.boundaryFaces();
  const auto& pos = mesh.positions();
  const auto& normals = mesh.vertexNormals();
  struct FaceData {
    TetMesh::Face vertices;
    Mat3 form;
    Vec3 normal;
    double area;
  };
  std::vector<FaceData> data(faces.size());
  tbb::parallel_for(std::size_t{0}, faces.size(), [&](std::size_t f) {
    FaceData& d = data[f];
    d.vertices = mesh.orientedBoundaryFace(faces[f]);
    const std::array<Vec3, 3> p = {pos[d.vertices[0]], pos[d.vertices[1]], pos[d.vertices[2]]};
    const std::array<Vec3, 3> n = {normals[d.vertices[0]], normals[d.vertices[1]],
                                   normals[d.vertices[2]]};
    d.form = faceForm(p, n, d.normal, d.area);
  });
  // Boundary vertex index of each mesh vertex.
  const auto& boundary = mesh.boundaryVertices();
  std::vector<int> slot(mesh.vertexCount(), -1);
  for (std::size_t i = 0; i < boundary.size(); ++i) slot[boundary[i]] = static_cast<int>(i);
  std::vector<Mat3> sum(boundary.size(), Mat3::Zero());
  std::vector<double> weight(boundary.size(), 0.0);
  for (const FaceData& d : data) {
    if (d.area <= 0) continue;
    for (int v : d.vertices) {
      const Vec3& nv = normals[v];
      const Mat3 r = rotationBetween(d.normal, nv);
      sum[slot[v]] += (d.area / 3) * (r * d.form * r.transpose());
      weight[slot[v]] += d.area / 3;
    }
  }
  std::vector<Tensor> result(boundary.size());
  tbb::parallel_for(std::size_t{0}, boundary.size(), [&](std::size_t i) {
    if (weight[i] <= 0) return;
    const Vec3& nv = normals[boundary[i]];
    const Mat3 proj = Mat3::Identity() - nv * nv.transpose();
    result[i] = Tensor::fromMatrix(proj * (sum[i] / weight[i]) * proj);
  });
  return result;
}

PrincipalCurvatures principalCurvatures(const Tensor& curvature, const Vec3& normal) {
  const Vec3 n = normal.normalized();
  // Express in a tangent basis (t1, t2) and solve the 2×2 eigenproblem.
  const Vec3 t1 = n.unitOrthogonal();
  const Vec3 t2 = n.cross(t1);
  const Mat3 m = curvature.matrix();
  Eigen::Matrix2d m2;
  m2 << t1.dot(m * t1), t1.dot(m * t2), t2.dot(m * t1), t2.dot(m * t2);
  m2 = 0.5 * (m2 + m2.transpose()).eval();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(m2);
  PrincipalCurvatures pc;
  pc.k1 = eig.eigenvalues()[1];
  pc.k2 = eig.eigenvalues()[0];
  const Eigen::Vector2d a = eig.eigenvectors().col(1), b = eig.eigenvectors().col(0);
  pc.d1 = (a[0] * t1 + a[1] * t2).normalized();
  pc.d2 = (b[0] * t1 + b[1] * t2).normalized();
  return pc;
}

Tensor liftCurvatureTensor(const Tensor& curvature, const Vec3& normal, double normalEigenvalue) {
  const Vec3 n = normal.normalized();
  const Mat3 proj = Mat3::Identity() - n * n.transpose();
  const Mat3 tangent = proj * curvature.matrix() * proj;
  return Tensor::fromMatrix(tangent + normalEigenvalue * n * n.transpose()).deviator();
}

}  // namespace tfd::core
