"""The names of the arrays the filters read and write, for consistent-remesh:
the same names, in the same order, as Filters/VTK/vtkCMPArrayNames.h (the
C++ constant kFeatureIdArray is FEATURE_ID_ARRAY here; the test
python.ArrayNames checks that the two agree). Arrays that carry a model
through the pipeline end in _ARRAY, one-value report field arrays in _FIELD,
the PCA tables' columns in _COLUMN."""

# Arrays that carry a model through the pipeline.
FEATURE_ID_ARRAY = "FeatureId"
FEATURE_COUNT_ARRAY = "FeatureCount"
PLACED_FEATURE_ID_ARRAY = "PlacedFeatureId"
PLACED_FEATURES_ARRAY = "PlacedFeatures"
PLACED_FEATURE_SPREAD_ARRAY = "PlacedFeatureSpread"
PLACED_FEATURE_CLIMB_ARRAY = "PlacedFeatureClimb"
PLACED_FEATURE_TIP_DISTORTION_ARRAY = "PlacedFeatureTipDistortion"
PLACED_FEATURE_MAPPED_DISTORTION_ARRAY = "PlacedFeatureMappedDistortion"
PROTRUSION_CONE_ROOTS_ARRAY = "ProtrusionConeRoots"
PROTRUSIONS_WITHOUT_CONE_ARRAY = "ProtrusionsWithoutCone"
PROTRUSION_TIPS_ARRAY = "ProtrusionTips"
PROTRUSION_ROOTS_ARRAY = "ProtrusionRoots"
FILE_TO_MESH_POINT_ARRAY = "FileToMeshPointId"
SOURCE_FILE_ARRAY = "SourceFile"
CORNER_T_COORDS_ARRAY = "CornerTCoords"
PATCH_ID_ARRAY = "PatchId"
BASE_TRIANGLE_ARRAY = "BaseTriangle"
BASE_COORDINATES_ARRAY = "BaseCoordinates"
VERTEX_LEVEL_ARRAY = "VertexLevel"
LEVEL_ARRAY = "Level"
FOLDED_ARRAY = "Folded"
CENTROID_FLIPPED_ARRAY = "CentroidFlipped"
NORMALS_ARRAY = "Normals"
T_COORDS_ARRAY = "TCoords"
RGBA_ARRAY = "RGBA"
RGB_ARRAY = "RGB"
UNSPLIT_POINT_ID_ARRAY = "UnsplitPointId"
BASE_EDGE_ID_ARRAY = "BaseEdgeId"
FEATURE_ID_A_ARRAY = "FeatureIdA"
FEATURE_ID_B_ARRAY = "FeatureIdB"

# Wavelet Detail Transfer's point and field arrays.
WAVELET_COEFFICIENTS_ARRAY = "WaveletCoefficients"
COARSE_MODEL_COEFFICIENTS_ARRAY = "CoarseModelCoefficients"
DETAIL_MODEL_COEFFICIENTS_ARRAY = "DetailModelCoefficients"
DETAIL_MAGNITUDE_ARRAY = "DetailMagnitude"
DETAIL_WEIGHTS_ARRAY = "DetailWeights"

# Mesh PCA: the mean's point arrays ("Mode0", "Mode1", ...), its field
# arrays and the columns of its coefficient and variance tables.
MODE_ARRAY_PREFIX = "Mode"
COEFFICIENT_COLUMN_PREFIX = "Coefficient"
MODEL_COLUMN = "Model"
INDEX_COLUMN = "Index"
MODE_COLUMN = "Mode"
VARIANCE_ARRAY = "Variance"
STANDARD_DEVIATION_COLUMN = "StandardDeviation"
EXPLAINED_VARIANCE_RATIO_ARRAY = "ExplainedVarianceRatio"
CUMULATIVE_RATIO_COLUMN = "CumulativeRatio"
MODEL_COUNT_FIELD = "ModelCount"
MODE_COUNT_FIELD = "ModeCount"
TOTAL_VARIANCE_FIELD = "TotalVariance"
ALIGNMENT_ITERATIONS_FIELD = "AlignmentIterations"
ALIGNMENT_CONVERGED_FIELD = "AlignmentConverged"
PCA_SECONDS_FIELD = "PCASeconds"

# Report field arrays, by the filter that writes them (a name two filters
# write means the same in both).
INPUT_CHECK_FIELD = "InputCheck"
WELDED_POINT_COUNT_FIELD = "WeldedPointCount"
MINIMUM_ANGLE_FIELD = "MinimumAngle"
MEAN_SHAPE_QUALITY_FIELD = "MeanShapeQuality"
FOLDING_COLLAPSES_FIELD = "FoldingCollapses"

