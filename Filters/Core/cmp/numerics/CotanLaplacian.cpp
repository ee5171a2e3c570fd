#include <cmp/numerics/CotanLaplacian.h>

#include <Eigen/Geometry>

#include <vector>

namespace cmp
{

Eigen::SparseMatrix<double> cotanLaplacian(const TriangleMesh& mesh)
{
  const int n = mesh.vertexCount();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(mesh.triangleCount()) * 12);
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    const Triangle& tri = mesh.triangles[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k)
    {
      // The angle at corner k faces the edge between the other two.
      const int a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
      const Vec3 u = mesh.points[static_cast<std::size_t>(b)] - mesh.points[static_cast<std::size_t>(a)];
      const Vec3 v = mesh.points[static_cast<std::size_t>(c)] - mesh.points[static_cast<std::size_t>(a)];
      const double sine = u.cross(v).norm();
      const double half = sine > 0.0 ? 0.5 * u.dot(v) / sine : 0.0;
      entries.emplace_back(b, c, -half);
      entries.emplace_back(c, b, -half);
      entries.emplace_back(b, b, half);
      entries.emplace_back(c, c, half);
    }
  }
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  return laplacian;
}

} // namespace cmp
