#include "TestShapes.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace cmp::test
{

TriangleMesh torus(int n, int m)
{
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      mesh.points.emplace_back((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v));
    }
  }
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m,
                d = i * m + (j + 1) % m;
      mesh.triangles.push_back({ a, b, c });
      mesh.triangles.push_back({ a, c, d });
    }
  }
  return mesh;
}

std::vector<Vec3> smoothField(const std::vector<Vec3>& points, double amplitude, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> frequency(0.5, 3.0), phase(0.0, 2.0 * kPi), direction(-1.0, 1.0);
  const Vec3 k1(frequency(random), frequency(random), frequency(random));
  const Vec3 k2(frequency(random), frequency(random), frequency(random));
  const Vec3 phases(phase(random), phase(random), phase(random));
  const Vec3 axis = Vec3(direction(random), direction(random), direction(random)).normalized();
  const Vec3 twist = Vec3(direction(random), direction(random), direction(random)).normalized();

  std::vector<Vec3> field;
  field.reserve(points.size());
  for (const Vec3& p : points)
  {
    const double a = std::sin(k1.dot(p) + phases.x()) * std::cos(k2.x() * p.y() + phases.y());
    const double b = std::cos(k2.dot(p) + phases.z());
    field.push_back(amplitude * (a * axis + 0.5 * b * twist.cross(p)));
  }
  return field;
}

ShapeList deformedCopies(
  const std::vector<Vec3>& base, const std::vector<std::vector<Vec3>>& fields, int modelCount, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> weight(-1.0, 1.0);
  ShapeList models;
  for (int i = 0; i < modelCount; ++i)
  {
    std::vector<Vec3> model = base;
    for (const std::vector<Vec3>& field : fields)
    {
      const double a = weight(random);
      for (std::size_t v = 0; v < model.size(); ++v)
        model[v] += a * field[v];
    }
    models.push_back(std::move(model));
  }
  return models;
}

Eigen::Matrix3d randomRotation(std::mt19937& random)
{
  // The Q of a Gaussian matrix, with the signs fixed, is uniform on O(3);
  // a reflection is turned into a rotation by flipping one column.
  std::normal_distribution<double> gaussian;
  Eigen::Matrix3d m;
  for (int i = 0; i < 9; ++i)
    m(i) = gaussian(random);
  const Eigen::HouseholderQR<Eigen::Matrix3d> qr(m);
  Eigen::Matrix3d q = qr.householderQ();
  for (int i = 0; i < 3; ++i)
  {
    if (qr.matrixQR()(i, i) < 0.0)
      q.col(i) *= -1.0;
  }
  if (q.determinant() < 0.0)
    q.col(0) *= -1.0;
  return q;
}

SimilarityTransform randomSimilarity(std::mt19937& random, double translation, double minScale, double maxScale)
{
  std::uniform_real_distribution<double> offset(-translation, translation), scale(minScale, maxScale);
  SimilarityTransform transform;
  transform.rotation = randomRotation(random);
  transform.translation = Vec3(offset(random), offset(random), offset(random));
  transform.scale = scale(random);
  return transform;
}

std::vector<Vec3> moved(const std::vector<Vec3>& points, const SimilarityTransform& transform)
{
  std::vector<Vec3> result;
  result.reserve(points.size());
  for (const Vec3& p : points)
    result.push_back(transform.apply(p));
  return result;
}

ShapeList partForRank(const ShapeList& models, const std::vector<int>& modelsPerRank, int rank)
{
  const int first = std::accumulate(modelsPerRank.begin(), modelsPerRank.begin() + rank, 0);
  return ShapeList(models.begin() + first, models.begin() + first + modelsPerRank[rank]);
}

Vec3 centroid(const std::vector<Vec3>& points)
{
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points)
    sum += p;
  return sum / static_cast<double>(points.size());
}

double maxDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  if (a.size() != b.size())
    return std::numeric_limits<double>::infinity();
  double largest = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
    largest = std::max(largest, (a[v] - b[v]).norm());
  return largest;
}

} // namespace cmp::test
