"""The stages of consistent-remesh on its VTK filters: per model read,
landmarks, check, base domain, trace and straighten; then the remeshing of
the whole collection, and on its remeshes the transfer of attributes or
details, principal components and blends. Each writes its outputs into the
output folder and gives the figures of the report; a stage that fails
raises StageError."""

import os
import time

import numpy

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_INT, vtkIntArray
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet, vtkPolyData
from vtkmodules.vtkFiltersTexture import vtkTextureMapToCylinder
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from . import CMPFilters as cmp
from . import array_names
from .isolation import polydata_to_text
from .figures import field_reader, folds_near_landmark, landmark_count, significant, table_column
from .summary import weights_text
from .vtkio import StageError, run, write_multiblock, write_polydata, write_table


BLEND_GRID_STEPS = 4
PCA_ALIGNMENT = "rigid, equal volume"  # vtkCMPMeshPCA's default, the paper's choice
# --blend-alignment: vtkCMPShapeBlend's Alignment values and their names in
# the report. Rigid, the default, blends sizes too; equal volume suits
# collections of very different sizes (a 15-unit triceratops, a 1-unit camel).
BLEND_ALIGNMENTS = {"none": (0, "none"), "rigid": (1, "rigid"), "equal-volume": (2, "rigid, equal volume"),
                    "unit-size": (3, "rigid, unit centroid size")}


class Model:
    """One input surface, its landmark file, and what happened to it."""

    def __init__(self, mesh_path, landmark_path):
        self.mesh_path = mesh_path
        self.landmark_path = landmark_path
        self.name = os.path.splitext(os.path.basename(mesh_path))[0]
        self.surface = None
        self.parameterized = None  # NetStraightener's surface, the remesher's input
        self.curves = None  # the last net filter's curves
        # Features this model's landmark file marks missing, once read, and
        # where the collection placed them ({feature: vertex}).
        self.missing = []
        self.placed = {}
        # The protrusion cones' tip vertices after the file's features (-1:
        # missing here), once the collection gave it some.
        self.cones = []
        self.report = {"mesh": mesh_path, "landmarks": landmark_path, "seconds": {}}

    def without_own_name(self, message):
        """`message` without the "NAME.off: " the filters put before their
        messages about a surface read from a file: wherever the tool shows a
        model's error, the model's name is already beside it."""
        prefix = os.path.basename(self.mesh_path) + ": "
        return message[len(prefix):] if message.startswith(prefix) else message

    def timed(self, stage, function, *args):
        start = time.perf_counter()
        try:
            return function(*args)
        finally:
            self.report["seconds"][stage] = round(time.perf_counter() - start, 4)

    def fail(self, error):
        self.report["status"] = "failed"
        self.report["error"] = self.without_own_name(str(error))
        self.surface = None
        self.parameterized = None


def read_landmarked_surface(model):
    reader = cmp.vtkCMPSurfaceReader()
    reader.SetFileName(model.mesh_path)
    surface = model.timed("read", run, reader)
    model.report["vertices"] = surface.GetNumberOfPoints()
    model.report["triangles"] = surface.GetNumberOfCells()
    landmarks = cmp.vtkCMPLandmarksFromFile()
    landmarks.SetInputData(surface)
    landmarks.SetLandmarkFile(model.landmark_path)
    surface = model.timed("landmarks", run, landmarks)
    check = cmp.vtkCMPInputCheck()
    check.SetInputData(surface)
    check.RequireLandmarksOn()
    check.AllowMissingLandmarksOn()
    model.surface = model.timed("check", run, check)
    model.report["landmark_count"] = landmark_count(model.surface)
    model.missing = missing_features(model.surface)
    if model.cones:
        model.missing = model.missing + apply_cone_landmarks(model, model.cones)
    if model.missing:
        model.report["missing_landmarks"] = model.missing
    if model.placed:
        apply_placed_landmarks(model, model.placed)


def missing_features(surface):
    """The features of `surface` that no vertex carries, below its field
    array FeatureCount (the features its landmark file has)."""
    count = surface.GetFieldData().GetArray(array_names.FEATURE_COUNT_ARRAY)
    ids = surface.GetPointData().GetArray(array_names.FEATURE_ID_ARRAY)
    if count is None or ids is None:
        return []
    present = set(numpy.unique(vtk_to_numpy(ids)).tolist())
    return [f for f in range(int(count.GetTuple1(0))) if f not in present]


def collection_blocks(models):
    """The surfaces of `models` as a multiblock, one block per model, named
    after it: the input of the filters that take a whole collection."""
    blocks = vtkMultiBlockDataSet()
    for index, model in enumerate(models):
        blocks.SetBlock(index, model.surface)
        blocks.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), model.name)
    return blocks


