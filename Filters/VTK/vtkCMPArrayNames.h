#pragma once
/// \file vtkCMPArrayNames.h
/// \brief The name of every point, cell, field and table array the filters
///        read or write, in one place (private header, not wrapped). The
///        Python package's `consistent_mesh.array_names` holds the same names for
///        `consistent-remesh`; a name changed here must change there too.
///
/// Arrays that carry a model through the pipeline (`FeatureId`,
/// `PatchId`, `BaseTriangle`, ...) end in `Array`; one-value field arrays
/// that report figures end in `Field`; columns of the PCA tables end in
/// `Column`.

namespace cmp::bridge
{

// Arrays that carry a model through the pipeline.

/// \brief Point array that marks landmark vertices (-1 or 0..F-1).
constexpr const char* kFeatureIdArray = "FeatureId";
/// \brief One-value field int array: how many features the surface's
///        landmark file has (F), so that `FeatureId` can leave some out,
///        even the last ones (features not placed on this model).
constexpr const char* kFeatureCountArray = "FeatureCount";
/// \brief Point array that marks the landmarks Missing Landmark Placer
///        placed (-1 elsewhere, the feature at a placed vertex).
constexpr const char* kPlacedFeatureIdArray = "PlacedFeatureId";
/// \brief Field int array: the features Missing Landmark Placer placed on
///        a surface.
constexpr const char* kPlacedFeaturesArray = "PlacedFeatures";
/// \brief Field double array: per placed feature, the median distance of
///        the points the sources carry it to, over sqrt(area).
constexpr const char* kPlacedFeatureSpreadArray = "PlacedFeatureSpread";
/// \brief Field double array: per placed feature, how far it climbed from
///        where the maps carried it to the tip its sources have it at, over
///        sqrt(area) (0: it did not climb).
constexpr const char* kPlacedFeatureClimbArray = "PlacedFeatureClimb";
/// \brief Field double arrays, with a base domain given to Missing Landmark
///        Placer: per placed feature that climbed, its model's map
///        distortion over that L0 with the feature at the tip and at the
///        vertex the maps gave (the less distorted one is kept; 0: not
///        judged; infinite: that model could not be mapped so).
constexpr const char* kPlacedFeatureTipDistortionArray = "PlacedFeatureTipDistortion";
constexpr const char* kPlacedFeatureMappedDistortionArray = "PlacedFeatureMappedDistortion";
/// \brief Field int array of the base domain Protrusion Cones builds: per
///        cone (features F, F + 1, ...), the feature whose landmark is its
///        root.
constexpr const char* kProtrusionConeRootsArray = "ProtrusionConeRoots";
/// \brief Field int array of that base domain, 2 components: per protrusion
///        the models share but got no cone because they disagree where it
///        leaves the body, its root feature and the first model (index in
///        the collection) whose tip lies in a base triangle that shares no
///        edge with the one the cone would have split.
constexpr const char* kProtrusionsWithoutConeArray = "ProtrusionsWithoutCone";
/// \brief Field int array: the tips of the landmark-free protrusions
///        Protrusion Cones found on a surface.
constexpr const char* kProtrusionTipsArray = "ProtrusionTips";
/// \brief Field int array: per tip of `ProtrusionTips`, the feature whose
///        landmark is nearest to it.
constexpr const char* kProtrusionRootsArray = "ProtrusionRoots";
/// \brief Field array mapping a file's point ids to welded ids.
constexpr const char* kFileToMeshPointArray = "FileToMeshPointId";
/// \brief One-value field string array naming the file a surface was read
///        from, without its folder (set by the surface reader).
constexpr const char* kSourceFileArray = "SourceFile";
/// \brief Cell array of per-corner texture coordinates (6 values).
constexpr const char* kCornerTCoordsArray = "CornerTCoords";
/// \brief Cell array holding the base triangle (patch) of each triangle.
constexpr const char* kPatchIdArray = "PatchId";
/// \brief Point array with each point's base triangle.
constexpr const char* kBaseTriangleArray = "BaseTriangle";
/// \brief Point array with each point's barycentric coordinates in it.
constexpr const char* kBaseCoordinatesArray = "BaseCoordinates";
/// \brief A remesh's point array: the level at which each vertex appears.
constexpr const char* kVertexLevelArray = "VertexLevel";
/// \brief A remesh's cell array: the quadrisection level of each triangle.
constexpr const char* kLevelArray = "Level";
/// \brief A remesh's cell array: 1 for a triangle facing against its surface.
constexpr const char* kFoldedArray = "Folded";
/// \brief A remesh's cell array: 1 for a triangle facing against the
///        surface nearest to its centroid (the centroid criterion).
constexpr const char* kCentroidFlippedArray = "CentroidFlipped";
/// \brief Point normals, as readers and the transfer name them.
constexpr const char* kNormalsArray = "Normals";
/// \brief Point texture coordinates.
constexpr const char* kTCoordsArray = "TCoords";
/// \brief Point colours with alpha (surface reader).
constexpr const char* kRGBAArray = "RGBA";
/// \brief Point or cell colours (surface reader).
constexpr const char* kRGBArray = "RGB";
/// \brief Attribute Transfer's point array: the target point each split
///        (seam) point was copied from.
constexpr const char* kUnsplitPointIdArray = "UnsplitPointId";
/// \brief Cell arrays of a net's curves: the base edge of each curve and
///        the features at its two ends.
constexpr const char* kBaseEdgeIdArray = "BaseEdgeId";
constexpr const char* kFeatureIdAArray = "FeatureIdA";
constexpr const char* kFeatureIdBArray = "FeatureIdB";

// Wavelet Detail Transfer's point and field arrays.

constexpr const char* kWaveletCoefficientsArray = "WaveletCoefficients";
constexpr const char* kCoarseModelCoefficientsArray = "CoarseModelCoefficients";
constexpr const char* kDetailModelCoefficientsArray = "DetailModelCoefficients";
constexpr const char* kDetailMagnitudeArray = "DetailMagnitude";
constexpr const char* kDetailWeightsArray = "DetailWeights";

// Mesh PCA: the mean's point arrays ("Mode0", "Mode1", ...), its field
// arrays and the columns of its coefficient and variance tables.

/// \brief Prefix of the mean's point array of mode k ("Mode" + k).
constexpr const char* kModeArrayPrefix = "Mode";
/// \brief Prefix of the coefficient table's column of mode k ("Coefficient" + k).
constexpr const char* kCoefficientColumnPrefix = "Coefficient";
constexpr const char* kModelColumn = "Model";
constexpr const char* kIndexColumn = "Index";
constexpr const char* kModeColumn = "Mode";
/// \brief The variance table's columns, also field arrays of the mean.
constexpr const char* kVarianceArray = "Variance";
constexpr const char* kStandardDeviationColumn = "StandardDeviation";
constexpr const char* kExplainedVarianceRatioArray = "ExplainedVarianceRatio";
constexpr const char* kCumulativeRatioColumn = "CumulativeRatio";
constexpr const char* kModelCountField = "ModelCount";
constexpr const char* kModeCountField = "ModeCount";
constexpr const char* kTotalVarianceField = "TotalVariance";
constexpr const char* kAlignmentIterationsField = "AlignmentIterations";
constexpr const char* kAlignmentConvergedField = "AlignmentConverged";
constexpr const char* kPCASecondsField = "PCASeconds";

// Report field arrays, by the filter that writes them (a name two filters
// write means the same in both).

/// \brief Check Inputs: "ok" when the inputs passed.
constexpr const char* kInputCheckField = "InputCheck";
/// \brief Surface Reader: points merged with an identical one.
constexpr const char* kWeldedPointCountField = "WeldedPointCount";

/// \brief Base Domain Builder and Semi-Regular Remesher: smallest corner
///        angle (degrees) and mean shape quality.
constexpr const char* kMinimumAngleField = "MinimumAngle";
constexpr const char* kMeanShapeQualityField = "MeanShapeQuality";
constexpr const char* kFoldingCollapsesField = "FoldingCollapses";

// Feature Net Tracer and Net Straightener.
constexpr const char* kNetLengthField = "NetLength";
constexpr const char* kNetLengthPerSqrtAreaField = "NetLengthPerSqrtArea";
constexpr const char* kNetValidField = "NetValid";
constexpr const char* kRetracedCurvesField = "RetracedCurves";
constexpr const char* kPenalisedCurvesField = "PenalisedCurves";
constexpr const char* kSplitEdgesField = "SplitEdges";
constexpr const char* kNetLengthBeforeField = "NetLengthBefore";
constexpr const char* kNetLengthAfterField = "NetLengthAfter";
constexpr const char* kStraightenedNetLengthField = "StraightenedNetLength";
constexpr const char* kNetLengthPerSqrtAreaAfterField = "NetLengthPerSqrtAreaAfter";
constexpr const char* kAreaVariationBeforeField = "AreaVariationBefore";
constexpr const char* kAreaVariationAfterField = "AreaVariationAfter";
constexpr const char* kSweepsField = "Sweeps";
constexpr const char* kSkippedStarsField = "SkippedStars";
/// \brief Net Straightener (parameterization) and Semi-Regular Remesher
///        (remesh, after repair): triangles facing the wrong way.
constexpr const char* kFlippedTrianglesField = "FlippedTriangles";
constexpr const char* kSmallestAreaRatioField = "SmallestAreaRatio";
constexpr const char* kWidestCurveGapField = "WidestCurveGap";
constexpr const char* kWidestCurveGapFeatureField = "WidestCurveGapFeature";
constexpr const char* kFreeCurvesAppliedField = "FreeCurvesApplied";
constexpr const char* kFreeCurvesReasonField = "FreeCurvesReason";
constexpr const char* kMapDistortionBeforeField = "MapDistortionBefore";
constexpr const char* kMapDistortionAfterField = "MapDistortionAfter";
constexpr const char* kMapIterationsField = "MapIterations";
constexpr const char* kMapCrossingVerticesField = "MapCrossingVertices";

// Semi-Regular Remesher.
constexpr const char* kRemeshLevelField = "RemeshLevel";
constexpr const char* kVertexCountField = "VertexCount";
constexpr const char* kTriangleCountField = "TriangleCount";
constexpr const char* kFoldedBeforeRepairField = "FoldedBeforeRepair";
/// \brief Triangles flipped by the centroid criterion (after repair).
constexpr const char* kCentroidFlipsField = "CentroidFlips";
/// \brief Per landmark (FeatureId order), the folded triangles nearest to it.
constexpr const char* kFoldsNearFeatureArray = "FoldsNearFeature";
constexpr const char* kRepairedVerticesField = "RepairedVertices";
constexpr const char* kSampleRelaxationRoundsField = "SampleRelaxationRounds";
/// \brief Adaptive remeshing: how many times the connectivity was made (0 uniform).
constexpr const char* kAdaptivePassesField = "AdaptivePasses";
constexpr const char* kSampleRelaxationSecondsField = "SampleRelaxationSeconds";
constexpr const char* kRebuildSecondsField = "RebuildSeconds";
constexpr const char* kPlacementSecondsField = "PlacementSeconds";
constexpr const char* kHausdorffDistanceField = "HausdorffDistance";
constexpr const char* kHausdorffDistanceRelativeField = "HausdorffDistanceRelative";
constexpr const char* kMeanDistanceField = "MeanDistance";
/// \brief One tuple of 3: where the Hausdorff distance is reached.
constexpr const char* kHausdorffPointField = "HausdorffPoint";
constexpr const char* kHausdorffPointOnInputField = "HausdorffPointOnInput";
constexpr const char* kHausdorffNearestFeatureField = "HausdorffNearestFeature";
constexpr const char* kHausdorffFeatureDistanceRelativeField = "HausdorffFeatureDistanceRelative";
constexpr const char* kDistanceSecondsField = "DistanceSeconds";
constexpr const char* kTotalSecondsField = "TotalSeconds";

// Attribute Transfer, Wavelet Detail Transfer and Shape Blend.
constexpr const char* kTransferredArraysField = "TransferredArrays";
constexpr const char* kSeamPointsAddedField = "SeamPointsAdded";
/// \brief Attribute Transfer and Wavelet Detail Transfer: the transfer's time.
constexpr const char* kTransferSecondsField = "TransferSeconds";
constexpr const char* kExtrapolatingField = "Extrapolating";
/// \brief Shape Blend's field array: the weights blended with.
constexpr const char* kWeightsArray = "Weights";

} // namespace cmp::bridge
