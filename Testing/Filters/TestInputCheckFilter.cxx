#include "FilterTestUtilities.h"
#include <cmp/mesh/TriangleMesh.h> // cmp::kPi
#include "vtkCMPInputCheck.h"
#include "vtkCMPSurfaceReader.h"

#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace cmp::test;

namespace
{

vtkSmartPointer<vtkPolyData> surfaceFromOFF(const std::string& name, const std::string& off)
{
  vtkNew<vtkCMPSurfaceReader> reader;
  reader->SetFileName(writeTempFile(name, off).c_str());
  EXPECT_TRUE(run(reader).succeeded);
  return reader->GetOutput();
}

std::string tetrahedraOFF(const std::string& points, const std::string& faces, int pointCount, int faceCount)
{
  return "OFF\n" + std::to_string(pointCount) + " " + std::to_string(faceCount) + " 0\n" + points + faces;
}

std::string torusOFF(int n, int m)
{
  std::ostringstream out;
  out << "OFF\n" << n * m << " " << 2 * n * m << " 0\n";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
    {
      const double u = 2 * cmp::kPi * i / n, v = 2 * cmp::kPi * j / m;
      out << (2 + std::cos(v)) * std::cos(u) << " " << (2 + std::cos(v)) * std::sin(u) << " " << std::sin(v) << "\n";
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
    {
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
      out << "3 " << a << " " << b << " " << c << "\n3 " << a << " " << c << " " << d << "\n";
    }
  return out.str();
}

RunResult check(vtkPolyData* surface, vtkPolyData* baseDomain = nullptr, bool requireLandmarks = false)
{
  vtkNew<vtkCMPInputCheck> filter;
  filter->SetInputData(0, surface);
  if (baseDomain)
    filter->SetInputData(1, baseDomain);
  filter->SetRequireLandmarks(requireLandmarks);
  RunResult result = run(filter);
  if (!result.succeeded)
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << "a failed check must produce no output";
  return result;
}

void expectFailure(const RunResult& result, const std::string& fragment)
{
  EXPECT_FALSE(result.succeeded);
  EXPECT_NE(result.error.find(fragment), std::string::npos) << "error: " << result.error;
}

vtkSmartPointer<vtkPolyData> octahedronBaseDomain()
{
  vtkSmartPointer<vtkPolyData> domain = surfaceFromOFF("l0.off", octahedronOFF());
  setFeatureIds(domain, { 0, 1, 2, 3, 4, 5 });
  return domain;
}

const std::string kTetraPoints = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const std::string kTetraFaces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

} // namespace

TEST(InputCheck, PassesAGoodSurfaceThrough)
{
  vtkSmartPointer<vtkPolyData> surface = surfaceFromOFF("good.off", octahedronOFF());
  vtkNew<vtkCMPInputCheck> filter;
  filter->SetInputData(surface);
  ASSERT_TRUE(run(filter).succeeded);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 6);
  EXPECT_NE(filter->GetOutput()->GetFieldData()->GetAbstractArray("InputCheck"), nullptr);
}

TEST(InputCheck, NamesEachSurfaceDefect)
{
  // An open surface is a sphere with holes (issue 27 B): accepted, but each
  // boundary loop of a landmarked one must carry 3 landmarks.
  vtkSmartPointer<vtkPolyData> open = surfaceFromOFF("open.off", octahedronOFF(true));
  EXPECT_TRUE(check(open).succeeded);
  setFeatureIds(open, { 0 });
  expectFailure(check(open), "passes through 1 landmark, but every boundary loop needs at least 3");
  expectFailure(check(surfaceFromOFF("nm-edge.off",
                  tetrahedraOFF(kTetraPoints + "0 -1 0\n0 0 -1\n", kTetraFaces + "3 0 4 1\n3 0 1 5\n3 0 5 4\n3 1 4 5\n", 6, 8))),
    "non-manifold edges, e.g. edge (0, 1) shared by 4 triangles");
  expectFailure(check(surfaceFromOFF("nm-vertex.off",
                  tetrahedraOFF(kTetraPoints + "-1 -1 -1\n0 -1 -1\n-1 0 -1\n",
                    kTetraFaces + "3 4 6 5\n3 4 5 0\n3 4 0 6\n3 5 6 0\n", 7, 8))),
    "non-manifold vertices");
  expectFailure(check(surfaceFromOFF("torus.off", torusOFF(10, 6))), "genus 1");
  expectFailure(check(surfaceFromOFF("two.off",
                  tetrahedraOFF(kTetraPoints + "5 0 0\n6 0 0\n5 1 0\n5 0 1\n",
                    kTetraFaces + "3 4 6 5\n3 4 5 7\n3 4 7 6\n3 5 6 7\n", 8, 8))),
    "2 connected components");
  std::string nan = octahedronOFF();
  nan.replace(nan.find("0 1 0\n"), 6, "nan 1 0\n");
  expectFailure(check(surfaceFromOFF("nan.off", nan)), "point 2 has a NaN");
  // A fin (a triangle hung on edge (0, 2) of the closed octahedron) is a
  // non-manifold edge, not just an open surface (issue 26).
  std::string fin = octahedronOFF();
  fin.replace(fin.find("6 8 0\n"), 6, "7 9 0\n");
  fin.replace(fin.find("3 0 2 4\n"), 0, "2 2 0\n");
  fin += "3 0 2 6\n";
  expectFailure(check(surfaceFromOFF("fin.off", fin)),
    "1 non-manifold edges, e.g. edge (0, 2) shared by 3 triangles (and 2 boundary edges");
  vtkNew<vtkPolyData> empty;
  expectFailure(check(empty), "empty surface");
  vtkSmartPointer<vtkPolyData> flipped = surfaceFromOFF("flip.off", octahedronOFF());
  flipped->GetPolys()->ReplaceCellAtId(0, { 2, 0, 4 });
  expectFailure(check(flipped), "inconsistent orientation");
}

