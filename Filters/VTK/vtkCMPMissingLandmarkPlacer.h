#pragma once
/// \file vtkCMPMissingLandmarkPlacer.h
/// \brief Places the landmarks some models of a collection miss where the
///        collection's maps carry them from the models that have them
///        (beyond the paper, whose future work lists missing feature points).

#include "CMPFiltersModule.h"

#include <vtkDataObjectAlgorithm.h>

/// \brief Completes the landmarks of a collection in which some models miss
///        some features, so that every model can then be traced, mapped and
///        remeshed over the full `L0` with the same connectivity.
///
/// Input: a vtkMultiBlockDataSet of landmarked surfaces (point array
/// `FeatureId`; a feature missing on a model is on none of its vertices,
/// as Landmarks From File leaves a `-1` of the file, and the field array
/// `FeatureCount` says how many features there are), or one such surface.
/// Output: the same structure, each surface with `FeatureId` complete and
/// the point array `PlacedFeatureId` (the feature at each vertex this filter
/// placed, -1 elsewhere, so that the placed points show in ParaView), and
/// field arrays `PlacedFeatures` (the features placed on that model) and
/// `PlacedFeatureSpread` (per placed feature, how far the sources' carried
/// points lie from it, over the square root of the surface's area).
///
/// Method (core `cmp::placeMissingLandmarks()`): the models that miss the
/// same features are mapped, with every model that has the others, over a
/// base domain built without those features from `BaseDomainModel`, the
/// collection is remeshed at `Level` with one connectivity, and each
/// missing feature is carried through the remeshes from every model that
/// has it; the geometric median of the carried points, projected onto the
/// model, gives the nearest vertex that carries no other feature. With the
/// optional second input, the base domain the collection will be mapped
/// over (L0, with FeatureId), a feature that climbed to a tip goes back to
/// where the maps carried it if its model's map over that L0 does not settle
/// with the climb (more than twice as distorted as without; field arrays
/// `PlacedFeatureTipDistortion` and `PlacedFeatureMappedDistortion`). Measured in
/// Documentation/filters/MissingLandmarkPlacer.md.
///
/// Fails with `vtkErrorMacro` and an empty output when an input is not a
/// closed genus-0 triangle surface with valid `FeatureId`, when a feature
/// is missing on every model, when no model has every feature (or
/// `BaseDomainModel` misses some), when fewer than 4 features would be
/// left, or when the reduced collection cannot be remeshed; a model that
/// misses features and cannot be mapped without them is a warning naming
/// it, and it keeps them missing.
class CMPFILTERS_EXPORT vtkCMPMissingLandmarkPlacer : public vtkDataObjectAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPMissingLandmarkPlacer* New();
  vtkTypeMacro(vtkCMPMissingLandmarkPlacer, vtkDataObjectAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;
  /// \brief The model (its index among the input's surfaces) the reduced
  ///        base domain is built from; -1 (default): the first model with
  ///        every feature.
  vtkSetMacro(BaseDomainModel, int);
  /// \brief The model the reduced base domain is built from (-1: first complete).
  vtkGetMacro(BaseDomainModel, int);
  /// \brief Level of the remesh the features are carried through (default
  ///        4, 1 to 8).
  vtkSetMacro(Level, int);
  /// \brief Level of the remesh the features are carried through.
  vtkGetMacro(Level, int);
  /// \brief The most models a missing feature is carried from, the likest
  ///        to its model by the shape of their common landmarks (default 8;
  ///        0: every model that has it). Bounds the work in a large
  ///        collection: each set of missing features maps its models and
  ///        their sources.
  vtkSetMacro(MaximumSources, int);
  /// \brief The most models a missing feature is carried from (0: all).
  vtkGetMacro(MaximumSources, int);
  /// \brief Whether a feature that the sources have at the tip of a
  ///        protrusion (a foot, a nose, a horn) climbs from where the maps
  ///        carry it to the tip near there (default on; the field array
  ///        `PlacedFeatureClimb` says how far).
  vtkSetMacro(ClimbToTips, bool);
  /// \brief Whether features at a tip on the sources climb to the tip.
  vtkGetMacro(ClimbToTips, bool);
  /// \brief Turns climbing to tips on.
  vtkBooleanMacro(ClimbToTips, bool);

protected:
  vtkCMPMissingLandmarkPlacer();
  ~vtkCMPMissingLandmarkPlacer() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPMissingLandmarkPlacer(const vtkCMPMissingLandmarkPlacer&) = delete;
  void operator=(const vtkCMPMissingLandmarkPlacer&) = delete;
  int BaseDomainModel = -1;
  int Level = 4;
  int MaximumSources = 8;
  bool ClimbToTips = true;
};
