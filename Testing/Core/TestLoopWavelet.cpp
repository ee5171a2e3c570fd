#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/analysis/LoopWavelet.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include "TestMeshes.h"

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <string>

using namespace cmp;

namespace
{

/// Largest entry of |a - b| relative to the largest entry of |b|.
double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

/// Loop subdivision by the textbook rules, written independently of the
/// transform: the midpoint of edge (a, b) of `coarse` is found as the one
/// vertex of `fine` adjacent to both a and b that is new at `fine`'s level.
/// On a boundary (an edge of one coarse triangle) the rules are the cubic
/// B-spline's: a boundary edge's midpoint is 1/2 (a + b), a boundary vertex
/// 3/4 of itself and 1/8 of each of its two boundary neighbours.
Eigen::MatrixXd textbookLoop(const SemiRegularMesh& coarse, const SemiRegularMesh& fine, const Eigen::MatrixXd& x)
{
  const int evenCount = coarse.vertexCount();
  std::vector<std::set<int>> neighbours(evenCount);
  std::map<std::pair<int, int>, int> trianglesAtEdge;
  for (const Triangle& t : coarse.triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      neighbours[a].insert(b);
      neighbours[b].insert(a);
      ++trianglesAtEdge[{ std::min(a, b), std::max(a, b) }];
    }
  std::vector<std::set<int>> boundaryNeighbours(evenCount);
  for (const auto& [edge, count] : trianglesAtEdge)
    if (count == 1)
    {
      boundaryNeighbours[edge.first].insert(edge.second);
      boundaryNeighbours[edge.second].insert(edge.first);
    }
  // In the fine mesh each new vertex is adjacent to exactly two old ones:
  // the endpoints of the edge it splits.
  std::map<int, std::set<int>> endpointsOf;
  for (const Triangle& t : fine.triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int u = t[k], w = t[(k + 1) % 3];
      if (u < evenCount && w >= evenCount)
        endpointsOf[w].insert(u);
      if (w < evenCount && u >= evenCount)
        endpointsOf[u].insert(w);
    }
  std::map<std::pair<int, int>, int> midpoint;
  for (const auto& [odd, ends] : endpointsOf)
  {
    EXPECT_EQ(ends.size(), 2u);
    midpoint[{ *ends.begin(), *ends.rbegin() }] = odd;
  }

  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(fine.vertexCount(), x.cols());
  for (int v = 0; v < evenCount; ++v)
  {
    if (!boundaryNeighbours[v].empty())
    {
      EXPECT_EQ(boundaryNeighbours[v].size(), 2u);
      y.row(v) = 3.0 / 4.0 * x.row(v);
      for (int u : boundaryNeighbours[v])
        y.row(v) += 1.0 / 8.0 * x.row(u);
      continue;
    }
    const int n = static_cast<int>(neighbours[v].size());
    const double c = 3.0 / 8.0 + std::cos(2.0 * kPi / n) / 4.0;
    const double beta = (5.0 / 8.0 - c * c) / n;
    y.row(v) = (1.0 - n * beta) * x.row(v);
    for (int u : neighbours[v])
      y.row(v) += beta * x.row(u);
  }
  for (const Triangle& t : coarse.triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3], opposite = t[(k + 2) % 3];
      const std::pair<int, int> edge{ std::min(a, b), std::max(a, b) };
      const int e = midpoint.at(edge);
      if (trianglesAtEdge.at(edge) == 1)
        y.row(e) = 0.5 * (x.row(a) + x.row(b));
      else // seen from its two triangles: half of 3/8 (a + b) each time
        y.row(e) += 3.0 / 16.0 * (x.row(a) + x.row(b)) + 1.0 / 8.0 * x.row(opposite);
    }
  return y;
}

Eigen::MatrixXd randomValues(int rows, int columns, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd values(rows, columns);
  for (Eigen::Index i = 0; i < values.size(); ++i)
    values.data()[i] = uniform(random);
  return values;
}

/// The remesh of `domain` drawn on the unit sphere.
Eigen::MatrixXd spherePositions(const BaseDomain& domain, const SemiRegularMesh& mesh)
{
  Eigen::MatrixXd positions = test::toMatrix(test::drawnOnDomain(domain, mesh).points);
  const Eigen::RowVector3d centre = test::toMatrix(domain.mesh.points).colwise().mean();
  positions = (positions.rowwise() - centre).rowwise().normalized();
  return positions;
}

