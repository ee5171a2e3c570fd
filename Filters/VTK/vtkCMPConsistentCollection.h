#pragma once
/// \file vtkCMPConsistentCollection.h
/// \brief A collection of remeshes that share one connectivity, read from a
///        vtkPolyData or a multiblock (possibly spread over ranks), for the
///        filters of the paper's Section 3 (private header, not wrapped).

#include <cmp/numerics/Communicator.h>
#include <cmp/analysis/ProcrustesAlignment.h>
#include <cmp/mesh/Status.h>
#include <cmp/mesh/TriangleMesh.h>
#include "vtkCMPCollection.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkDataObject;
class vtkPolyData;

namespace cmp::bridge
{

/// \brief The local models of a collection with identical connectivity.
struct ConsistentCollection
{
  SurfaceCollection surfaces;               ///< The local surfaces, in order.
  std::vector<std::vector<Vec3>> positions; ///< Point positions of each local surface.
  std::vector<Triangle> triangles;          ///< The shared triangles (on every rank).
  int pointCount = 0;                       ///< Points per model (on every rank).
  int globalModelCount = 0;                 ///< Models over all ranks.
  int firstGlobalIndex = 0;                 ///< Global index of this rank's first model.
  std::vector<std::string> globalNames;     ///< Block name of every model (on every rank).
};

/// \brief Reads every leaf of `input` and checks, on this rank and across
///        ranks, that all have the same points count and the same triangles
///        (the collection was remeshed in one Semi-Regular Remesher run) and
///        finite coordinates. A rank may hold no models, as long as some
///        rank holds one; the triangles then come from the first rank that
///        does. Collective.
Status readConsistentCollection(vtkDataObject* input, Communicator& communicator, ConsistentCollection& out);

/// \brief Alignment choices shared by the filters' `Alignment` property:
///        0 none, 1 rigid, 2 rigid and equal volume, 3 rigid and unit
///        centroid size.
enum class CollectionAlignment
{
  None = 0,
  Rigid = 1,
  RigidEqualVolume = 2,
  RigidUnitCentroidSize = 3
};

/// \brief The local models aligned as `mode` says (copied as they are for
///        `None`); `details` receives the alignment's figures when not
///        null. Collective.
Status alignCollection(const ConsistentCollection& collection, CollectionAlignment mode, Communicator& communicator,
  ShapeList& aligned, ShapeAlignment* details = nullptr);

/// \brief Copies to `shape` what every remesh of a collection shares:
///        the point arrays of its correspondence (`FeatureId`,
///        `BaseTriangle`, `BaseCoordinates`, `VertexLevel`) and the cell
///        arrays of `model` (`PatchId`, `Level`, ...). Nothing if `model`
///        is null.
void copyCorrespondenceArrays(vtkPolyData* model, vtkPolyData* shape);

/// \brief A polydata with `points` and the collection's triangles.
vtkSmartPointer<vtkPolyData> toPolyData(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles);

} // namespace cmp::bridge
