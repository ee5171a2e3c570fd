"""Mesh PCA, Shape Blend and Wavelet Detail Transfer through the ParaView
plugin, as a pvpython user drives them: three SHREC'07 four-legged models
remeshed together at level 4 (L0 from model 381), their principal
components, a blend that must give a model back, and the paper's Figure 13
(one model's coarse shape with another's details) rendered to a PNG that
must show three animals.

Usage: pvpython TestPluginShapeAnalysis.py --plugin PLUGIN.so --data SHARED_DATA [--image OUT.png]
"""
import sys

sys.dont_write_bytecode = True  # keep the source folder clean

import numpy
from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from cmp_test_support import check, check_equal, landmarked_shrec, plugin_test_setup, screenshot_pixels, white_view
from cmp_test_support import required_field as field

MODELS = ["381", "383", "387"]


def points_of(polydata):
    return vtk_to_numpy(polydata.GetPoints().GetData()).astype(float)


def check_pca(names, remesher):
    pca = names["MeshPCA"](Input=remesher)
    check_equal((pca.Alignment, pca.NumberOfModes), ("Rigid, equal volume", 5), "Mesh PCA defaults")
    check_equal([pca.SMProxy.GetOutputPortName(i) for i in range(5)],
                ["Mean", "Coefficients", "Variances", "Synthesis", "Aligned"], "Mesh PCA output ports")
    pca.UpdatePipeline()
    mean = servermanager.Fetch(pca, idx=0)
    coefficients = servermanager.Fetch(pca, idx=1)
    # Three models span two modes; the filter must not invent more.
    modes = [mean.GetPointData().GetArray("Mode%d" % k) for k in range(3)]
    check(modes[0] is not None and modes[1] is not None and modes[2] is None,
          "expected arrays Mode0 and Mode1 only on the mean")
    check_equal(coefficients.GetNumberOfRows(), len(MODELS), "coefficient rows")
    ratios = vtk_to_numpy(mean.GetFieldData().GetArray("ExplainedVarianceRatio"))
    check(abs(ratios.sum() - 1) < 1e-9 and ratios[0] >= ratios[1] > 0,
          "explained variance ratios %s" % ratios)
    return ratios


def check_blend(names, remesher, remeshes):
    blend = names["ShapeBlend"](Input=remesher, Alignment="None")
    blend.Weights = [0, 1, 0]
    blend.UpdatePipeline()
    result = servermanager.Fetch(blend)
    error = numpy.abs(points_of(result) - points_of(remeshes.GetBlock(1))).max()
    check(error < 1e-9, "weights (0, 1, 0) without alignment are %.3g away from model 1" % error)
    check_equal(field(result, "Extrapolating"), 0.0, "Extrapolating for weights in [0, 1]")


def check_detail_transfer(names, remesher, remeshes):
    transfer = names["WaveletDetailTransfer"](Input=remesher, CoarseModel=0, DetailModel=2)
    check_equal((transfer.LastCoarseLevel, transfer.LocalFrames, transfer.ScaleDetailsToCoarseSize), (2, 1, 1),
                "Wavelet Detail Transfer defaults")
    check_equal([transfer.SMProxy.GetOutputPortName(i) for i in range(2)], ["Result", "Levels"],
                "Wavelet Detail Transfer output ports")
    transfer.UpdatePipeline()
    result = servermanager.Fetch(transfer, idx=0)
    levels = servermanager.Fetch(transfer, idx=1)
    check_equal(levels.GetNumberOfBlocks(), 5, "level meshes of a level-4 remesh")
    check_equal(list(vtk_to_numpy(result.GetFieldData().GetArray("DetailWeights"))), [0, 0, 0, 1, 1],
                "schedule of Last Coarse Level 2")

    # A schedule of zeros gives the coarse model back; its level-2 mesh is
    # the result's: the coarse shape is kept, only details change.
    transfer.DetailWeights = [0, 0, 0, 0, 0]
    transfer.UpdatePipeline()
    alone = servermanager.Fetch(transfer, idx=0)
    alone_levels = servermanager.Fetch(transfer, idx=1)
    model0 = points_of(remeshes.GetBlock(0))
    size = numpy.ptp(model0, axis=0).max()
    check(numpy.abs(points_of(alone) - model0).max() < 1e-9 * size, "weights 0 do not give model 0 back")
    coarse_change = numpy.abs(points_of(levels.GetBlock(2)) - points_of(alone_levels.GetBlock(2))).max()
    check(coarse_change < 1e-9 * size, "level 2 moved by %.3g" % coarse_change)
    change = numpy.abs(points_of(result) - model0).max()
    check(1e-3 * size < change < 0.1 * size, "the details changed model 0 by %.3g of its size" % (change / size))
    transfer.DetailWeights = []
    transfer.UpdatePipeline()
    return transfer, field(result, "TransferSeconds")


