"""The mean shape of a collection (the paper's Figure 1), through the ParaView
plugin: SHREC'07 four-legged animals remeshed with one connectivity, then
averaged vertex by vertex with plain numpy.

Usage (a display is needed for the picture; on a headless machine prefix
`xvfb-run -a`):

  pvpython mean_shape.py PLUGIN.so DATA_DIR OUTPUT_FOLDER [MODEL ...]

DATA_DIR is the shared data folder (with shrec07-fourleg/); MODEL are SHREC'07
model numbers with landmarks, at least two (default 381 385 388 392: these
four stand in the same frame, nose along +x and legs along -y, so their plain
mean is meaningful; models in other poses would have to be aligned first).

The pipeline, as a GUI user builds it: L0 from model 381 (Base Domain
Builder), the models grouped (Group Datasets), traced (Feature Net Tracer),
straightened (Net Straightener) and remeshed at level 4 (Semi-Regular
Remesher) in one run, so that every remesh has the same triangles and vertex
k is the same place on every model. Then the mean is a numpy mean over the
models' point arrays.

Writes into OUTPUT_FOLDER: NAME.remesh.vtp per model, mean.vtp (the shared
connectivity with the mean points and the connectivity's arrays) and
mean_shape.png (the remeshes and their mean side by side, coloured by the L0
triangle each triangle belongs to). Fails (exit status 1) if the remeshes do
not share their connectivity or the mean's vertex f is not the mean of the
models' landmark f.
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the source folder clean
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "images"))

import numpy
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import landmarked_shrec, white_view
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

LEVEL = 4


def require(condition, message):
    """Stops with exit status 1 and `message` unless `condition` holds."""
    if not condition:
        sys.exit("mean_shape.py: " + message)


if len(sys.argv) < 4:
    sys.exit(__doc__)
plugin, data, output = sys.argv[1:4]
models = sys.argv[4:] or ["381", "385", "388", "392"]
require(len(models) >= 2, "give at least two models to average")
os.makedirs(output, exist_ok=True)
LoadPlugin(plugin, ns=globals())

# The pipeline: one multiblock with a block per model, named after it.
base = BaseDomainBuilder(Input=landmarked_shrec(globals(), data, "381"))
group = GroupDatasets(Input=[landmarked_shrec(globals(), data, m) for m in models], BlockNames=models)
tracer = FeatureNetTracer(Input=group, BaseDomain=base)
straightener = NetStraightener(Input=tracer, BaseDomain=base)
remesher = SemiRegularRemesher(Input=straightener, BaseDomain=base, Level=LEVEL)
remesher.UpdatePipeline()

remeshes = servermanager.Fetch(remesher, idx=0)
connectivity = servermanager.Fetch(remesher, idx=1)
straightened = servermanager.Fetch(straightener, idx=0)
require(remeshes.GetNumberOfBlocks() == len(models), "the remesher failed (see the messages above)")


def cells(polydata):
    polys = polydata.GetPolys()
    return vtk_to_numpy(polys.GetOffsetsArray()), vtk_to_numpy(polys.GetConnectivityArray())


def landmarks(surface):
    """Landmark positions of a surface, row f = landmark f."""
    feature = vtk_to_numpy(surface.GetPointData().GetArray("FeatureId"))
    points = vtk_to_numpy(surface.GetPoints().GetData()).astype(numpy.float64)
    ids = numpy.flatnonzero(feature >= 0)
    return points[ids[numpy.argsort(feature[ids])]]


def write(polydata, path):
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(polydata)
    writer.SetDataModeToBinary()  # appended mode cannot be read back (Documentation/known-issues.md)
    require(writer.Write(), "cannot write " + path)


positions = []
for index, model in enumerate(models):
    remesh = remeshes.GetBlock(index)
    name = remeshes.GetMetaData(index).Get(remeshes.NAME())
    require(name == model, "block %d is %r, not model %s" % (index, name, model))
    # One connectivity: the same triangles, vertex for vertex.
    for mine, shared in zip(cells(remesh), cells(connectivity)):
        require(numpy.array_equal(mine, shared), model + ": the remesh does not have the shared connectivity")
    positions.append(vtk_to_numpy(remesh.GetPoints().GetData()).astype(numpy.float64))
    write(remesh, os.path.join(output, model + ".remesh.vtp"))
    field = remesh.GetFieldData()
    print("%s: %d vertices, Hausdorff distance %.1f %% of the diagonal, %d flipped triangles"
          % (model, remesh.GetNumberOfPoints(), 100 * field.GetArray("HausdorffDistanceRelative").GetValue(0),
             field.GetArray("FlippedTriangles").GetValue(0)))

# The mean shape: vertex k of the mean is the mean of vertex k of every model.
stacked = numpy.stack(positions)  # models x vertices x 3
mean = stacked.mean(axis=0)

# Vertex f of every remesh is landmark f, so the mean's vertex f is the mean
# of the models' landmark f (independently read off the straightened surfaces).
expected = numpy.mean([landmarks(straightened.GetBlock(i)) for i in range(len(models))], axis=0)
require(len(expected) == connectivity.GetPointData().GetArray("FeatureId").GetRange()[1] + 1, "landmark count")
worst = numpy.abs(mean[:len(expected)] - expected).max()
require(worst < 1e-12, "the mean's landmarks are %g away from the mean of the models' landmarks" % worst)
spread = numpy.sqrt(((stacked - mean) ** 2).sum(axis=2).mean())
diagonal = numpy.linalg.norm(mean.max(axis=0) - mean.min(axis=0))
print("mean shape: %d vertices, the models are %.1f %% of its diagonal from it (RMS)"
      % (len(mean), 100 * spread / diagonal))
if spread > 0.2 * diagonal:
    print("warning: the models are far from their mean: are they in the same pose frame?")

shape = vtkPolyData()
shape.ShallowCopy(connectivity)  # the triangles and the arrays of the shared connectivity
points = vtkPoints()
points.SetData(numpy_to_vtk(mean, deep=True))
shape.SetPoints(points)
mean_path = os.path.join(output, "mean.vtp")
write(shape, mean_path)

# The picture: the remeshes in a row, then their mean, seen from the side.
width, height = 1800, 480
view = white_view(width, height)
view.CameraParallelProjection = 1
lut = GetColorTransferFunction("PatchId")
lut.ApplyPreset("Rainbow Uniform", True)
lut.RescaleTransferFunction(0, connectivity.GetCellData().GetArray("PatchId").GetRange()[1])
low, high = stacked[:, :, 0].min(), stacked[:, :, 0].max()
step = 1.15 * (high - low)
files = [(m, os.path.join(output, m + ".remesh.vtp")) for m in models] + [("mean", mean_path)]
for slot, (label, path) in enumerate(files):
    # A wider gap before the mean.
    moved = Transform(Input=XMLPolyDataReader(FileName=[path]))
    moved.Transform.Translate = [step * (slot + (0.25 if label == "mean" else 0.0)), 0, 0]
    shown = Show(moved, view)
    ColorBy(shown, ("CELLS", "PatchId"))
    shown.LookupTable = lut
    shown.SetScalarBarVisibility(view, False)
Render(view)  # the first render resets the camera; set it afterwards
# Fit the row: half its width or half the tallest shape, whichever needs more.
right = high + step * (len(files) - 0.75)
bottom, top = stacked[:, :, 1].min(), stacked[:, :, 1].max()
centre = [0.5 * (low + right), 0.5 * (bottom + top) - 0.06 * (top - bottom), 0]
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0], centre[1], 10]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelScale = 1.08 * max(0.5 * (right - low) * height / width, 0.5 * (top - bottom))
Render(view)
# Labels under each shape, where the camera put it.
renderer = view.GetRenderer()
for slot, (label, _) in enumerate(files):
    x = 0.5 * (low + high) + step * (slot + (0.25 if label == "mean" else 0.0))
    renderer.SetWorldPoint(x, bottom, 0, 1)
    renderer.WorldToDisplay()
    left, below = renderer.GetDisplayPoint()[0] / width, renderer.GetDisplayPoint()[1] / height
    text = Show(Text(Text=label), view)
    text.WindowLocation = "Any Location"
    text.Position = [min(max(left - 0.01, 0.0), 0.95), max(below - 0.12, 0.0)]
    text.Color = [0, 0, 0]
    text.FontSize = 22
picture = os.path.join(output, "mean_shape.png")
require(SaveScreenshot(picture, view, ImageResolution=[width, height]), "cannot write " + picture)
print("wrote %s, %s and %d remeshes" % (picture, mean_path, len(models)))
