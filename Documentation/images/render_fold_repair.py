"""Renders Documentation/images/fold-repair-spot.png: Spot remeshed at level
5 with L0 from model 381, the Semi-Regular Remesher's RepairFolds off (left)
and on (right), triangles facing against the surface (cell array Folded) in
red. L0 lands on Spot's belly as a long thin band whose needle triangles tip
over; the repair slides their vertices along the surface.

Usage: pvpython render_fold_repair.py PLUGIN.so DATA_DIR OUTPUT.png
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import aim, landmarked_shrec, show_folds, show_grey, side_by_side

plugin, data, output = sys.argv[1:4]
LoadPlugin(plugin, ns=globals())

base = BaseDomainBuilder(Input=landmarked_shrec(globals(), data, "381"))
spot = LandmarksFromFile(Input=ConsistentMeshSurfaceReader(FileName=data + "/spot/spot.obj"),
                         LandmarkFile=data + "/spot/spot_shrec07.pinned")
straightener = NetStraightener(Input=FeatureNetTracer(Input=spot, BaseDomain=base), BaseDomain=base)

layout, views = side_by_side("fold repair")
for view, repair in zip(views, (0, 1)):
    remesher = SemiRegularRemesher(Input=straightener, BaseDomain=base, Level=5, RepairFolds=repair,
                                   ComputeDistance=0)
    show_grey(OutputPort(remesher, 0), view, edges=False)
    show_folds(OutputPort(remesher, 0), view)
    # From below, a little from the front: the belly and the front legs.
    aim(view, (0.0, -0.15, -0.1), (0.5, -1.3, 0.2), up=(0, 0, -1), angle=30)
SaveScreenshot(output, layout, ImageResolution=[1400, 600])
print("wrote", output)
