"""PNG pictures of consistent-remesh results, drawn off screen with plain VTK.

A picture is a sheet of panels (one surface each, optionally labelled) that
share one view direction and one scale, so that shapes side by side compare
at a glance: the mean, the modes at plus and minus two standard deviations,
a grid of blends, a transferred texture. `run_pictures` makes those of the
stages a consistent-remesh run went through, each on its own.

ParaView's VTK on Debian draws through GLX: making a render window without a
reachable X server with GLX aborts the whole process, so `unavailable_reason`
asks Xlib first and the caller skips the pictures instead.
"""

import colorsys
import ctypes
import ctypes.util
import os
import time

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOImage import vtkImageReader2Factory, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkColorTransferFunction,
    vtkLightKit,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkTextActor,
    vtkTexture,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (the text actors' font backend)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the render window's implementation)

from . import array_names
from .figures import field_reader, landmark_points
from .summary import weights_text
from .vtkio import StageError, read_polydata

BACKGROUND = (1.0, 1.0, 1.0)
CLAY = (0.86, 0.80, 0.71)
TEXT = (0.1, 0.1, 0.1)
# The surface correspondence arrays every remesh carries: nothing to look at.
CORRESPONDENCE_ARRAYS = {array_names.FEATURE_ID_ARRAY, array_names.BASE_TRIANGLE_ARRAY,
                         array_names.BASE_COORDINATES_ARRAY, array_names.UNSPLIT_POINT_ID_ARRAY,
                         array_names.NORMALS_ARRAY, array_names.T_COORDS_ARRAY, array_names.VERTEX_LEVEL_ARRAY}
CURVE_COLOUR = (0.12, 0.12, 0.14)
TEXTURE_SIZE = 1024
TITLE_HEIGHT = 36  # pixels above the panels when a sheet has a title
AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1)}
# Rows of pca-modes.png: more would make the picture too large to read.
RENDERED_MODES = 3


class RenderError(Exception):
    """A picture could not be made or written; the message says why."""


def unavailable_reason():
    """None when a render window can be made here, otherwise why not."""
    display_name = os.environ.get("DISPLAY", "")
    if not display_name:
        return "no X display (DISPLAY is not set): run under xvfb-run -a to get the pictures"
    library = ctypes.util.find_library("X11") or "libX11.so.6"
    try:
        x11 = ctypes.CDLL(library)
    except OSError as error:
        return "cannot load the X library %s: %s" % (library, error)
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
    x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
    x11.XQueryExtension.argtypes = [ctypes.c_void_p, ctypes.c_char_p] + [ctypes.POINTER(ctypes.c_int)] * 3
    display = x11.XOpenDisplay(None)
    if not display:
        return "cannot open the X display %s: run under xvfb-run -a to get the pictures" % display_name
    try:
        codes = [ctypes.c_int() for _ in range(3)]
        if not x11.XQueryExtension(display, b"GLX", *[ctypes.byref(c) for c in codes]):
            return "the X display %s has no GLX extension, which VTK needs to draw" % display_name
    finally:
        x11.XCloseDisplay(display)
    return None


def parse_axis(text):
    """'y', '+y' or '-z' as a unit vector."""
    sign = -1.0 if text.startswith("-") else 1.0
    axis = text.lstrip("+-")
    if axis not in AXES:
        raise ValueError("give x, y or z with an optional sign, e.g. +y or -z")
    return sign * numpy.array(AXES[axis], dtype=float)