TEST(InputCheck, RejectsNonTriangleCells)
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 4; ++i)
    points->InsertNextPoint(i % 2, i / 2, 0);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 3, 2 });
  vtkNew<vtkPolyData> quad;
  quad->SetPoints(points);
  quad->SetPolys(polys);
  expectFailure(check(quad), "cell 0 is a polygon with 4 points; only triangles are accepted");
}

TEST(InputCheck, ChecksLandmarks)
{
  vtkSmartPointer<vtkPolyData> surface = surfaceFromOFF("lm.off", octahedronOFF());
  expectFailure(check(surface, nullptr, true), "missing point array 'FeatureId'");
  setFeatureIds(surface, { 0, 1, 1 });
  expectFailure(check(surface), "duplicate landmark: feature 1 is on vertices 1 and 2");
  setFeatureIds(surface, { 0, 2 });
  expectFailure(check(surface), "missing landmark: feature 1 is on no vertex");
  setFeatureIds(surface, { 0, 1, 2, 3, 4, 5 });
  EXPECT_TRUE(check(surface, nullptr, true).succeeded);
}

TEST(InputCheck, ChecksTheBaseDomainAgainstTheSurface)
{
  vtkSmartPointer<vtkPolyData> surface = surfaceFromOFF("s.off", octahedronOFF());
  setFeatureIds(surface, { 5, 4, 3, 2, 1, 0 });
  EXPECT_TRUE(check(surface, octahedronBaseDomain()).succeeded);

  setFeatureIds(surface, { 0, 1, 2, 3 });
  expectFailure(check(surface, octahedronBaseDomain()), "base domain has 6 vertices but the surface has 4 landmarks");

  setFeatureIds(surface, { 0, 1, 2, 3, 4, 5 });
  vtkSmartPointer<vtkPolyData> open = surfaceFromOFF("l0open.off", octahedronOFF(true));
  setFeatureIds(open, { 0, 1, 2, 3, 4, 5 });
  // An open L0 asks for an open surface whose boundary is L0's.
  expectFailure(check(surface, open), "the surface is closed but the base domain has 1 boundary loop(s)");
  EXPECT_TRUE(check(open, open).succeeded) << check(open, open).error;

  vtkSmartPointer<vtkPolyData> unlabelled = surfaceFromOFF("l0bare.off", octahedronOFF());
  expectFailure(check(surface, unlabelled), "base domain: missing point array 'FeatureId'");

  vtkSmartPointer<vtkPolyData> duplicate = octahedronBaseDomain();
  setFeatureIds(duplicate, { 0, 1, 2, 3, 4, 4 });
  expectFailure(check(surface, duplicate), "base domain: FeatureId 4 is on vertices 4 and 5");
}

// Per-surface messages name the file the surface was read from, so that a
// failing model of a collection can be found; in-memory surfaces have none.
TEST(InputCheckFilter, NamesTheSurfaceFile)
{
  vtkSmartPointer<vtkPolyData> read = surfaceFromOFF("check-named-octa.off", octahedronOFF());
  RunResult result = check(read, nullptr, true);
  EXPECT_FALSE(result.succeeded);
  EXPECT_NE(result.error.find("): check-named-octa.off: missing point array 'FeatureId'"), std::string::npos)
    << result.error;

  read->GetFieldData()->RemoveArray("SourceFile");
  result = check(read, nullptr, true);
  EXPECT_FALSE(result.succeeded);
  EXPECT_NE(result.error.find("): missing point array 'FeatureId'"), std::string::npos) << result.error;
}