/// Root mean square of the rows of `values`.
double rms(const Eigen::MatrixXd& values)
{
  return std::sqrt(values.squaredNorm() / values.rows());
}

/// The finest-level values `coefficients` give with every detail above
/// level `l` dropped: the smooth surface level l describes.
Eigen::MatrixXd withoutDetailsAbove(
  const LoopWaveletTransform& transform, const WaveletCoefficients& coefficients, int l)
{
  WaveletCoefficients truncated = coefficients;
  truncated.values.bottomRows(transform.vertexCount(transform.level()) - transform.vertexCount(l)).setZero();
  Eigen::MatrixXd values;
  EXPECT_TRUE(transform.synthesize(truncated, values).ok());
  return values;
}

struct NamedDomain
{
  std::string name;
  BaseDomain domain;
  /// Base triangles left out of its remeshes (an open remesh, as of a
  /// surface with boundaries); empty: closed.
  std::vector<char> holes;
};

/// Closed domains, and open remeshes of them: one base triangle left out
/// (a disk's boundary of 3 base vertices), or two that share no vertex.
std::vector<NamedDomain> smallDomains()
{
  const BaseDomain octahedron = test::octahedronDomain(), mixed = test::mixedValenceDomain();
  std::vector<char> one(octahedron.mesh.triangleCount(), 0), two = one, oneOfMixed(mixed.mesh.triangleCount(), 0);
  one[0] = 1;
  oneOfMixed[0] = 1;
  two[0] = 1;
  // The octahedron's triangle opposite triangle 0: no vertex in common.
  for (int t = 1; t < octahedron.mesh.triangleCount(); ++t)
  {
    const Triangle &a = octahedron.mesh.triangles[0], &b = octahedron.mesh.triangles[t];
    if (std::none_of(b.begin(), b.end(), [&](int v) { return std::find(a.begin(), a.end(), v) != a.end(); }))
      two[t] = 1;
  }
  return { { "octahedron", octahedron, {} }, { "tetrahedron", test::tetrahedronDomain(), {} },
    { "mixed valence", mixed, {} }, { "octahedron, one hole", octahedron, one },
    { "octahedron, two holes", octahedron, two }, { "mixed valence, one hole", mixed, oneOfMixed } };
}

/// The uniform remesh of `named` at `level`, open where it has holes.
SemiRegularMesh remeshOf(const NamedDomain& named, int level)
{
  SemiRegularMesh mesh;
  EXPECT_TRUE(buildSemiRegularMesh(named.domain, level, mesh).ok());
  if (!named.holes.empty())
    EXPECT_TRUE(removeHoleTriangles(named.domain, named.holes, mesh).ok());
  return mesh;
}

} // namespace

TEST(LoopWavelet, ReconstructsAnyValuesToRounding)
{
  for (const NamedDomain& named : smallDomains())
    for (int level = 0; level <= 4; ++level)
    {
      const std::string& name = named.name;
      const BaseDomain& domain = named.domain;
      const SemiRegularMesh mesh = remeshOf(named, level);
      LoopWaveletTransform transform;
      ASSERT_TRUE(transform.build(mesh).ok());
      for (int columns : { 1, 3, 5 })
        for (DetailFrame frame : { DetailFrame::Global, DetailFrame::Local })
        {
          if (frame == DetailFrame::Local && columns != 3)
            continue;
          const Eigen::MatrixXd values = randomValues(mesh.vertexCount(), columns, 7u * level + columns);
          WaveletCoefficients coefficients;
          ASSERT_TRUE(transform.analyze(values, frame, coefficients).ok());
          EXPECT_EQ(coefficients.level(), level);
          Eigen::MatrixXd back;
          ASSERT_TRUE(transform.synthesize(coefficients, back).ok());
          EXPECT_LT(relativeDifference(back, values), 1e-12)
            << name << " level " << level << ", " << columns << " columns, frame " << static_cast<int>(frame);
          if (level > 0)
            EXPECT_GT((coefficients.values - values).norm(), 0.1 * values.norm()) << "the transform did nothing";
        }
      // Smooth positions with local frames.
      WaveletCoefficients coefficients;
      const Eigen::MatrixXd sphere = spherePositions(domain, mesh);
      ASSERT_TRUE(transform.analyze(sphere, DetailFrame::Local, coefficients).ok());
      Eigen::MatrixXd back;
      ASSERT_TRUE(transform.synthesize(coefficients, back).ok());
      EXPECT_LT(relativeDifference(back, sphere), 1e-12) << name << " level " << level;
    }
}

