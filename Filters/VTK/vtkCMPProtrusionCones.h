#pragma once
/// \file vtkCMPProtrusionCones.h
/// \brief VTK filter: finds the landmark-free protrusions (tails) a
///        collection shares and gives each a cone: a landmark at its tip on
///        every model that has it (missing on the others, for Missing
///        Landmark Placer) and a vertex of L0 (beyond the paper;
///        `cmp::addProtrusionCones()`).
///
/// Input: the collection (a multiblock of landmarked surfaces, `FeatureId`
/// and `FeatureCount`, as Missing Landmark Placer takes it; closed, or all
/// with holes, L0 then open). Output 0: the
/// same surfaces, their `FeatureId` and `FeatureCount` holding the cones
/// after the files' features (a model without the protrusion misses the
/// cone's feature), and field arrays `ProtrusionTips` and
/// `ProtrusionRoots` (every protrusion found, and the feature nearest to
/// each). Output 1: L0 built from model `BaseDomainModel` with the cones,
/// field array `ProtrusionConeRoots` (per cone, its root feature) and
/// `ProtrusionsWithoutCone` (root feature and model of each protrusion
/// left without a cone because the models disagree where it leaves the
/// body). Input 1 (optional): a given L0 (point array `FeatureId`, one
/// vertex per file feature); the cones then split its triangles, which it
/// otherwise keeps, and `BaseDomainModel` is not used. Fails (vtkErrorMacro, both outputs
/// empty) naming the model when a surface or its landmarks do not fit,
/// when the L0 model misses landmarks, when L0 cannot be built, or when
/// the given L0 is not a base domain of the files' features.

#include "CMPFiltersModule.h"

#include <vtkDataObjectAlgorithm.h>

class CMPFILTERS_EXPORT vtkCMPProtrusionCones : public vtkDataObjectAlgorithm
{
public:
  /// \brief Standard VTK factory.
  static vtkCMPProtrusionCones* New();
  vtkTypeMacro(vtkCMPProtrusionCones, vtkDataObjectAlgorithm);
  /// \brief Prints the properties.
  void PrintSelf(ostream& os, vtkIndent indent) override;
  /// \brief The model (its index among the input's surfaces) L0 is built
  ///        from (default 0; not used when input 1 gives L0); it must have
  ///        every landmark.
  vtkSetMacro(BaseDomainModel, int);
  /// \brief The model L0 is built from.
  vtkGetMacro(BaseDomainModel, int);
  /// \brief A cone where at least this many models have exactly one
  ///        protrusion nearest to the same landmark (default 2, at least 1).
  vtkSetMacro(LeastModels, int);
  /// \brief How many models must have a protrusion for it to get a cone.
  vtkGetMacro(LeastModels, int);
  /// \brief A protrusion's ball of radius 0.075 sqrt(area) (or 2 or 4
  ///        times that, `BallScales`) round its tip holds less than this
  ///        share of a flat disk's area (default 0.32; long thin tails 0.11
  ///        to 0.28, flanks 0.7 and more) and leaves the landmarks outside
  ///        it in one piece.
  vtkSetMacro(LargestBallShare, double);
  /// \brief The ball share below which a peak is a protrusion.
  vtkGetMacro(LargestBallShare, double);
  /// \brief Balls of 0.075 sqrt(area) times 1, 2, 4, ... are tried, this
  ///        many (default 3, 1 to 8; the larger ones up to half the tip's
  ///        depth): a tufted or clubbed tail is thin only against a larger
  ///        ball.
  vtkSetClampMacro(BallScales, int, 1, 8);
  /// \brief How many ball radii are tried.
  vtkGetMacro(BallScales, int);

protected:
  vtkCMPProtrusionCones();
  ~vtkCMPProtrusionCones() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCMPProtrusionCones(const vtkCMPProtrusionCones&) = delete;
  void operator=(const vtkCMPProtrusionCones&) = delete;
  int BaseDomainModel = 0;
  int LeastModels = 2;
  double LargestBallShare = 0.32;
  int BallScales = 3;
};
