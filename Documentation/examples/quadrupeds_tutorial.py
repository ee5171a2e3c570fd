"""The pvpython tutorial (Documentation/pvpython-tutorial.md) as one script:
five animals of Debian's libcgal-demo package remeshed with one
connectivity through the ParaView plugin, then their mean shape, principal
modes and a blend.

Usage (a display is needed for the pictures; on a headless machine prefix
`xvfb-run -a`):

  pvpython quadrupeds_tutorial.py PLUGIN.so OUTPUT_FOLDER [MESH_FOLDER]

PLUGIN.so is build/lib/paraview-plugins/ConsistentMeshParameterizations/
ConsistentMeshParameterizations.so. MESH_FOLDER holds triceratops.off,
camel.off, bull.off, bear.off and bear_bis.off; without it they are unpacked
from /usr/share/doc/libcgal-dev/data.tar.gz (package libcgal-demo) into
OUTPUT_FOLDER/meshes.

Writes into OUTPUT_FOLDER: remeshes.vtm (the five remeshes), aligned.vtm
(the same, aligned and scaled to one volume), mean.vtp (their mean with the
principal modes as point arrays), pca-variances.csv, blend.vtp (half
triceratops, half camel), and two pictures: tutorial-remeshes.png (the
aligned remeshes and their mean, coloured by base triangle) and
tutorial-blend.png (triceratops to camel in five steps). Fails with exit
status 1 and a message if a stage fails, the remeshes do not share one
connectivity or Mesh PCA's outputs do not fit together.
"""
import hashlib
import json
import os
import sys
import tarfile
import time

import numpy
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from vtkmodules.util.numpy_support import vtk_to_numpy

COLLECTION = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data", "cgal-quadrupeds")
LEVEL = 3  # L0's 38 triangles split 1-to-4 three times: 2432 triangles, 1218 vertices per remesh


def fail(message):
    """Stops the script with exit status 1 and `message` on stderr."""
    sys.exit("quadrupeds_tutorial.py: " + message)


def require(condition, message):
    if not condition:
        fail(message)


if len(sys.argv) not in (3, 4):
    sys.exit(__doc__)
plugin, output = sys.argv[1:3]
# Debian's ParaView renders through X: without a display pvpython crashes at
# the first picture, so say it now rather than after the work.
require(os.environ.get("DISPLAY"), "the pictures need a display: run it under xvfb-run -a")
os.makedirs(output, exist_ok=True)

# ---------------------------------------------------------------- the meshes
# collection.json names the models in order, their member of the CGAL archive
# and their SHA-256: the landmark files give vertex numbers, so they only fit
# the very mesh they were picked on.
with open(os.path.join(COLLECTION, "collection.json")) as f:
    collection = json.load(f)
models = [model["name"] for model in collection["models"]]

if len(sys.argv) == 4:
    meshes = sys.argv[3]
else:
    meshes = os.path.join(output, "meshes")
    os.makedirs(meshes, exist_ok=True)
    archives = [path for path in collection["archive"]["paths"] if os.path.isfile(path)]
    require(archives, "the meshes come from Debian's libcgal-demo package: install it (apt-get install "
            "libcgal-demo) or give a MESH_FOLDER")
    with tarfile.open(archives[0]) as archive:
        for model in collection["models"]:
            with open(os.path.join(meshes, model["name"] + ".off"), "wb") as out:
                out.write(archive.extractfile(model["member"]).read())
for model in collection["models"]:
    path = os.path.join(meshes, model["name"] + ".off")
    require(os.path.isfile(path), "no " + path)
    with open(path, "rb") as f:
        require(hashlib.sha256(f.read()).hexdigest() == model["sha256"],
                path + " is not the mesh the landmarks were picked on")

# ---------------------------------------------------------------- the plugin
# ns=globals() puts one function per filter of the plugin into this script:
# a filter's label without spaces ("Feature Net Tracer" -> FeatureNetTracer).
LoadPlugin(plugin, ns=globals())
timings = []


def run(proxy, what):
    """Updates `proxy` (the pipeline is lazy: nothing runs before this) and
    notes how long it took."""
    start = time.time()
    proxy.UpdatePipeline()
    timings.append((what, time.time() - start))