def place_missing_landmarks(models, base_domain_model, domain=None):
    """Missing Landmark Placer on the surfaces of `models` (a multiblock, one
    block per model), with `domain` (the L0 they will be mapped over, or
    None) to judge the climbs to tips by: for each model, the list of what
    was placed on it, {"feature", "vertex", "position",
    "spread_per_sqrt_area", "climbed_per_sqrt_area"} and, for a judged
    climb, "tip_distortion" and "mapped_distortion" (its model's map
    distortion over `domain` with and without the climb; None: it could not
    be mapped so) and "climb_undone", and the message of a model whose
    features could not be placed (None if they were). Raises StageError if
    the filter fails."""
    placer = cmp.vtkCMPMissingLandmarkPlacer()
    placer.SetInputData(collection_blocks(models))
    if domain is not None:
        placer.SetInputData(1, domain)
    placer.SetBaseDomainModel(base_domain_model)
    placed = run(placer)
    results = []
    for index, model in enumerate(models):
        surface = placed.GetBlock(index)
        marks = surface.GetPointData().GetArray(array_names.PLACED_FEATURE_ID_ARRAY)
        spreads = surface.GetFieldData().GetArray(array_names.PLACED_FEATURE_SPREAD_ARRAY)
        features = surface.GetFieldData().GetArray(array_names.PLACED_FEATURES_ARRAY)
        climbs = surface.GetFieldData().GetArray(array_names.PLACED_FEATURE_CLIMB_ARRAY)
        spread_of = {int(features.GetTuple1(i)): spreads.GetTuple1(i) for i in range(features.GetNumberOfTuples())}
        climb_of = {int(features.GetTuple1(i)): climbs.GetTuple1(i) for i in range(features.GetNumberOfTuples())}
        judged = {}
        tips = surface.GetFieldData().GetArray(array_names.PLACED_FEATURE_TIP_DISTORTION_ARRAY)
        mapped = surface.GetFieldData().GetArray(array_names.PLACED_FEATURE_MAPPED_DISTORTION_ARRAY)
        for i in range(features.GetNumberOfTuples() if tips and mapped else 0):
            tip, at_mapped = tips.GetTuple1(i), mapped.GetTuple1(i)
            if tip != 0.0 or at_mapped != 0.0:
                judged[int(features.GetTuple1(i))] = (tip, at_mapped)
        entries = []
        for vertex in numpy.flatnonzero(vtk_to_numpy(marks) >= 0).tolist():
            feature = int(marks.GetTuple1(vertex))
            entry = {"feature": feature, "vertex": vertex,
                     "position": [significant(x) for x in surface.GetPoint(vertex)],
                     "spread_per_sqrt_area": significant(spread_of[feature]),
                     "climbed_per_sqrt_area": significant(climb_of[feature])}
            if feature in judged:
                tip, at_mapped = judged[feature]
                entry["tip_distortion"] = significant(tip) if numpy.isfinite(tip) else None
                entry["mapped_distortion"] = significant(at_mapped) if numpy.isfinite(at_mapped) else None
                entry["climb_undone"] = bool(climb_of[feature] == 0.0)
            entries.append(entry)
        entries.sort(key=lambda entry: entry["feature"])
        left = [f for f in model.missing if f not in {entry["feature"] for entry in entries}]
        results.append((entries, "feature%s %s could not be placed" % ("" if len(left) == 1 else "s",
                                                                      ", ".join(map(str, left))) if left else None))
    return results


def is_closed(surface):
    """Whether every edge of the triangles of `surface` joins exactly two
    of them."""
    cells = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    edges = numpy.sort(numpy.concatenate([cells[:, [0, 1]], cells[:, [1, 2]], cells[:, [2, 0]]]), axis=1)
    _, counts = numpy.unique(edges, axis=0, return_counts=True)
    return bool(len(counts)) and bool(numpy.all(counts == 2))


