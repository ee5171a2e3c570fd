#include <cmp/numerics/SymmetricDirichletRelaxation.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace cmp
{

namespace
{

/// Per triangle, the operator from its three corner values to their
/// gradient in an orthonormal frame of the surface triangle (2 x 3), zero
/// for a triangle without area.
std::vector<Eigen::Matrix<double, 2, 3>> cornerGradients(const TriangleMesh& surface)
{
  std::vector<Eigen::Matrix<double, 2, 3>> gradients(surface.triangleCount());
  Eigen::Matrix<double, 2, 3> differences;
  differences << -1, 1, 0, -1, 0, 1;
  for (int t = 0; t < surface.triangleCount(); ++t)
  {
    const Triangle& tri = surface.triangles[t];
    const Vec3 a = surface.points[tri[1]] - surface.points[tri[0]];
    const Vec3 b = surface.points[tri[2]] - surface.points[tri[0]];
    const Vec3 normal = a.cross(b);
    gradients[t].setZero();
    if (!(normal.norm() > 0.0))
      continue; // no area: the energy skips it (areas_ is 0 there)
    const Vec3 e1 = a.normalized(), e2 = normal.cross(a).normalized();
    Eigen::Matrix2d corners; // rows: corners 1 and 2 in the frame (corner 0 at the origin)
    corners << a.norm(), 0.0, b.dot(e1), b.dot(e2);
    gradients[t] = corners.inverse() * differences;
  }
  return gradients;
}

/// The map's differential on triangle `t`.
Eigen::Matrix2d jacobian(const Triangle& tri, const Eigen::Matrix<double, 2, 3>& gradient, const Eigen::MatrixXd& plane)
{
  Eigen::Matrix<double, 2, 3> corners;
  for (int k = 0; k < 3; ++k)
    corners.col(k) = plane.row(tri[k]).transpose();
  return corners * gradient.transpose();
}

/// How much of `before` the energy `after` saves. An energy that overflowed
/// (a triangle crushed below double precision) counts any finite one as a
/// full gain.
double relativeGain(double before, double after)
{
  return std::isfinite(before) ? (before - after) / before : 1.0;
}

/// Largest |log| of a singular value: how far, as a scale factor in either
/// direction, a differential is from a rotation.
double logDistortion(const Eigen::Matrix2d& J)
{
  const Eigen::Vector2d sigma = Eigen::JacobiSVD<Eigen::Matrix2d>(J).singularValues();
  return std::max(std::abs(std::log(sigma[0])), std::abs(std::log(sigma[1])));
}

/// The relaxation of one map: the energy, the SLIM step and the flip-free
/// step length, sharing the surface's gradients and the factorization. The
/// energy is measured against reference shapes: the surface's triangles,
/// or during the progressive phase shapes between those and the map's.
class Relaxation
{
public:
  Relaxation(const TriangleMesh& surface, const std::vector<char>& fixed)
    : surface_(surface), gradients_(cornerGradients(surface)), unknown_(fixed.size(), -1)
  {
    areas_.resize(surface.triangleCount());
    for (int t = 0; t < surface.triangleCount(); ++t)
      areas_[t] = gradients_[t].allFinite() ? triangleArea(surface, t) : 0.0;
    for (std::size_t v = 0; v < fixed.size(); ++v)
      if (!fixed[v])
        unknown_[v] = unknowns_++;
    reference_ = gradients_;
  }

  /// Largest `logDistortion()` of the map against the surface.
  double largestDistortion(const Eigen::MatrixXd& plane) const
  {
    double largest = 0.0;
    for (int t = 0; t < surface_.triangleCount(); ++t)
      if (areas_[t] > 0.0)
        largest = std::max(largest, logDistortion(jacobian(surface_.triangles[t], gradients_[t], plane)));
    return largest;
  }

  /// Measures against the surface's triangles stretched along each map
  /// differential's singular directions by its singular values raised to
  /// `share` (0: the surface; 1: the map's own shapes, up to rotation).
  /// Stretching is symmetric (V S^share V^T), so orientations are kept.
  void measureAgainstIntermediateShapes(const Eigen::MatrixXd& plane, double share)
  {
    for (int t = 0; t < surface_.triangleCount(); ++t)
    {
      if (areas_[t] == 0.0)
        continue;
      const Eigen::JacobiSVD<Eigen::Matrix2d> svd(
        jacobian(surface_.triangles[t], gradients_[t], plane), Eigen::ComputeFullU | Eigen::ComputeFullV);
      const Eigen::Vector2d shrink = svd.singularValues().array().pow(-share);
      reference_[t] = svd.matrixV() * shrink.asDiagonal() * svd.matrixV().transpose() * gradients_[t];
    }
  }

  void measureAgainstSurface() { reference_ = gradients_; }

  double energy(const Eigen::MatrixXd& plane) const
  {
    double sum = 0.0;
    for (int t = 0; t < surface_.triangleCount(); ++t)
    {
      if (areas_[t] == 0.0)
        continue;
      const Eigen::Matrix2d J = jacobian(surface_.triangles[t], reference_[t], plane);
      const double det = J.determinant();
      if (!(det > 0.0))
        return std::numeric_limits<double>::infinity();
      const double squared = J.squaredNorm();
      sum += areas_[t] * (squared + squared / (det * det));
    }
    return sum;
  }

  /// One SLIM step from `plane` (energy `energy`): both updated when the
  /// step lowers the energy. Returns the relative gain (1 from an infinite
  /// energy, 0 if the step was not taken).
  double step(Eigen::MatrixXd& plane, double& energy)
  {
    Eigen::MatrixXd target;
    if (!solveProxy(plane, target))
      return 0.0;
    const Eigen::MatrixXd direction = target - plane;
    double length = std::min(1.0, 0.8 * largestFlipFreeStep(plane, direction));
    for (int halvings = 0; halvings < 40 && length > 0.0; ++halvings, length *= 0.5)
    {
      Eigen::MatrixXd trial = plane + length * direction;
      const double trialEnergy = this->energy(trial);
      if (trialEnergy < energy)
      {
        const double gain = relativeGain(energy, trialEnergy);
        plane.swap(trial);
        energy = trialEnergy;
        return gain;
      }
    }
    return 0.0;
  }

private:
  /// The local-global step: per triangle the closest rotation and SLIM's
  /// weights, then the weighted least-squares map to those rotations.
  bool solveProxy(const Eigen::MatrixXd& plane, Eigen::MatrixXd& target)
  {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(36 * static_cast<std::size_t>(surface_.triangleCount()));
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * unknowns_);
    for (int t = 0; t < surface_.triangleCount(); ++t)
      if (areas_[t] > 0.0)
        addTriangle(t, plane, entries, rhs);
    Eigen::SparseMatrix<double> system(2 * unknowns_, 2 * unknowns_);
    system.setFromTriplets(entries.begin(), entries.end());
    if (!analyzed_)
    {
      solver_.analyzePattern(system);
      analyzed_ = true;
    }
    solver_.factorize(system);
    if (solver_.info() != Eigen::Success)
      return false;
    const Eigen::VectorXd solution = solver_.solve(rhs);
    if (solver_.info() != Eigen::Success || !solution.allFinite())
      return false;
    target = plane;
    for (int v = 0; v < plane.rows(); ++v)
      if (unknown_[v] >= 0)
        target.row(v) << solution[2 * unknown_[v]], solution[2 * unknown_[v] + 1];
    return true;
  }

  /// Adds area x |W (J - R)|^2 of triangle t to the normal equations, R the
  /// rotation closest to J and W the weights that make the quadratic match
  /// the symmetric Dirichlet energy's curvature along J's singular vectors.
  void addTriangle(int t, const Eigen::MatrixXd& plane, std::vector<Eigen::Triplet<double>>& entries,
    Eigen::VectorXd& rhs) const
  {
    const Triangle& tri = surface_.triangles[t];
    const Eigen::Matrix<double, 2, 3>& G = reference_[t];
    const Eigen::Matrix2d J = jacobian(tri, G, plane);
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Matrix2d rotation = svd.matrixU() * svd.matrixV().transpose();
    Eigen::Vector2d w;
    for (int i = 0; i < 2; ++i)
    {
      const double s = std::max(svd.singularValues()[i], 1e-12);
      w[i] = std::abs(s - 1.0) < 1e-8 ? 2.0 : std::sqrt((s - std::pow(s, -3.0)) / (s - 1.0));
    }
    const Eigen::Matrix2d W = svd.matrixU() * w.asDiagonal() * svd.matrixU().transpose();
    const Eigen::Matrix2d goal = W * rotation;
    // Residual (a, c) = sum over plane axis r and corner k of W(a, r) G(c, k)
    // x(corner k, axis r) - goal(a, c); unknown (k, r) is entry 2k + r.
    Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> g = Eigen::Matrix<double, 6, 1>::Zero();
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < 2; ++c)
      {
        Eigen::Matrix<double, 6, 1> row;
        for (int k = 0; k < 3; ++k)
          for (int r = 0; r < 2; ++r)
            row[2 * k + r] = W(a, r) * G(c, k);
        H += row * row.transpose();
        g += row * goal(a, c);
      }
    const double area = areas_[t];
    for (int i = 0; i < 6; ++i)
    {
      const int ui = unknown_[tri[i / 2]];
      if (ui < 0)
        continue;
      const int I = 2 * ui + i % 2;
      rhs[I] += area * g[i];
      for (int j = 0; j < 6; ++j)
      {
        const int uj = unknown_[tri[j / 2]];
        if (uj >= 0)
          entries.emplace_back(I, 2 * uj + j % 2, area * H(i, j));
        else
          rhs[I] -= area * H(i, j) * plane(tri[j / 2], j % 2);
      }
    }
  }

  /// The largest step along `direction` before some triangle's image
  /// reaches zero area (infinite if none ever does): the smallest positive
  /// root of each triangle's signed area, a quadratic in the step.
  double largestFlipFreeStep(const Eigen::MatrixXd& plane, const Eigen::MatrixXd& direction) const
  {
    double largest = std::numeric_limits<double>::infinity();
    for (const Triangle& tri : surface_.triangles)
    {
      const Eigen::Vector2d a = plane.row(tri[1]) - plane.row(tri[0]), b = plane.row(tri[2]) - plane.row(tri[0]);
      const Eigen::Vector2d da = direction.row(tri[1]) - direction.row(tri[0]);
      const Eigen::Vector2d db = direction.row(tri[2]) - direction.row(tri[0]);
      const double quadratic = cross2(da, db), linear = cross2(a, db) + cross2(da, b), constant = cross2(a, b);
      if (std::abs(quadratic) < 1e-300)
      {
        if (linear < 0.0)
          largest = std::min(largest, -constant / linear);
        continue;
      }
      const double discriminant = linear * linear - 4.0 * quadratic * constant;
      if (discriminant < 0.0)
        continue;
      // The cancellation-free pair of roots: q / quadratic and constant / q.
      const double q = -0.5 * (linear + std::copysign(std::sqrt(discriminant), linear));
      for (double s : { q / quadratic, q != 0.0 ? constant / q : 0.0 })
        if (s > 0.0)
          largest = std::min(largest, s);
    }
    return largest;
  }

  const TriangleMesh& surface_;
  std::vector<Eigen::Matrix<double, 2, 3>> gradients_;
  std::vector<Eigen::Matrix<double, 2, 3>> reference_; // gradients_ of the reference shapes
  std::vector<double> areas_;
  std::vector<int> unknown_;
  int unknowns_ = 0;
  bool analyzed_ = false;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

/// The progressive phase: steps towards shapes `options.progressiveStepDistortion`
/// away from the current map, while the energy against the surface falls by
/// at least `options.leastRelativeGain` per step. A step that would raise
/// it is undone and ends the phase.
void relaxProgressively(Relaxation& relaxation, const SymmetricDirichletOptions& options, Eigen::MatrixXd& plane,
  double& energy, SymmetricDirichletReport& done)
{
  const double stepDistortion = std::log(options.progressiveStepDistortion);
  double distortion = relaxation.largestDistortion(plane);
  if (!(stepDistortion > 0.0) || !(distortion > std::log(options.progressiveAbove)))
    return;
  for (; done.iterations < options.maximumIterations && distortion > stepDistortion;
       distortion = relaxation.largestDistortion(plane))
  {
    const Eigen::MatrixXd before = plane;
    relaxation.measureAgainstIntermediateShapes(plane, 1.0 - stepDistortion / distortion);
    double referenceEnergy = relaxation.energy(plane);
    const double referenceGain = relaxation.step(plane, referenceEnergy);
    relaxation.measureAgainstSurface();
    if (!(referenceGain > 0.0))
      break;
    const double after = relaxation.energy(plane);
    if (!(after < energy))
    {
      plane = before;
      break;
    }
    const double gain = relativeGain(energy, after);
    energy = after;
    ++done.iterations;
    ++done.progressiveIterations;
    if (gain < options.leastRelativeGain)
      break;
  }
}

Status checkStart(const TriangleMesh& surface, const std::vector<char>& fixed, const Eigen::MatrixXd& plane)
{
  if (plane.rows() != surface.vertexCount() || plane.cols() != 2)
    return Status::error("the map has " + std::to_string(plane.rows()) + " x " + std::to_string(plane.cols()) +
      " coordinates for " + std::to_string(surface.vertexCount()) + " vertices (n x 2 expected)");
  if (fixed.size() != surface.points.size())
    return Status::error("the fixed-vertex mask has " + std::to_string(fixed.size()) + " entries for " +
      std::to_string(surface.vertexCount()) + " vertices");
  if (!plane.allFinite())
    return Status::error("the map has a coordinate that is not finite");
  if (std::none_of(fixed.begin(), fixed.end(), [](char f) { return f != 0; }))
    return Status::error("no vertex is fixed, so the map is free to drift");
  for (int t = 0; t < surface.triangleCount(); ++t)
  {
    const Triangle& tri = surface.triangles[t];
    const Eigen::Vector2d a = plane.row(tri[1]) - plane.row(tri[0]), b = plane.row(tri[2]) - plane.row(tri[0]);
    if (!(cross2(a, b) > 0.0) && triangleArea(surface, t) > 0.0)
      return Status::error("triangle " + std::to_string(t) +
        " of the starting map is clockwise or has no area (a counter-clockwise bijective map is required)");
  }
  return {};
}

} // namespace

