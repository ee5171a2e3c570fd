"""Landmarks picked in ParaView: a point selection turned into FeatureId by
Landmarks From Selection (ParaView keeps an id selection sorted, so the
features follow ascending point ids; PointIds gives any order), saved with
the Landmark
file writer in each format, and read back by Landmarks From File, as a GUI
user does it (the selection made with SelectIDs on the source, as picking
makes it, and taken up when the filter is created).

Usage: pvpython TestPluginLandmarks.py PLUGIN.so EXAMPLES_DIR OUTPUT_DIR
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the source folder clean

from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from cmp_test_support import ErrorCapture, check, check_contains, check_equal, load_plugin_proxies, read_vts


def landmarks_of(proxy):
    """Vertex id of each feature, from the FeatureId array of `proxy`'s output."""
    surface = servermanager.Fetch(proxy)
    feature = vtk_to_numpy(surface.GetPointData().GetArray("FeatureId"))
    marked = {int(f): v for v, f in enumerate(feature) if f >= 0}
    check_equal(sorted(marked), list(range(len(marked))), "features")
    return [marked[f] for f in range(len(marked))]


def main():
    plugin, examples, output = sys.argv[1:4]
    os.makedirs(output, exist_ok=True)
    names = load_plugin_proxies(plugin)
    reader = names["ConsistentMeshSurfaceReader"](FileName=os.path.join(examples, "blob.off"))
    expected = [vertex for vertex, _ in read_vts(os.path.join(examples, "blob.vts"))]
    # Picked in reverse: the selection sorts them, PointIds keeps them.
    picked = list(reversed(expected))

    # As in the GUI: show the surface, select the points on it, then create
    # the filter.
    view = simple.CreateView("RenderView")
    simple.Show(reader, view)
    simple.SetActiveView(view)
    simple.SetActiveSource(reader)
    simple.SelectIDs(IDs=[value for vertex in picked for value in (0, vertex)], FieldType="POINT", Source=reader)
    from_selection = names["LandmarksFromSelection"](Input=reader)
    check(from_selection.Selection is not None, "the filter did not take up the current selection")
    check_equal(landmarks_of(from_selection), sorted(picked), "landmarks from the current selection")

    # Explicit ids win over the selection, in their order.
    from_selection.PointIds = picked
    check_equal(landmarks_of(from_selection), picked, "landmarks from PointIds")

    for extension in ("vts", "pinned", "csv"):
        path = os.path.join(output, "blob-picked." + extension)
        simple.SaveData(path, proxy=from_selection)
        check(os.path.exists(path), "no %s written" % path)
        reread = names["LandmarksFromFile"](Input=reader, LandmarkFile=path)
        check_equal(landmarks_of(reread), picked, "landmarks read back from ." + extension)

    # Bad input: a duplicate id, and a cell selection.
    from_selection.PointIds = [expected[0], expected[0]]
    algorithm = from_selection.GetClientSideObject()
    with ErrorCapture(algorithm) as errors:
        from_selection.UpdatePipeline()
    check_contains(errors.text, "duplicate landmark", "duplicate id")
    from_selection.PointIds = []
    from_selection.Selection = simple.IDSelectionSource(IDs=[0, 1], FieldType="CELL")
    with ErrorCapture(algorithm) as errors:
        from_selection.UpdatePipeline()
    check_contains(errors.text, "the selection holds cells, not points", "cell selection")
    print("%d landmarks from a selection and in a given order, saved as .vts, .pinned and .csv and read back"
          % len(expected))


if __name__ == "__main__":
    main()