class View:
    """A side view: `up` as given (the data's up axis), looking along the
    direction perpendicular to it in which the reference shape is thinnest,
    which is across a four-legged animal's body, so its legs, back and head
    are all in sight."""

    def __init__(self, references, up):
        """`references`: the surfaces the view is made for, one or a list;
        each counts with its vertices around its own centre."""
        if not isinstance(references, (list, tuple)):
            references = [references]
        points = numpy.concatenate([points_of(r) - points_of(r).mean(axis=0) for r in references])
        up = numpy.asarray(up, dtype=float)
        up /= numpy.linalg.norm(up)
        # A basis of the plane perpendicular to up, then the covariance of
        # the points in that plane: its weakest direction is the thinnest.
        helper = numpy.eye(3)[numpy.argmin(numpy.abs(up))]
        a = numpy.cross(up, helper)
        a /= numpy.linalg.norm(a)
        b = numpy.cross(up, a)
        flat = (points - points.mean(axis=0)) @ numpy.column_stack([a, b])
        _, vectors = numpy.linalg.eigh(flat.T @ flat)
        direction = vectors[0, 0] * a + vectors[1, 0] * b
        # The camera stays on one side whatever sign the eigenvector came with.
        if direction[numpy.argmax(numpy.abs(direction))] < 0:
            direction = -direction
        self.direction = direction / numpy.linalg.norm(direction)  # from the model towards the camera
        self.up = up
        self.right = numpy.cross(up, self.direction)

    def extent(self, polydata):
        """(centre, width, height) of the surface seen in this view."""
        points = points_of(polydata)
        horizontal, vertical, depth = points @ self.right, points @ self.up, points @ self.direction
        low = numpy.array([horizontal.min(), vertical.min(), depth.min()])
        high = numpy.array([horizontal.max(), vertical.max(), depth.max()])
        middle = (low + high) / 2
        centre = middle[0] * self.right + middle[1] * self.up + middle[2] * self.direction
        return centre, high[0] - low[0], high[1] - low[1]


class Panel:
    """One surface in a sheet: plain, coloured by a point array, or
    textured."""

    def __init__(self, polydata, label=None, scalars=None, scalar_range=None, texture=None):
        self.polydata = polydata
        self.label = label
        self.scalars = scalars
        self.scalar_range = scalar_range
        self.texture = texture
        self.patches = None  # a cell array of patch ids, each drawn in its own colour
        self.curves = None  # polylines drawn over the surface


def patch_panel(surface, label, patches=array_names.PATCH_ID_ARRAY, curves=None):
    """A panel of `surface` with each patch (cell array `patches`) in its
    own colour, optionally with `curves` drawn over it."""
    panel = Panel(surface, label)
    panel.patches = patches
    panel.curves = curves
    return panel


class Sheet:
    """Panels in cells of `cell_size` pixels; a panel's cell is (column,
    row) from the top left, in cell units (halves allowed, for the triangle
    of a blend grid)."""

    def __init__(self, columns, rows, cell_size, title=None):
        self.columns = columns
        self.rows = rows
        self.cell_size = cell_size
        self.title = title
        self.panels = []

    def add(self, column, row, panel):
        self.panels.append((column, row, panel))

    def write(self, path, view, margin=1.05):
        width, height = self.columns * self.cell_size[0], self.rows * self.cell_size[1]
        title_height = TITLE_HEIGHT if self.title else 0
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetMultiSamples(8)
        window.SetSize(width, height + title_height)
        total_height = height + title_height
        # One scale for every panel, fitted to the largest.
        aspect = self.cell_size[0] / self.cell_size[1]
        extents = [view.extent(panel.polydata) for _, _, panel in self.panels]
        label_room = 1.12 if any(panel.label for _, _, panel in self.panels) else 1.0
        scale = margin * label_room * max(max(h / 2, w / 2 / aspect) for _, w, h in extents)
        # The whole window, under the panels: what no panel covers stays
        # white (a grid of blends is a triangle), and the title goes here.
        backdrop = vtkRenderer()
        backdrop.SetBackground(*BACKGROUND)
        if title_height:
            backdrop.AddActor2D(_text(self.title, 18, width / 2, height + title_height / 2 - 8, centred=True))
        window.AddRenderer(backdrop)
        for (column, row, panel), (centre, _, _) in zip(self.panels, extents):
            renderer = vtkRenderer()
            x0 = column * self.cell_size[0] / width
            y1 = 1.0 - (row * self.cell_size[1] + title_height) / total_height
            renderer.SetViewport(x0, y1 - self.cell_size[1] / total_height,
                                 x0 + self.cell_size[0] / width, y1)
            renderer.SetBackground(*BACKGROUND)
            renderer.AddActor(_actor(panel))
            if panel.curves is not None:
                renderer.AddActor(_curve_actor(panel.curves))
            if panel.label:
                renderer.AddActor2D(_text(panel.label, 15, self.cell_size[0] / 2, 8, centred=True))
            # The label sits below the shape: the camera looks a little
            # lower, which lifts the shape into the room left above it.
            focus = centre - (label_room - 1.0) * scale / label_room * view.up if panel.label else centre
            camera = renderer.GetActiveCamera()
            camera.ParallelProjectionOn()
            camera.SetFocalPoint(*focus)
            camera.SetPosition(*(focus + 10.0 * scale * view.direction))
            camera.SetViewUp(*view.up)
            camera.SetParallelScale(scale)
            renderer.ResetCameraClippingRange()
            vtkLightKit().AddLightsToRenderer(renderer)
            window.AddRenderer(renderer)
        try:
            window.Render()
            grab = vtkWindowToImageFilter()
            grab.SetInput(window)
            grab.ReadFrontBufferOff()
            grab.Update()
            writer = vtkPNGWriter()
            writer.SetFileName(path)
            writer.SetInputConnection(grab.GetOutputPort())
            writer.Write()
            if writer.GetErrorCode():
                raise RenderError("cannot write '%s'" % path)
        finally:
            window.Finalize()


