"""Landmark files that mark features missing (-1) in ParaView (issue 27 A):
Landmarks From File leaves them off FeatureId and says how many features
the file has, Check Inputs accepts them with AllowMissingLandmarks and
names them without, Base Domain Builder refuses such a model, the landmark
writer writes them back as missing, and Missing Landmark Placer places them
from the models of the collection that have them, marking what it placed;
Protrusion Cones then finds no protrusion to give a cone on them, keeps a
given L0 and refuses one of other features.
On the shipped examples (6 landmarks each): blob misses feature 2 (.vts),
peanut its last feature (.csv, nan,nan,nan), capsule has all.

Usage: pvpython TestPluginMissingLandmarks.py PLUGIN.so EXAMPLES_DIR OUTPUT_DIR
"""
import math
import os
import sys

sys.dont_write_bytecode = True  # keep the source folder clean

from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from cmp_test_support import ErrorCapture, check, check_contains, check_equal, load_plugin_proxies, write_text


def feature_ids(surface):
    return {int(f): v for v, f in enumerate(vtk_to_numpy(surface.GetPointData().GetArray("FeatureId"))) if f >= 0}


def tetrahedron_domain():
    """A 4-vertex base domain (FeatureId 0 to 3)."""
    from vtkmodules.vtkCommonCore import vtkIntArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    points = vtkPoints()
    for p in ((1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)):
        points.InsertNextPoint(p)
    cells = vtkCellArray()
    for t in ((0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)):
        cells.InsertNextCell(3, t)
    ids = vtkIntArray()
    ids.SetName("FeatureId")
    for i in range(4):
        ids.InsertNextValue(i)
    domain = vtkPolyData()
    domain.SetPoints(points)
    domain.SetPolys(cells)
    domain.GetPointData().AddArray(ids)
    return domain


