"""Renders Documentation/images/missed-tips.png: where each model's remesh
lies farthest from its surface, from a `consistent-remesh` report. Every
model is drawn from its side (the first model looking along its narrowest
principal axis, legs down; the others turned the same way by their
landmarks), with its landmarks in blue, the landmark nearest to the
farthest point in green and that point (`hausdorff_point` in the report)
in red when it lies on the model (a part the remesh misses) or orange when
it lies on the remesh, labelled with the model's name and its Hausdorff
distance in percent of its bounding-box diagonal. On the SHREC'07 animals
and Spot the red points sit on the tips of tails, horns and hoofs beyond
the last landmark.

Usage: pvpython render_missed_tips.py PLUGIN.so REPORT.json OUTPUT.png
(REPORT.json written by, for example, `consistent-remesh --mesh ... --level
5 --lower-stretch --relax-samples 4 --no-render --output DIR`). The report
names the meshes and landmark files as they were given to
`consistent-remesh`: relative names are looked up from the current folder,
then from the report's.
"""
import json
import os
import sys
import tempfile

import numpy as np
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import aim, show_grey, white_view
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkImagingCore import vtkImageConstantPad
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter

TILE = (500, 380)
COLUMNS = 4

plugin, report_file, output = sys.argv[1:4]
LoadPlugin(plugin, ns=globals())
with open(report_file) as opened:
    report = json.load(opened)


def located(path):
    """`path` as given to consistent-remesh, found from here or from the
    report's folder."""
    beside_report = os.path.join(os.path.dirname(os.path.abspath(report_file)), path)
    return path if os.path.isabs(path) or os.path.exists(path) else beside_report


def side_view(points):
    """Camera direction (towards the camera) and view up for a side view of
    a four-legged animal: along its narrowest principal axis, up along the
    middle one, pointing to where its mass sits (legs are thin)."""
    centre = points.mean(axis=0)
    _, _, axes = np.linalg.svd(points - centre, full_matrices=False)
    box_centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    up = axes[1] if np.dot(centre - box_centre, axes[1]) >= 0.0 else -axes[1]
    return axes[2], up


def rotation_onto(moving, fixed):
    """The rotation R (Kabsch) that best turns the centred rows of `moving`
    onto those of `fixed`: fixed ~ moving @ R.T."""
    a = moving - moving.mean(axis=0)
    b = fixed - fixed.mean(axis=0)
    u, _, vt = np.linalg.svd(a.T @ b)
    flip = np.diag([1.0, 1.0, np.sign(np.linalg.det(u @ vt))])
    return (u @ flip @ vt).T


def read_model(model):
    """The model's surface proxy, its points and its landmarks' positions
    in FeatureId order."""
    surface = LandmarksFromFile(Input=ConsistentMeshSurfaceReader(FileName=located(model["mesh"])),
                                LandmarkFile=located(model["landmarks"]))
    mesh = servermanager.Fetch(surface)
    points = vtk_to_numpy(mesh.GetPoints().GetData())
    feature = vtk_to_numpy(mesh.GetPointData().GetArray("FeatureId"))
    order = np.flatnonzero(feature >= 0)
    order = order[np.argsort(feature[order])]
    return surface, points, feature, points[order]


def show_marker(centre, radius, colour, view):
    """A ball of the given colour at `centre`."""
    marker = Show(Sphere(Center=list(centre), Radius=radius), view)
    marker.ColorArrayName = [None, ""]
    marker.DiffuseColor = colour


def render_model(name, model, read, path, reference):
    """One tile of `model` (`read` is what read_model() gave), seen the way
    `reference` (the first model's landmarks and side view) is seen once
    this model's landmarks are turned onto its own, so every animal faces
    the same way."""
    surface, points, feature, landmarks = read
    reference_landmarks, (towards, up) = reference
    if len(landmarks) == len(reference_landmarks):
        rotation = rotation_onto(landmarks, reference_landmarks)
        towards, up = rotation.T @ towards, rotation.T @ up
    else:  # landmarks that do not correspond: its own side view
        towards, up = side_view(points)
    remesh = model["remesh"]
    nearest = remesh.get("hausdorff_nearest_landmark", -1)
    view = white_view(*TILE)
    show_grey(surface, view, edges=False).Opacity = 0.6  # markers behind the surface show through
    extent = np.linalg.norm(points.max(axis=0) - points.min(axis=0))
    for vertex in np.flatnonzero(feature >= 0):
        big = feature[vertex] == nearest
        show_marker(points[vertex], extent * (0.018 if big else 0.008), [0.1, 0.7, 0.1] if big else [0.2, 0.3, 0.9],
                    view)
    if remesh.get("hausdorff_point") is not None:
        on_model = remesh.get("hausdorff_point_on") == "input"
        show_marker(remesh["hausdorff_point"], extent * 0.018, [0.9, 0.1, 0.1] if on_model else [1.0, 0.55, 0.0],
                    view)
    label = Show(Text(Text="%s: %.1f%%" % (name, 100.0 * remesh["hausdorff_per_diagonal"])), view)
    label.Color = [0, 0, 0]
    label.FontSize = 22
    label.WindowLocation = "Upper Left Corner"
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    aim(view, centre, centre + 3.0 * extent * towards, up=up, scale=0.42 * extent)
    SaveScreenshot(path, view, ImageResolution=list(TILE))
    Delete(view)


def tile(paths, output):
    """The pictures in rows of COLUMNS, the first row on top, blank tiles
    where the last row is short."""
    rows = []
    for start in range(0, len(paths), COLUMNS):
        row = vtkImageAppend()
        row.SetAppendAxis(0)
        for path in paths[start:start + COLUMNS]:
            reader = vtkPNGReader()
            reader.SetFileName(path)
            row.AddInputConnection(reader.GetOutputPort())
        pad = vtkImageConstantPad()
        pad.SetInputConnection(row.GetOutputPort())
        pad.SetOutputWholeExtent(0, COLUMNS * TILE[0] - 1, 0, TILE[1] - 1, 0, 0)
        pad.SetConstant(255)
        rows.append(pad)
    grid = vtkImageAppend()
    grid.SetAppendAxis(1)
    for row in reversed(rows):  # images grow upwards
        grid.AddInputConnection(row.GetOutputPort())
    writer = vtkPNGWriter()
    writer.SetInputConnection(grid.GetOutputPort())
    writer.SetFileName(output)
    writer.Write()


folder = tempfile.mkdtemp()
models = [(name, model) for name, model in report["models"].items()
          if model.get("status") == "ok" and "remesh" in model]
if not models:
    sys.exit("render_missed_tips.py: no remeshed model in " + report_file)
paths, reference = [], None
for name, model in models:
    read = read_model(model)
    if reference is None:  # the first model: the side view every tile follows
        reference = (read[3], side_view(read[1]))
    paths.append(os.path.join(folder, name + ".png"))
    render_model(name, model, read, paths[-1], reference)
tile(paths, output)
print("wrote", output)