def _text(text, size, x, y, centred=False):
    actor = vtkTextActor()
    actor.SetInput(text)
    properties = actor.GetTextProperty()
    properties.SetFontSize(size)
    properties.SetColor(*TEXT)
    if centred:
        properties.SetJustificationToCentered()
    # In pixels from the corner of the actor's own viewport, not the window's.
    actor.GetPositionCoordinate().SetCoordinateSystemToViewport()
    actor.GetPositionCoordinate().SetValue(x, y)
    return actor


def _actor(panel):
    normals = vtkPolyDataNormals()
    normals.SetInputData(panel.polydata)
    # Smooth shading over the whole surface: the remesh has no sharp edges
    # worth keeping, and splitting would show the patch layout as creases.
    normals.SplittingOff()
    normals.ConsistencyOff()
    normals.Update()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    properties = actor.GetProperty()
    properties.SetAmbient(0.12)
    properties.SetDiffuse(0.85)
    properties.SetSpecular(0.12)
    properties.SetSpecularPower(25)
    if panel.patches is not None:
        count = int(panel.polydata.GetCellData().GetArray(panel.patches).GetRange()[1]) + 1
        mapper.SetLookupTable(patch_colours(count))
        mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray(panel.patches)
        mapper.SetScalarRange(0, count - 1)
        mapper.ScalarVisibilityOn()
    elif panel.texture is not None:
        mapper.ScalarVisibilityOff()
        properties.SetColor(1, 1, 1)
        properties.SetSpecular(0.05)
        actor.SetTexture(panel.texture)
    elif panel.scalars is not None:
        low, high = panel.scalar_range
        colours = vtkColorTransferFunction()
        colours.AddRGBPoint(low, *CLAY)
        colours.AddRGBPoint(low + 0.5 * (high - low), 0.93, 0.55, 0.24)
        colours.AddRGBPoint(high, 0.70, 0.10, 0.08)
        mapper.SetLookupTable(colours)
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(panel.scalars)
        mapper.SetUseLookupTableScalarRange(True)
        mapper.ScalarVisibilityOn()
    else:
        mapper.ScalarVisibilityOff()
        properties.SetColor(*CLAY)
    return actor


def _curve_actor(curves):
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(curves)
    mapper.ScalarVisibilityOff()
    # Drawn over the surface they lie on, not half hidden in it.
    mapper.SetResolveCoincidentTopologyToPolygonOffset()
    mapper.SetRelativeCoincidentTopologyLineOffsetParameters(0, -66000)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*CURVE_COLOUR)
    actor.GetProperty().SetLineWidth(2.0)
    actor.GetProperty().LightingOff()
    return actor