TEST(LoopWavelet, LevelsAreTheCoarserRemeshes)
{
  const BaseDomain domain = test::mixedValenceDomain();
  SemiRegularMesh finest;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 3, finest).ok());
  LoopWaveletTransform transform;
  ASSERT_TRUE(transform.build(finest).ok());
  ASSERT_EQ(transform.level(), 3);
  for (int l = 0; l <= 3; ++l)
  {
    SemiRegularMesh mesh;
    ASSERT_TRUE(buildSemiRegularMesh(domain, l, mesh).ok());
    EXPECT_EQ(transform.vertexCount(l), mesh.vertexCount());
    EXPECT_EQ(transform.triangles(l), mesh.triangles) << "level " << l;
  }
}

TEST(LoopWavelet, ZeroDetailsSynthesizeLoopSubdivision)
{
  const int finest = 4;
  for (const NamedDomain& named : smallDomains())
  {
    const std::string& name = named.name;
    const BaseDomain& domain = named.domain;
    std::vector<SemiRegularMesh> meshes(finest + 1);
    for (int l = 0; l <= finest; ++l)
      meshes[l] = remeshOf(named, l);
    LoopWaveletTransform transform;
    ASSERT_TRUE(transform.build(meshes[finest]).ok());
    for (DetailFrame frame : { DetailFrame::Global, DetailFrame::Local })
    {
      WaveletCoefficients coefficients;
      ASSERT_TRUE(transform.analyze(spherePositions(domain, meshes[finest]), frame, coefficients).ok());
      const Eigen::MatrixXd coarse = randomValues(transform.vertexCount(0), 3, 11);
      coefficients.values.setZero();
      coefficients.values.topRows(coarse.rows()) = coarse;
      Eigen::MatrixXd loop = coarse;
      for (int l = 1; l <= finest; ++l)
      {
        loop = textbookLoop(meshes[l - 1], meshes[l], loop);
        Eigen::MatrixXd synthesized;
        ASSERT_TRUE(transform.synthesize(coefficients, l, synthesized).ok());
        ASSERT_EQ(synthesized.rows(), loop.rows());
        EXPECT_LT(relativeDifference(synthesized, loop), 1e-13) << name << " level " << l;
      }
    }
  }
}

TEST(LoopWavelet, EachLevelIsTheLeastSquaresLoopFitOfTheNextFinerOne)
{
  // The update step makes level l-1 the control mesh whose Loop subdivision
  // is closest to level l (up to the tolerance of its iterative solve);
  // here the fit is computed directly with the textbook Loop matrix.
  const int finest = 3;
  for (const NamedDomain& named : smallDomains())
  {
    const std::string& name = named.name;
    const BaseDomain& domain = named.domain;
    std::vector<SemiRegularMesh> meshes(finest + 1);
    for (int l = 0; l <= finest; ++l)
      meshes[l] = remeshOf(named, l);
    LoopWaveletTransform transform;
    ASSERT_TRUE(transform.build(meshes[finest]).ok());
    WaveletCoefficients coefficients;
    ASSERT_TRUE(
      transform.analyze(randomValues(meshes[finest].vertexCount(), 2, 5), DetailFrame::Global, coefficients).ok());
    for (int l = 1; l <= finest; ++l)
    {
      const int coarseCount = meshes[l - 1].vertexCount();
      const Eigen::MatrixXd loop =
        textbookLoop(meshes[l - 1], meshes[l], Eigen::MatrixXd::Identity(coarseCount, coarseCount));
      Eigen::MatrixXd fine, coarse;
      ASSERT_TRUE(transform.synthesize(coefficients, l, fine).ok());
      ASSERT_TRUE(transform.synthesize(coefficients, l - 1, coarse).ok());
      const Eigen::MatrixXd leastSquares = (loop.transpose() * loop).ldlt().solve(loop.transpose() * fine);
      const double difference = relativeDifference(coarse, leastSquares);
      EXPECT_LT(difference, 0.05) << name << " level " << l;
      // Plain subsampling is far from it.
      EXPECT_GT(relativeDifference(fine.topRows(coarseCount), leastSquares), 0.5) << name << " level " << l;
    }
  }
}

