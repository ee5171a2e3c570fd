"""Semi-Regular Remesher through the ParaView plugin, as a pvpython user
drives it: L0 from model 381, two models traced and straightened as a
multiblock, remeshed at level 3 into two blocks with one connectivity, the
mean shape computed with numpy, then property changes and bad input.

Usage: pvpython TestPluginRemesher.py --plugin PLUGIN.so --data SHARED_DATA
"""
import sys

sys.dont_write_bytecode = True  # keep the source folder clean

import numpy
from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from cmp_test_support import (ErrorCapture, check, check_contains, check_equal, landmark_positions, landmarked_shrec,
                              landmarked_shrec_with_x, plugin_test_setup)
from cmp_test_support import required_field as field

LEVEL = 3
LANDMARKS = 21
L0_TRIANGLES = 2 * LANDMARKS - 4


def connectivity_of(polydata):
    """The raw cell arrays (offsets, connectivity) as numpy arrays."""
    polys = polydata.GetPolys()
    return vtk_to_numpy(polys.GetOffsetsArray()), vtk_to_numpy(polys.GetConnectivityArray())


def check_block(remesh, straightened, what):
    """Everything a user reads off one remeshed model."""
    triangles = L0_TRIANGLES * 4 ** LEVEL
    vertices = 2 + triangles // 2
    check_equal(remesh.GetNumberOfPoints(), vertices, what + ": points")
    check_equal(remesh.GetNumberOfCells(), triangles, what + ": triangles")
    check_equal(field(remesh, "RemeshLevel"), LEVEL, what + ": RemeshLevel")
    check_equal(field(remesh, "VertexCount"), vertices, what + ": VertexCount")
    flipped = field(remesh, "FlippedTriangles")
    check(0 <= flipped < 0.02 * triangles, what + ": FlippedTriangles %d" % flipped)
    check(0 < field(remesh, "MinimumAngle") <= 60, what + ": MinimumAngle")
    check(0.2 < field(remesh, "MeanShapeQuality") <= 1, what + ": MeanShapeQuality")
    relative = field(remesh, "HausdorffDistanceRelative")
    check(0 < relative < 0.2, what + ": HausdorffDistanceRelative %g" % relative)
    check(0 < field(remesh, "MeanDistance") < field(remesh, "HausdorffDistance"), what + ": MeanDistance")

    points = vtk_to_numpy(remesh.GetPoints().GetData())
    feature = vtk_to_numpy(remesh.GetPointData().GetArray("FeatureId"))
    check((feature[:LANDMARKS] == numpy.arange(LANDMARKS)).all() and (feature[LANDMARKS:] == -1).all(),
          what + ": FeatureId is not f at vertex f and -1 elsewhere")
    # Vertex f is landmark f, exactly.
    for f, position in landmark_positions(straightened).items():
        check((points[f] == numpy.array(position)).all(), what + ": vertex %d is not landmark %d" % (f, f))
    # The made-up point array follows the vertices: X is x.
    x = remesh.GetPointData().GetArray("X")
    check(x is not None, what + ": the made-up point array X was not carried")
    worst = numpy.abs(vtk_to_numpy(x) - points[:, 0]).max()
    check(worst < 1e-9, what + ": X differs from x by %g" % worst)
    for name in ("BaseTriangle", "BaseCoordinates"):
        check(remesh.GetPointData().GetArray(name) is not None, what + ": no point array " + name)
    for name in ("PatchId", "Level", "Folded"):
        check(remesh.GetCellData().GetArray(name) is not None, what + ": no cell array " + name)
    check_equal(int(vtk_to_numpy(remesh.GetCellData().GetArray("Folded")).sum()), flipped,
                what + ": Folded against FlippedTriangles")
    near = remesh.GetFieldData().GetArray("FoldsNearFeature")
    check(near is not None, what + ": no field array FoldsNearFeature")
    check_equal(near.GetNumberOfTuples(), LANDMARKS, what + ": FoldsNearFeature has one count per landmark")
    check_equal(int(vtk_to_numpy(near).sum()), flipped, what + ": FoldsNearFeature against FlippedTriangles")
    print("%s: %d vertices, %d flipped, minimum angle %.2f deg, Hausdorff %.4f of the diagonal, %.3f s"
          % (what, vertices, flipped, field(remesh, "MinimumAngle"), relative, field(remesh, "TotalSeconds")))
    return points