def find_protrusion_cones(models, base_domain_model, base_domain=None):
    """Protrusion Cones on the surfaces of `models` (a multiblock, one block
    per model), L0 from model `base_domain_model`, or the given L0
    `base_domain` (a polydata; its triangles are split): (first, roots, tips,
    found, domain, without): first the files' feature count F, roots the
    feature nearest to each cone's tip (cone i is feature F + i), tips per
    model the cones' tip vertices (-1 where the model has none), found per
    model every protrusion as [vertex, nearest feature], domain L0 with the
    cones as text (isolation.polydata_to_text), and without the protrusions
    left without a cone as [root feature, position of the model whose tip
    lies apart from the others'].
    Raises StageError if the filter fails."""
    cones = cmp.vtkCMPProtrusionCones()
    cones.SetInputData(collection_blocks(models))
    cones.SetBaseDomainModel(base_domain_model)
    if base_domain is not None:
        cones.SetInputData(1, base_domain)
    surfaces = run(cones)
    domain = cones.GetOutputDataObject(1)
    roots_array = domain.GetFieldData().GetArray(array_names.PROTRUSION_CONE_ROOTS_ARRAY)
    roots = [int(roots_array.GetTuple1(i)) for i in range(roots_array.GetNumberOfTuples())]
    tips, found, first = [], [], 0
    for index in range(len(models)):
        surface = surfaces.GetBlock(index)
        ids = vtk_to_numpy(surface.GetPointData().GetArray(array_names.FEATURE_ID_ARRAY))
        count = int(surface.GetFieldData().GetArray(array_names.FEATURE_COUNT_ARRAY).GetTuple1(0))
        first = count - len(roots)
        tips.append([int(numpy.flatnonzero(ids == first + i)[0]) if numpy.any(ids == first + i) else -1
                     for i in range(len(roots))])
        field = surface.GetFieldData()
        vertices = field.GetArray(array_names.PROTRUSION_TIPS_ARRAY)
        nearest = field.GetArray(array_names.PROTRUSION_ROOTS_ARRAY)
        found.append([[int(vertices.GetTuple1(i)), int(nearest.GetTuple1(i))]
                      for i in range(vertices.GetNumberOfTuples())])
    apart = domain.GetFieldData().GetArray(array_names.PROTRUSIONS_WITHOUT_CONE_ARRAY)
    without = [[int(apart.GetComponent(i, 0)), int(apart.GetComponent(i, 1))]
               for i in range(apart.GetNumberOfTuples())] if apart is not None else []
    return first, roots, tips, found, polydata_to_text(domain), without


def apply_cone_landmarks(model, tips):
    """Gives `model`'s surface the cones after its file's features: feature
    F + i at vertex tips[i], or missing where it is -1 (FeatureCount grows
    by the cones either way); returns the cones' missing features."""
    field = model.surface.GetFieldData()
    first = int(field.GetArray(array_names.FEATURE_COUNT_ARRAY).GetTuple1(0))
    counted = vtkIntArray()
    counted.SetName(array_names.FEATURE_COUNT_ARRAY)
    counted.InsertNextValue(first + len(tips))
    field.AddArray(counted)
    apply_placed_landmarks(model, {first + i: vertex for i, vertex in enumerate(tips) if vertex >= 0})
    return [first + i for i, vertex in enumerate(tips) if vertex < 0]


def mark_placed_landmarks(remesh, placed):
    """Adds the point array PlacedFeatureId to a remesh: f at the vertex of
    each placed feature f (its FeatureId), -1 elsewhere, so that the
    landmarks the collection placed show in ParaView."""
    ids = vtk_to_numpy(remesh.GetPointData().GetArray(array_names.FEATURE_ID_ARRAY))
    values = numpy.where(numpy.isin(ids, list(placed)), ids, -1).astype(numpy.int32)
    marks = numpy_to_vtk(values, deep=True, array_type=VTK_INT)
    marks.SetName(array_names.PLACED_FEATURE_ID_ARRAY)
    remesh.GetPointData().AddArray(marks)


def apply_placed_landmarks(model, placed):
    """Marks the placed features ({feature: vertex}) in the FeatureId of
    `model`'s surface; the model then has every feature."""
    ids = model.surface.GetPointData().GetArray(array_names.FEATURE_ID_ARRAY)
    marked = vtkIntArray()
    marked.DeepCopy(ids)
    marked.SetName(array_names.FEATURE_ID_ARRAY)
    for feature, vertex in placed.items():
        marked.SetValue(int(vertex), int(feature))
    model.surface.GetPointData().AddArray(marked)
    model.report["landmark_count"] = landmark_count(model.surface)


def load_base_domain(path):
    """A .vtp base domain carries FeatureId; in any other surface format
    vertex i stands for landmark i."""
    if path.lower().endswith(".vtp"):
        reader = vtkXMLPolyDataReader()
    else:
        reader = cmp.vtkCMPSurfaceReader()
    reader.SetFileName(path)
    domain = run(reader)
    if domain.GetNumberOfPoints() == 0:
        raise StageError("cannot read a base domain from '%s'" % path)
    if domain.GetPointData().GetArray(array_names.FEATURE_ID_ARRAY) is None:
        ids = vtkIntArray()
        ids.SetName(array_names.FEATURE_ID_ARRAY)
        for i in range(domain.GetNumberOfPoints()):
            ids.InsertNextValue(i)
        domain.GetPointData().AddArray(ids)
    return domain


def build_base_domain(model):
    builder = cmp.vtkCMPBaseDomainBuilder()
    builder.SetInputData(model.surface)
    return model.timed("base_domain", run, builder)


