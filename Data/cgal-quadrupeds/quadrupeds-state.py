# ParaView state (File > Load State, or `paraview --state=THIS_FILE`): the
# whole consistent-parameterization pipeline on the default collection, the
# five CGAL quadrupeds of Debian's libcgal-demo.
#
# Every model is read and landmarked, the five are grouped, traced,
# straightened and remeshed in one run (one connectivity), then analysed
# (Mesh PCA) and blended (Shape Blend). Two views: the triceratops with its
# straightened patch layout, and the collection's mean remesh with its edges,
# both coloured by base triangle.
#
# It is a Python state because the meshes are not files of this project: they
# are unpacked from /usr/share/doc/libcgal-dev/data.tar.gz into a cache (as
# `consistent-remesh` does), which needs the consistent_mesh Python package,
# and a .pvsm could only hold one machine's paths. The plugin and the package
# are looked for in the build tree beside this file (build/), else where
# PV_PLUGIN_PATH and PYTHONPATH point, or an installed copy.
import glob
import os
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's state style)
import paraview.simple as simple

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.join(HERE, "..", "..", "build")
PLUGIN = "ConsistentMeshParameterizations"


def load_plugin():
    """The plugin's proxies in this script's namespace: already loaded (the
    GUI autoloads it from PV_PLUGIN_PATH), else from the build tree."""
    if hasattr(simple, "FeatureNetTracer"):
        return
    built = os.path.join(BUILD, "lib", "paraview-plugins", PLUGIN, PLUGIN + ".so")
    if os.path.isfile(built):
        LoadPlugin(built, remote=False, ns=globals())
    else:
        LoadDistributedPlugin(PLUGIN, remote=False, ns=globals())
    if "FeatureNetTracer" not in globals():
        raise RuntimeError("the %s plugin is not loaded: load it with Tools > Manage Plugins, or set "
                           "PV_PLUGIN_PATH to its folder" % PLUGIN)


def default_collection():
    """The collection (consistent_mesh.collection.Collection) of this
    folder, its meshes unpacked."""
    for site in sorted(glob.glob(os.path.join(BUILD, "lib", "python3*", "site-packages"))):
        if site not in sys.path:
            sys.path.insert(0, site)
    try:
        from consistent_mesh import collection
    except ImportError as error:
        raise RuntimeError("cannot import the consistent_mesh package (%s): build the project beside this "
                           "file, or put its site-packages on PYTHONPATH" % error)
    data = collection.Collection(HERE)
    data.unpack(lambda message: print(message))
    return data


def function(name):
    """A proxy function, wherever the plugin put it."""
    return globals().get(name) or getattr(simple, name)


load_plugin()
data = default_collection()
names = [name for name, _, _, _ in data.models]

landmarked = []
for name, mesh, landmarks in zip(names, data.mesh_paths(), data.landmark_paths()):
    reader = function("ConsistentMeshSurfaceReader")(registrationName=name, FileName=mesh)
    landmarked.append(function("LandmarksFromFile")(registrationName=name + " landmarks", Input=reader,
                                                    LandmarkFile=landmarks))
base = XMLPolyDataReader(registrationName="L0 (base domain)", FileName=[data.base_domain])
group = GroupDatasets(registrationName="collection", Input=landmarked, BlockNames=names)
tracer = function("FeatureNetTracer")(registrationName="Feature Net Tracer", Input=group, BaseDomain=base)
straightener = function("NetStraightener")(registrationName="Net Straightener", Input=tracer, BaseDomain=base)
remesher = function("SemiRegularRemesher")(registrationName="Semi-Regular Remesher", Input=straightener,
                                           BaseDomain=base, Level=data.stages.get("level", 4),
                                           SampleRelaxationIterations=data.stages.get("relax_samples", 0))
pca = function("MeshPCA")(registrationName="Mesh PCA", Input=remesher, NumberOfModes=data.stages.get("pca", 3))
# Half the first model, a quarter each of the next two: the collection's
# blend grid's middle.
function("ShapeBlend")(registrationName="Shape Blend", Input=remesher,
                       Weights=[0.5, 0.25, 0.25] + [0.0] * (len(names) - 3))
base.UpdatePipeline()
patch_count = base.GetDataInformation().GetNumberOfCells()



def view_of(sources_and_styles, camera_direction, block=None):
    """A white render view showing each (source, style); style "patches"
    colours by PatchId, "edges" also shows the triangles, "lines" is a
    black net. `block`: the one block of a collection to show (a display
    setting: an Extract Block filter would do as well, but the GUI takes
    its block list for an edit not yet applied)."""
    view = CreateView("RenderView")
    view.Background = [1.0, 1.0, 1.0]
    view.UseColorPaletteForBackground = 0
    view.OrientationAxesVisibility = 0
    for source, style in sources_and_styles:
        display = Show(source, view)
        if block is not None:
            display.BlockSelectors = ["/Root/" + block]
        if style == "lines":
            display.ColorArrayName = [None, ""]
            display.AmbientColor = display.DiffuseColor = [0.1, 0.1, 0.1]
            display.LineWidth = 2.0
            continue
        ColorBy(display, ("CELLS", "PatchId"))
        table = GetColorTransferFunction("PatchId")
        table.ApplyPreset("Rainbow Uniform", True)
        table.RescaleTransferFunction(0.0, patch_count - 1.0)
        HideScalarBarIfNotNeeded(table, view)
        display.SetScalarBarVisibility(view, False)
        if style == "edges":
            display.SetRepresentationType("Surface With Edges")
            display.EdgeColor = [0.15, 0.15, 0.15]
    view.CameraPosition = camera_direction
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    return view


# The GUI starts with a layout holding one empty view (reused); pvpython has
# none.
for view in list(GetViews()):
    Delete(view)
layouts = list(GetLayouts().values())
layout = layouts[0] if layouts else CreateLayout("Consistent Mesh")
# The first model's straightened surface and net, and the collection's mean.
left = view_of([(straightener, "patches"), (OutputPort(straightener, 1), "lines")], [0.3, 0.35, 1.0],
               block=names[0])
right = view_of([(OutputPort(pca, 0), "edges")], [0.3, 0.35, 1.0])
layout.SplitHorizontal(0, 0.5)
layout.AssignView(1, left)
layout.AssignView(2, right)
for view in (left, right):
    view.ResetCamera(False)
SetActiveView(right)
SetActiveSource(remesher)