def patch_colours(count):
    """`count` colours that neighbours can tell apart: hues stepped by the
    golden angle, light enough for the shading to read."""
    table = vtkLookupTable()
    table.SetNumberOfTableValues(max(count, 1))
    for index in range(max(count, 1)):
        hue = (index * 0.618033988749895) % 1.0
        saturation = 0.45 + 0.2 * (index % 3) / 2
        red, green, blue = colorsys.hsv_to_rgb(hue, saturation, 0.95)
        table.SetTableValue(index, red, green, blue, 1.0)
    table.SetTableRange(0, max(count - 1, 1))
    table.Build()
    return table


def read_texture(path):
    """A vtkTexture of the image at `path` (any format VTK reads)."""
    reader = vtkImageReader2Factory.CreateImageReader2(path)
    if reader is None:
        raise RenderError("cannot read the texture image '%s': not an image format VTK knows" % path)
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        raise RenderError("cannot read the texture image '%s'" % path)
    # Every picture is its own window, which uploads the texture again:
    # Spot's 4096 x 4096 image took a second a picture, and a picture
    # shows no more than this much of it anyway.
    width, height, _ = image.GetDimensions()
    factor = -(-max(width, height) // TEXTURE_SIZE)
    if factor > 1:
        image = _shrink(image, factor)
    return _texture(image)


def _shrink(image, factor):
    """`image` with each `factor` x `factor` block of pixels averaged into
    one (vtkImageResize takes seconds on a 4096 x 4096 image)."""
    width, height, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    components = scalars.GetNumberOfComponents()
    pixels = vtk_to_numpy(scalars).reshape(height, width, components)
    rows, columns = height // factor, width // factor
    blocks = pixels[:rows * factor, :columns * factor].reshape(rows, factor, columns, factor, components)
    averaged = blocks.mean(axis=(1, 3)).round().astype(pixels.dtype)
    small = vtkImageData()
    small.SetDimensions(columns, rows, 1)
    array = numpy_to_vtk(averaged.reshape(-1, components), deep=True, array_type=scalars.GetDataType())
    small.GetPointData().SetScalars(array)
    return small


def checkerboard_texture(squares=16, size=512):
    """Light and dark squares: shows how texture coordinates lie on a
    surface when the model's own texture image is not at hand."""
    index = numpy.arange(size) * squares // size
    dark = (index[:, None] + index[None, :]) % 2 == 1
    pixels = numpy.where(dark[..., None], [70, 110, 170], [235, 235, 225]).astype(numpy.uint8)
    image = vtkImageData()
    image.SetDimensions(size, size, 1)
    colours = vtkUnsignedCharArray()
    colours.SetNumberOfComponents(3)
    colours.SetNumberOfTuples(size * size)
    vtk_to_numpy(colours)[:] = pixels.reshape(-1, 3)
    image.GetPointData().SetScalars(colours)
    return _texture(image)


def _texture(image):
    texture = vtkTexture()
    texture.SetInputData(image)
    texture.InterpolateOn()
    return texture


def find_texture_image(mesh_path):
    """The image a model's texture coordinates refer to: STEM_texture.png
    beside the mesh, else the first map_Kd of the OBJ's material library;
    None if there is neither."""
    folder = os.path.dirname(os.path.abspath(mesh_path))
    stem = os.path.splitext(os.path.basename(mesh_path))[0]
    beside = os.path.join(folder, stem + "_texture.png")
    if os.path.isfile(beside):
        return beside
    if not mesh_path.lower().endswith(".obj"):
        return None
    try:
        with open(mesh_path, errors="replace") as obj:
            libraries = [line.split(None, 1)[1].strip() for line in obj
                         if line.startswith("mtllib") and len(line.split(None, 1)) == 2]
        for library in libraries:
            with open(os.path.join(folder, library), errors="replace") as mtl:
                for line in mtl:
                    words = line.split()
                    # map_Kd may carry options (-s 1 1 1 ...): the file name is last.
                    if len(words) >= 2 and words[0] == "map_Kd":
                        image = os.path.join(folder, words[-1])
                        if os.path.isfile(image):
                            return image
    except OSError:
        return None
    return None


def colour_array(polydata):
    """The first one-component point array that is not a correspondence
    array, or None."""
    arrays = polydata.GetPointData()
    for index in range(arrays.GetNumberOfArrays()):
        array = arrays.GetArray(index)
        if array is not None and array.GetName() not in CORRESPONDENCE_ARRAYS and array.GetNumberOfComponents() == 1:
            return array.GetName()
    return None


def rigid_motion(moving, fixed):
    """The rotation R and translation t that carry the points `moving` as
    close as they go to their counterparts `fixed` (least squares, the
    Kabsch method): fixed ~ moving @ R.T + t."""
    moving_centre, fixed_centre = moving.mean(axis=0), fixed.mean(axis=0)
    u, _, vt = numpy.linalg.svd((fixed - fixed_centre).T @ (moving - moving_centre))
    # A reflection is no motion: flip the weakest axis instead.
    d = numpy.sign(numpy.linalg.det(u @ vt)) or 1.0
    rotation = u @ numpy.diag([1.0, 1.0, d]) @ vt
    return rotation, fixed_centre - moving_centre @ rotation.T


def normalised(points):
    """`points` moved to their centre and scaled to a root-mean-square
    radius of 1: (points, centre, radius)."""
    centre = points.mean(axis=0)
    radius = float(numpy.sqrt(((points - centre) ** 2).sum(axis=1).mean())) or 1.0
    return (points - centre) / radius, centre, radius


def similarity_to(moving, fixed):
    """The map that brings the points `moving` to their centre and a unit
    root-mean-square radius and turns them as `fixed`, brought there too,
    stand (counterparts row by row): a function of a polydata.
    Shapes of very different sizes (a camel of 1.4 units, a triceratops
    of 20) then share one picture."""
    moving_unit, moving_centre, moving_radius = normalised(moving)
    fixed_unit, _, _ = normalised(fixed)
    rotation, _ = rigid_motion(moving_unit, fixed_unit)
    return lambda polydata: _with_points(polydata, ((points_of(polydata) - moving_centre) / moving_radius)
                                         @ rotation.T)


def moved(polydata, rotation, translation):
    """A copy of `polydata` with its points moved rigidly."""
    points = vtk_to_numpy(polydata.GetPoints().GetData()).astype(float)
    return _with_points(polydata, points @ rotation.T + translation)


def _with_points(polydata, points):
    copy = vtkPolyData()
    copy.ShallowCopy(polydata)
    vtk_points = vtkPoints()
    vtk_points.SetDataTypeToDouble()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points), deep=True))
    copy.SetPoints(vtk_points)
    return copy


