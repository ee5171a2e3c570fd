#include <cmp/basedomain/BaseDomainBuilder.h>
#include <cmp/analysis/DetailTransfer.h>
#include <cmp/analysis/LoopWavelet.h>
#include <cmp/remesh/SemiRegularRemesher.h>
#include <cmp/mesh/SurfaceDistance.h>
#include "TestMeshes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace cmp;

namespace
{

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

/// RMS distance of the rows from their mean, written out independently.
double spread(const Eigen::MatrixXd& values)
{
  const Eigen::RowVectorXd mean = values.colwise().sum() / static_cast<double>(values.rows());
  double sum = 0.0;
  for (Eigen::Index i = 0; i < values.rows(); ++i)
    sum += (values.row(i) - mean).squaredNorm();
  return std::sqrt(sum / static_cast<double>(values.rows()));
}

/// A bumpy closed surface drawn on `domain`'s remesh: the drawing pushed to
/// the unit sphere around the domain's centre, then radially by `bumps`.
Eigen::MatrixXd bumpyPositions(const BaseDomain& domain, const SemiRegularMesh& mesh, const Vec3& bumps)
{
  Eigen::MatrixXd positions = test::toMatrix(test::drawnOnDomain(domain, mesh).points);
  const Eigen::RowVector3d centre = test::toMatrix(domain.mesh.points).colwise().mean();
  for (Eigen::Index i = 0; i < positions.rows(); ++i)
  {
    const Vec3 p = (positions.row(i) - centre).normalized().transpose();
    const double radius =
      1.0 + 0.1 * std::sin(bumps.x() * p.x()) * std::sin(bumps.y() * p.y()) * std::sin(bumps.z() * p.z());
    positions.row(i) = radius * p.transpose();
  }
  return positions;
}

/// A transform of `domain` refined `level` times, ready to use.
struct Fixture
{
  BaseDomain domain;
  SemiRegularMesh mesh;
  LoopWaveletTransform transform;
};

void makeFixture(const BaseDomain& domain, int level, Fixture& fixture)
{
  fixture.domain = domain;
  ASSERT_TRUE(buildSemiRegularMesh(domain, level, fixture.mesh).ok());
  ASSERT_TRUE(fixture.transform.build(fixture.mesh).ok());
}

} // namespace

TEST(DetailTransfer, DetailsOfBAboveIsTheFigure13Schedule)
{
  EXPECT_EQ(detailsOfBAbove(3, 0), (DetailSchedule{ 0, 1, 1, 1 }));
  EXPECT_EQ(detailsOfBAbove(3, 1), (DetailSchedule{ 0, 0, 1, 1 }));
  EXPECT_EQ(detailsOfBAbove(3, 3), (DetailSchedule{ 0, 0, 0, 0 }));
  EXPECT_EQ(detailsOfBAbove(0, 0), (DetailSchedule{ 0 }));
}

