"""What the documentation pictures share: white render views without axes,
two of them side by side, a grey remesh, curves, folded triangles in red, a
camera aimed in one call."""
from paraview.simple import AssignViewToLayout, CreateLayout, CreateView, Show, Threshold


def white_view(width, height):
    """A render view of the given size with a white background and no
    orientation axes, whatever the user's color palette says."""
    view = CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:  # ParaView versions without palettes
        pass
    return view


def landmarked_shrec(names, data, model):
    """A SHREC'07 model of the shared data read and given its landmarks,
    with the plugin's proxy functions found in `names` (where LoadPlugin put
    them)."""
    folder = data + "/shrec07-fourleg/"
    reader = names["ConsistentMeshSurfaceReader"](FileName=folder + model + ".off")
    return names["LandmarksFromFile"](Input=reader, LandmarkFile=folder + model + ".vts")


def side_by_side(title, width=700, height=600):
    """A layout of two white views of the given size, left and right: the
    layout and the two views."""
    layout = CreateLayout(title)
    layout.SplitHorizontal(0, 0.5)
    views = []
    for cell in (1, 2):
        view = white_view(width, height)
        AssignViewToLayout(view=view, layout=layout, hint=cell)
        views.append(view)
    return layout, views


def show_grey(port, view, edges=True):
    """`port` shown in light grey, with dark edges unless `edges` is false."""
    shown = Show(port, view)
    shown.SetRepresentationType("Surface With Edges" if edges else "Surface")
    shown.ColorArrayName = [None, ""]
    shown.DiffuseColor = [0.85, 0.85, 0.85]
    if edges:
        shown.EdgeColor = [0.25, 0.25, 0.25]
    return shown


def show_curves(port, view, grey, width):
    """The polylines of `port` (a layout's curves) in the grey level `grey`
    (0 black, 1 white), `width` pixels wide."""
    shown = Show(port, view)
    shown.SetRepresentationType("Wireframe")
    shown.ColorArrayName = [None, ""]
    shown.AmbientColor = shown.DiffuseColor = [grey] * 3
    shown.LineWidth = width
    return shown


def show_folds(remesh, view):
    """The triangles of `remesh` that face against their surface (cell array
    Folded) as thick red outlines: they are needles, too thin to see filled."""
    folds = Threshold(Input=remesh, Scalars=["CELLS", "Folded"])
    folds.LowerThreshold, folds.UpperThreshold = 0.5, 1.5
    shown = Show(folds, view)
    shown.SetRepresentationType("Wireframe")
    shown.ColorArrayName = [None, ""]
    shown.AmbientColor = shown.DiffuseColor = [0.9, 0.05, 0.05]
    shown.LineWidth = 3
    return shown


def aim(view, focus, position, up=(0, 1, 0), scale=None, angle=None):
    """Points the camera of `view` from `position` at `focus`: a parallel
    projection of half-height `scale`, or a perspective of view `angle`."""
    view.CameraFocalPoint = list(focus)
    view.CameraPosition = list(position)
    view.CameraViewUp = list(up)
    if scale is not None:
        view.CameraParallelProjection = 1
        view.CameraParallelScale = scale
    elif angle is not None:
        view.CameraViewAngle = angle
