"""Attribute Transfer through the ParaView plugin, as a pvpython user drives
it: Spot's texture carried onto the level-4 remesh of SHREC model 387 (L0
from model 381), the texture coordinates of the landmarks compared with
Spot's own, and the textured remesh rendered to a PNG that must show the
texture.

Usage: pvpython TestPluginTransfer.py --plugin PLUGIN.so --data SHARED_DATA [--image OUT.png]
"""
import os
import sys

sys.dont_write_bytecode = True  # keep the source folder clean

import numpy
from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from cmp_test_support import check, check_equal, landmarked_shrec, load_plugin_proxies, screenshot_pixels, white_view
from cmp_test_support import required_field as field


def corner_values_at_landmarks(surface):
    """{feature: [(u, v) of every corner of the surface at that landmark]}."""
    feature = vtk_to_numpy(surface.GetPointData().GetArray("FeatureId"))
    corners = vtk_to_numpy(surface.GetCellData().GetArray("CornerTCoords")).reshape(-1, 3, 2)
    triangles = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    values = {}
    for t, k in zip(*numpy.nonzero(feature[triangles] >= 0)):
        values.setdefault(int(feature[triangles[t, k]]), []).append(corners[t, k])
    return values


def textured_view(transfer, texture_file, image):
    """Renders the transfer's output with the texture and returns the image
    as an (h, w, 3) array."""
    view = white_view(640, 480)
    display = simple.Show(transfer, view)
    display.ColorArrayName = [None, ""]
    display.DiffuseColor = [1, 1, 1]
    display.Texture = simple.CreateTexture(texture_file)
    view.CameraPosition = [0.6, -0.4, 2.6]
    view.CameraViewUp = [0, 1, 0]
    simple.ResetCamera(view)
    view.GetActiveCamera().Dolly(1.5)
    simple.Render(view)
    return screenshot_pixels(view, image)


def main():
    import argparse
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--image", default="spot-texture-on-387.png")
    args = parser.parse_args()
    names = load_plugin_proxies(args.plugin)

    base = names["BaseDomainBuilder"](Input=landmarked_shrec(names, args.data, "381"))
    spot_folder = os.path.join(args.data, "spot")
    spot = names["LandmarksFromFile"](
        Input=names["ConsistentMeshSurfaceReader"](FileName=os.path.join(spot_folder, "spot.obj")),
        LandmarkFile=os.path.join(spot_folder, "spot_shrec07.pinned"))
    spot_param = names["NetStraightener"](Input=names["FeatureNetTracer"](Input=spot, BaseDomain=base),
                                          BaseDomain=base)
    target_param = names["NetStraightener"](
        Input=names["FeatureNetTracer"](Input=landmarked_shrec(names, args.data, "387"), BaseDomain=base),
        BaseDomain=base)
    remesh = names["SemiRegularRemesher"](Input=target_param, BaseDomain=base, Level=4, ComputeDistance=0)
    transfer = names["AttributeTransfer"](Input=remesh, Source=spot_param, BaseDomain=base)
    check_equal(transfer.SplitTextureSeams, 1, "SplitTextureSeams default")
    transfer.UpdatePipeline()

    textured = servermanager.Fetch(transfer)
    remeshed = servermanager.Fetch(remesh)
    source = servermanager.Fetch(spot_param)
    added = int(field(textured, "SeamPointsAdded"))
    check_equal(textured.GetNumberOfPoints(), remeshed.GetNumberOfPoints() + added, "points after seam splitting")
    check_equal(textured.GetNumberOfCells(), remeshed.GetNumberOfCells(), "triangles")
    check(0 < added < 0.1 * remeshed.GetNumberOfPoints(), "seam points added: %d" % added)
    check(textured.GetPointData().GetTCoords() is not None, "no active texture coordinates")

    # Landmark f of 387 must read the texture where Spot's landmark f is.
    spot_values = corner_values_at_landmarks(source)
    worst = 0.0
    for f, values in corner_values_at_landmarks(textured).items():
        for uv in values:
            worst = max(worst, min(numpy.abs(uv - s).sum() for s in spot_values[f]))
    check(worst < 1e-4, "a landmark corner reads texture coordinates %.2g away from Spot's" % worst)

    # Without splitting, the remesh keeps the collection's connectivity.
    transfer.SplitTextureSeams = 0
    transfer.UpdatePipeline()
    unsplit = servermanager.Fetch(transfer)
    check(numpy.array_equal(vtk_to_numpy(unsplit.GetPolys().GetConnectivityArray()),
                            vtk_to_numpy(remeshed.GetPolys().GetConnectivityArray())), "unsplit connectivity changed")
    transfer.SplitTextureSeams = 1

    pixels = textured_view(transfer, os.path.join(spot_folder, "spot_texture.png"), args.image)
    background = (pixels == 255).all(axis=2)
    covered = 1.0 - background.mean()
    colours = len(numpy.unique(pixels[~background].reshape(-1, 3) // 16, axis=0))
    check(covered > 0.1, "the textured remesh covers %.1f%% of the image" % (100 * covered))
    # White shading of an untextured surface gives a few grey levels; Spot's
    # texture gives many colours.
    check(colours > 50, "only %d distinct colours: is the texture applied?" % colours)
    print("Spot's texture on 387 (level 4): %d seam points added, worst landmark corner %.2g, %.3f s, "
          "%.0f%% of the image covered, %d colours; wrote %s"
          % (added, worst, field(textured, "TransferSeconds"), 100 * covered, colours, args.image))


if __name__ == "__main__":
    main()