TEST(DetailTransfer, ScheduleBlendsTheCoefficientsLevelByLevel)
{
  Fixture f;
  makeFixture(test::mixedValenceDomain(), 3, f);
  const Eigen::MatrixXd a = bumpyPositions(f.domain, f.mesh, Vec3(5, 4, 3));
  const Eigen::MatrixXd b = 1.3 * bumpyPositions(f.domain, f.mesh, Vec3(2, 7, 6));
  WaveletCoefficients ca, cb, out;
  ASSERT_TRUE(f.transform.analyze(a, DetailFrame::Local, ca).ok());
  ASSERT_TRUE(f.transform.analyze(b, DetailFrame::Local, cb).ok());

  // All of A: A itself.
  ASSERT_TRUE(transferDetails(ca, cb, DetailSchedule(4, 0.0), out).ok());
  EXPECT_EQ(out.values, ca.values);
  Eigen::MatrixXd positions;
  ASSERT_TRUE(f.transform.synthesize(out, positions).ok());
  EXPECT_LT(relativeDifference(positions, a), 1e-12);
  // All of B when A is B: still A.
  ASSERT_TRUE(transferDetails(ca, ca, DetailSchedule(4, 1.0), out).ok());
  EXPECT_EQ(out.values, ca.values);
  // All of B: B itself, whatever the sizes.
  ASSERT_TRUE(transferDetails(ca, cb, DetailSchedule(4, 1.0), out).ok());
  EXPECT_EQ(out.values, cb.values);
  // Figure 13: A's coarsest values, every detail of B (as they are, or
  // scaled from B's size to A's).
  ASSERT_TRUE(transferDetails(ca, cb, detailsOfBAbove(3, 0), out, DetailScaling::Absolute).ok());
  EXPECT_EQ(Eigen::MatrixXd(out.coarse()), Eigen::MatrixXd(ca.coarse()));
  for (int l = 1; l <= 3; ++l)
    EXPECT_EQ(Eigen::MatrixXd(out.details(l)), Eigen::MatrixXd(cb.details(l))) << "level " << l;
  ASSERT_TRUE(transferDetails(ca, cb, detailsOfBAbove(3, 0), out).ok());
  EXPECT_EQ(Eigen::MatrixXd(out.coarse()), Eigen::MatrixXd(ca.coarse()));
  const double sizeRatio = spread(ca.coarse()) / spread(cb.coarse());
  EXPECT_NEAR(sizeRatio, 1.0 / 1.3, 0.02);
  for (int l = 1; l <= 3; ++l)
    EXPECT_LT(relativeDifference(out.details(l), sizeRatio * cb.details(l)), 1e-15) << "level " << l;
  // A threshold keeps A's details up to it.
  ASSERT_TRUE(transferDetails(ca, cb, detailsOfBAbove(3, 2), out, DetailScaling::Absolute).ok());
  EXPECT_EQ(Eigen::MatrixXd(out.details(2)), Eigen::MatrixXd(ca.details(2)));
  EXPECT_EQ(Eigen::MatrixXd(out.details(3)), Eigen::MatrixXd(cb.details(3)));
  // Per-level blends and extrapolation, the coarsest level included; with
  // relative scaling each model's details follow the blended coarse size.
  const DetailSchedule mixed{ 0.25, 0.5, 2.0, -1.0 };
  ASSERT_TRUE(transferDetails(ca, cb, mixed, out, DetailScaling::Absolute).ok());
  const Eigen::MatrixXd coarse = 0.75 * ca.coarse() + 0.25 * cb.coarse();
  EXPECT_LT(relativeDifference(out.coarse(), coarse), 1e-15);
  EXPECT_LT(relativeDifference(out.details(1), 0.5 * (ca.details(1) + cb.details(1))), 1e-15);
  EXPECT_LT(relativeDifference(out.details(2), 2.0 * cb.details(2) - ca.details(2)), 1e-15);
  EXPECT_LT(relativeDifference(out.details(3), 2.0 * ca.details(3) - cb.details(3)), 1e-15);
  ASSERT_TRUE(transferDetails(ca, cb, mixed, out).ok());
  const double toA = spread(coarse) / spread(ca.coarse()), toB = spread(coarse) / spread(cb.coarse());
  EXPECT_LT(relativeDifference(out.details(2), 2.0 * toB * cb.details(2) - toA * ca.details(2)), 1e-14);
  // The output may be one of the inputs.
  WaveletCoefficients inPlace = ca;
  ASSERT_TRUE(transferDetails(inPlace, cb, detailsOfBAbove(3, 0), inPlace, DetailScaling::Absolute).ok());
  EXPECT_EQ(Eigen::MatrixXd(inPlace.details(1)), Eigen::MatrixXd(cb.details(1)));
  EXPECT_EQ(Eigen::MatrixXd(inPlace.coarse()), Eigen::MatrixXd(ca.coarse()));

  // Global frames blend the same way and give the same result when the
  // schedule takes every level from one model.
  Eigen::MatrixXd blended;
  ASSERT_TRUE(transferDetails(f.transform, a, b, DetailSchedule(4, 1.0), blended, DetailFrame::Global).ok());
  EXPECT_LT(relativeDifference(blended, b), 1e-12);
}

