// Sign-free vertex normal lines of an indexed triangle mesh: dominant eigenvector of the
// area-weighted sum of face normal outer products (works on non-orientable meshes).
#include "envcrust/normals.h"

#include "envcrust/errors.h"

#include <Eigen/Dense>

#include <cmath>

namespace envcrust::normals {

std::vector<Vector3> mesh_vertex_normal_lines(const TriangleMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (const Index v : mesh.triangles[f]) {
      if (v >= n) {
        throw InvalidInput("face " + std::to_string(f) + " has vertex index " +
                           std::to_string(v) + ", but the mesh has " + std::to_string(n) +
                           " vertices");
      }
    }
  }
  std::vector<Eigen::Matrix3d> tensors(n, Eigen::Matrix3d::Zero());
  std::vector<Eigen::Vector3d> oriented(n, Eigen::Vector3d::Zero());
  auto to_eigen = [](const Point3& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); };
  for (const auto& tri : mesh.triangles) {
    const Eigen::Vector3d a = to_eigen(mesh.vertices[tri[0]]);
    const Eigen::Vector3d b = to_eigen(mesh.vertices[tri[1]]);
    const Eigen::Vector3d c = to_eigen(mesh.vertices[tri[2]]);
    const Eigen::Vector3d cross = (b - a).cross(c - a);  // |cross| = 2 area
    const double len = cross.norm();
    if (!(len > 0)) continue;
    // area * n n^T = cross cross^T / (2 |cross|)
    const Eigen::Matrix3d term = cross * cross.transpose() / (2.0 * len);
    for (const Index v : tri) {
      tensors[v] += term;
      oriented[v] += 0.5 * cross;
    }
  }
  std::vector<Vector3> out(n, Vector3(0, 0, 0));
  for (std::size_t v = 0; v < n; ++v) {
    if (tensors[v].trace() <= 0) continue;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(tensors[v]);
    Eigen::Vector3d e = solver.eigenvectors().col(2);  // eigenvalues are increasing
    if (e.dot(oriented[v]) < 0) e = -e;
    e.normalize();
    out[v] = Vector3(e.x(), e.y(), e.z());
  }
  return out;
}

}  // namespace envcrust::normals