def check_against_base_domain(model, domain):
    check = cmp.vtkCMPInputCheck()
    check.SetInputData(0, model.surface)
    check.SetInputData(1, domain)
    model.timed("base_domain_check", run, check)


def _run_net_filter(model, stage, algorithm, surface, domain, output_folder, surface_suffix, curves_suffix):
    """Runs a (surface, L0) -> (surface, curves) filter as `stage`, writes
    both outputs as NAME.<suffix>.vtp and returns the output surface and a
    reader of its field values."""
    algorithm.SetInputData(0, surface)
    algorithm.SetInputData(1, domain)
    result = model.timed(stage, run, algorithm)
    write_polydata(result, os.path.join(output_folder, model.name + surface_suffix))
    model.curves = algorithm.GetOutputDataObject(1)
    write_polydata(model.curves, os.path.join(output_folder, model.name + curves_suffix))
    return result, field_reader(result)


def trace_net(model, domain, output_folder):
    """FeatureNetTracer: writes NAME.net.vtp (the refined surface with
    PatchId) and NAME.curves.vtp (one polyline per base-domain edge)."""
    surface, value = _run_net_filter(model, "trace", cmp.vtkCMPFeatureNetTracer(), model.surface, domain,
                                     output_folder, ".net.vtp", ".curves.vtp")
    model.report["net"] = {
        "length": round(value(array_names.NET_LENGTH_FIELD), 6),
        "length_per_sqrt_area": round(value(array_names.NET_LENGTH_PER_SQRT_AREA_FIELD), 4),
        "valid": bool(value(array_names.NET_VALID_FIELD)),
        "retraced_curves": int(value(array_names.RETRACED_CURVES_FIELD)),
        "penalised_curves": int(value(array_names.PENALISED_CURVES_FIELD)),
        "split_edges": int(value(array_names.SPLIT_EDGES_FIELD)),
        "vertices": surface.GetNumberOfPoints(),
    }
    if not model.report["net"]["valid"]:
        raise StageError("the traced net failed the layout check")
    return surface


def straighten_net(model, domain, traced, output_folder, lower_stretch=False, free_curves=True,
                   free_curves_maximum_triangles=None):
    """NetStraightener on the tracer's surface: writes NAME.param.vtp (the
    re-triangulated surface with PatchId, BaseTriangle and BaseCoordinates)
    and NAME.straight-curves.vtp (the straightened curves). With
    lower_stretch, every patch's map is made less stretched (the filter's
    LowerStretch); with free_curves, the curves move where one map of the
    whole surface puts them (FreeCurves), on surfaces of at most
    free_curves_maximum_triangles triangles (None: the filter's default;
    FreeCurvesMaximumTriangles)."""
    straightener = cmp.vtkCMPNetStraightener()
    straightener.SetLowerStretch(lower_stretch)
    straightener.SetFreeCurves(free_curves)
    if free_curves_maximum_triangles is not None:
        straightener.SetFreeCurvesMaximumTriangles(free_curves_maximum_triangles)
    surface, value = _run_net_filter(model, "straighten", straightener, traced, domain,
                                     output_folder, ".param.vtp", ".straight-curves.vtp")
    model.report["straighten"] = {
        "net_length_before": round(value(array_names.NET_LENGTH_BEFORE_FIELD), 6),
        "net_length_after": round(value(array_names.NET_LENGTH_AFTER_FIELD), 6),
        "straightened_net_length": round(value(array_names.STRAIGHTENED_NET_LENGTH_FIELD), 6),
        "net_length_per_sqrt_area_after": round(value(array_names.NET_LENGTH_PER_SQRT_AREA_AFTER_FIELD), 4),
        "area_variation_before": round(value(array_names.AREA_VARIATION_BEFORE_FIELD), 6),
        "area_variation_after": round(value(array_names.AREA_VARIATION_AFTER_FIELD), 6),
        "sweeps": int(value(array_names.SWEEPS_FIELD)),
        "skipped_stars": int(value(array_names.SKIPPED_STARS_FIELD)),
        # Not a failure: the parameterization is still written, and the
        # count says where it is not bijective.
        "flipped_triangles": int(value(array_names.FLIPPED_TRIANGLES_FIELD)),
        "smallest_area_ratio": significant(value(array_names.SMALLEST_AREA_RATIO_FIELD), 4),
        # Above about 250 degrees the curves leave that landmark bunched and
        # the remesh often keeps folds there.
        "widest_curve_gap_degrees": round(value(array_names.WIDEST_CURVE_GAP_FIELD), 1),
        "widest_curve_gap_landmark": int(value(array_names.WIDEST_CURVE_GAP_FEATURE_FIELD)),
        "net_valid": bool(value(array_names.NET_VALID_FIELD)),
        "vertices": surface.GetNumberOfPoints(),
        "lower_stretch": bool(lower_stretch),
        "free_curves": bool(free_curves),
    }
    if free_curves:
        model.report["straighten"]["map"] = {
            "applied": bool(value(array_names.FREE_CURVES_APPLIED_FIELD)),
            "distortion_before": significant(value(array_names.MAP_DISTORTION_BEFORE_FIELD), 4),
            "distortion_after": significant(value(array_names.MAP_DISTORTION_AFTER_FIELD), 4),
            "iterations": int(value(array_names.MAP_ITERATIONS_FIELD)),
            "crossing_vertices": int(value(array_names.MAP_CROSSING_VERTICES_FIELD)),
        }
        if not model.report["straighten"]["map"]["applied"]:
            reason = surface.GetFieldData().GetAbstractArray(array_names.FREE_CURVES_REASON_FIELD)
            model.report["straighten"]["map"]["reason"] = reason.GetValue(0) if reason is not None else ""
    if not model.report["straighten"]["net_valid"]:
        raise StageError("the straightened net failed the layout check")
    model.parameterized = surface