def points_of(polydata):
    return vtk_to_numpy(polydata.GetPoints().GetData()).astype(float)


def displaced(polydata, displacement, factor):
    """A copy of `polydata` with every point moved by `factor` times the
    point array `displacement`."""
    shift = factor * vtk_to_numpy(polydata.GetPointData().GetArray(displacement)).astype(float)
    return _with_points(polydata, points_of(polydata) + shift)


def _magnitude(polydata, vectors, name):
    """Adds point array `name`: the length of point array `vectors`."""
    values = numpy.linalg.norm(vtk_to_numpy(polydata.GetPointData().GetArray(vectors)), axis=1)
    array = numpy_to_vtk(values, deep=True)
    array.SetName(name)
    polydata.GetPointData().AddArray(array)
    return float(values.max())


def picture_mean(mean, model_count, view, path):
    sheet = Sheet(1, 1, (900, 640), "Mean of %d models" % model_count)
    sheet.add(0, 0, Panel(mean))
    sheet.write(path, view)


def picture_modes(mean, deviations, ratios, view, path):
    """One row per mode: the mean moved by -2, 0 and +2 standard deviations
    along it, coloured by how far the mode moves each point, so that where
    a mode acts shows even where the change of shape is subtle."""
    sheet = Sheet(3, len(deviations), (400, 280),
                  "Modes at -2, 0, +2 standard deviations (colour: displacement along the mode)")
    for row, (deviation, ratio) in enumerate(zip(deviations, ratios)):
        mode = "%s%d" % (array_names.MODE_ARRAY_PREFIX, row)
        for column, factor in enumerate((-2.0, 0.0, 2.0)):
            shape = displaced(mean, mode, factor)
            largest = _magnitude(shape, mode, array_names.DISPLACEMENT_ARRAY)
            if column == 1:
                label = "%s: sd %.3g, %.1f %% of the variance" % (mode, deviation, 100 * ratio)
            else:
                label = "%s %+g sd" % (mode, factor)
            sheet.add(column, row, Panel(shape, label, array_names.DISPLACEMENT_ARRAY, (0.0, max(largest, 1e-30))))
    sheet.write(path, view)


