#include <cmp/analysis/LoopWavelet.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

// One refinement takes level l-1 (the "even" vertices, numbered
// 0..V_{l-1}-1) to level l (adding the "odd" vertices, one per edge of
// level l-1). x are values at level l-1, y at level l, d details. Odd
// vertex e splits edge (a, b), c and d are the vertices opposite that edge;
// even vertex v has valence n and Loop's neighbour weight
//   beta(n) = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n.
// Loop subdivision y = S x is
//   odd:  y_e = 3/8 (x_a + x_b) + 1/8 (x_c + x_d)
//   even: y_v = (1 - n beta) x_v + beta * (sum of the n neighbours of v).
//
// Synthesis runs four lifting steps. S2-S4 factor Loop's rules the way
// lifted Loop wavelets do (Bertram, "Biorthogonal Loop-subdivision
// wavelets", 2004, as far as public implementations of it show); the
// update S1 is our own:
//   S1 update:  x' = x - U d
//   S2 predict: y_e = d_e + 3/8 (x'_a + x'_b) + 1/8 (x'_c + x'_d)
//   S3 scale:   y_v = (1 - n delta) x'_v,  delta = 8 beta / 5
//   S4 lift:    y_v += delta * (sum of y_e over the n odd vertices around v)
// With d = 0, S2-S4 are Loop subdivision: the n odd vertices around v sum
// to 3n/8 x_v + 5/8 (sum of v's neighbours), since each neighbour is an
// endpoint once and an opposite vertex twice, so
//   y_v = (1 - n delta + 3n/8 delta) x_v + 5/8 delta (neighbours)
//       = (1 - n beta) x_v + beta (neighbours).
// The scale 1 - n delta = 8/5 (3/8 + cos(2 pi / n) / 4)^2 is at least 1/10
// for every valence n >= 3, so each step is invertible. Analysis runs the
// inverse steps in reverse order:
//   A1: y_v -= delta * (sum of y_e around v)
//   A2: x'_v = y_v / (1 - n delta)
//   A3: d_e = y_e - (3/8 (x'_a + x'_b) + 1/8 (x'_c + x'_d))
//   A4: x = x' + U d
// Without the update (U = 0, the "lazy" Loop wavelet) A1-A2 invert Loop's
// even rule, a sharpening filter, and the coarse levels amplify noise.
// S2-S4 give y = S x' + W d, where column e of W (the lazy wavelet) is 1 at
// e and delta at a and b. Then the least-squares fit of y by S x, with
// G = S^T S,
//   x = G^{-1} S^T y = x' + G^{-1} (S^T W) d,
// so U = G^{-1} S^T W makes each coarse level the least-squares Loop
// control mesh of the finer one (in the l2 product of level-l values), and
// the wavelets orthogonal to every coarse scaling function. G^{-1} is not
// sparse; U applies it approximately, by a fixed number of Jacobi-
// preconditioned Chebyshev steps. That keeps U linear, O(vertices) and
// identical in analysis and synthesis, which is all that exact
// reconstruction needs; only how closely the coarse level matches the
// least-squares fit depends on the step count. (A sparse Cholesky factor
// of G applies G^{-1} exactly, but its fill grows with the level: 0.4 s to
// factor at level 6 and 5 s at level 7 were measured.) Local orthogonalisation
// against the scaling functions of a few neighbours instead (a, b, c, d as
// in Bertram's update, or k-disks as in Lounsbery et al.) was measured on
// these meshes: with a, b, c, d or the 1-rings of a and b, noise grew
// from level to level; with the 1-rings of a, b, c, d the coarsest level
// still kept several times more noise than the least-squares fit.
//
// At a boundary (an open remesh, beyond the paper) Loop's rules are the
// cubic B-spline's along the boundary curve (Hoppe et al. 1994, Biermann
// et al. 2000 keep them): an odd vertex on a boundary edge (a, b), which
// has no vertex d, is y_e = 1/2 (x_a + x_b); a boundary even vertex v with
// boundary neighbours p and q is y_v = 3/4 x_v + 1/8 (x_p + x_q), and no
// interior value enters either, so the boundary curve subdivides on its
// own. The same four lifting steps factor them: S2 predicts a boundary odd
// vertex from a and b by 1/2 each; a boundary even vertex is scaled by 1/2
// in S3 and lifted in S4 by delta = 1/4 from its two boundary odd vertices
// only (the odd vertices on its interior edges lift it by 0), since with
// d = 0 those two are 1/2 (x_v + x_p) and 1/2 (x_v + x_q), and
//   1/2 x_v + 1/4 (x_v + 1/2 (x_p + x_q)) = 3/4 x_v + 1/8 (x_p + x_q). An
// interior even vertex keeps Loop's interior rule, also next to the
// boundary, and an odd vertex on an interior edge keeps 3/8 and 1/8. Each
// odd vertex thus lifts its two ends by its own weights (`endLift`): delta
// of the end for an interior end, 0 for a boundary end of an interior
// edge, 1/4 for both ends of a boundary edge; W and the update follow.
//
// Local detail frames (DetailFrame::Local) come from the surface predicted
// from level l-1, its Loop subdivision: the normal at the odd vertex is the
// area-weighted normal of its predicted triangles, the first tangent its
// parent edge a->b projected to the tangent plane. Only coarse values enter,
// so synthesis can rebuild the frame before it knows the detail.