def remesh_collection(models, domain, level, adaptive_tolerance, output_folder, repair_folds=True,
                      sample_relaxation=0):
    """SemiRegularRemesher on every straightened model at once (a multiblock
    with one block per model, named after it), so that they all get the same
    connectivity and base locations, adaptive refinement and sample
    relaxation included; repair_folds is the filter's RepairFolds and
    sample_relaxation its SampleRelaxationIterations. Writes NAME.remesh.vtp per
    model, collection.vtm (all of them) and remesh_connectivity.vtp (the
    connectivity on L0); fills each model's "remesh" figures and returns the
    collection's (size, time). Raises StageError if the filter fails or a
    file cannot be written."""
    blocks = vtkMultiBlockDataSet()
    for index, model in enumerate(models):
        blocks.SetBlock(index, model.parameterized)
        blocks.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), model.name)
    remesher = cmp.vtkCMPSemiRegularRemesher()
    remesher.SetInputData(0, blocks)
    remesher.SetInputData(1, domain)
    remesher.SetLevel(level)
    remesher.SetAdaptiveTolerance(adaptive_tolerance)
    remesher.ComputeDistanceOn()
    remesher.SetRepairFolds(repair_folds)
    remesher.SetSampleRelaxationIterations(sample_relaxation)
    start = time.perf_counter()
    remeshes = run(remesher)
    seconds = time.perf_counter() - start

    figures = []
    for index, model in enumerate(models):
        remesh = remeshes.GetBlock(index)
        name = remeshes.GetMetaData(index).Get(vtkCompositeDataSet.NAME()) if remeshes.HasMetaData(index) else None
        if remesh is None or name != model.name:
            raise StageError("the remesher's block %d is not model %s" % (index, model.name))
        value = field_reader(remesh)
        figures.append({
            "level": int(value(array_names.REMESH_LEVEL_FIELD)),
            "vertices": int(value(array_names.VERTEX_COUNT_FIELD)),
            "triangles": int(value(array_names.TRIANGLE_COUNT_FIELD)),
            "hausdorff_distance": significant(value(array_names.HAUSDORFF_DISTANCE_FIELD)),
            "hausdorff_per_diagonal": significant(value(array_names.HAUSDORFF_DISTANCE_RELATIVE_FIELD)),
            "mean_distance": significant(value(array_names.MEAN_DISTANCE_FIELD)),
            # Where the Hausdorff distance is reached: on the input, a part
            # the remesh misses (a tail without a landmark at its tip).
            "hausdorff_point": [significant(x) for x in
                                remesh.GetFieldData().GetArray(array_names.HAUSDORFF_POINT_FIELD).GetTuple3(0)],
            "hausdorff_point_on": "input" if value(array_names.HAUSDORFF_POINT_ON_INPUT_FIELD) == 1 else "remesh",
            "hausdorff_nearest_landmark": int(value(array_names.HAUSDORFF_NEAREST_FEATURE_FIELD)),
            "hausdorff_landmark_distance_per_diagonal":
                significant(value(array_names.HAUSDORFF_FEATURE_DISTANCE_RELATIVE_FIELD)),
            # Reported, not a failure, as for the straightener.
            "flipped_triangles": int(value(array_names.FLIPPED_TRIANGLES_FIELD)),
            "folds_near_landmark": folds_near_landmark(remesh),
            "folded_before_repair": int(value(array_names.FOLDED_BEFORE_REPAIR_FIELD)),
            # The centroid criterion: against the surface nearest to the
            # triangle's middle rather than under its corners.
            "centroid_flips": int(value(array_names.CENTROID_FLIPS_FIELD)),
            "repaired_vertices": int(value(array_names.REPAIRED_VERTICES_FIELD)),
            "min_angle_degrees": round(value(array_names.MINIMUM_ANGLE_FIELD), 4),
            "mean_shape_quality": round(value(array_names.MEAN_SHAPE_QUALITY_FIELD), 4),
            "seconds": round(value(array_names.TOTAL_SECONDS_FIELD), 4),
        })
        if model.placed:
            mark_placed_landmarks(remesh, model.placed)
        write_polydata(remesh, os.path.join(output_folder, model.name + ".remesh.vtp"))
    write_multiblock(remeshes, os.path.join(output_folder, "collection.vtm"))
    connectivity = remesher.GetOutputDataObject(1)
    write_polydata(connectivity, os.path.join(output_folder, "remesh_connectivity.vtp"))
    # Only a complete stage gives figures.
    for model, model_figures in zip(models, figures):
        model.report["remesh"] = model_figures
        model.report["seconds"]["remesh"] = model_figures["seconds"]
    shared = field_reader(connectivity)
    return remeshes, {
        "vertices": connectivity.GetNumberOfPoints(),
        "triangles": connectivity.GetNumberOfCells(),
        "sample_relaxation_rounds": int(shared(array_names.SAMPLE_RELAXATION_ROUNDS_FIELD)),
        "sample_relaxation_seconds": round(shared(array_names.SAMPLE_RELAXATION_SECONDS_FIELD), 4),
        "adaptive_passes": int(shared(array_names.ADAPTIVE_PASSES_FIELD)),
        "fold_repair": bool(repair_folds),
        "seconds": round(seconds, 4),
    }


