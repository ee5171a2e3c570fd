#pragma once
/// \file vtkCMPPolyDataBridge.h
/// \brief Conversions between vtkPolyData and the core's types, shared by
///        all filters of the module (private header, not wrapped).

#include <cmp/basedomain/BaseDomain.h>
#include <cmp/io/Landmarks.h>
#include <cmp/map/NetStraightener.h>
#include <cmp/layout/OpenSurface.h>
#include <cmp/layout/PatchLayout.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/SurfaceCheck.h>
#include <cmp/mesh/TriangleMesh.h>

#include "vtkCMPArrayNames.h"

#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

class vtkDataArray;
class vtkDataObject;
class vtkIntArray;
class vtkPolyData;
class vtkDataSet;
class vtkFieldData;

namespace cmp::bridge
{

// Array names: vtkCMPArrayNames.h.

/// \brief Copies points and triangles; fails, naming the cell, if `input`
///        has cells that are not triangles (vertices, lines, polygons, strips).
Status toTriangleMesh(vtkPolyData* input, TriangleMesh& mesh);

/// \brief Like `toCheckedSurface()`, but a surface with boundary loops
///        passes when it is a sphere with holes (`checkSurfaceWithBoundaries()`).
Status toCheckedSurfaceWithBoundaries(vtkPolyData* input, TriangleMesh& mesh);

/// \brief Converts and runs `checkSurface()`, so a filter can reject bad
///        input with one call.
Status toCheckedSurface(vtkPolyData* input, TriangleMesh& mesh);

/// \brief Reads the `FeatureId` point array (any integer type) as landmarks,
///        as many as the field array `FeatureCount` says when present
///        (`landmarksFromFeatureIds()`). A feature on no vertex fails,
///        unless `allowMissing` (it is then `kMissingLandmark`).
Status readLandmarks(vtkPolyData* input, LandmarkList& landmarks, bool allowMissing = false);

/// \brief The field array `FeatureCount` of `data`, or -1 without one.
int featureCountOf(vtkDataObject* data);

/// \brief Reads the `PatchId` cell array (any integer type, one value per
///        triangle), as Feature Net Tracer writes it.
Status readPatchIds(vtkPolyData* input, std::vector<int>& patchIds);

/// \brief Reads a base domain polydata (points, triangles, `FeatureId`) and
///        checks it, and that it has `landmarkCount` vertices when >= 0.
Status toBaseDomain(vtkPolyData* input, BaseDomain& domain, int landmarkCount = -1);

/// \brief Reads a base domain polydata, closed or with boundary loops, and
///        closes its holes (`closeBaseDomain()`): `domain` is the closed L0
///        every stage runs on, `holes` what closing added (empty for a
///        closed L0). With `landmarkCount >= 0`, the open L0 must have that
///        many vertices.
Status toClosedBaseDomain(vtkPolyData* input, BaseDomain& domain, BaseDomainHoles& holes, int landmarkCount = -1);

/// \brief Reads a given base domain polydata, closed or with boundary loops,
///        checked as `toClosedBaseDomain()` checks it, and keeps it as given
///        (its holes open), for the core stages that close it themselves.
Status toCheckedBaseDomain(vtkPolyData* input, BaseDomain& domain);

/// \brief A surface as the stages read it: `open` as given (closed or with
///        boundary loops), `closed` with its holes capped against L0's
///        (`closeSurface()`) and checked (`checkSurface()`), its landmarks
///        with the caps' centres, and what the caps added.
struct ClosedSurface
{
  TriangleMesh open;
  TriangleMesh closed;
  LandmarkList closedLandmarks;
  SurfaceHoles holes;
};

/// \brief Closes a surface read and checked by
///        `toCheckedSurfaceWithBoundaries()` (`checked`, taken over) against
///        `holes` (L0's): checks the contract of surfaces with boundaries
///        and the capped surface, so that a filter reads and checks its
///        input once. `capped`: how the capped surface is checked (a
///        remesher's input, parameterized already, is checked for its
///        topology only). Fails (Status) on what `closeSurface()` or
///        `checkSurface()` refuse, in the user's terms.
Status toClosedSurface(TriangleMesh checked, const LandmarkList& landmarks, const BaseDomainHoles& holes,
  ClosedSurface& out, const SurfaceCheckOptions& capped = {});

/// \brief Builds a polydata of points and triangles.
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh);

