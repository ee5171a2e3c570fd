"""The plugin's pipeline used the way a ParaView user scripts it in pvpython:
read Spot, mark its landmarks, check it and build the base domain L0.

  pvpython TestPluginPipeline.py --data DATA --plugin PLUGIN.so
      loads the plugin with LoadPlugin (PV_PLUGIN_PATH must not provide it);
  pvpython TestPluginPipeline.py --data DATA --autoload PLUGIN_DIR
      expects ParaView to have loaded it from PV_PLUGIN_PATH at start-up.
"""

import argparse
import os
import sys

sys.dont_write_bytecode = True  # keep the source folder clean

from cmp_test_support import (
    ErrorCapture,
    array_values,
    check,
    check_base_domain,
    check_equal,
    field_value,
    landmark_ids,
    read_pinned,
)

from paraview.simple import *  # noqa: F401,F403 (as a ParaView user would)
from paraview.modules.vtkRemotingCore import vtkPVPluginTracker

PROXY_FUNCTIONS = ("ConsistentMeshSurfaceReader", "LandmarksFromFile", "CheckInputs", "BaseDomainBuilder")


def loaded_plugin_files():
    tracker = vtkPVPluginTracker.GetInstance()
    return [
        tracker.GetPluginFileName(i)
        for i in range(tracker.GetNumberOfPlugins())
        if tracker.GetPluginLoaded(i) and tracker.GetPluginName(i) == "ConsistentMeshParameterizations"
    ]


def load(args):
    if args.plugin:
        check(
            not any(name in globals() for name in PROXY_FUNCTIONS),
            "the plugin's proxies exist before LoadPlugin (is PV_PLUGIN_PATH set?)",
        )
        LoadPlugin(args.plugin, ns=globals())  # noqa: F405
        expected = os.path.realpath(args.plugin)
    else:
        expected_dir = os.path.realpath(args.autoload)
        expected = None
    for name in PROXY_FUNCTIONS:
        check(name in globals(), "paraview.simple did not provide %s()" % name)
    files = [os.path.realpath(f) for f in loaded_plugin_files()]
    check_equal(len(files), 1, "number of loaded ConsistentMeshParameterizations plugins")
    if expected:
        check_equal(files[0], expected, "loaded plugin file")
    else:
        check_equal(os.path.dirname(files[0]), expected_dir, "folder of the auto-loaded plugin")


def obj_texture_coordinates(path):
    with open(path) as f:
        return [tuple(float(w) for w in line.split()[1:3]) for line in f if line.startswith("vt ")]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--plugin", help="plugin library to load with LoadPlugin")
    mode.add_argument("--autoload", help="folder the plugin must have been auto-loaded from")
    args = parser.parse_args()
    load(args)

    obj = os.path.join(args.data, "spot", "spot.obj")
    pinned = os.path.join(args.data, "spot", "spot_shrec07.pinned")
    reader = ConsistentMeshSurfaceReader(FileName=obj)  # noqa: F405
    landmarks = LandmarksFromFile(Input=reader, LandmarkFile=pinned)  # noqa: F405
    checked = CheckInputs(Input=landmarks, RequireLandmarks=1)  # noqa: F405
    builder = BaseDomainBuilder(Input=checked)  # noqa: F405
    check_equal(builder.ShapeWeight, 1.0, "default ShapeWeight")
    check_equal(landmarks.ExpectedLandmarkCount, -1, "default ExpectedLandmarkCount")

    proxies = (reader, landmarks, checked, builder)
    with ErrorCapture(*(p.GetClientSideObject() for p in proxies)) as errors:
        surface = servermanager.Fetch(checked)  # noqa: F405
        domain = servermanager.Fetch(builder)  # noqa: F405
    check_equal(errors.messages, [], "errors of a valid pipeline")

    # The surface, as the reader made it and the check passed it on.
    check_equal(surface.GetNumberOfPoints(), 2930, "Spot points")
    check_equal(surface.GetNumberOfCells(), 5856, "Spot triangles")
    check_equal(field_value(surface, "InputCheck"), "ok", "InputCheck field value")
    check_equal(field_value(surface, "WeldedPointCount"), 0.0, "WeldedPointCount of spot.obj")
    corner = surface.GetCellData().GetArray("CornerTCoords")
    check(corner is not None, "no CornerTCoords cell array on the OBJ surface")
    check_equal((corner.GetNumberOfComponents(), corner.GetNumberOfTuples()), (6, 5856), "CornerTCoords shape")
    uv = array_values(corner)
    file_uv = obj_texture_coordinates(obj)
    for k, axis in enumerate("uv"):
        got = (min(uv[k::2]), max(uv[k::2]))
        want = (min(t[k] for t in file_uv), max(t[k] for t in file_uv))
        check(all(abs(g - w) < 1e-6 for g, w in zip(got, want)),
              "CornerTCoords %s range %r, the OBJ's vt range is %r" % (axis, got, want))

    feature = surface.GetPointData().GetArray("FeatureId")
    check(feature is not None, "no FeatureId point array")
    marked = [v for v in array_values(feature) if v >= 0]
    check_equal(len(marked), 21, "number of non-negative FeatureId values")
    check_equal(sorted(marked), list(range(21)), "FeatureId values")
    check_equal(landmark_ids(surface), dict(enumerate(read_pinned(pinned))), "landmark vertices (feature: vertex)")

    # The base domain.
    check_base_domain(domain, surface, 21, "L0")
    min_angle = field_value(domain, "MinimumAngle")
    check(min_angle is not None, "no MinimumAngle field array on L0")
    check(0.0 < min_angle <= 60.0, "MinimumAngle %r not in (0, 60] degrees" % min_angle)
    quality = field_value(domain, "MeanShapeQuality")
    check(quality is not None and 0.0 < quality <= 1.0, "MeanShapeQuality %r not in (0, 1]" % quality)

    # What the Information panel shows, through the proxies.
    check_equal(builder.GetDataInformation().GetNumberOfPoints(), 21, "L0 points (data information)")
    check_equal(builder.GetDataInformation().GetNumberOfCells(), 38, "L0 cells (data information)")
    check_equal(tuple(builder.PointData["FeatureId"].GetRange()), (0.0, 20.0), "L0 FeatureId range")
    check_equal(tuple(landmarks.PointData["FeatureId"].GetRange()), (-1.0, 20.0), "surface FeatureId range")

    # A property change re-executes the filter.
    builder.ShapeWeight = 0.0
    with ErrorCapture(builder.GetClientSideObject()) as errors:
        geometric = servermanager.Fetch(builder)  # noqa: F405
    check_equal(errors.messages, [], "errors with ShapeWeight 0")
    check_base_domain(geometric, surface, 21, "L0 with ShapeWeight 0")

    print("plugin pipeline: ok (L0 minimum angle %.2f degrees, mean shape quality %.3f)" % (min_angle, quality))
    return 0


if __name__ == "__main__":
    sys.exit(main())
