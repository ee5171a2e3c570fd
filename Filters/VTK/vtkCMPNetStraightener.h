#pragma once
/// \file vtkCMPNetStraightener.h
/// \brief Straightens a traced patch layout and maps every patch onto its
///        base triangle (paper Section 2.2, "Edge Straightening").

#include "CMPFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

/// \brief Replaces the curves of a traced net by straight lines of planar
///        maps of the landmarks' stars (the paper's edge straightening), then
///        parameterizes every patch over its base triangle.
///
/// Input 0: the Surface output of vtkCMPFeatureNetTracer (cell array
/// `PatchId`, point array `FeatureId`), or a multiblock of such surfaces
/// (straightened block by block against the same `L0`). Input 1: the base
/// domain `L0` the net was traced against.
///
/// Output 0: the surface re-triangulated along the straightened curves (the
/// geometry does not change: new points lie on the input triangles). Every
/// input point array is interpolated at the new points from the input
/// vertices around them; `FeatureId` is rewritten (-1 except at the
/// landmarks, never interpolated); every input cell array is copied from the
/// input triangle each new triangle lies in (`CornerTCoords` is interpolated
/// at the new corners instead); `PatchId` holds the new patches. New point
/// arrays: `BaseTriangle` (the `L0` triangle a point is expressed in) and
/// `BaseCoordinates` (its barycentric coordinates there, in the order of
/// that `L0` cell's points). Field arrays: `NetLengthBefore`,
/// `NetLengthAfter`, `NetLengthPerSqrtAreaAfter`, `AreaVariationBefore`,
/// `AreaVariationAfter`, `Sweeps`, `SkippedStars`, `FlippedTriangles`,
/// `SmallestAreaRatio` (over all triangles, the share of its base
/// triangle's area a triangle's image takes divided by its share of its
/// patch's surface area: 1 for an area-preserving map, tiny where a part
/// without landmarks is crushed), `WidestCurveGap` and
/// `WidestCurveGapFeature` (the largest angle, in degrees, between two
/// consecutive curves leaving a landmark, and that landmark: far above
/// 360 / valence the curves leave bunched and a remesh often folds there;
/// see CurveSpread.h) and `NetValid` (1 when the independent layout check
/// passes on the result).
/// Output 1: the net as polylines, one per `L0` edge, with cell arrays
/// `BaseEdgeId`, `FeatureIdA` and `FeatureIdB`, and the same field arrays.
///
/// Paper §2.2 ("Edge Straightening") and the per-patch maps of §2;
/// `LowerStretch` and `FreeCurves` are beyond the paper. Fails with
/// `vtkErrorMacro` and no output when `L0` is not connected, a property is
/// out of range, the surface, its landmarks or `L0` fail the checks of
/// Check Inputs, `PatchId` is missing or its layout is not equivalent to
/// `L0`, or the straightening or a patch's map cannot be solved; warns (the
/// output is still made) when the curves could not be freed, the result
/// fails the layout check or a triangle's image is flipped. The messages
/// are listed in Documentation/filters/NetStraightener.md.
class CMPFILTERS_EXPORT vtkCMPNetStraightener : public vtkPolyDataAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPNetStraightener* New();
  vtkTypeMacro(vtkCMPNetStraightener, vtkPolyDataAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// \brief Connects the base domain `L0` to input port 1.
  void SetBaseDomainConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// \brief At most this many sweeps over all landmarks (default 5; 0 only
  ///        splits edges so every patch can be parameterized). Not clamped:
  ///        a negative value is reported when the filter runs.
  vtkSetMacro(MaximumSweeps, int);
  /// \brief At most this many sweeps over all landmarks.
  vtkGetMacro(MaximumSweeps, int);

  /// \brief Stop sweeping when a sweep changes the total net length by less
  ///        than this fraction (default 0.002; must be >= 0).
  vtkSetMacro(Tolerance, double);
  /// \brief Relative net length change below which sweeping stops.
  vtkGetMacro(Tolerance, double);

  /// \brief A straight curve that crosses a mesh edge within this fraction
  ///        of the edge's length from a vertex goes through that vertex, so
  ///        no sliver triangles are cut (default 0.1; must be in [0, 0.5)).
  vtkSetMacro(SnapTolerance, double);
  /// \brief Fraction of an edge's length within which curves snap to vertices.
  vtkGetMacro(SnapTolerance, double);

  /// \brief Relax every patch's map towards an isometry (default off):
  ///        parts of the surface that carry no landmark (ears, horns, tails)
  ///        get more of the base domain, so a uniform remesh reaches further
  ///        into them, at several times the parameterization's cost
  ///        (Documentation/filters/NetStraightener.md, "Speed").
  ///        Off, only patches where such a part is crushed to almost no area
  ///        are spread.
  vtkSetMacro(LowerStretch, bool);
  /// \brief Lower the stretch of every patch's map.
  vtkGetMacro(LowerStretch, bool);
  /// \brief Lower the stretch of every patch's map.
  vtkBooleanMacro(LowerStretch, bool);

  /// \brief Move the curves where one low-distortion map of the whole
  ///        surface onto L0 puts its edges (default on; `cmp::freeCurves()`):
  ///        after straightening, every vertex but the landmarks may cross the
  ///        curves to lower the map's symmetric Dirichlet energy against
  ///        equilateral base triangles of equal area (one seamless map of the
  ///        whole surface, Newton steps that never fold a triangle), then the
  ///        surface is cut exactly along the map's preimages of L0's edges,
  ///        so that the remesher samples the map itself. Should the cut not
  ///        give an equivalent layout, the straightened net is kept with a
  ///        warning. Off, the paper's fixed straightened curves and per-patch
  ///        maps. Field arrays `FreeCurvesApplied`, `MapDistortionBefore`,
  ///        `MapDistortionAfter`, `MapIterations`, `MapCrossingVertices`.
  ///        Measured figures are in Documentation/filters/NetStraightener.md.
  vtkSetMacro(FreeCurves, bool);
  /// \brief Move the curves where one map of the whole surface puts them.
  vtkGetMacro(FreeCurves, bool);
  /// \brief Move the curves where one map of the whole surface puts them.
  vtkBooleanMacro(FreeCurves, bool);

  /// \brief Newton steps of the whole-surface map at most (default 100;
  ///        >= 0), with FreeCurves.
  vtkSetMacro(MapIterations, int);
  /// \brief Newton steps of the whole-surface map at most.
  vtkGetMacro(MapIterations, int);

  /// \brief With FreeCurves, the most triangles the traced surface may have
  ///        for its curves to be freed (default 150000; 0: no limit). The
  ///        whole-surface map's time grows faster than the surface (times
  ///        in Documentation/filters/NetStraightener.md): above the limit the
  ///        straightened curves are kept, with a warning and the reason in
  ///        Field Data FreeCurvesReason.
  vtkSetMacro(FreeCurvesMaximumTriangles, int);
  /// \brief The most triangles for FreeCurves (0: no limit).
  vtkGetMacro(FreeCurvesMaximumTriangles, int);

protected:
  vtkCMPNetStraightener();
  ~vtkCMPNetStraightener() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPNetStraightener(const vtkCMPNetStraightener&) = delete;
  void operator=(const vtkCMPNetStraightener&) = delete;

  int MaximumSweeps = 5;
  double Tolerance = 0.002;
  double SnapTolerance = 0.1;
  bool LowerStretch = false;
  bool FreeCurves = true;
  int MapIterations = 100;
  int FreeCurvesMaximumTriangles = 150000;
};
