"""What the documentation pictures share: a white render view without axes."""
from paraview.simple import CreateView


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