def field(dataset, name):
    """The first value of a field-data array."""
    array = dataset.GetFieldData().GetAbstractArray(name)
    require(array is not None, "no field array " + name)
    return array.GetVariantValue(0).ToDouble()


# ------------------------------------------------------ 1. read and landmark
# Each mesh is read and welded (Consistent Mesh Surface Reader), then gets
# its 21 landmarks as the point array FeatureId (f on landmark f, -1 elsewhere).
landmarked = []
for name in models:
    surface = ConsistentMeshSurfaceReader(FileName=os.path.join(meshes, name + ".off"))
    landmarked.append(LandmarksFromFile(Input=surface,
                                        LandmarkFile=os.path.join(COLLECTION, name + ".landmarks")))

# ------------------------------------------------------- 2. the base domain
# L0: a coarse triangle mesh with one vertex per landmark. Its triangles are
# the patches every model is cut into. This one was built from the
# triceratops with Base Domain Builder and is shipped with the collection.
base = XMLPolyDataReader(FileName=[os.path.join(COLLECTION, collection["base_domain"])])

# --------------------------------------------------------------- 3. group
# One multiblock with a block per model, named after it: the remesher must
# see the whole collection in one run to give every model one connectivity.
group = GroupDatasets(Input=landmarked, BlockNames=models)
run(group, "read, landmark and group")

# ---------------------------------------------------- 4. trace the feature net
# A curve on each model for every edge of L0, between the same landmarks and
# in the same order around each landmark: the models are cut into 38 patches
# that match L0's triangles (cell array PatchId).
tracer = FeatureNetTracer(Input=group, BaseDomain=base)
run(tracer, "trace")

# --------------------------------------------------------- 5. straighten
# Moves the curves to smoother places and maps every patch onto its L0
# triangle (point arrays BaseTriangle, BaseCoordinates).
straightener = NetStraightener(Input=tracer, BaseDomain=base)
run(straightener, "straighten")

# ------------------------------------------------------------- 6. remesh
# L0 refined LEVEL times, placed on every model through its parameterization.
# Output 0 (Remesh) has the models; output 1 (Connectivity) the shared triangles.
remesher = SemiRegularRemesher(Input=straightener, BaseDomain=base, Level=LEVEL)
run(remesher, "remesh")

remeshes = servermanager.Fetch(remesher, idx=0)  # brings the data into this script
shared = servermanager.Fetch(remesher, idx=1)
require(remeshes.GetNumberOfBlocks() == len(models) and all(
    remeshes.GetBlock(i) is not None and remeshes.GetBlock(i).GetNumberOfPoints() > 0 for i in range(len(models))),
    "the remesher failed (see the messages above)")


def triangles(polydata):
    polys = polydata.GetPolys()
    return vtk_to_numpy(polys.GetOffsetsArray()), vtk_to_numpy(polys.GetConnectivityArray())


def check_one_connectivity(collection_data, what):
    """Every block has the shared triangles, vertex for vertex: the whole
    point of the method."""
    for index in range(collection_data.GetNumberOfBlocks()):
        block = collection_data.GetBlock(index)
        name = collection_data.GetMetaData(index).Get(collection_data.NAME())
        require(name == models[index], "%s: block %d is %r, not %s" % (what, index, name, models[index]))
        require(block.GetNumberOfPoints() == shared.GetNumberOfPoints(),
                "%s: %s has %d vertices, the connectivity %d" % (what, name, block.GetNumberOfPoints(),
                                                                 shared.GetNumberOfPoints()))
        for mine, theirs in zip(triangles(block), triangles(shared)):
            require(numpy.array_equal(mine, theirs), "%s: %s does not have the shared triangles" % (what, name))


check_one_connectivity(remeshes, "remesh")
require(shared.GetNumberOfPoints() == 1218 and shared.GetNumberOfCells() == 2432,
        "a level-3 remesh of a 38-triangle L0 has 1218 vertices and 2432 triangles")