TEST(LoopWavelet, CoarseLevelsSmoothNoise)
{
  // Low pass: the surface a level describes (its Loop subdivision, finer
  // details dropped) keeps less of independent noise the coarser the
  // level, instead of the subsampled noise a lazy wavelet would keep.
  const BaseDomain domain = test::mixedValenceDomain();
  const int finest = 5;
  SemiRegularMesh mesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, finest, mesh).ok());
  LoopWaveletTransform transform;
  ASSERT_TRUE(transform.build(mesh).ok());
  const Eigen::MatrixXd noise = randomValues(mesh.vertexCount(), 1, 3);
  WaveletCoefficients coefficients;
  ASSERT_TRUE(transform.analyze(noise, DetailFrame::Global, coefficients).ok());
  double finer = rms(noise);
  for (int l = finest - 1; l >= 0; --l)
  {
    const Eigen::MatrixXd surface = withoutDetailsAbove(transform, coefficients, l);
    EXPECT_LT(rms(surface), 0.8 * finer) << "level " << l;
    finer = rms(surface);
  }
  EXPECT_LT(finer, 0.1 * rms(noise));
}

TEST(LoopWavelet, DetailsOfASmoothSurfaceDecayWithLevel)
{
  const BaseDomain domain = test::octahedronDomain();
  const int finest = 6;
  SemiRegularMesh mesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, finest, mesh).ok());
  LoopWaveletTransform transform;
  ASSERT_TRUE(transform.build(mesh).ok());
  for (DetailFrame frame : { DetailFrame::Global, DetailFrame::Local })
  {
    WaveletCoefficients coefficients;
    ASSERT_TRUE(transform.analyze(spherePositions(domain, mesh), frame, coefficients).ok());
    for (int l = 2; l <= finest; ++l)
      EXPECT_LT(rms(coefficients.details(l)), 0.5 * rms(coefficients.details(l - 1))) << "level " << l;
    // Without details, the coarsest values synthesize a smooth Loop surface close to the sphere.
    const Eigen::VectorXd radius = withoutDetailsAbove(transform, coefficients, 0).rowwise().norm();
    EXPECT_GT(radius.minCoeff(), 0.95);
    EXPECT_LT(radius.maxCoeff(), 1.05);
  }
}

TEST(LoopWavelet, IsLinear)
{
  const BaseDomain domain = test::mixedValenceDomain();
  SemiRegularMesh mesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 3, mesh).ok());
  LoopWaveletTransform transform;
  ASSERT_TRUE(transform.build(mesh).ok());
  const Eigen::MatrixXd u = randomValues(mesh.vertexCount(), 2, 1), v = randomValues(mesh.vertexCount(), 2, 2);
  WaveletCoefficients cu, cv, cuv;
  ASSERT_TRUE(transform.analyze(u, DetailFrame::Global, cu).ok());
  ASSERT_TRUE(transform.analyze(v, DetailFrame::Global, cv).ok());
  ASSERT_TRUE(transform.analyze(2.0 * u - 3.0 * v, DetailFrame::Global, cuv).ok());
  EXPECT_LT(relativeDifference(cuv.values, 2.0 * cu.values - 3.0 * cv.values), 1e-13);
}