def transfer_attributes(source, remeshes, domain, output_folder):
    """AttributeTransfer from `source`'s parameterized surface (its point
    arrays and texture coordinates) onto every remesh of the collection,
    texture seams split so the result renders: writes
    TARGET.from-SOURCE.vtp per other model and returns the stage's figures.
    Raises StageError if the filter fails or a file cannot be written."""
    start = time.perf_counter()
    surface, generated = with_texture_coordinates(source.parameterized)
    transfer = cmp.vtkCMPAttributeTransfer()
    transfer.SetInputData(0, remeshes)
    transfer.SetInputData(1, surface)
    transfer.SetInputData(2, domain)
    transfer.SplitTextureSeamsOn()
    results = run(transfer)
    figures = {"source": source.name, "targets": {}}
    if generated:
        figures["texture_coordinates"] = "generated: %s has none, so it got cylindrical ones" % source.name
    for index in range(results.GetNumberOfBlocks()):
        name = results.GetMetaData(index).Get(vtkCompositeDataSet.NAME())
        if name == source.name:
            continue
        result = results.GetBlock(index)
        value = field_reader(result)
        write_polydata(result, os.path.join(output_folder, "%s.from-%s.vtp" % (name, source.name)))
        figures["targets"][name] = {
            "arrays": int(value(array_names.TRANSFERRED_ARRAYS_FIELD)),
            "seam_points_added": int(value(array_names.SEAM_POINTS_ADDED_FIELD)),
            "textured": result.GetPointData().GetTCoords() is not None,
        }
    figures["seconds"] = round(time.perf_counter() - start, 4)
    return figures


def with_texture_coordinates(surface):
    """(surface, False) if it has texture coordinates (per point or per
    triangle corner), else (a copy with
    cylindrical ones about its longest axis, True): a model without a
    texture (the CGAL quadrupeds have none) still shows where its surface
    lands on the others, as a checkerboard in the pictures."""
    # The reader keeps texture coordinates with seams per triangle corner.
    corners = surface.GetCellData().GetArray(array_names.CORNER_T_COORDS_ARRAY)
    if surface.GetPointData().GetTCoords() is not None or corners:
        return surface, False
    cylinder = vtkTextureMapToCylinder()
    cylinder.SetInputData(surface)
    cylinder.AutomaticCylinderGenerationOn()
    # Mirrored instead of wrapping from 1 back to 0, which would smear the
    # whole texture across one column of triangles.
    cylinder.PreventSeamOn()
    textured = vtkPolyData()
    textured.ShallowCopy(run(cylinder))
    return textured, True


def run_transfer(source_name, ready, remeshes, domain, output_folder):
    """The --transfer-from stage, reported but never fatal to the models."""
    source = next((m for m in ready if m.name == source_name), None)
    if remeshes is None or source is None or source.parameterized is None:
        return {"source": source_name, "error": "model %s was not remeshed with the collection" % source_name}
    print("transferring %s's attributes onto the other remeshes" % source_name, flush=True)
    try:
        return transfer_attributes(source, remeshes, domain, output_folder)
    except StageError as error:
        return {"source": source_name, "error": str(error)}