for index, name in enumerate(models):
    remesh = remeshes.GetBlock(index)
    print("%-11s %d vertices, Hausdorff distance %4.1f %% of the diagonal, %d flipped triangles"
          % (name, remesh.GetNumberOfPoints(), 100 * field(remesh, "HausdorffDistanceRelative"),
             field(remesh, "FlippedTriangles")))

# ------------------------------------------------------------------ 7. PCA
# One connectivity makes every model a point in a 3 x 1218-dimensional space.
# Mesh PCA aligns the models (rotation, translation and scale to the mean
# volume), then gives the mean (output 0) and the modes in which they vary.
pca = MeshPCA(Input=remesher, NumberOfModes=3)
run(pca, "PCA")
mean = servermanager.Fetch(pca, idx=0)
coefficients = servermanager.Fetch(pca, idx=1)
aligned = servermanager.Fetch(pca, idx=4)

require(mean.GetNumberOfPoints() == shared.GetNumberOfPoints(), "Mesh PCA gave no mean (see the messages above)")
require(field(mean, "ModelCount") == len(models), "the mean is not of the %d models" % len(models))
check_one_connectivity(aligned, "PCA's aligned models")
# The mean is the average of the aligned models, vertex by vertex.
stacked = numpy.stack([vtk_to_numpy(aligned.GetBlock(i).GetPoints().GetData()) for i in range(len(models))])
mean_points = vtk_to_numpy(mean.GetPoints().GetData())
diagonal = numpy.linalg.norm(mean_points.max(axis=0) - mean_points.min(axis=0))
worst = numpy.abs(stacked.mean(axis=0) - mean_points).max()
require(worst < 1e-9 * diagonal, "the mean is %g away from the average of the aligned models" % worst)
# Mode k is one standard deviation of displacement: model i's coefficient on
# it is its distance from the mean along the mode, and the coefficients' spread
# is the mode's variance.
variances = vtk_to_numpy(mean.GetFieldData().GetArray("Variance"))
require(len(variances) == 3 and field(mean, "ModeCount") == 3, "Mesh PCA kept %d modes, not 3" % len(variances))
require(all(variances[:-1] >= variances[1:]), "the modes are not in decreasing variance")
for k, variance in enumerate(variances):
    mode = vtk_to_numpy(mean.GetPointData().GetArray("Mode%d" % k))
    require(abs((mode ** 2).sum() - variance) <= 1e-9 * variance, "Mode%d squared does not sum to its variance" % k)
    projected = ((stacked - mean_points) * mode).sum(axis=(1, 2)) / numpy.sqrt(variance)
    given = vtk_to_numpy(coefficients.GetColumnByName("Coefficient%d" % k))
    require(numpy.abs(projected - given).max() <= 1e-8 * numpy.sqrt(variance),
            "Coefficient%d is not the models' projection on Mode%d" % (k, k))
ratios = vtk_to_numpy(mean.GetFieldData().GetArray("ExplainedVarianceRatio"))
print("PCA: %d models, modes explain %s of the variance"
      % (len(models), ", ".join("%.0f %%" % (100 * r) for r in ratios)))

# ---------------------------------------------------------------- 8. blend
# With one connectivity a blend is a weighted sum of the models, vertex by
# vertex. Aligned and scaled as for the PCA, half triceratops, half camel:
blend = ShapeBlend(Input=remesher, Weights=[0.5, 0.5, 0, 0, 0], Alignment="Rigid, equal volume")
run(blend, "blend")
blended = vtk_to_numpy(servermanager.Fetch(blend).GetPoints().GetData())
worst = numpy.abs(blended - 0.5 * (stacked[0] + stacked[1])).max()
require(worst < 1e-9 * diagonal, "the blend is %g away from half triceratops, half camel" % worst)

# ----------------------------------------------------------------- 9. save
# Binary, not ParaView's default appended mode, which Debian bookworm's VTK
# cannot read back (Documentation/known-issues.md).
start = time.time()
SaveData(os.path.join(output, "remeshes.vtm"), proxy=remesher, DataMode="Binary")
SaveData(os.path.join(output, "aligned.vtm"), proxy=OutputPort(pca, 4), DataMode="Binary")
SaveData(os.path.join(output, "mean.vtp"), proxy=OutputPort(pca, 0), DataMode="Binary")
SaveData(os.path.join(output, "pca-variances.csv"), proxy=OutputPort(pca, 2))
SaveData(os.path.join(output, "blend.vtp"), proxy=blend, DataMode="Binary")
timings.append(("save", time.time() - start))

