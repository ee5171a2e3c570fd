#!/usr/bin/pvpython
"""Renders the models of the CGAL faces collection with their numbered
landmarks and their boundary loop, to check the placements by eye.

  pvpython render_face_landmarks.py [NAME...] [--views front,below] [--zoom 1.2]
                                    [--output faces.png]

One column per model (default: all three), one row per view. Views are
seen from the model's frame (forward, up, right):

  front   from the front (the face);
  below   from behind and below, looking into the neck's opening (on the
          mask: at the back of the mask, whose rim is the boundary);
  right, left, back, top, bottom, three-quarter (from front-right-below),
  three-quarter-left (from front-left-below).

The surface is drawn beige from outside and blue from inside (its back
faces); the boundary loop is a green line with small arrow heads showing its
direction (the direction in which a boundary edge (a, b) appears in its
triangle); face landmarks are red, boundary landmarks green; a landmark
hidden by the surface in a view, or a face landmark seen from inside, is
not drawn there. The meshes are
read from the libcgal-demo data archive and the landmarks from
../NAME.landmarks. Needs an X display (xvfb-run -a).
"""

import argparse
import os
import sys
import tarfile

import numpy
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text rendering)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (render window)
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkProperty, vtkRenderer,
                                         vtkRenderWindow, vtkTextActor, vtkWindowToImageFilter)

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import pick_face_landmarks as pick  # noqa: E402

# Camera direction per view, in frame axes (forward, up, right), and the
# screen's up in frame axes.
VIEWS = {
    "front": ((1, 0, 0), (0, 1, 0)),
    "below": ((-1, -1.2, 0), (1, -0.8, 0)),
    "right": ((0, 0, 1), (0, 1, 0)),
    "left": ((0, 0, -1), (0, 1, 0)),
    "back": ((-1, 0, 0), (0, 1, 0)),
    "top": ((0, 1, 0), (1, 0, 0)),
    "bottom": ((0, -1, 0), (1, 0, 0)),
    "three-quarter": ((1, -0.4, 0.8), (0, 1, 0)),
    "three-quarter-left": ((1, -0.4, -0.8), (0, 1, 0)),
}


def polydata(points, triangles=None, lines=None):
    """A vtkPolyData of triangles (or of one polyline through `lines`)."""
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points, float), deep=True))
    surface = vtkPolyData()
    surface.SetPoints(vtk_points)
    cells = vtkCellArray()
    if triangles is not None:
        offsets = numpy.arange(0, 3 * len(triangles) + 1, 3)
        cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                      numpy_to_vtkIdTypeArray(numpy.ascontiguousarray(triangles).ravel(), deep=True))
        surface.SetPolys(cells)
    else:
        offsets = numpy.array([0, len(lines)])
        cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                      numpy_to_vtkIdTypeArray(numpy.asarray(lines), deep=True))
        surface.SetLines(cells)
    return surface


def read_landmark_ids(path):
    """Ids of a landmark file (`ID` per line, `#` comments)."""
    ids = []
    with open(path) as lines:
        for line in lines:
            words = line.split("#", 1)[0].split()
            if words:
                ids.append(int(words[-1]))
    return ids


def actor(source, colour, width=None, output_port=False):
    """An actor of a vtkPolyData (or of an algorithm's output)."""
    mapper = vtkPolyDataMapper()
    if output_port:
        mapper.SetInputConnection(source.GetOutputPort())
    else:
        mapper.SetInputData(source)
    mapper.ScalarVisibilityOff()
    result = vtkActor()
    result.SetMapper(mapper)
    result.GetProperty().SetColor(*colour)
    if width:
        result.GetProperty().SetLineWidth(width)
        result.GetProperty().SetLighting(False)
    return result