def main():
    data, names = plugin_test_setup()

    def landmarked(model):
        return landmarked_shrec(names, data, model)

    def with_x(model):
        return landmarked_shrec_with_x(names, data, model)

    base = names["BaseDomainBuilder"](Input=landmarked("381"))
    models = ["384", "387"]
    group = simple.GroupDatasets(Input=[with_x(m) for m in models])
    tracer = names["FeatureNetTracer"](Input=group, BaseDomain=base)
    straightener = names["NetStraightener"](Input=tracer, BaseDomain=base)
    remesher = names["SemiRegularRemesher"](Input=straightener, BaseDomain=base)
    check_equal((remesher.Level, remesher.ComputeDistance, remesher.RepairFolds, remesher.SampleRelaxationIterations),
                (4, 1, 1, 0), "defaults")
    check_equal([remesher.SMProxy.GetOutputPortName(i) for i in range(2)], ["Remesh", "Connectivity"],
                "output port names")
    remesher.Level = LEVEL
    remesher.UpdatePipeline()

    straightened = servermanager.Fetch(straightener, idx=0)
    remeshes = servermanager.Fetch(remesher, idx=0)
    connectivity = servermanager.Fetch(remesher, idx=1)
    check_equal(remeshes.GetClassName(), "vtkMultiBlockDataSet", "output 0 type")
    check_equal(remeshes.GetNumberOfBlocks(), 2, "output 0 blocks")
    check_equal(connectivity.GetClassName(), "vtkPolyData", "output 1 type")
    positions = []
    for block, model in enumerate(models):
        # Group Datasets names the blocks; the remesher keeps the names.
        name = straightened.GetMetaData(block).Get(straightened.NAME())
        check(name, "block %d of the straightened group has no name" % block)
        check_equal(remeshes.GetMetaData(block).Get(remeshes.NAME()), name, "block %d name" % block)
        positions.append(check_block(remeshes.GetBlock(block), straightened.GetBlock(block),
                                     "block %d (%s)" % (block, model)))

    # One connectivity for both models and output 1: the same raw cell
    # arrays and the same patch of every triangle.
    first = remeshes.GetBlock(0)
    for other, what in ((remeshes.GetBlock(1), "block 1"), (connectivity, "output 1")):
        for mine, theirs, part in zip(connectivity_of(first), connectivity_of(other), ("offsets", "connectivity")):
            check(mine.dtype == theirs.dtype and numpy.array_equal(mine, theirs), "%s: %s differ" % (what, part))
        for name in ("PatchId", "Level"):
            check(numpy.array_equal(vtk_to_numpy(first.GetCellData().GetArray(name)),
                                    vtk_to_numpy(other.GetCellData().GetArray(name))), "%s: %s differ" % (what, name))
    level = vtk_to_numpy(connectivity.GetPointData().GetArray("VertexLevel"))
    check_equal([int((level <= l).sum()) for l in range(LEVEL + 1)],
                [2 + L0_TRIANGLES * 4 ** l // 2 for l in range(LEVEL + 1)], "vertices per level")

    # The mean shape, as the paper's applications start: the same vertex of
    # every remesh averaged. Its landmarks are the landmarks' mean.
    stacked = numpy.stack(positions)
    mean = stacked.mean(axis=0)
    check_equal(mean.shape, (first.GetNumberOfPoints(), 3), "mean shape")
    for f in range(LANDMARKS):
        expected = (numpy.array(landmark_positions(straightened.GetBlock(0))[f]) +
                    numpy.array(landmark_positions(straightened.GetBlock(1))[f])) / 2
        check(numpy.allclose(mean[f], expected, rtol=0, atol=1e-12), "mean shape landmark %d" % f)
    corners = connectivity_of(first)[1].reshape(-1, 3)
    areas = 0.5 * numpy.linalg.norm(numpy.cross(mean[corners[:, 1]] - mean[corners[:, 0]],
                                                mean[corners[:, 2]] - mean[corners[:, 0]]), axis=1)
    check(numpy.isfinite(areas).all() and areas.sum() > 0, "mean shape area")
    spread = numpy.linalg.norm(stacked[0] - stacked[1], axis=1)
    print("mean shape: %d vertices, area %.3f, the two models %.3f apart on average" %
          (len(mean), areas.sum(), spread.mean()))

    # Without distances: no distance arrays, the rest unchanged.
    remesher.ComputeDistance = 0
    remesher.UpdatePipeline()
    quick = servermanager.Fetch(remesher, idx=0).GetBlock(0)
    check(quick.GetFieldData().GetArray("HausdorffDistance") is None, "ComputeDistance 0 still measures")
    check(numpy.array_equal(vtk_to_numpy(quick.GetPoints().GetData()), positions[0]), "ComputeDistance 0 moved points")
    remesher.ComputeDistance = 1

    # Without fold repair: every vertex exactly where the parameterization
    # puts it, FlippedTriangles back to FoldedBeforeRepair; with it, only
    # the reported vertices had moved.
    remesher.RepairFolds = 0
    remesher.UpdatePipeline()
    exact = servermanager.Fetch(remesher, idx=0)
    for block in range(2):
        remesh, repaired = exact.GetBlock(block), remeshes.GetBlock(block)
        check_equal(field(remesh, "RepairedVertices"), 0, "block %d: RepairedVertices without repair" % block)
        check_equal(field(remesh, "FlippedTriangles"), field(remesh, "FoldedBeforeRepair"),
                    "block %d: folds without repair" % block)
        check_equal(field(repaired, "FoldedBeforeRepair"), field(remesh, "FlippedTriangles"),
                    "block %d: folds before repair" % block)
        check(field(repaired, "FlippedTriangles") <= field(remesh, "FlippedTriangles"),
              "block %d: the repair added folds" % block)
        moved = numpy.any(vtk_to_numpy(remesh.GetPoints().GetData()) != positions[block], axis=1)
        check_equal(int(moved.sum()), field(repaired, "RepairedVertices"), "block %d: moved vertices" % block)
        print("block %d: %d folded triangles, %d after moving %d vertices"
              % (block, field(remesh, "FlippedTriangles"), field(repaired, "FlippedTriangles"), moved.sum()))
    check(any(field(remeshes.GetBlock(b), "RepairedVertices") > 0 for b in range(2)), "no vertex repaired")
    remesher.RepairFolds = 1

    # Sample relaxation: the same connectivity, base locations moved alike
    # for both models (the connectivity output carries them), closer to the
    # models.
    remesher.SampleRelaxationIterations = 4
    remesher.UpdatePipeline()
    relaxed = servermanager.Fetch(remesher, idx=0)
    relaxed_connectivity = servermanager.Fetch(remesher, idx=1)
    remesher.SampleRelaxationIterations = 0
    for block in range(2):
        for mine, theirs, part in zip(connectivity_of(first), connectivity_of(relaxed.GetBlock(block)),
                                      ("offsets", "connectivity")):
            check(numpy.array_equal(mine, theirs), "relaxed block %d: %s differ" % (block, part))
    locations = vtk_to_numpy(relaxed_connectivity.GetPointData().GetArray("BaseCoordinates"))
    before = vtk_to_numpy(connectivity.GetPointData().GetArray("BaseCoordinates"))
    for block in range(2):
        check(numpy.array_equal(vtk_to_numpy(relaxed.GetBlock(block).GetPointData().GetArray("BaseCoordinates")),
                                locations), "relaxed block %d: BaseCoordinates are not the shared ones" % block)
    moved = int(numpy.any(locations != before, axis=1).sum())
    check(moved > len(before) // 2, "relaxation moved only %d of %d base locations" % (moved, len(before)))
    distances = [(field(remeshes.GetBlock(b), "HausdorffDistanceRelative"),
                  field(relaxed.GetBlock(b), "HausdorffDistanceRelative")) for b in range(2)]
    check(sum(d[1] for d in distances) < sum(d[0] for d in distances),
          "relaxation did not bring the remeshes closer: %r" % distances)
    print("sample relaxation (4 rounds): %d base locations moved, Hausdorff / diagonal %s"
          % (moved, ", ".join("%.4f -> %.4f" % d for d in distances)))

    # Bad input: reported by the filter, no output.
    def expect_failure(proxy, fragment, what):
        with ErrorCapture(proxy.GetClientSideObject()) as errors:
            data = servermanager.Fetch(proxy, idx=0)
        check(data.GetNumberOfPoints() == 0 if data.IsA("vtkPolyData") else data.GetNumberOfBlocks() == 0,
              what + ": output produced")
        check_contains(errors.text, fragment, what)
        print("%s: %s" % (what, errors.text.strip().splitlines()[-1]))

    remesher.Level = 9
    expect_failure(remesher, "Level must be between 0 and 8 (it is 9)", "Level 9")
    remesher.Level = LEVEL
    remesher.SampleRelaxationIterations = -2
    expect_failure(remesher, "SampleRelaxationIterations must be 0 (none) or a positive number of rounds (it is -2)",
                   "SampleRelaxationIterations -2")
    remesher.SampleRelaxationIterations = 0
    unstraightened = names["SemiRegularRemesher"](Input=tracer, BaseDomain=base)
    expect_failure(unstraightened, "input has no BaseTriangle point array: run Net Straightener first",
                   "traced, not straightened")
    print("plugin remesher: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