namespace cmp
{
namespace
{

/// Row-major storage keeps the few columns of one vertex together in the
/// sparse products of the update.
using RowMajorSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Relative error (in Chebyshev's bound) to which the update solves for
/// the least-squares coarse level.
constexpr double updateTolerance = 1e-3;

/// Loop's weight of each neighbour in the even rule.
double loopBeta(int valence)
{
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * kPi / valence);
  return (5.0 / 8.0 - c * c) / valence;
}

Status notUniform(const std::string& why)
{
  return Status::error("the wavelet transform needs a uniform semi-regular mesh (buildSemiRegularMesh), but " + why);
}

/// Checks the per-vertex and per-triangle levels of `mesh` and counts the
/// vertices of each level.
Status countLevelVertices(const SemiRegularMesh& mesh, std::vector<int>& vertexCount)
{
  const int level = mesh.level;
  if (!isRemeshLevel(level))
    return notUniform("its " + remeshLevelProblem(level));
  if (mesh.triangles.empty() || mesh.triangles.size() % (std::size_t(1) << (2 * level)) != 0)
    return notUniform("it has " + std::to_string(mesh.triangles.size()) + " triangles, not a multiple of 4^" +
      std::to_string(level));
  if (mesh.levelOfTriangle.size() != mesh.triangles.size() ||
    std::any_of(mesh.levelOfTriangle.begin(), mesh.levelOfTriangle.end(), [&](int l) { return l != level; }))
    return notUniform("its triangles are not all of level " + std::to_string(level) + " (an adaptive remesh?)");
  const std::vector<int>& levels = mesh.levelOfVertex;
  if (static_cast<int>(levels.size()) != mesh.vertexCount() || levels.empty() ||
    !std::is_sorted(levels.begin(), levels.end()) || levels.front() != 0 || levels.back() > level)
    return notUniform("its vertices are not numbered level by level");
  vertexCount.resize(level + 1);
  for (int l = 0; l <= level; ++l)
    vertexCount[l] = static_cast<int>(std::upper_bound(levels.begin(), levels.end(), l) - levels.begin());
  return {};
}

/// Recovers level l-1 from level l: every four consecutive triangles of
/// level l are the quadrisection (a, ab, ca), (ab, b, bc), (ca, bc, c),
/// (ab, bc, ca) of one triangle (a, b, c). Records for each odd vertex its
/// edge a->b and the vertices left (c) and right (d) of it; d is -1 on a
/// boundary edge, which one coarser triangle has.
Status coarsen(const std::vector<Triangle>& fine, int evenCount, int oddCount, std::vector<Triangle>& coarse,
  std::vector<std::array<int, 4>>& stencil)
{
  const auto isEven = [&](int v) { return v >= 0 && v < evenCount; };
  const auto isOdd = [&](int v) { return v >= evenCount && v < evenCount + oddCount; };
  stencil.assign(oddCount, { { -1, -1, -1, -1 } });
  // The first triangle met along an odd vertex's edge gives a, b, c; the
  // second must run the other way and gives d.
  const auto addSide = [&](int odd, int from, int to, int left)
  {
    std::array<int, 4>& s = stencil[odd - evenCount];
    if (s[0] < 0)
      s = { { from, to, left, -1 } };
    else if (s[3] < 0 && s[0] == to && s[1] == from)
      s[3] = left;
    else
      return false;
    return true;
  };
  coarse.clear();
  coarse.reserve(fine.size() / 4);
  for (std::size_t t = 0; t + 3 < fine.size(); t += 4)
  {
    const Triangle &t0 = fine[t], &t1 = fine[t + 1], &t2 = fine[t + 2], &t3 = fine[t + 3];
    const int a = t0[0], b = t1[1], c = t2[2], ab = t0[1], bc = t1[2], ca = t2[0];
    const bool quadrisection = t1[0] == ab && t3[0] == ab && t2[1] == bc && t3[1] == bc && t0[2] == ca &&
      t3[2] == ca && isEven(a) && isEven(b) && isEven(c) && isOdd(ab) && isOdd(bc) && isOdd(ca);
    if (!quadrisection)
      return notUniform("triangles " + std::to_string(t) + ".." + std::to_string(t + 3) +
        " are not the quadrisection of one coarser triangle");
    if (!addSide(ab, a, b, c) || !addSide(bc, b, c, a) || !addSide(ca, c, a, b))
      return notUniform("an edge near triangle " + std::to_string(t) + " is not shared by two coarser triangles");
    coarse.push_back({ { a, b, c } });
  }
  for (int i = 0; i < oddCount; ++i)
    if (stencil[i][0] < 0 || stencil[i][2] == stencil[i][3])
      return notUniform("vertex " + std::to_string(evenCount + i) + " is not on an edge of two coarser triangles or "
                                                                    "of the boundary");
  return {};
}

/// Column p of the level's subdivision matrix is the Loop scaling function
/// of even vertex p sampled at level l. Rows: evens, then odd vertices.
/// `beta` is 0 for a boundary even vertex, which has the boundary rule.
Eigen::SparseMatrix<double> subdivisionMatrix(const std::vector<std::array<int, 4>>& stencil,
  const std::vector<int>& valence, const std::vector<double>& beta, const std::vector<char>& boundary)
{
  const int evenCount = static_cast<int>(valence.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(evenCount + 6 * stencil.size());
  for (int v = 0; v < evenCount; ++v)
    entries.emplace_back(v, v, boundary[v] ? 3.0 / 4.0 : 1.0 - valence[v] * beta[v]);
  for (int i = 0; i < static_cast<int>(stencil.size()); ++i)
  {
    const auto [a, b, c, d] = stencil[i];
    const int e = evenCount + i;
    if (d < 0) // a boundary edge
    {
      entries.emplace_back(a, b, 1.0 / 8.0);
      entries.emplace_back(b, a, 1.0 / 8.0);
      entries.emplace_back(e, a, 1.0 / 2.0);
      entries.emplace_back(e, b, 1.0 / 2.0);
      continue;
    }
    if (!boundary[a])
      entries.emplace_back(a, b, beta[a]);
    if (!boundary[b])
      entries.emplace_back(b, a, beta[b]);
    entries.emplace_back(e, a, 3.0 / 8.0);
    entries.emplace_back(e, b, 3.0 / 8.0);
    entries.emplace_back(e, c, 1.0 / 8.0);
    entries.emplace_back(e, d, 1.0 / 8.0);
  }
  Eigen::SparseMatrix<double> s(evenCount + static_cast<int>(stencil.size()), evenCount);
  s.setFromTriplets(entries.begin(), entries.end());
  return s;
}

/// Loop's odd rule at the odd vertex of `s` from the even values `y`: 3/8
/// and 1/8 inside, 1/2 and 1/2 on a boundary edge.
double predict(const std::array<int, 4>& s, const double* y)
{
  if (s[3] < 0)
    return 0.5 * (y[s[0]] + y[s[1]]);
  return 3.0 / 8.0 * (y[s[0]] + y[s[1]]) + 1.0 / 8.0 * (y[s[2]] + y[s[3]]);
}

/// An orthonormal frame with `normal` as its third axis and `along`,
/// projected to the plane normal to it, as its first. Degenerate input
/// gets a fixed but arbitrary frame, so that the result is always a
/// rotation.
Eigen::Matrix3d orthonormalFrame(const Vec3& normal, const Vec3& along)
{
  const double normalLength = normal.norm();
  const Vec3 unitNormal = normalLength > 0.0 ? Vec3(normal / normalLength) : Vec3::UnitZ();
  const Vec3 tangential = along - along.dot(unitNormal) * unitNormal;
  const double tangentialLength = tangential.norm();
  const Vec3 tangent = tangentialLength > 1e-12 * along.norm() && tangentialLength > 0.0
    ? Vec3(tangential / tangentialLength)
    : Vec3(unitNormal.unitOrthogonal());
  Eigen::Matrix3d frame;
  frame.col(0) = tangent;
  frame.col(1) = unitNormal.cross(tangent);
  frame.col(2) = unitNormal;
  return frame;
}

} // namespace

/// \brief What one refinement (level l-1 to l) needs.
struct LoopWaveletTransform::Level
{
  /// \brief Per odd vertex (vertex V_{l-1} + i): the endpoints a, b of its
  ///        parent edge, then c to the left of a->b and d to the right (-1
  ///        on a boundary edge).
  std::vector<std::array<int, 4>> stencil;
  /// \brief Per odd vertex: how much it lifts a and b in S4, delta =
  ///         8 beta / 5 of an interior end, 0 of a boundary end of an
  ///         interior edge, 1/4 of each end of a boundary edge.
  std::vector<std::array<double, 2>> endLift;
  std::vector<double> evenScale; ///< Per even vertex: 1 - n delta, or 1/2 on the boundary.
  RowMajorSparse gram;                       ///< G = S^T S (evens x evens).
  RowMajorSparse lazyProducts;               ///< S^T W (evens x odds).
  Eigen::VectorXd inverseDiagonal;           ///< 1 / diag(G), the preconditioner.
  double lowest = 0.0, highest = 0.0;        ///< Spectrum interval of diag(G)^{-1} G.
  int chebyshevSteps = 0;                    ///< Steps of the update's solve.

