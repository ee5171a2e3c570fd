#!/usr/bin/pvpython
"""Renders a model of the CGAL quadruped collection with its numbered
landmarks, seen from the sides of its anatomical frame, to check the
placements by eye.

  pvpython render_landmarks.py NAME [--views right,left,front] [--focus 0,1 --zoom 3]
  pvpython render_landmarks.py NAME --remesh RUN/NAME.remesh.vtp

The mesh is read from the libcgal-demo data archive and the landmarks from
../NAME.landmarks (or --landmarks FILE); with --remesh, the remesh is drawn
instead with its FeatureId vertices as landmarks. Needs an X display
(xvfb-run -a) and writes NAME.png (or --output FILE).
"""

import argparse
import os
import sys
import tarfile

import numpy
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text rendering)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (render window)
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkTextActor, vtkWindowToImageFilter)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pick_landmarks  # noqa: E402

# Camera direction per view, in frame axes (forward, up, right), and the
# frame axis that points up on the screen.
VIEWS = {
    "right": ((0, 0, 1), 1), "left": ((0, 0, -1), 1),
    "front": ((1, 0, 0), 1), "back": ((-1, 0, 0), 1),
    "top": ((0, 1, 0), 0), "bottom": ((0, -1, 0), 0),
}


def polydata(points, triangles):
    """A vtkPolyData of triangles."""
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points, float), deep=True))
    cells = vtkCellArray()
    offsets = numpy.arange(0, 3 * len(triangles) + 1, 3)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(numpy.ascontiguousarray(triangles).ravel(), deep=True))
    surface = vtkPolyData()
    surface.SetPoints(vtk_points)
    surface.SetPolys(cells)
    return surface


def read_landmark_ids(path):
    """Ids of a landmark file (`ID` or `lk ID` per line, `#` comments)."""
    ids = []
    with open(path) as lines:
        for line in lines:
            words = line.split("#", 1)[0].split()
            if words:
                ids.append(int(words[-1]))
    return ids


def remesh_with_landmarks(path):
    """A remesh and its landmark vertices (FeatureId f on vertex f)."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    surface = reader.GetOutput()
    feature = vtk_to_numpy(surface.GetPointData().GetArray("FeatureId"))
    ids = [int(numpy.flatnonzero(feature == f)[0]) for f in range(int(feature.max()) + 1)]
    return surface, vtk_to_numpy(surface.GetPoints().GetData()), ids


def add_view(window, viewport, surface, points, ids, centre, frame_axes, view, options):
    """One renderer: the surface and a sphere per landmark, seen from side
    `view` of the frame, looking at `centre`."""
    renderer = vtkRenderer()
    renderer.SetViewport(*viewport)
    renderer.SetBackground(1, 1, 1)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(surface)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.8, 0.75, 0.65)
    renderer.AddActor(actor)
    diagonal = numpy.linalg.norm(points.max(axis=0) - points.min(axis=0))
    for v in ids:
        sphere = vtkSphereSource()
        sphere.SetCenter(*points[v])
        sphere.SetRadius(options.radius * diagonal)
        sphere_mapper = vtkPolyDataMapper()
        sphere_mapper.SetInputConnection(sphere.GetOutputPort())
        sphere_actor = vtkActor()
        sphere_actor.SetMapper(sphere_mapper)
        sphere_actor.GetProperty().SetColor(0.9, 0.1, 0.1)
        renderer.AddActor(sphere_actor)
    direction, up_axis = VIEWS[view]
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + 2 * diagonal * (numpy.asarray(direction) @ frame_axes)))
    camera.SetViewUp(*frame_axes[up_axis])
    renderer.ResetCamera()
    camera.SetFocalPoint(*centre)
    camera.Zoom(options.zoom)
    renderer.ResetCameraClippingRange()
    window.AddRenderer(renderer)
    return renderer


def label(renderer, points, ids, numbers, font_size):
    """Numbers drawn over the scene (so that no surface hides them)."""
    for number, v in zip(numbers, ids):
        renderer.SetWorldPoint(*points[v], 1.0)
        renderer.WorldToDisplay()
        x, y, _ = renderer.GetDisplayPoint()
        text = vtkTextActor()
        text.SetInput(str(number))
        text.SetDisplayPosition(int(x) + 4, int(y) + 4)
        text.GetTextProperty().SetFontSize(font_size)
        text.GetTextProperty().SetColor(0, 0, 0.8)
        text.GetTextProperty().BoldOn()
        renderer.AddActor2D(text)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("name")
    parser.add_argument("--archive", default=pick_landmarks.DEFAULT_ARCHIVE)
    parser.add_argument("--landmarks", help="default: ../NAME.landmarks")
    parser.add_argument("--remesh", help="draw this NAME.remesh.vtp instead of the input mesh")
    parser.add_argument("--views", default="right,left,front,bottom")
    parser.add_argument("--focus", help="comma-separated features to centre on, e.g. 0,1 for the head")
    parser.add_argument("--zoom", type=float, default=1.3)
    parser.add_argument("--radius", type=float, default=0.008, help="sphere radius / diagonal")
    parser.add_argument("--size", type=int, default=600)
    parser.add_argument("--output")
    options = parser.parse_args()

    if options.remesh:
        surface, points, ids = remesh_with_landmarks(options.remesh)
    else:
        with tarfile.open(options.archive) as archive:
            text = archive.extractfile(pick_landmarks.MESH_MEMBER % options.name).read().decode()
        points, triangles = pick_landmarks.read_off(text)
        surface = polydata(points, triangles)
        ids = read_landmark_ids(options.landmarks or os.path.join(os.path.dirname(here), options.name + ".landmarks"))
    frame = pick_landmarks.Frame(points, *pick_landmarks.MODELS[options.name]["frame"])
    if options.focus:
        centre = points[[ids[int(k)] for k in options.focus.split(",")]].mean(axis=0)
    else:
        centre = (points.max(axis=0) + points.min(axis=0)) / 2
    views = options.views.split(",")
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(options.size * len(views), options.size)
    renderers = []
    for k, view in enumerate(views):
        viewport = (k / len(views), 0, (k + 1) / len(views), 1)
        renderers.append(add_view(window, viewport, surface, points, ids, centre, frame.rotation, view, options))
    window.Render()
    for renderer in renderers:
        label(renderer, points, ids, range(len(ids)), options.size // 28)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(options.output or options.name + ".png")
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    return 0


if __name__ == "__main__":
    sys.exit(main())
