#pragma once
/// \file FilterTestUtilities.h
/// \brief Helpers for the VTK filter tests: running an algorithm while
///        capturing its error message, writing small surfaces to files.

#include "TestData.h"

#include <vtkSmartPointer.h>

#include <array>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkPolyData;

class vtkMultiBlockDataSet;

namespace cmp::test
{

/// \brief Outcome of running one algorithm.
struct RunResult
{
  bool succeeded = false; ///< Update() returned true and no error was reported.
  std::string error;      ///< First error message the algorithm reported.
};

/// \brief Updates `algorithm`, capturing its ErrorEvent instead of printing it.
RunResult run(vtkAlgorithm* algorithm);

/// \brief OFF text of a regular octahedron, optionally without its last triangle.
std::string octahedronOFF(bool open = false);

/// \brief Sets point array FeatureId to `ids`, padded with -1 to the point count.
void setFeatureIds(vtkPolyData* surface, std::vector<int> ids);

/// \brief Surface area of `surface` (vtkMassProperties).
double areaOf(vtkPolyData* surface);

/// \brief First value of field array `name`, NaN if there is none.
double fieldValue(vtkPolyData* data, const char* name);

/// \brief Reads a surface with vtkCMPSurfaceReader and adds landmarks from a file.
vtkSmartPointer<vtkPolyData> readLandmarked(const std::string& mesh, const std::string& landmarks);

/// \brief The shipped example collection folder (Data/examples).
std::string examplesDir();

/// \brief L0 built by the Base Domain Builder from a landmarked surface
///        (a test failure if it does not build).
vtkSmartPointer<vtkPolyData> baseDomainOf(vtkPolyData* surface);

/// \brief A copy of `l0` with the landmarks of features 0 and 1 swapped: a
///        valid base domain that a layout traced against `l0` does not fit.
vtkSmartPointer<vtkPolyData> withFeatures0And1Swapped(vtkPolyData* l0);

/// \brief A tetrahedron with FeatureIds 0..3: a base domain with fewer
///        landmarks than a six-landmark layout (written to a temporary file
///        `fileName` and read back, as a user's L0 would be).
vtkSmartPointer<vtkPolyData> tetrahedronBaseDomain(const std::string& fileName);

/// \brief `surface` traced against `l0` and straightened (a test failure
///        if either fails): the input of the filters that read a
///        parameterization. `freeCurves` is the straightener's FreeCurves
///        (its default, on; off: the paper's fixed curves).
vtkSmartPointer<vtkPolyData> parameterized(vtkPolyData* surface, vtkPolyData* l0, bool freeCurves = true);

/// \brief The three shipped examples (blob, capsule, peanut) traced and
///        straightened against `l0`, as one multiblock with blocks named
///        after them: the input of a Semi-Regular Remesher collection.
vtkSmartPointer<vtkMultiBlockDataSet> parameterizedExamples(vtkPolyData* l0);

/// \brief A multiblock of `surfaces`, block k = surface k (not copied).
vtkSmartPointer<vtkMultiBlockDataSet> blocksOf(std::initializer_list<vtkPolyData*> surfaces);

/// \brief A copy of `surface` whose point `point` has a NaN coordinate.
vtkSmartPointer<vtkPolyData> withNaNAt(vtkPolyData* surface, vtkIdType point);

/// \brief Adds cell array `CornerTCoords`: at every triangle corner, (u, v) =
///        coordinates `uAxis` and `vAxis` of the corner's point. Linear over
///        every triangle, so a filter that cuts or splits triangles must give
///        each new corner its own point's coordinates, not copy the old ones.
void addCornerTCoords(vtkPolyData* surface, int uAxis, int vAxis);

/// \brief Adds cell array `CornerTCoords` with (u, v) = `uvAt(point, cell)`
///        at every corner: `point` is the corner's coordinates, `cell` its
///        triangle.
void addCornerTCoords(
  vtkPolyData* surface, const std::function<std::array<double, 2>(const double* point, vtkIdType cell)>& uvAt);

/// \brief Corners whose `CornerTCoords` differ from coordinates `uAxis` and
///        `vAxis` of their point by more than `tolerance`.
int cornersNotAtTheirPoints(vtkPolyData* surface, int uAxis, int vAxis, double tolerance);

} // namespace cmp::test