TEST(DetailTransfer, LocalDetailsFollowTheCoarseShape)
{
  // A is B turned, moved and doubled: in local frames and relative to the
  // coarse size A's details are B's, so putting B's details on A's coarse
  // shape gives back A. Global details would stay in B's orientation, and
  // absolute ones at B's size.
  Fixture f;
  makeFixture(test::mixedValenceDomain(), 4, f);
  const Eigen::MatrixXd b = bumpyPositions(f.domain, f.mesh, Vec3(5, 4, 3));
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.1, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::MatrixXd a = (2.0 * b * turn.transpose()).rowwise() + Eigen::RowVector3d(0.5, -2.0, 1.0);
  const DetailSchedule allOfB = detailsOfBAbove(4, 0);
  Eigen::MatrixXd local, global, absolute;
  ASSERT_TRUE(transferDetails(f.transform, a, b, allOfB, local).ok());
  ASSERT_TRUE(transferDetails(f.transform, a, b, allOfB, global, DetailFrame::Global).ok());
  ASSERT_TRUE(
    transferDetails(f.transform, a, b, allOfB, absolute, DetailFrame::Local, DetailScaling::Absolute).ok());
  EXPECT_LT(relativeDifference(local, a), 1e-12);
  EXPECT_GT(relativeDifference(global, a), 1e-2);
  EXPECT_GT(relativeDifference(absolute, a), 1e-2);
}

TEST(DetailTransfer, RejectsMismatchedInput)
{
  Fixture f, coarser;
  makeFixture(test::octahedronDomain(), 2, f);
  makeFixture(test::octahedronDomain(), 1, coarser);
  const Eigen::MatrixXd positions = bumpyPositions(f.domain, f.mesh, Vec3(3, 3, 3));
  WaveletCoefficients local, global, scalar, otherLevel, out;
  ASSERT_TRUE(f.transform.analyze(positions, DetailFrame::Local, local).ok());
  ASSERT_TRUE(f.transform.analyze(positions, DetailFrame::Global, global).ok());
  ASSERT_TRUE(f.transform.analyze(positions.leftCols(1), DetailFrame::Global, scalar).ok());
  ASSERT_TRUE(coarser.transform
                .analyze(bumpyPositions(coarser.domain, coarser.mesh, Vec3(3, 3, 3)), DetailFrame::Local, otherLevel)
                .ok());
  const auto expectError = [](const Status& status, const std::string& part)
  { EXPECT_NE(status.message().find(part), std::string::npos) << status.message(); };
  expectError(transferDetails(local, otherLevel, DetailSchedule(3, 1.0), out), "different levels");
  expectError(transferDetails(local, global, DetailSchedule(3, 1.0), out), "frames");
  expectError(transferDetails(global, scalar, DetailSchedule(3, 1.0), out), "columns");
  expectError(transferDetails(local, local, DetailSchedule(2, 1.0), out), "schedule has 2 weights");
  expectError(transferDetails(local, local, { 0.0, std::nan(""), 1.0 }, out), "NaN");
  WaveletCoefficients withNaN = local;
  withNaN.values(7, 2) = std::nan("");
  expectError(transferDetails(local, withNaN, DetailSchedule(3, 1.0), out), "NaN");
  expectError(transferDetails(WaveletCoefficients{}, WaveletCoefficients{}, {}, out), "empty");
  WaveletCoefficients flat = global;
  flat.values.topRows(6).setOnes();
  expectError(transferDetails(global, flat, DetailSchedule(3, 1.0), out, DetailScaling::RelativeToCoarseSize),
    "all equal");
  EXPECT_TRUE(transferDetails(global, flat, DetailSchedule(3, 1.0), out, DetailScaling::Absolute).ok());
  Eigen::MatrixXd result;
  expectError(transferDetails(f.transform, positions, positions.topRows(5), DetailSchedule(3, 1.0), result),
    "model B");
  expectError(transferDetails(f.transform, positions.leftCols(2), positions.leftCols(2), DetailSchedule(3, 1.0), result),
    "3 columns");
}