def transfer_details(source_name, remeshes, output_folder):
    """WaveletDetailTransfer with every other remesh's coarse shape and
    `source_name`'s details (above level 2, the filter's default): writes
    TARGET.details-from-SOURCE.vtp and returns the stage's figures. Raises
    StageError if the filter fails or a file cannot be written."""
    names = [remeshes.GetMetaData(i).Get(vtkCompositeDataSet.NAME()) for i in range(remeshes.GetNumberOfBlocks())]
    transfer = cmp.vtkCMPWaveletDetailTransfer()
    transfer.SetInputData(remeshes)
    transfer.SetDetailModel(names.index(source_name))
    figures = {"source": source_name, "last_coarse_level": transfer.GetLastCoarseLevel(), "targets": {}}
    start = time.perf_counter()
    for index, name in enumerate(names):
        if name == source_name:
            continue
        transfer.SetCoarseModel(index)
        result = run(transfer)
        path = os.path.join(output_folder, "%s.details-from-%s.vtp" % (name, source_name))
        write_polydata(result, path)
        figures["targets"][name] = {"file": os.path.basename(path),
                                    "seconds": round(field_reader(result)(array_names.TRANSFER_SECONDS_FIELD), 4)}
    figures["seconds"] = round(time.perf_counter() - start, 4)
    return figures


def run_details(source_name, ready, remeshes, output_folder):
    """The --details-from stage, reported but never fatal to the models."""
    if remeshes is None or source_name not in [m.name for m in ready]:
        return {"source": source_name, "error": "model %s was not remeshed with the collection" % source_name}
    print("putting %s's details on the other remeshes" % source_name, flush=True)
    try:
        return transfer_details(source_name, remeshes, output_folder)
    except StageError as error:
        return {"source": source_name, "error": str(error)}


def principal_components(remeshes, modes, output_folder):
    """MeshPCA on the collection of remeshes: writes mean.vtp (the mean
    with point arrays Mode0.. of one standard deviation each),
    pca-coefficients.csv (one row per model), pca-variances.csv (one row per
    mode) and pca-aligned.vtm (the models aligned as the analysis saw them);
    returns the stage's figures and the mean. Raises StageError if the
    filter fails or a file cannot be written."""
    pca = cmp.vtkCMPMeshPCA()
    pca.SetInputData(remeshes)
    pca.SetNumberOfModes(modes)
    start = time.perf_counter()
    mean = run(pca)
    seconds = time.perf_counter() - start
    coefficients = pca.GetOutputDataObject(1)
    variances = pca.GetOutputDataObject(2)
    write_polydata(mean, os.path.join(output_folder, "mean.vtp"))
    write_table(coefficients, os.path.join(output_folder, "pca-coefficients.csv"))
    write_table(variances, os.path.join(output_folder, "pca-variances.csv"))
    write_multiblock(pca.GetOutputDataObject(4), os.path.join(output_folder, "pca-aligned.vtm"))
    value = field_reader(mean)
    ratios = table_column(variances, array_names.EXPLAINED_VARIANCE_RATIO_ARRAY)
    figures = {
        "requested_modes": modes,
        "modes": int(value(array_names.MODE_COUNT_FIELD)),
        "models": table_column(coefficients, array_names.MODEL_COLUMN),
        "alignment": PCA_ALIGNMENT,
        "alignment_iterations": int(value(array_names.ALIGNMENT_ITERATIONS_FIELD)),
        "alignment_converged": bool(value(array_names.ALIGNMENT_CONVERGED_FIELD)),
        "total_variance": significant(value(array_names.TOTAL_VARIANCE_FIELD)),
        "variances": [significant(v) for v in table_column(variances, array_names.VARIANCE_ARRAY)],
        "standard_deviations": [significant(v) for v in table_column(variances, array_names.STANDARD_DEVIATION_COLUMN)],
        "explained_variance_ratios": [round(r, 6) for r in ratios],
        "explained_variance": round(sum(ratios), 6),
        "files": ["mean.vtp", "pca-coefficients.csv", "pca-variances.csv", "pca-aligned.vtm"],
        "seconds": round(seconds, 4),
    }
    return figures, mean


def run_pca(modes, ready, remeshes, output_folder):
    """The --pca stage, reported but never fatal to the models: (figures,
    mean or None)."""
    remeshed = 0 if remeshes is None else len(ready)
    if remeshed < 2:
        return {"requested_modes": modes,
                "error": "principal components need at least two remeshed models, not %d" % remeshed}, None
    print("principal components of %d models" % len(ready), flush=True)
    try:
        return principal_components(remeshes, modes, output_folder)
    except StageError as error:
        return {"requested_modes": modes, "error": str(error)}, None