def picture_blend_grid(entries, columns, rows, title, view, path):
    """`entries`: (column, row, surface, label) for each blend."""
    sheet = Sheet(columns, rows, (300, 230), title)
    for column, row, surface, label in entries:
        sheet.add(column, row, Panel(surface, label))
    sheet.write(path, view)


def picture_single(surface, label, view, texture, scalars, path):
    """One surface, plain, textured, or coloured by point array `scalars`."""
    scalar_range = None
    if scalars is not None:
        scalar_range = surface.GetPointData().GetArray(scalars).GetRange()
    sheet = Sheet(1, 1, (800, 600), label)
    sheet.add(0, 0, Panel(surface, None, scalars, scalar_range, texture))
    sheet.write(path, view)


def picture_patches(entries, title, view, path, columns=3):
    """`entries`: (surface, curves or None, label) per model, in a grid of
    `columns`; every surface coloured by its PatchId."""
    rows = -(-len(entries) // columns)
    sheet = Sheet(min(columns, len(entries)), rows, (420, 320), title)
    for index, (surface, curves, label) in enumerate(entries):
        sheet.add(index % columns, index // columns, patch_panel(surface, label, curves=curves))
    sheet.write(path, view)


class Pictures:
    """The PNGs of the run, each made on its own so that one failure does
    not stop the others."""

    def __init__(self, output_folder, up):
        self.output_folder = output_folder
        self.up = up
        self.files = []
        self.notes = []
        self.errors = {}

    def make(self, name, function, *args):
        path = os.path.join(self.output_folder, name)
        try:
            function(*args, path)
            self.files.append(name)
        except (RenderError, StageError) as error:
            self.errors[name] = str(error)

    def view(self, surface):
        return View(surface, self.up)


def make_pictures(pictures, stages, models):
    """Draws what the stages in `stages` (name -> what its picture needs)
    produced."""
    overview = stages.get("overview")
    if overview is not None:
        make_overview_pictures(pictures, *overview)
    pca = stages.get("pca")
    if pca is not None:
        mean, figures = pca
        view = pictures.view(mean)
        pictures.make("mean.png", picture_mean, mean, len(figures["models"]), view)
        shown = min(figures["modes"], RENDERED_MODES)
        if shown:
            pictures.make("pca-modes.png", picture_modes, mean, figures["standard_deviations"][:shown],
                          figures["explained_variance_ratios"][:shown], view)
        else:
            pictures.notes.append("pca-modes.png: the collection has no mode of variation to show")
    grid = stages.get("blend_grid")
    if grid is not None:
        (entries, (columns, rows)), names = grid
        if len(names) == 3:
            title = "Blends of %s (top), %s (bottom left), %s (bottom right)" % tuple(names)
        else:
            title = "Blends from %s (left) to %s (right)" % tuple(names)
        pictures.make("blend-grid.png", picture_blend_grid, entries, columns, rows, title,
                      pictures.view([surface for _, _, surface, _ in entries]))
    blend = stages.get("blend")
    if blend is not None:
        surface, weights = blend
        pictures.make("blend.png", picture_single, surface, "Blend with weights %s" % weights_text(weights),
                      pictures.view(surface), None, None)
    transfer = stages.get("transfer")
    if transfer is not None:
        figures, remeshes = transfer
        make_transfer_pictures(pictures, figures, next(m for m in models if m.name == figures["source"]), remeshes)


def make_overview_pictures(pictures, ready, remeshes):
    """inputs.png: every parameterized model with its straightened net,
    coloured by patch; remeshes.png: every remesh coloured by the base
    triangle it samples. A patch has the same colour on every model, and
    each model is scaled to one size and turned as the first one stands
    (by its remesh, or its landmarks if the remeshing failed)."""
    first = ready[0]
    remesh = _block_by_name(remeshes) if remeshes is not None else {}

    def correspondence(model):
        if model.name in remesh:
            return points_of(remesh[model.name])
        return points_of(model.parameterized)[landmark_points(model.parameterized)]

    reference = correspondence(first)
    places = {m.name: similarity_to(correspondence(m), reference) for m in ready}
    inputs = [(places[m.name](m.parameterized), places[m.name](m.curves), m.name) for m in ready]
    view = pictures.view([surface for surface, _, _ in inputs])
    pictures.make("inputs.png", picture_patches, inputs,
                  "The models and their patch layouts (a patch has one colour on every model)", view)
    if remesh:
        level = int(field_reader(remesh[first.name])(array_names.REMESH_LEVEL_FIELD))
        remeshed = [(places[m.name](remesh[m.name]), None, m.name) for m in ready]
        pictures.make("remeshes.png", picture_patches, remeshed,
                      "Remeshes of level %d: one connectivity, coloured by base triangle" % level, view)


def _block_by_name(blocks):
    return {blocks.GetMetaData(i).Get(vtkCompositeDataSet.NAME()): blocks.GetBlock(i)
            for i in range(blocks.GetNumberOfBlocks())}


def make_transfer_pictures(pictures, figures, source, remeshes):
    """TARGET.from-SOURCE.png per target: the source's texture image on the
    target when there is one; else a checkerboard on the transferred
    texture coordinates, or the first transferred point array in colour.
    Each target is turned as the source stands (collections come in every
    orientation), by the rigid motion that best carries its remesh vertices
    onto the source's, so all are seen from the same side."""
    remesh = _block_by_name(remeshes)
    source_points = points_of(remesh[source.name])
    view = pictures.view(remesh[source.name])
    image = find_texture_image(source.mesh_path)
    texture = None
    if image is not None:
        try:
            texture = read_texture(image)
        except RenderError as error:
            pictures.notes.append("%s; the transfers are drawn without it" % error)
    checker = None
    for target in figures["targets"]:
        name = "%s.from-%s" % (target, source.name)
        try:
            surface = read_polydata(os.path.join(pictures.output_folder, name + ".vtp"))
        except StageError as error:
            pictures.errors[name + ".png"] = str(error)
            continue
        surface = moved(surface, *rigid_motion(points_of(remesh[target]), source_points))
        title = "%s's %%s on %s" % (source.name, target)
        if surface.GetPointData().GetTCoords() is not None:
            if texture is None:
                if checker is None:
                    if "texture_coordinates" in figures:
                        note = ("%s has no texture: the cylindrical texture coordinates it got are drawn with a "
                                "checkerboard" % source.name)
                    else:
                        note = ("no texture image beside %s (%s_texture.png or map_Kd of its .mtl): its texture "
                                "coordinates are drawn with a checkerboard" % (source.mesh_path, source.name))
                    pictures.notes.append(note)
                    checker = checkerboard_texture()
                pictures.make(name + ".png", picture_single, surface, title % "texture coordinates",
                              view, checker, None)
            else:
                pictures.make(name + ".png", picture_single, surface, title % "texture",
                              view, texture, None)
            continue
        array = colour_array(surface)
        if array is None:
            pictures.notes.append("%s.png: %s has neither texture coordinates nor a point array to colour by"
                                  % (name, source.name))
            continue
        pictures.make(name + ".png", picture_single, surface, title % array, view, None, array)


def run_pictures(args, stages, models):
    """The pictures of the stages that ran: the report's "renders"."""
    if args.no_render:
        return {"skipped": "--no-render"}
    reason = unavailable_reason()
    if reason is not None:
        return {"skipped": reason}
    print("rendering", flush=True)
    pictures = Pictures(args.output, args.view_up)
    start = time.perf_counter()
    make_pictures(pictures, stages, models)
    figures = {"files": pictures.files, "seconds": round(time.perf_counter() - start, 4)}
    if pictures.notes:
        figures["notes"] = pictures.notes
    if pictures.errors:
        figures["errors"] = pictures.errors
    return figures