TEST(DetailTransfer, DetailsOfARealModelOnTheCoarseShapeOfAnother)
{
  // The paper's Figure 13 on the shared data: the cow's (Spot's) details
  // on a SHREC animal's coarsest control mesh, both remeshed with one
  // connectivity.
  CMP_REQUIRE_SHARED_DATA();
  const test::LandmarkedModel animal = test::landmarkedRealModel("381"), cow = test::landmarkedRealModel("spot");
  BaseDomain domain;
  ASSERT_TRUE(buildBaseDomain(animal.data.mesh, animal.landmarks, domain).ok());
  const int level = 5;
  SemiRegularMesh remesh;
  ASSERT_TRUE(buildSemiRegularMesh(domain, level, remesh).ok());
  std::vector<Eigen::MatrixXd> positions;
  for (const test::LandmarkedModel* model : { &animal, &cow })
  {
    test::ParameterizedModel parameterized;
    const Status status = test::parameterizeOnDomain(*model, domain, parameterized);
    ASSERT_TRUE(status.ok()) << status.message();
    std::vector<SurfacePoint> samples;
    ASSERT_TRUE(placeOnSurface(remesh, parameterized.net, domain, parameterized.parameterization, samples).ok());
    positions.push_back(test::toMatrix(samplePositions(parameterized.net, samples)));
  }
  const Eigen::MatrixXd& a = positions[0];
  const Eigen::MatrixXd& b = positions[1];

  LoopWaveletTransform transform;
  ASSERT_TRUE(transform.build(remesh).ok());
  WaveletCoefficients ca, cb;
  ASSERT_TRUE(transform.analyze(a, DetailFrame::Local, ca).ok());
  ASSERT_TRUE(transform.analyze(b, DetailFrame::Local, cb).ok());
  for (const auto& [model, coefficients] : { std::pair{ &a, &ca }, std::pair{ &b, &cb } })
  {
    Eigen::MatrixXd back;
    ASSERT_TRUE(transform.synthesize(*coefficients, back).ok());
    EXPECT_LT(relativeDifference(back, *model), 1e-12);
  }

  Eigen::MatrixXd result;
  ASSERT_TRUE(transferDetails(transform, a, b, detailsOfBAbove(level, 0), result).ok());
  ASSERT_TRUE(result.allFinite());
  // Analyzed again, the result has A's coarsest level and B's details,
  // scaled from B's size to A's (Spot is about half as large as 381).
  WaveletCoefficients again;
  ASSERT_TRUE(transform.analyze(result, DetailFrame::Local, again).ok());
  EXPECT_LT(relativeDifference(again.coarse(), ca.coarse()), 1e-10);
  const double sizeRatio = spread(ca.coarse()) / spread(cb.coarse());
  EXPECT_GT(sizeRatio, 1.5);
  for (int l = 1; l <= level; ++l)
    EXPECT_LT(relativeDifference(again.details(l), sizeRatio * cb.details(l)), 1e-9) << "level " << l;

  // It is a new shape: as far from A as from B in the details, but with
  // A's size and place.
  TriangleMesh surfaceA{ {}, remesh.triangles }, surfaceResult{ {}, remesh.triangles };
  for (Eigen::Index i = 0; i < a.rows(); ++i)
  {
    surfaceA.points.push_back(a.row(i).transpose());
    surfaceResult.points.push_back(result.row(i).transpose());
  }
  const double diagonal = boundingBoxDiagonal(surfaceA);
  const double fromA = surfaceDistance(surfaceResult, surfaceA, 1).meanAToB / diagonal;
  std::cout << "Spot's details on 381's coarsest level: mean distance to 381 " << fromA << " of its diagonal, "
            << "bounding box diagonal " << boundingBoxDiagonal(surfaceResult) / diagonal << " of 381's\n";
  EXPECT_GT(fromA, 1e-3);
  EXPECT_LT(fromA, 0.1);
  EXPECT_NEAR(boundingBoxDiagonal(surfaceResult) / diagonal, 1.0, 0.25);
}
