#pragma once
/// \file vtkCMPSemiRegularRemesher.h
/// \brief Remeshes parameterized surfaces with one semi-regular connectivity:
///        the base domain refined by 1-to-4 quadrisection (paper Section 2).

#include "CMPFiltersModule.h"

#include <vtkDataObjectAlgorithm.h>
#include <vtkSmartPointer.h>

class vtkMultiBlockDataSet;
class vtkMultiProcessController;
class vtkPolyData;

/// \brief Remeshes every model of a collection with the same connectivity:
///        `L0` refined `Level` times by 1-to-4 quadrisection. Vertex k of
///        every remesh is the same base-domain location on every model
///        (up to the short moves of `RepairFolds`).
///
/// Input 0: the Surface output of vtkCMPNetStraightener (point arrays
/// `FeatureId`, `BaseTriangle`, `BaseCoordinates`, cell array `PatchId`),
/// or a vtkMultiBlockDataSet of such surfaces (each block remeshed against
/// the same `L0`; the output keeps the block structure and block names).
/// Input 1: the base domain `L0` the surfaces were parameterized over. The
/// parameterization is read from the input's arrays, never recomputed.
///
/// Output 0: per model a vtkPolyData (a multiblock for a multiblock input):
/// points on the model's surface, the shared triangles (identical for every
/// model). Point arrays: every input point array carried to the remesh
/// vertices (floating-point arrays interpolated with the weights of the
/// input triangle each vertex lies in, `Normals` renormalized; integer and
/// non-numeric arrays copied from the input point with the largest weight),
/// `FeatureId` (f at vertex f, -1 elsewhere), `BaseTriangle` and
/// `BaseCoordinates` of every remesh vertex. Cell arrays: `PatchId` (the
/// `L0` triangle of each triangle), `Level` and `Folded` (1 for a triangle
/// facing against the surface, the ones `FlippedTriangles` counts) and
/// `CentroidFlipped` (1 for a triangle facing against the surface nearest
/// to its centroid, `cmp::centroidFlippedTriangles()`, the ones
/// `CentroidFlips` counts). Field arrays: `RemeshLevel`,
/// `VertexCount`, `TriangleCount`, `FlippedTriangles` (after repair),
/// `FoldedBeforeRepair`, `CentroidFlips`, `FoldsNearFeature` (one count per landmark, in
/// `FeatureId` order: the folded triangles `FlippedTriangles` counts,
/// after repair when `RepairFolds` is on, nearest to it in remesh edges),
/// `RepairedVertices`, `MinimumAngle`,
/// `MeanShapeQuality`, `SampleRelaxationRounds`, timings (`RebuildSeconds`,
/// `SampleRelaxationSeconds`, `PlacementSeconds`, `TotalSeconds`) and, with ComputeDistance, the distances to the input
/// (`HausdorffDistance`, `HausdorffDistanceRelative`, `MeanDistance`,
/// `DistanceSeconds`).
/// Output 1: the connectivity once, drawn on `L0` (every vertex at its base
/// location), with point arrays `BaseTriangle`, `BaseCoordinates`,
/// `VertexLevel`, `FeatureId` and cell arrays `PatchId`, `Level`.
///
/// Paper §2 (quadrisection, "possibly adaptive"); sample relaxation, fold
/// repair and the distances are beyond the paper (core `cmp::remesh()`).
/// Fails with `vtkErrorMacro` and an empty output when a property is out of
/// range, `L0` is not connected or invalid, an input is not a parameterized
/// surface of that `L0` (checks of Check Inputs, missing or inconsistent
/// `BaseTriangle`, `BaseCoordinates` or `PatchId`, a layout not equivalent
/// to `L0`), or the remesh cannot be placed on a model; the message names
/// the block. With sample relaxation under MPI a rank that fails makes
/// every rank fail with its message. The messages are listed in
/// Documentation/filters/SemiRegularRemesher.md.
class CMPFILTERS_EXPORT vtkCMPSemiRegularRemesher : public vtkDataObjectAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPSemiRegularRemesher* New();
  vtkTypeMacro(vtkCMPSemiRegularRemesher, vtkDataObjectAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Connects the base domain `L0` to input port 1.
  void SetBaseDomainConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// \brief Number of 1-to-4 quadrisections of `L0` (default 4; must be in
  ///        0..8). Not clamped: a value out of range is reported when the
  ///        filter runs. A remesh has 2 + T·4^Level/2 vertices for T `L0`
  ///        triangles.
  vtkSetMacro(Level, int);
  /// \brief Number of 1-to-4 quadrisections of `L0`.
  vtkGetMacro(Level, int);

  /// \brief Adaptive refinement (default 0: uniform). With a value t > 0,
  ///        `Level` is the maximum level and a triangle is quadrisected
  ///        only while, on any model of the input, the surface at one of
  ///        the 12 points of its next two quadrisections is farther than t times that
  ///        model's bounding-box diagonal from the flat triangle. Neighbours
  ///        then differ by at most one level and T-junctions are closed by
  ///        bisection, so every model still shares one connectivity (give
  ///        the whole collection as one multiblock for that).
  vtkSetMacro(AdaptiveTolerance, double);
  /// \brief Adaptive refinement tolerance (0: uniform).
  vtkGetMacro(AdaptiveTolerance, double);

  /// \brief Rounds of sample relaxation (default 0: every vertex at its
  ///        quadrisection place). Each round moves every vertex but the
  ///        landmarks, within its `L0` triangle or along its `L0` edge,
  ///        towards the centroid of the surface area its triangles cover,
  ///        weighted by area density and summed over all models of the
  ///        input, so that samples gather where some model's
  ///        parameterization crowds (tails, ears). One set of base
  ///        locations for the whole collection: the connectivity and the
  ///        vertex correspondence stay shared, but the locations depend on
  ///        every model given, so remesh the whole collection in one run
  ///        (under MPI, every rank's models count, and the ranks must
  ///        remesh one connectivity: an adaptive remesh refined per rank is
  ///        refused). Where a model's map crowds a part without a landmark,
  ///        the remesh then reaches further into it (measured in
  ///        Documentation/filters/SemiRegularRemesher.md, "Sample
  ///        relaxation"). Negative values are reported when the filter runs.
  vtkSetMacro(SampleRelaxationIterations, int);
  /// \brief Rounds of sample relaxation (0: none).
  vtkGetMacro(SampleRelaxationIterations, int);

  /// \brief The processes that share the collection for sample relaxation
  ///        (default: the global controller; a vtkDummyController makes this
  ///        process work alone). Not used while SampleRelaxationIterations
  ///        is 0.
  void SetController(vtkMultiProcessController* controller);
  /// \brief The processes that share the collection.
  vtkMultiProcessController* GetController();

  /// \brief Measure how far each remesh is from its input (default on):
  ///        field arrays `HausdorffDistance`, `HausdorffDistanceRelative`
  ///        (divided by the input's bounding-box diagonal), `MeanDistance`
  ///        and `DistanceSeconds`. Sampled, both ways; usually the
  ///        costliest part of the filter (times in
  ///        Documentation/filters/SemiRegularRemesher.md, "Measured").
  vtkSetMacro(ComputeDistance, bool);
  /// \brief Measure how far each remesh is from its input.
  vtkGetMacro(ComputeDistance, bool);
  /// \brief Measure how far each remesh is from its input.
  vtkBooleanMacro(ComputeDistance, bool);

  /// \brief Unfold remesh triangles that face against their surface
  ///        (default on). A thin triangle on a curved part can tip over
  ///        even though the parameterization is bijective; the vertices of
  ///        such triangles are slid along the surface (with their
  ///        neighbours, then alone), never more than two median edges (half of
  ///        one where that suffices), until their triangles agree with the
  ///        surface or no short move helps; then the corners of triangles
  ///        flipped by the centroid criterion (`CentroidFlips`) try short
  ///        moves that fold nothing more. Landmarks never move. A moved
  ///        vertex is no longer exactly at its `BaseCoordinates` on that
  ///        model; turn off to keep every vertex exactly there.
  vtkSetMacro(RepairFolds, bool);
  /// \brief Unfold remesh triangles that face against their surface.
  vtkGetMacro(RepairFolds, bool);
  /// \brief Unfold remesh triangles that face against their surface.
  vtkBooleanMacro(RepairFolds, bool);

protected:
  vtkCMPSemiRegularRemesher();
  ~vtkCMPSemiRegularRemesher() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPSemiRegularRemesher(const vtkCMPSemiRegularRemesher&) = delete;
  void operator=(const vtkCMPSemiRegularRemesher&) = delete;

  int Level = 4;
  double AdaptiveTolerance = 0.0;
  bool ComputeDistance = true;
  bool RepairFolds = true;
  int SampleRelaxationIterations = 0;
  vtkSmartPointer<vtkMultiProcessController> Controller;
};