  Status build(const std::vector<Triangle>& fine, int evenCount, int oddCount, std::vector<Triangle>& coarse);
  void buildUpdate(const std::vector<int>& valence, const std::vector<double>& beta, const std::vector<char>& boundary);
  Eigen::MatrixXd update(const Eigen::Ref<const Eigen::MatrixXd>& details) const;
  void analyze(Eigen::MatrixXd& values) const;
  void subdivide(Eigen::MatrixXd& values) const;
  void synthesize(Eigen::MatrixXd& values) const;
  std::vector<Eigen::Matrix3d> detailFrames(const Eigen::MatrixXd& values, const std::vector<Triangle>& fine) const;
  void detailsToLocal(
    const Eigen::MatrixXd& approximation, const std::vector<Triangle>& fine, Eigen::MatrixXd& coefficients) const;
  void detailsToGlobal(const std::vector<Triangle>& fine, Eigen::MatrixXd& values) const;
  int evenCount() const { return static_cast<int>(evenScale.size()); }
  int oddCount() const { return static_cast<int>(stencil.size()); }
};

Status LoopWaveletTransform::Level::build(
  const std::vector<Triangle>& fine, int evenCount, int oddCount, std::vector<Triangle>& coarse)
{
  if (Status s = coarsen(fine, evenCount, oddCount, coarse, stencil); !s.ok())
    return s;
  std::vector<int> valence(evenCount, 0), boundaryEdges(evenCount, 0);
  for (const auto& s : stencil)
  {
    ++valence[s[0]];
    ++valence[s[1]];
    if (s[3] < 0)
    {
      ++boundaryEdges[s[0]];
      ++boundaryEdges[s[1]];
    }
  }
  std::vector<double> beta(evenCount, 0.0), evenLift(evenCount, 0.0);
  std::vector<char> boundary(evenCount, 0);
  evenScale.resize(evenCount);
  for (int v = 0; v < evenCount; ++v)
  {
    if (boundaryEdges[v] != 0 && boundaryEdges[v] != 2)
      return notUniform("vertex " + std::to_string(v) + " is on " + std::to_string(boundaryEdges[v]) +
        " boundary edges (a boundary vertex is on 2)");
    boundary[v] = boundaryEdges[v] == 2;
    if (boundary[v])
    {
      evenScale[v] = 0.5;
      continue;
    }
    if (valence[v] < 3)
      return notUniform("vertex " + std::to_string(v) + " has valence " + std::to_string(valence[v]));
    beta[v] = loopBeta(valence[v]);
    evenLift[v] = 8.0 / 5.0 * beta[v];
    evenScale[v] = 1.0 - valence[v] * evenLift[v];
  }
  endLift.resize(stencil.size());
  for (std::size_t i = 0; i < stencil.size(); ++i)
  {
    const auto& s = stencil[i];
    if (s[3] < 0)
      endLift[i] = { { 0.25, 0.25 } };
    else
      endLift[i] = { { boundary[s[0]] ? 0.0 : evenLift[s[0]], boundary[s[1]] ? 0.0 : evenLift[s[1]] } };
  }
  buildUpdate(valence, beta, boundary);
  return {};
}

void LoopWaveletTransform::Level::buildUpdate(
  const std::vector<int>& valence, const std::vector<double>& beta, const std::vector<char>& boundary)
{
  const int evens = evenCount(), odds = oddCount();
  const Eigen::SparseMatrix<double> subdivision = subdivisionMatrix(stencil, valence, beta, boundary);
  std::vector<Eigen::Triplet<double>> lazy;
  lazy.reserve(3 * odds);
  for (int i = 0; i < odds; ++i)
  {
    lazy.emplace_back(evens + i, i, 1.0);
    lazy.emplace_back(stencil[i][0], i, endLift[i][0]);
    lazy.emplace_back(stencil[i][1], i, endLift[i][1]);
  }
  Eigen::SparseMatrix<double> lazyWavelets(evens + odds, odds);
  lazyWavelets.setFromTriplets(lazy.begin(), lazy.end());
  gram = subdivision.transpose() * subdivision;
  lazyProducts = subdivision.transpose() * lazyWavelets;

  // G >= 0 entrywise, so Gershgorin's row bound of diag(G)^{-1} G is a
  // safe top of its spectrum (an overestimate would make the Chebyshev
  // polynomial grow there). The bottom, never below 0.11 on the measured
  // domains (about 0.18 on fine levels), may be guessed: a guess above the
  // true value only slows convergence for those few components.
  inverseDiagonal = gram.diagonal().cwiseInverse();
  Eigen::VectorXd rowSums = Eigen::VectorXd::Zero(evens);
  for (int row = 0; row < gram.outerSize(); ++row)
    for (RowMajorSparse::InnerIterator it(gram, row); it; ++it)
      rowSums(row) += std::abs(it.value());
  highest = rowSums.cwiseProduct(inverseDiagonal).maxCoeff();
  lowest = 0.1;
  // Chebyshev's bound on the error after k steps: 2 rate^k.
  const double root = std::sqrt(highest / lowest), rate = (root - 1.0) / (root + 1.0);
  chebyshevSteps = std::max(1, static_cast<int>(std::ceil(std::log(2.0 / updateTolerance) / -std::log(rate))));
}

Eigen::MatrixXd LoopWaveletTransform::Level::update(const Eigen::Ref<const Eigen::MatrixXd>& details) const
{
  // Chebyshev iteration for G u = r (Saad, Iterative Methods for Sparse
  // Linear Systems, Algorithm 12.1) preconditioned by diag(G), from u = 0.
  const double centre = 0.5 * (highest + lowest), halfWidth = 0.5 * (highest - lowest);
  const double sigma = centre / halfWidth;
  RowMajorMatrix residual = lazyProducts * RowMajorMatrix(details);
  RowMajorMatrix step = inverseDiagonal.asDiagonal() * residual / centre;
  RowMajorMatrix solution = step;
  double rho = 1.0 / sigma;
  for (int k = 1; k < chebyshevSteps; ++k)
  {
    residual.noalias() -= gram * step;
    const double next = 1.0 / (2.0 * sigma - rho);
    step = (next * rho) * step + (2.0 * next / halfWidth) * (inverseDiagonal.asDiagonal() * residual);
    rho = next;
    solution += step;
  }
  return solution;
}

void LoopWaveletTransform::Level::analyze(Eigen::MatrixXd& values) const
{
  const int evens = evenCount(), odds = oddCount();
  for (Eigen::Index column = 0; column < values.cols(); ++column)
  {
    double* y = values.col(column).data();
    for (int i = 0; i < odds; ++i) // A1
    {
      const auto& s = stencil[i];
      y[s[0]] -= endLift[i][0] * y[evens + i];
      y[s[1]] -= endLift[i][1] * y[evens + i];
    }
    for (int v = 0; v < evens; ++v) // A2
      y[v] /= evenScale[v];
    for (int i = 0; i < odds; ++i) // A3
      y[evens + i] -= predict(stencil[i], y);
  }
  values.topRows(evens) += update(values.middleRows(evens, odds)); // A4
}

void LoopWaveletTransform::Level::subdivide(Eigen::MatrixXd& values) const
{
  const int evens = evenCount(), odds = oddCount();
  for (Eigen::Index column = 0; column < values.cols(); ++column)
  {
    double* y = values.col(column).data();
    for (int i = 0; i < odds; ++i) // S2
      y[evens + i] += predict(stencil[i], y);
    for (int v = 0; v < evens; ++v) // S3
      y[v] *= evenScale[v];
    for (int i = 0; i < odds; ++i) // S4
    {
      const auto& s = stencil[i];
      y[s[0]] += endLift[i][0] * y[evens + i];
      y[s[1]] += endLift[i][1] * y[evens + i];
    }
  }
}

void LoopWaveletTransform::Level::synthesize(Eigen::MatrixXd& values) const
{
  const int evens = evenCount(), odds = oddCount();
  values.topRows(evens) -= update(values.middleRows(evens, odds)); // S1
  subdivide(values);
}

std::vector<Eigen::Matrix3d> LoopWaveletTransform::Level::detailFrames(
  const Eigen::MatrixXd& values, const std::vector<Triangle>& fine) const
{
  // The surface predicted from the coarse level alone: its Loop subdivision.
  const int evens = evenCount(), odds = oddCount();
  Eigen::MatrixXd predicted = Eigen::MatrixXd::Zero(evens + odds, 3);
  predicted.topRows(evens) = values.topRows(evens);
  subdivide(predicted);
  // Area-weighted normals of the predicted triangles around each odd vertex.
  std::vector<Vec3> normal(odds, Vec3::Zero());
  for (const Triangle& t : fine)
  {
    const Vec3 p0 = predicted.row(t[0]).transpose(), p1 = predicted.row(t[1]).transpose(),
               p2 = predicted.row(t[2]).transpose();
    const Vec3 n = (p1 - p0).cross(p2 - p0);
    for (int v : t)
      if (v >= evens)
        normal[v - evens] += n;
  }
  std::vector<Eigen::Matrix3d> frames(odds);
  for (int i = 0; i < odds; ++i)
  {
    const Vec3 along = predicted.row(stencil[i][1]).transpose() - predicted.row(stencil[i][0]).transpose();
    frames[i] = orthonormalFrame(normal[i], along);
  }
  return frames;
}

void LoopWaveletTransform::Level::detailsToLocal(
  const Eigen::MatrixXd& approximation, const std::vector<Triangle>& fine, Eigen::MatrixXd& coefficients) const
{
  const int evens = evenCount();
  const std::vector<Eigen::Matrix3d> frames = detailFrames(approximation, fine);
  for (int i = 0; i < oddCount(); ++i)
    coefficients.row(evens + i) = coefficients.row(evens + i) * frames[i];
}

void LoopWaveletTransform::Level::detailsToGlobal(const std::vector<Triangle>& fine, Eigen::MatrixXd& values) const
{
  const int evens = evenCount();
  const std::vector<Eigen::Matrix3d> frames = detailFrames(values, fine);
  for (int i = 0; i < oddCount(); ++i)
    values.row(evens + i) = values.row(evens + i) * frames[i].transpose();
}

LoopWaveletTransform::LoopWaveletTransform() = default;
LoopWaveletTransform::~LoopWaveletTransform() = default;
LoopWaveletTransform::LoopWaveletTransform(const LoopWaveletTransform&) = default;
LoopWaveletTransform& LoopWaveletTransform::operator=(const LoopWaveletTransform&) = default;
LoopWaveletTransform::LoopWaveletTransform(LoopWaveletTransform&&) noexcept = default;
LoopWaveletTransform& LoopWaveletTransform::operator=(LoopWaveletTransform&&) noexcept = default;

Status LoopWaveletTransform::build(const SemiRegularMesh& mesh)
{
  *this = LoopWaveletTransform{};
  std::vector<int> vertexCount;
  if (Status s = countLevelVertices(mesh, vertexCount); !s.ok())
    return s;
  const int finest = mesh.level;
  std::vector<std::vector<Triangle>> triangles(finest + 1);
  std::vector<Level> levels(finest + 1);
  triangles[finest] = mesh.triangles;
  for (int l = finest; l >= 1; --l)
  {
    const int evenCount = vertexCount[l - 1], oddCount = vertexCount[l] - evenCount;
    if (Status s = levels[l].build(triangles[l], evenCount, oddCount, triangles[l - 1]); !s.ok())
      return s;
  }
  vertexCount_ = std::move(vertexCount);
  triangles_ = std::move(triangles);
  levels_ = std::move(levels);
  return {};
}

Status LoopWaveletTransform::analyze(const Eigen::MatrixXd& values, DetailFrame frame, WaveletCoefficients& out) const
{
  if (level() < 0)
    return Status::error("the wavelet transform is not built");
  if (values.rows() != vertexCount_.back())
    return Status::error("values have " + std::to_string(values.rows()) + " rows but the mesh has " +
      std::to_string(vertexCount_.back()) + " vertices");
  if (values.cols() < 1)
    return Status::error("values have no columns");
  if (frame == DetailFrame::Local && values.cols() != 3)
    return Status::error("local detail frames need 3 columns (positions), not " + std::to_string(values.cols()));
  if (!values.allFinite())
    return Status::error("values contain NaN or infinite entries");
  Eigen::MatrixXd coefficients = values;
  for (int l = level(); l >= 1; --l)
    levels_[l].analyze(coefficients);
  if (frame == DetailFrame::Local)
    expressDetailsLocally(coefficients);
  out.values = std::move(coefficients);
  out.levelVertexCount = vertexCount_;
  out.frame = frame;
  return {};
}

void LoopWaveletTransform::expressDetailsLocally(Eigen::MatrixXd& coefficients) const
{
  // Frames come from the coarse level as synthesis will rebuild it, not as
  // analysis computed it: the two differ by rounding, and where a frame is
  // nearly degenerate (a fold) that difference would rotate the detail and
  // grow from level to level. Replaying synthesis here makes the frames of
  // both directions bitwise equal.
  Eigen::MatrixXd approximation = coefficients;
  for (int l = 1; l <= level(); ++l)
  {
    const Level& refinement = levels_[l];
    refinement.detailsToLocal(approximation, triangles_[l], coefficients);
    approximation.middleRows(vertexCount_[l - 1], vertexCount_[l] - vertexCount_[l - 1]) =
      coefficients.middleRows(vertexCount_[l - 1], vertexCount_[l] - vertexCount_[l - 1]);
    refinement.detailsToGlobal(triangles_[l], approximation);
    refinement.synthesize(approximation);
  }
}

Status LoopWaveletTransform::checkCoefficients(const WaveletCoefficients& coefficients, int l) const
{
  if (level() < 0)
    return Status::error("the wavelet transform is not built");
  if (coefficients.levelVertexCount != vertexCount_)
    return Status::error("the coefficients are of level " + std::to_string(coefficients.level()) +
      " or of another mesh; the transform is of level " + std::to_string(level()) + " with " +
      std::to_string(vertexCount_.back()) + " vertices");
  if (coefficients.values.rows() != vertexCount_.back() || coefficients.values.cols() < 1)
    return Status::error("the coefficients have " + std::to_string(coefficients.values.rows()) + " rows and " +
      std::to_string(coefficients.values.cols()) + " columns; expected " + std::to_string(vertexCount_.back()) +
      " rows");
  if (coefficients.frame == DetailFrame::Local && coefficients.values.cols() != 3)
    return Status::error("local detail frames need 3 columns (positions), not " +
      std::to_string(coefficients.values.cols()));
  if (l < 0 || l > level())
    return Status::error("level " + std::to_string(l) + " is out of range (0 to " + std::to_string(level()) + ")");
  if (!coefficients.values.allFinite())
    return Status::error("the coefficients contain NaN or infinite entries");
  return {};
}

Status LoopWaveletTransform::synthesize(const WaveletCoefficients& coefficients, Eigen::MatrixXd& values) const
{
  return synthesize(coefficients, level(), values);
}

Status LoopWaveletTransform::synthesize(const WaveletCoefficients& coefficients, int l, Eigen::MatrixXd& values) const
{
  if (Status s = checkCoefficients(coefficients, l); !s.ok())
    return s;
  Eigen::MatrixXd result = coefficients.values.topRows(vertexCount_[l]);
  for (int m = 1; m <= l; ++m)
  {
    if (coefficients.frame == DetailFrame::Local)
      levels_[m].detailsToGlobal(triangles_[m], result);
    levels_[m].synthesize(result);
  }
  values = std::move(result);
  return {};
}

} // namespace cmp