TEST(LoopWavelet, RejectsBadInput)
{
  const BaseDomain domain = test::octahedronDomain();
  LoopWaveletTransform transform;
  WaveletCoefficients coefficients;
  Eigen::MatrixXd values;
  EXPECT_FALSE(transform.analyze(Eigen::MatrixXd::Zero(6, 3), DetailFrame::Global, coefficients).ok())
    << "not built";

  // An adaptive remesh is refused; adaptive with every split is uniform.
  SemiRegularMesh adaptive;
  ASSERT_TRUE(buildAdaptiveSemiRegularMesh(
    domain, 3, [](const std::array<SurfacePoint, 3>& corners, int) { return corners[0].triangle == 0; }, adaptive)
                .ok());
  const Status refused = transform.build(adaptive);
  EXPECT_NE(refused.message().find("uniform"), std::string::npos) << refused.message();
  ASSERT_TRUE(buildAdaptiveSemiRegularMesh(domain, 2, [](const auto&, int) { return true; }, adaptive).ok());
  EXPECT_TRUE(transform.build(adaptive).ok());

  // Damaged connectivity.
  SemiRegularMesh mesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 2, mesh).ok());
  SemiRegularMesh shuffled = mesh;
  std::swap(shuffled.triangles[0], shuffled.triangles[5]);
  EXPECT_FALSE(transform.build(shuffled).ok());
  SemiRegularMesh unsorted = mesh;
  std::swap(unsorted.levelOfVertex[0], unsorted.levelOfVertex.back());
  EXPECT_FALSE(transform.build(unsorted).ok());

  // Two holes that meet at one base vertex: a vertex on four boundary
  // edges, where Loop's boundary rule is not defined.
  std::vector<char> pinched(domain.mesh.triangleCount(), 0);
  pinched[0] = 1;
  for (int t = 1; t < domain.mesh.triangleCount(); ++t)
  {
    const Triangle &a = domain.mesh.triangles[0], &b = domain.mesh.triangles[t];
    if (std::count_if(b.begin(), b.end(), [&](int v) { return std::find(a.begin(), a.end(), v) != a.end(); }) == 1)
    {
      pinched[t] = 1;
      break;
    }
  }
  SemiRegularMesh open = mesh;
  ASSERT_TRUE(removeHoleTriangles(domain, pinched, open).ok());
  const Status pinch = transform.build(open);
  EXPECT_NE(pinch.message().find("4 boundary edges"), std::string::npos) << pinch.message();

  ASSERT_TRUE(transform.build(mesh).ok());
  const int n = mesh.vertexCount();
  EXPECT_NE(transform.analyze(Eigen::MatrixXd::Zero(n - 1, 3), DetailFrame::Global, coefficients)
              .message()
              .find("rows"),
    std::string::npos);
  EXPECT_FALSE(transform.analyze(Eigen::MatrixXd::Zero(n, 0), DetailFrame::Global, coefficients).ok());
  EXPECT_NE(transform.analyze(Eigen::MatrixXd::Zero(n, 2), DetailFrame::Local, coefficients).message().find("3"),
    std::string::npos);
  Eigen::MatrixXd withNaN = Eigen::MatrixXd::Zero(n, 3);
  withNaN(4, 1) = std::nan("");
  EXPECT_NE(transform.analyze(withNaN, DetailFrame::Global, coefficients).message().find("NaN"), std::string::npos);

  ASSERT_TRUE(transform.analyze(Eigen::MatrixXd::Ones(n, 3), DetailFrame::Global, coefficients).ok());
  EXPECT_FALSE(transform.synthesize(coefficients, 3, values).ok()) << "level out of range";
  EXPECT_FALSE(transform.synthesize(coefficients, -1, values).ok());
  WaveletCoefficients nan = coefficients;
  nan.values(n - 1, 0) = std::nan("");
  EXPECT_NE(transform.synthesize(nan, values).message().find("NaN"), std::string::npos);
  SemiRegularMesh coarser;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 1, coarser).ok());
  LoopWaveletTransform other;
  ASSERT_TRUE(other.build(coarser).ok());
  EXPECT_NE(other.synthesize(coefficients, values).message().find("level"), std::string::npos);
}

// Its speed is measured by the benchmark's `wavelet` stage (wavelet_seconds),
// not asserted here: a test must not fail on a busy machine.
TEST(LoopWavelet, Level6AnalysisAndSynthesisOfARealBaseDomainAreInverses)
{
  CMP_REQUIRE_SHARED_DATA();
  const BaseDomain domain = test::realBaseDomain("381");
  ASSERT_GT(domain.mesh.vertexCount(), 0);
  SemiRegularMesh mesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, 6, mesh).ok());
  LoopWaveletTransform transform;
  ASSERT_TRUE(transform.build(mesh).ok());
  const Eigen::MatrixXd positions = spherePositions(domain, mesh);
  WaveletCoefficients coefficients;
  Eigen::MatrixXd back;
  ASSERT_TRUE(transform.analyze(positions, DetailFrame::Local, coefficients).ok());
  ASSERT_TRUE(transform.synthesize(coefficients, back).ok());
  EXPECT_LT(relativeDifference(back, positions), 1e-12);
}