def main():
    plugin, examples, output = sys.argv[1:4]
    os.makedirs(output, exist_ok=True)
    names = load_plugin_proxies(plugin)
    with open(os.path.join(examples, "blob.vts")) as f:
        blob_lines = f.read().splitlines()
    true_blob = int(blob_lines[2].split()[0])
    blob_lines[2] = "-1"
    blob_vts = write_text(os.path.join(output, "blob-missing.vts"), "\n".join(blob_lines) + "\n")
    with open(os.path.join(examples, "peanut.csv")) as f:
        peanut_rows = f.read().splitlines()
    peanut_rows[6] = "nan,nan,nan"
    peanut_csv = write_text(os.path.join(output, "peanut-missing.csv"), "\n".join(peanut_rows) + "\n")

    def landmarked(mesh, landmarks):
        reader = names["ConsistentMeshSurfaceReader"](FileName=os.path.join(examples, mesh))
        return reader, names["LandmarksFromFile"](Input=reader, LandmarkFile=landmarks)

    blob_reader, blob = landmarked("blob.off", blob_vts)
    _, capsule = landmarked("capsule.obj", os.path.join(examples, "capsule.pinned"))
    peanut_reader, peanut = landmarked("peanut.off", peanut_csv)
    read = servermanager.Fetch(blob)
    check_equal(sorted(feature_ids(read)), [0, 1, 3, 4, 5], "blob's features read")
    check_equal(int(read.GetFieldData().GetArray("FeatureCount").GetValue(0)), 6, "blob's FeatureCount")
    read = servermanager.Fetch(peanut)
    check_equal(sorted(feature_ids(read)), [0, 1, 2, 3, 4], "peanut's features read")
    check_equal(int(read.GetFieldData().GetArray("FeatureCount").GetValue(0)), 6, "peanut's FeatureCount")

    # Check Inputs names the missing feature, even the last one, unless
    # missing features are allowed.
    for source, feature in ((blob, 2), (peanut, 5)):
        check_inputs = names["CheckInputs"](Input=source, RequireLandmarks=1)
        with ErrorCapture(check_inputs.GetClientSideObject()) as errors:
            check_inputs.UpdatePipeline()
        check_contains(errors.text, "missing landmark: feature %d is on no vertex" % feature, "Check Inputs")
        check_inputs.AllowMissingLandmarks = 1
        with ErrorCapture(check_inputs.GetClientSideObject()) as errors:
            check_inputs.UpdatePipeline()
        check_equal(errors.text, "", "Check Inputs with AllowMissingLandmarks")
    builder = names["BaseDomainBuilder"](Input=blob)
    with ErrorCapture(builder.GetClientSideObject()) as errors:
        builder.UpdatePipeline()
    check_contains(errors.text, "this model misses landmark 2: a base domain is built from a model with every "
                   "landmark", "Base Domain Builder")

    # The landmark writer writes a missing feature as missing.
    for extension, line in (("vts", "-1"), ("pinned", "lk -1"), ("csv", "nan,nan,nan")):
        path = os.path.join(output, "peanut-saved." + extension)
        simple.SaveData(path, proxy=peanut)
        with open(path) as f:
            lines = f.read().splitlines()
        check_equal(lines[-1], line, "the last line of " + path)
        reread = names["LandmarksFromFile"](Input=peanut_reader, LandmarkFile=path)
        check_equal(sorted(feature_ids(servermanager.Fetch(reread))), [0, 1, 2, 3, 4], path + " read back")

    # The collection: the placer completes every model.
    group = simple.GroupDatasets(Input=[blob, capsule, peanut])
    placer = names["MissingLandmarkPlacer"](Input=group)
    placed = servermanager.Fetch(placer)
    check_equal(placed.GetNumberOfBlocks(), 3, "blocks")
    expected = {0: ([2], true_blob), 1: ([], None), 2: ([5], None)}
    for block, (features, truth) in expected.items():
        surface = placed.GetBlock(block)
        ids = feature_ids(surface)
        check_equal(sorted(ids), list(range(6)), "block %d's features after placing" % block)
        marks = {int(f): v for v, f in enumerate(vtk_to_numpy(surface.GetPointData().GetArray("PlacedFeatureId")))
                 if f >= 0}
        check_equal(sorted(marks), features, "block %d's PlacedFeatureId" % block)
        field = surface.GetFieldData()
        check_equal([int(field.GetArray("PlacedFeatures").GetValue(i))
                     for i in range(field.GetArray("PlacedFeatures").GetNumberOfTuples())], features,
                    "block %d's PlacedFeatures" % block)
        for feature in features:
            check_equal(ids[feature], marks[feature], "block %d: FeatureId and PlacedFeatureId" % block)
        climbs = field.GetArray("PlacedFeatureClimb")
        check(climbs is not None, "block %d has PlacedFeatureClimb" % block)
        check_equal(climbs.GetNumberOfTuples(), len(features), "block %d's PlacedFeatureClimb" % block)
        check(all(climbs.GetValue(i) >= 0.0 for i in range(climbs.GetNumberOfTuples())),
              "block %d's climbs are distances" % block)
        if truth is not None:
            # The blob's missing feature, carried from the capsule, lands
            # near where the file had it (a bump of the blob).
            points = vtk_to_numpy(surface.GetPoints().GetData())
            span = max(points.max(axis=0) - points.min(axis=0))
            error = math.dist(points[ids[2]], points[truth])
            check(error < 0.25 * span, "blob's feature 2 placed %.3f from the file's (span %.3f)" % (error, span))
    # Without climbing to tips, no placed feature climbs.
    staying = names["MissingLandmarkPlacer"](Input=group, ClimbToTips=0)
    staying_output = servermanager.Fetch(staying)
    for block in range(3):
        climbs = staying_output.GetBlock(block).GetFieldData().GetArray("PlacedFeatureClimb")
        check(all(climbs.GetValue(i) == 0.0 for i in range(climbs.GetNumberOfTuples())),
              "block %d climbed with ClimbToTips off" % block)
    # A complete model passes through as it was.
    capsule_before = feature_ids(servermanager.Fetch(capsule))
    check_equal(feature_ids(placed.GetBlock(1)), capsule_before, "the capsule's landmarks")

    # Protrusion Cones on the completed collection: the examples have no
    # long landmark-free protrusion, so L0 (output 1) keeps their 6
    # landmarks and the surfaces (output 0) keep theirs.
    cones = names["ProtrusionCones"](Input=placer)
    with ErrorCapture(cones.GetClientSideObject()) as errors:
        cones.UpdatePipeline()
    check_equal(errors.text, "", "Protrusion Cones on the examples")
    cone_surfaces = servermanager.Fetch(cones, idx=0)
    cone_domain = servermanager.Fetch(cones, idx=1)
    check_equal(cone_domain.GetNumberOfPoints(), 6, "Protrusion Cones' L0 points")
    check_equal(cone_domain.GetFieldData().GetArray("ProtrusionConeRoots").GetNumberOfTuples(), 0, "cones")
    for block in range(3):
        check_equal(sorted(feature_ids(cone_surfaces.GetBlock(block))), list(range(6)),
                    "block %d's features after Protrusion Cones" % block)
        check(cone_surfaces.GetBlock(block).GetFieldData().GetArray("ProtrusionTips") is not None,
              "block %d has ProtrusionTips" % block)

    # With a given L0 (input 1, built from the capsule) the filter keeps it
    # when there are no cones; an L0 of other features is refused by name.
    capsule_domain = names["BaseDomainBuilder"](Input=capsule)
    given = names["ProtrusionCones"](Input=placer, BaseDomain=capsule_domain)
    with ErrorCapture(given.GetClientSideObject()) as errors:
        given.UpdatePipeline()
    check_equal(errors.text, "", "Protrusion Cones with a given L0")
    given_domain = servermanager.Fetch(given, idx=1)
    built_domain = servermanager.Fetch(capsule_domain)
    check_equal((given_domain.GetNumberOfPoints(), given_domain.GetNumberOfCells()),
                (built_domain.GetNumberOfPoints(), built_domain.GetNumberOfCells()), "the given L0 kept")
    tetrahedron = simple.PVTrivialProducer()
    tetrahedron.GetClientSideObject().SetOutput(tetrahedron_domain())
    refused = names["ProtrusionCones"](Input=placer, BaseDomain=tetrahedron)
    with ErrorCapture(refused.GetClientSideObject()) as errors:
        refused.UpdatePipeline()
    check_contains(errors.text, "model 0 has 6 features, the given L0 4", "Protrusion Cones with a 4-vertex L0")
    check_equal(servermanager.Fetch(refused, idx=1).GetNumberOfPoints(), 0, "L0 after the refusal")
    # With the L0 the collection will be mapped over (input 1), the placer
    # judges each climb by the model's map over it and says both
    # distortions; an L0 of other features is refused by name.
    judged = names["MissingLandmarkPlacer"](Input=group, BaseDomain=capsule_domain)
    with ErrorCapture(judged.GetClientSideObject()) as errors:
        judged_output = servermanager.Fetch(judged)
    check_equal(errors.text, "", "the placer with a base domain")
    for block, (features, _) in expected.items():
        field = judged_output.GetBlock(block).GetFieldData()
        climbs = field.GetArray("PlacedFeatureClimb")
        for name in ("PlacedFeatureTipDistortion", "PlacedFeatureMappedDistortion"):
            values = field.GetArray(name)
            check(values is not None and values.GetNumberOfTuples() == len(features),
                  "block %d's %s" % (block, name))
        tips = field.GetArray("PlacedFeatureTipDistortion")
        mapped = field.GetArray("PlacedFeatureMappedDistortion")
        for i in range(len(features)):
            if tips.GetValue(i) != 0.0 or mapped.GetValue(i) != 0.0:
                # Judged: the climb is undone only where its map is more
                # than twice as distorted (the core's unsettledRatio).
                check_equal(climbs.GetValue(i) > 0.0, not 2.0 * mapped.GetValue(i) < tips.GetValue(i),
                            "block %d: the climb kept unless its map is unsettled" % block)
    refused = names["MissingLandmarkPlacer"](Input=group, BaseDomain=tetrahedron)
    with ErrorCapture(refused.GetClientSideObject()) as errors:
        refused.UpdatePipeline()
    check_contains(errors.text, "the base domain the climbs are judged over has 4 vertices but the models 6 "
                   "features", "the placer with a 4-vertex L0")
    # No model with every feature: the placer says so.
    lonely = names["MissingLandmarkPlacer"](Input=simple.GroupDatasets(Input=[blob, peanut]))
    with ErrorCapture(lonely.GetClientSideObject()) as errors:
        lonely.UpdatePipeline()
    check_contains(errors.text, "no model has every feature", "placer without a complete model")
    print("missing landmarks read, checked, written and placed on the shipped examples")


if __name__ == "__main__":
    main()