class Model:
    """A mesh of the collection with its frame, loop and landmarks."""

    def __init__(self, archive, name, landmarks=None):
        text = archive.extractfile(pick.MESH_MEMBER % name).read().decode()
        self.name = name
        self.points, self.triangles = pick.read_off(text)
        self.frame = pick.Frame(self.points, *pick.MODELS[name]["frame"])
        self.loop = pick.boundary_loop(self.triangles)
        self.ids = read_landmark_ids(landmarks or os.path.join(os.path.dirname(HERE), name + ".landmarks"))
        corners = self.points[self.triangles]
        self.corner_a = corners[:, 0]
        self.edge_ab = corners[:, 1] - corners[:, 0]
        self.edge_ac = corners[:, 2] - corners[:, 0]
        normals = numpy.zeros_like(self.points)
        for k in range(3):
            numpy.add.at(normals, self.triangles[:, k], numpy.cross(self.edge_ab, self.edge_ac))
        self.normals = normals / numpy.linalg.norm(normals, axis=1)[:, None]
        self.boundary = set(self.loop)
        self.diagonal = numpy.linalg.norm(self.points.max(axis=0) - self.points.min(axis=0))

    def visible_from(self, eye, v):
        """Whether vertex v is seen from `eye`: from outside the surface
        (unless v is on the boundary), and no triangle but its own crosses
        the segment from `eye` to it (Moller-Trumbore on every triangle)."""
        towards = self.points[v] - eye
        if v not in self.boundary and self.normals[v] @ towards >= 0:
            return False
        p = numpy.cross(towards, self.edge_ac)
        det = numpy.einsum("ij,ij->i", self.edge_ab, p)
        ok = numpy.abs(det) > 1e-300
        inverse = numpy.where(ok, 1.0 / numpy.where(ok, det, 1.0), 0.0)
        offset = eye - self.corner_a
        u = numpy.einsum("ij,ij->i", offset, p) * inverse
        q = numpy.cross(offset, self.edge_ab)
        w = (q @ towards) * inverse
        t = numpy.einsum("ij,ij->i", self.edge_ac, q) * inverse
        own = (self.triangles == v).any(axis=1)
        hit = ok & ~own & (u >= 0) & (w >= 0) & (u + w <= 1) & (t > 0) & (t < 1 - 1e-9)
        return not hit.any()


def add_view(window, viewport, model, view, options):
    """One renderer: the model seen from `view`, with its boundary loop and
    the landmarks seen from the camera; returns it, the glyph actors and
    the features shown."""
    renderer = vtkRenderer()
    renderer.SetViewport(*viewport)
    renderer.SetBackground(1, 1, 1)
    normals = vtkPolyDataNormals()
    normals.SetInputData(polydata(model.points, model.triangles))
    normals.SplittingOff()
    normals.ConsistencyOff()
    normals.AutoOrientNormalsOff()
    surface = actor(normals, (0.85, 0.78, 0.65), output_port=True)
    inside = vtkProperty()
    inside.SetColor(0.45, 0.6, 0.9)
    surface.SetBackfaceProperty(inside)
    if options.edges:
        surface.GetProperty().EdgeVisibilityOn()
        surface.GetProperty().SetEdgeColor(0.55, 0.5, 0.45)
    renderer.AddActor(surface)
    loop = model.loop + [model.loop[0]]
    renderer.AddActor(actor(polydata(model.points[loop], lines=numpy.arange(len(loop))), (0.0, 0.55, 0.0), 4))
    spheres = []
    radius = options.radius * model.diagonal
    # The loop's direction: a small arrow head on every third edge.
    for a, b in list(zip(model.loop, model.loop[1:] + model.loop[:1]))[::3]:
        cone = vtkConeSource()
        cone.SetCenter(*(0.5 * (model.points[a] + model.points[b])))
        cone.SetDirection(*(model.points[b] - model.points[a]))
        cone.SetHeight(1.6 * radius)
        cone.SetRadius(0.55 * radius)
        cone.SetResolution(12)
        spheres.append(actor(cone, (0.0, 0.35, 0.0), output_port=True))
    direction, up = VIEWS[view]
    axes = model.frame.rotation
    direction = numpy.asarray(direction, float) @ axes
    direction /= numpy.linalg.norm(direction)
    if options.focus:
        centre = model.points[[model.ids[int(k)] for k in options.focus.split(",")]].mean(axis=0)
    else:
        centre = (model.points.max(axis=0) + model.points.min(axis=0)) / 2
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + 3 * model.diagonal * direction))
    camera.SetViewUp(*(numpy.asarray(up, float) @ axes))
    renderer.ResetCamera()
    camera.SetFocalPoint(*centre)
    camera.Zoom(options.zoom)
    renderer.ResetCameraClippingRange()
    shown = [k for k, v in enumerate(model.ids) if model.visible_from(numpy.array(camera.GetPosition()), v)]
    for k in shown:
        v = model.ids[k]
        sphere = vtkSphereSource()
        sphere.SetCenter(*model.points[v])
        sphere.SetRadius(radius)
        sphere.SetThetaResolution(16)
        sphere.SetPhiResolution(16)
        colour = (0.9, 0.1, 0.1) if k < pick.INTERIOR else (0.0, 0.7, 0.0)
        spheres.append(actor(sphere, colour, output_port=True))
    for sphere in spheres:
        renderer.AddActor(sphere)
    window.AddRenderer(renderer)
    return renderer, spheres, shown