def _sub_collection(remeshes, indices):
    """The blocks `indices` of `remeshes`, names kept."""
    blocks = vtkMultiBlockDataSet()
    for position, index in enumerate(indices):
        blocks.SetBlock(position, remeshes.GetBlock(index))
        blocks.GetMetaData(position).Set(vtkCompositeDataSet.NAME(),
                                         remeshes.GetMetaData(index).Get(vtkCompositeDataSet.NAME()))
    return blocks


def _blend(blocks, weights, alignment):
    """ShapeBlend of `blocks` with `weights` after `alignment` (a key of
    BLEND_ALIGNMENTS): (surface, extrapolating)."""
    blend = cmp.vtkCMPShapeBlend()
    blend.SetInputData(blocks)
    blend.SetAlignment(BLEND_ALIGNMENTS[alignment][0])
    blend.SetWeights([float(w) for w in weights])
    surface = vtkPolyData()
    surface.ShallowCopy(run(blend))
    return surface, bool(field_reader(surface)(array_names.EXTRAPOLATING_FIELD))


def blend_grid_layout(count):
    """[(weights, column, row)] and the grid's (columns, rows): for three
    models the paper's triangle of blends (Figure 14), model 0 at the top,
    1 bottom left, 2 bottom right, in steps of 1/BLEND_GRID_STEPS; for two,
    one row from model 0 to model 1."""
    n = BLEND_GRID_STEPS
    if count == 2:
        return [((1 - c / n, c / n), c, 0) for c in range(n + 1)], (n + 1, 1)
    layout = []
    for row in range(n + 1):
        for c in range(row + 1):
            layout.append(((1 - row / n, (row - c) / n, c / n), (n - row) / 2 + c, row))
    return layout, (n + 1, n + 1)


def blend_grid(ready, remeshes, output_folder, alignment):
    """Blends of the first three remeshed models (two if there are only
    two) on a grid of weights: writes blend-grid.vtm, one block per blend
    named by its weights; returns the figures and the blends for the
    picture. Raises StageError if a blend fails or the file cannot be
    written."""
    names = [m.name for m in ready[:3]]
    blocks = _sub_collection(remeshes, range(len(names)))
    layout, grid = blend_grid_layout(len(names))
    start = time.perf_counter()
    results = vtkMultiBlockDataSet()
    entries = []
    for index, (weights, column, row) in enumerate(layout):
        surface, _ = _blend(blocks, weights, alignment)
        label = " + ".join("%g %s" % (w, name) for w, name in zip(weights, names) if w)
        results.SetBlock(index, surface)
        results.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), label)
        # A corner is one model: its name says more than its weights.
        corner = [name for w, name in zip(weights, names) if w == 1]
        entries.append((column, row, surface, corner[0] if corner else weights_text(weights)))
    write_multiblock(results, os.path.join(output_folder, "blend-grid.vtm"))
    figures = {
        "models": names,
        "alignment": BLEND_ALIGNMENTS[alignment][1],
        "blends": len(layout),
        "weights": [list(weights) for weights, _, _ in layout],
        "file": "blend-grid.vtm",
        "seconds": round(time.perf_counter() - start, 4),
    }
    return figures, (entries, grid)


def run_blend_grid(ready, remeshes, output_folder, alignment):
    """The --blend stage, reported but never fatal to the models: (figures,
    what the picture needs or None)."""
    remeshed = 0 if remeshes is None else len(ready)
    if remeshed < 2:
        return {"models": [m.name for m in ready[:3]] if remeshes is not None else [],
                "error": "a blend needs at least two remeshed models, not %d" % remeshed}, None
    print("blending %s" % ", ".join(m.name for m in ready[:3]), flush=True)
    try:
        return blend_grid(ready, remeshes, output_folder, alignment)
    except StageError as error:
        return {"models": [m.name for m in ready[:3]], "error": str(error)}, None


def run_blend(weights, models, ready, remeshes, output_folder, alignment):
    """The --blend-weights stage: one blend of every model with the given
    weights, written to blend.vtp; (figures, blend or None)."""
    named = {m.name: w for m, w in zip(models, weights)}
    missing = [m.name for m in models if m not in ready]
    if remeshes is None or missing:
        failed = missing or [m.name for m in models]
        return {"weights": named, "error": "the weights are for every model, and %s %s not remeshed"
                % (", ".join(failed), "was" if len(failed) == 1 else "were")}, None
    print("blending every model with weights %s" % weights_text(weights), flush=True)
    start = time.perf_counter()
    try:
        surface, extrapolating = _blend(remeshes, weights, alignment)
        write_polydata(surface, os.path.join(output_folder, "blend.vtp"))
    except StageError as error:
        return {"weights": named, "error": str(error)}, None
    return {"weights": named, "alignment": BLEND_ALIGNMENTS[alignment][1], "extrapolating": extrapolating, "file": "blend.vtp",
            "seconds": round(time.perf_counter() - start, 4)}, surface