/// \brief Builds the base domain polydata with its `FeatureId` point array.
vtkSmartPointer<vtkPolyData> toPolyData(const BaseDomain& domain);

/// \brief The curves of a patch layout as polylines, one cell per base edge
///        (in base edge order) on a compact point set, with cell arrays
///        `BaseEdgeId`, `FeatureIdA` and `FeatureIdB` (the landmarks at each
///        curve's first and last point).
vtkSmartPointer<vtkPolyData> toPolyLines(const TracedNet& net, const BaseDomain& domain);

/// \brief The same without the curves of the caps (a curve to a cap's
///        centre, a feature not below `holes.openVertexCount`): the patch
///        layout of an open surface. All curves when `holes` is empty.
vtkSmartPointer<vtkPolyData> toPolyLines(const TracedNet& net, const BaseDomain& domain, const BaseDomainHoles& holes);

/// \brief A vtkIntArray named `name` holding `values`.
vtkSmartPointer<vtkIntArray> intArray(const char* name, const std::vector<int>& values);

/// \brief A one-component array of type `ArrayType` (vtkUnsignedCharArray,
///        vtkIdTypeArray, ...) named `name` holding `values`, converted.
template <class ArrayType, class Value>
vtkSmartPointer<ArrayType> valueArray(const char* name, const std::vector<Value>& values)
{
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  return array;
}

/// \brief Adds (or replaces) the point array `FeatureId` of `surface`
///        (int: -1, or the feature index at each landmark vertex; a missing
///        feature is on no vertex) and the field array `FeatureCount`.
void setFeatureIds(vtkPolyData* surface, const LandmarkList& landmarks);

/// \brief The file-to-mesh point map the surface reader leaves in field
///        array `FileToMeshPointId` (empty when the reader welded nothing).
std::vector<int> fileToMeshPointMap(vtkPolyData* surface);

/// \brief Adds (or replaces) a one-value double array in field data.
void setFieldValue(vtkFieldData* fieldData, const char* name, double value);

/// \brief Adds (or replaces) a one-tuple, three-component double array in
///        field data (a point or a vector).
void setFieldTuple(vtkFieldData* fieldData, const char* name, const Vec3& value);

/// \brief Adds (or replaces) a one-value string array in field data.
void setFieldString(vtkFieldData* fieldData, const char* name, const std::string& value);

/// \brief The prefix naming the model in a filter's messages: "camel.off: "
///        when `data` carries the `SourceFile` field array, "" otherwise.
/// A per-surface filter run block by block on a multiblock is not told the
/// block's name (VTK 9.2's composite pipeline hands it the leaf alone), so
/// the file name travelling with the data is the only way to say which
/// model of a collection an error is about.
std::string modelPrefix(vtkDataObject* data);

/// \brief Copies the `SourceFile` field array of `from` (if any) to `to`,
///        for filters that build their output anew rather than copying the input.
void copySourceFile(vtkDataObject* from, vtkDataObject* to);

/// \brief Interpolates per-corner texture coordinates (`CornerTCoords`) on a
///        surface whose triangles are pieces of `input`'s: piece t lies in
///        input triangle `homeOf(t)`, and its corner c is the input surface
///        point `cornerPoint(t, c)`. Each corner gets the home triangle's
///        corner values at those input vertices, with those weights; a
///        piece with a corner outside its home triangle (or a point without
///        vertices) keeps the values already in `corners`.
void interpolateCornerTCoords(vtkDataArray* corners, vtkDataArray* inputCorners, const TriangleMesh& input,
  int pieces, const std::function<int(int)>& homeOf, const std::function<SurfacePoint(int, int)>& cornerPoint);

} // namespace cmp::bridge