def render_figure13(names, remesher, transfer, image):
    """The coarse model, the detail model and the result side by side;
    returns the image as an (h, w, 3) array."""
    view = white_view(900, 300)
    # A blend with one weight 1 and no alignment is that model (checked above).
    shapes = [names["ShapeBlend"](Input=remesher, Alignment="None", Weights=[1, 0, 0]),
              names["ShapeBlend"](Input=remesher, Alignment="None", Weights=[0, 0, 1]), transfer]
    bounds = servermanager.Fetch(remesher).GetBlock(0).GetBounds()
    step = 1.3 * (bounds[1] - bounds[0])
    for index, shape in enumerate(shapes):
        display = simple.Show(shape, view)
        display.ColorArrayName = [None, ""]
        display.DiffuseColor = [0.85, 0.78, 0.65]
        display.Position = [index * step, 0, 0]
    # The first render resets the camera: place it afterwards. The models
    # face +x with y up (as SHREC's are); a parallel side view as wide as the
    # row of three.
    simple.Render(view)
    centre = [step + 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])]
    view.CameraPosition = [centre[0], centre[1], centre[2] + 10 * step]
    view.CameraFocalPoint = centre
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 1.1 * (2 * step + bounds[1] - bounds[0]) / 6
    simple.Render(view)
    return screenshot_pixels(view, image)


def main():
    image = "wavelet-detail-transfer.png"
    if "--image" in sys.argv:
        at = sys.argv.index("--image")
        image = sys.argv[at + 1]
        del sys.argv[at:at + 2]
    data, names = plugin_test_setup()
    base = names["BaseDomainBuilder"](Input=landmarked_shrec(names, data, MODELS[0]))
    group = simple.GroupDatasets(Input=[landmarked_shrec(names, data, m) for m in MODELS])
    group.BlockNames = MODELS
    straightener = names["NetStraightener"](Input=names["FeatureNetTracer"](Input=group, BaseDomain=base),
                                           BaseDomain=base)
    remesher = names["SemiRegularRemesher"](Input=straightener, BaseDomain=base, Level=4, ComputeDistance=0)
    remesher.UpdatePipeline()
    remeshes = servermanager.Fetch(remesher)
    check_equal(remeshes.GetNumberOfBlocks(), len(MODELS), "remeshed blocks")

    ratios = check_pca(names, remesher)
    check_blend(names, remesher, remeshes)
    transfer, seconds = check_detail_transfer(names, remesher, remeshes)

    pixels = render_figure13(names, remesher, transfer, image)
    background = (pixels == 255).all(axis=2)
    # Three animals side by side: each third of the image shows one.
    for third in range(3):
        part = background[:, third * pixels.shape[1] // 3:(third + 1) * pixels.shape[1] // 3]
        covered = 1.0 - part.mean()
        check(covered > 0.05, "third %d of the picture is %.1f%% covered: a model is missing" % (third, 100 * covered))
    print("PCA of %s at level 4: explained %s; detail transfer %.3f s; wrote %s"
          % (", ".join(MODELS), numpy.round(ratios, 3), seconds, image))


if __name__ == "__main__":
    main()