# --------------------------------------------------------------- 10. look
# The raw models differ in size (the triceratops is 15 units long, the camel
# 1) and in how they are placed, so the pictures show Mesh PCA's aligned
# output (output 4): turned into the triceratops's frame (x along the body,
# y up) and scaled to one volume.
start = time.time()
lut = GetColorTransferFunction("PatchId")
lut.ApplyPreset("Rainbow Uniform", True)
lut.RescaleTransferFunction(0, 37)  # one colour per L0 triangle


def picture(shapes, path, width=1800):
    """Draws `shapes` ((label, proxy) pairs) in a row, seen from the side,
    coloured by PatchId, with the label under each, and saves the view."""
    for _, proxy in shapes:
        proxy.UpdatePipeline()  # a proxy knows its bounds only once it has run
    bounds = [proxy.GetDataInformation().GetBounds() for _, proxy in shapes]
    step = 1.15 * max(b[1] - b[0] for b in bounds)  # room for the widest
    tallest = max(b[3] - b[2] for b in bounds)
    # The camera shows the row's width and 1.4 times the tallest shape's
    # height: the shapes standing on y = 0, their labels under them.
    left, right = -0.5 * step, (len(shapes) - 0.5) * step
    height = int(round(width * 1.4 * tallest / (right - left)))
    view = CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0  # white, whatever the user's palette says
    view.Background = [1, 1, 1]
    view.CameraParallelProjection = 1
    for slot, ((label, proxy), b) in enumerate(zip(shapes, bounds)):
        # Move each shape so that it stands on y = 0, centred on x = slot * step.
        moved = Transform(Input=proxy)
        moved.Transform.Translate = [slot * step - 0.5 * (b[0] + b[1]), -b[2], 0]
        display = Show(moved, view)
        ColorBy(display, ("CELLS", "PatchId"))
        display.LookupTable = lut
        display.SetScalarBarVisibility(view, False)
    Render(view)  # the first render resets the camera: set it afterwards
    centre = [0.5 * (left + right), 0.42 * tallest, 0]  # y from -0.28 to 1.12 times the tallest
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0], centre[1], 100]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = 0.7 * tallest  # half the visible height
    for slot, (label, _) in enumerate(shapes):
        text = Show(Text(Text=label), view)
        text.WindowLocation = "Any Location"
        x = (slot + 0.5) / len(shapes)  # the slot's centre, in fractions of the width
        text.Position = [x - 0.0055 * len(label), 0.03]  # roughly centred
        text.Color = [0, 0, 0]
        text.FontSize = 20
    require(SaveScreenshot(path, view, ImageResolution=[width, height]), "cannot write " + path)
    Delete(view)


def aligned_model(name):
    """One block of Mesh PCA's aligned output, picked by its name."""
    return ExtractBlock(Input=OutputPort(pca, 4), Selectors=["/Root/" + name])


picture([(name, aligned_model(name)) for name in models] + [("mean", OutputPort(pca, 0))],
        os.path.join(output, "tutorial-remeshes.png"))
# From the triceratops to the camel: weight 1 - t on the first, t on the second.
blends = [("%d %% camel" % (100 * t), ShapeBlend(Input=remesher, Weights=[1 - t, t, 0, 0, 0],
                                                 Alignment="Rigid, equal volume")) for t in (0, 0.25, 0.5, 0.75, 1)]
picture(blends, os.path.join(output, "tutorial-blend.png"))
timings.append(("pictures", time.time() - start))

for what, seconds in timings:
    print("%-25s %6.2f s" % (what, seconds))
print("wrote remeshes.vtm, aligned.vtm, mean.vtp, pca-variances.csv, blend.vtp, tutorial-remeshes.png and "
      "tutorial-blend.png into " + output)
