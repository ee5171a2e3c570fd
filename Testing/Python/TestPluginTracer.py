"""Feature Net Tracer through the ParaView plugin, as a pvpython user drives
it: L0 from model 381, a multiblock of two models traced block by block.

Usage: pvpython TestPluginTracer.py --plugin PLUGIN.so --data SHARED_DATA
"""
import sys

sys.dont_write_bytecode = True  # keep the source folder clean

from paraview import servermanager
from paraview import simple

from cmp_test_support import landmarked_shrec, plugin_test_setup
from cmp_test_support import required_field as field


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def main():
    data, names = plugin_test_setup()

    def landmarked(model):
        return landmarked_shrec(names, data, model)

    base = names["BaseDomainBuilder"](Input=landmarked("381"))
    group = simple.GroupDatasets(Input=[landmarked("384"), landmarked("391")])
    tracer = names["FeatureNetTracer"](Input=group, BaseDomain=base)
    if abs(tracer.ParameterizationWeight - 2.0) > 1e-12 or tracer.DetectSwirls != 1:
        fail("unexpected defaults %s %s" % (tracer.ParameterizationWeight, tracer.DetectSwirls))
    tracer.UpdatePipeline()

    surfaces = servermanager.Fetch(tracer, idx=0)
    curves = servermanager.Fetch(tracer, idx=1)
    if surfaces.GetClassName() != "vtkMultiBlockDataSet" or surfaces.GetNumberOfBlocks() != 2:
        fail("output 0 is not a two-block multiblock: %s" % surfaces.GetClassName())
    if curves.GetNumberOfBlocks() != 2:
        fail("output 1 has %d blocks" % curves.GetNumberOfBlocks())
    for block in range(2):
        surface, net = surfaces.GetBlock(block), curves.GetBlock(block)
        if field(surface, "NetValid") != 1:
            fail("block %d: net not valid" % block)
        patch = surface.GetCellData().GetArray("PatchId")
        if patch is None or patch.GetRange() != (0.0, 37.0):
            fail("block %d: PatchId %s" % (block, patch and patch.GetRange()))
        if net.GetNumberOfLines() != 57:
            fail("block %d: %d curves" % (block, net.GetNumberOfLines()))
        length = field(net, "NetLengthPerSqrtArea")
        if not 10.0 < length < 24.0:
            fail("block %d: net length / sqrt(area) %.2f" % (block, length))
        print("block %d: %d triangles, %d curves, net length / sqrt(area) %.2f"
              % (block, surface.GetNumberOfCells(), net.GetNumberOfLines(), length))

    # Shortest paths (weight 0) are still a valid layout, and no longer than the default's.
    default_length = field(servermanager.Fetch(tracer, idx=1).GetBlock(0), "NetLength")
    tracer.ParameterizationWeight = 0.0
    tracer.UpdatePipeline()
    shortest = servermanager.Fetch(tracer, idx=1).GetBlock(0)
    if field(shortest, "NetValid") != 1:
        fail("weight 0: net not valid")
    if field(shortest, "NetLength") > default_length * 1.001:
        fail("weight 0 gave a longer net (%.3f) than weight 2 (%.3f)" % (field(shortest, "NetLength"), default_length))
    print("plugin tracer: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