double symmetricDirichletEnergy(const TriangleMesh& surface, const Eigen::MatrixXd& plane)
{
  return Relaxation(surface, std::vector<char>(surface.points.size(), 1)).energy(plane);
}

Status relaxSymmetricDirichlet(const TriangleMesh& surface, const std::vector<char>& fixed, Eigen::MatrixXd& plane,
  const SymmetricDirichletOptions& options, SymmetricDirichletReport* report)
{
  if (Status s = checkStart(surface, fixed, plane); !s.ok())
    return s;
  const Eigen::MatrixXd start = plane;
  Relaxation relaxation(surface, fixed);
  double energy = relaxation.energy(plane);
  SymmetricDirichletReport done;
  done.energyBefore = energy;
  relaxProgressively(relaxation, options, plane, energy, done);
  while (done.iterations < options.maximumIterations)
  {
    const double gain = relaxation.step(plane, energy);
    if (!(gain > 0.0))
      break;
    ++done.iterations;
    if (gain < options.leastRelativeGain)
      break;
  }
  for (std::size_t v = 0; v < fixed.size(); ++v)
    if (fixed[v]) // bit for bit, -0.0 included (a step adds +0.0 to it)
      plane.row(v) = start.row(v);
  done.energyAfter = energy;
  if (report)
    *report = done;
  return {};
}

} // namespace cmp