def labels(renderer, model, shown, font_size):
    """Numbers of the landmarks `shown`, drawn beside them."""
    texts = []
    for k in shown:
        renderer.SetWorldPoint(*model.points[model.ids[k]], 1.0)
        renderer.WorldToDisplay()
        x, y, _ = renderer.GetDisplayPoint()
        text = vtkTextActor()
        text.SetInput(str(k))
        text.SetDisplayPosition(int(x) + 5, int(y) + 3)
        text.GetTextProperty().SetFontSize(font_size)
        text.GetTextProperty().SetColor((0, 0, 0.8) if k < pick.INTERIOR else (0, 0.4, 0))
        text.GetTextProperty().BoldOn()
        texts.append(text)
    return texts


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", default=list(pick.MODELS))
    parser.add_argument("--archive", default=pick.DEFAULT_ARCHIVE)
    parser.add_argument("--views", default="front,below")
    parser.add_argument("--focus", help="comma-separated features to centre on, e.g. 0,6")
    parser.add_argument("--zoom", type=float, default=1.15)
    parser.add_argument("--radius", type=float, default=0.012, help="sphere radius / diagonal")
    parser.add_argument("--size", type=int, default=520, help="pixels per view")
    parser.add_argument("--edges", action="store_true", help="draw the mesh's edges")
    parser.add_argument("--titles", action="store_true", help="write each model's name above its column")
    parser.add_argument("--output", default="faces.png")
    options = parser.parse_args()

    with tarfile.open(options.archive) as archive:
        models = [Model(archive, name) for name in options.names]
    views = options.views.split(",")
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(options.size * len(models), options.size * len(views))
    panes = []
    for column, model in enumerate(models):
        for row, view in enumerate(views):
            viewport = (column / len(models), 1 - (row + 1) / len(views),
                        (column + 1) / len(models), 1 - row / len(views))
            panes.append((model, row) + add_view(window, viewport, model, view, options))
    window.Render()
    for model, row, renderer, _, shown in panes:
        for text in labels(renderer, model, shown, options.size // 26):
            renderer.AddActor2D(text)
        if options.titles and row == 0:
            title = vtkTextActor()
            title.SetInput(model.name)
            x0, _, _, y1 = renderer.GetViewport()
            width, height = window.GetSize()
            title.SetDisplayPosition(int(x0 * width) + 10, int(y1 * height) - options.size // 14)
            title.GetTextProperty().SetFontSize(options.size // 22)
            title.GetTextProperty().SetColor(0, 0, 0)
            renderer.AddActor2D(title)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetFileName(options.output)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    return 0


if __name__ == "__main__":
    sys.exit(main())