# Feature Net Tracer and Net Straightener.
NET_LENGTH_FIELD = "NetLength"
NET_LENGTH_PER_SQRT_AREA_FIELD = "NetLengthPerSqrtArea"
NET_VALID_FIELD = "NetValid"
RETRACED_CURVES_FIELD = "RetracedCurves"
PENALISED_CURVES_FIELD = "PenalisedCurves"
SPLIT_EDGES_FIELD = "SplitEdges"
NET_LENGTH_BEFORE_FIELD = "NetLengthBefore"
NET_LENGTH_AFTER_FIELD = "NetLengthAfter"
STRAIGHTENED_NET_LENGTH_FIELD = "StraightenedNetLength"
NET_LENGTH_PER_SQRT_AREA_AFTER_FIELD = "NetLengthPerSqrtAreaAfter"
AREA_VARIATION_BEFORE_FIELD = "AreaVariationBefore"
AREA_VARIATION_AFTER_FIELD = "AreaVariationAfter"
SWEEPS_FIELD = "Sweeps"
SKIPPED_STARS_FIELD = "SkippedStars"
FLIPPED_TRIANGLES_FIELD = "FlippedTriangles"
SMALLEST_AREA_RATIO_FIELD = "SmallestAreaRatio"
WIDEST_CURVE_GAP_FIELD = "WidestCurveGap"
WIDEST_CURVE_GAP_FEATURE_FIELD = "WidestCurveGapFeature"
FREE_CURVES_APPLIED_FIELD = "FreeCurvesApplied"
FREE_CURVES_REASON_FIELD = "FreeCurvesReason"
MAP_DISTORTION_BEFORE_FIELD = "MapDistortionBefore"
MAP_DISTORTION_AFTER_FIELD = "MapDistortionAfter"
MAP_ITERATIONS_FIELD = "MapIterations"
MAP_CROSSING_VERTICES_FIELD = "MapCrossingVertices"

# Semi-Regular Remesher.
REMESH_LEVEL_FIELD = "RemeshLevel"
VERTEX_COUNT_FIELD = "VertexCount"
TRIANGLE_COUNT_FIELD = "TriangleCount"
FOLDED_BEFORE_REPAIR_FIELD = "FoldedBeforeRepair"
CENTROID_FLIPS_FIELD = "CentroidFlips"
FOLDS_NEAR_FEATURE_ARRAY = "FoldsNearFeature"
REPAIRED_VERTICES_FIELD = "RepairedVertices"
SAMPLE_RELAXATION_ROUNDS_FIELD = "SampleRelaxationRounds"
ADAPTIVE_PASSES_FIELD = "AdaptivePasses"
SAMPLE_RELAXATION_SECONDS_FIELD = "SampleRelaxationSeconds"
REBUILD_SECONDS_FIELD = "RebuildSeconds"
PLACEMENT_SECONDS_FIELD = "PlacementSeconds"
HAUSDORFF_DISTANCE_FIELD = "HausdorffDistance"
HAUSDORFF_DISTANCE_RELATIVE_FIELD = "HausdorffDistanceRelative"
MEAN_DISTANCE_FIELD = "MeanDistance"
HAUSDORFF_POINT_FIELD = "HausdorffPoint"
HAUSDORFF_POINT_ON_INPUT_FIELD = "HausdorffPointOnInput"
HAUSDORFF_NEAREST_FEATURE_FIELD = "HausdorffNearestFeature"
HAUSDORFF_FEATURE_DISTANCE_RELATIVE_FIELD = "HausdorffFeatureDistanceRelative"
DISTANCE_SECONDS_FIELD = "DistanceSeconds"
TOTAL_SECONDS_FIELD = "TotalSeconds"

# Attribute Transfer, Wavelet Detail Transfer and Shape Blend.
TRANSFERRED_ARRAYS_FIELD = "TransferredArrays"
SEAM_POINTS_ADDED_FIELD = "SeamPointsAdded"
TRANSFER_SECONDS_FIELD = "TransferSeconds"
EXTRAPOLATING_FIELD = "Extrapolating"
WEIGHTS_ARRAY = "Weights"

# consistent-remesh's own: the PCA picture's per-point length of a mode.
DISPLACEMENT_ARRAY = "Displacement"

# The field arrays that hold how long a filter took: they differ from run to
# run, so consistent-remesh leaves them out of the files it writes (unless
# --timing-arrays) and puts its timings in timings.json instead.
TIMING_FIELDS = frozenset(value for name, value in list(globals().items())
                          if name.endswith("_SECONDS_FIELD"))
